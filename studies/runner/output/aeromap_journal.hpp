// The journal that makes an aero map resumable: DIR/aeromap.journal holds one line per finished
// point, in point order (trim/aero_map_stream.hpp hands the points over in order), appended as
// soon as the point is handed over, so a killed run loses at most its in-flight points and the
// finished ones waiting for them (at most kAeroMapLookaheadPerThread per thread). The journal is
// also where aeromap.csv is made from at the end (replay), so no result is kept in memory: a map
// of any size runs in bounded memory. The file mechanics (torn lines, atomic rewrite, appends)
// are JournalFile's (journal_file.hpp); the records are PointJournal's (point_journal.hpp).
//
// Format (text, one record per line):
//   # ornithopter aeromap journal v2 fingerprint=<16 hex digits> points=<N>
//   <16 hex digits FNV-1a of the rest> <index>,<status>,<cycles_run>,<steady_cycle>,
//       <last_cycle_change>,<FV_N>,<FH_N>,<M_Nm>,<power_aero_W>,<power_hinge_W>,<message>
// (one line; numbers in shortest round-trip form, so a resumed point is bit-identical to a computed
// one). A record is trusted only when it ends with a newline, its checksum matches, every field
// parses and it is the next point in order (0, 1, 2, ...): a torn last line (kill during a write)
// is dropped and recomputed, and so is every record after a gap. The fingerprint is a hash of the
// version and the resolved study; a journal with another fingerprint, point count or format
// version (v1 kept the completion order) is discarded. Each record is one write(2) to the kernel
// (survives a killed process at once); fdatasync runs at most once a second and when the journal
// is closed (an operating-system crash may lose the last second of points, never trust a bad one).
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <string_view>

#include "studies/runner/output/journal_file.hpp"
#include "studies/runner/output/point_journal.hpp"
#include "trim/aero_map.hpp"

namespace orni::studies {

/// One journal line (with its newline) for point `index`.
std::string journalRecord(std::size_t index, const AeroMapPoint& point);
/// Parses one journal line (without its newline); false when it is not a valid record of a map of
/// `points` points.
bool parseJournalRecord(std::string_view line, std::size_t points, std::size_t* index,
                        AeroMapPoint* point);

/// What reopening a journal found.
struct JournalResume {
  bool existed = false;               ///< a journal file was there
  bool fingerprint_matched = false;   ///< ... written by the same study and version
  std::size_t records = 0;            ///< valid records taken over: points 0 .. records - 1
  std::size_t rejected_lines = 0;     ///< torn, corrupt or out-of-order lines dropped
};

class AeroMapJournal {
 public:
  /// Opens `file` for a map of `points` points. A journal with the same fingerprint and point
  /// count is resumed (its valid records in order are kept, *resume says how many); anything else
  /// there is discarded. The file is then rewritten atomically with the header and the kept
  /// records only, and kept open for appending. Throws std::runtime_error when the file cannot be
  /// written.
  AeroMapJournal(std::filesystem::path file, std::uint64_t fingerprint, std::size_t points,
                 JournalResume* resume);
  AeroMapJournal(const AeroMapJournal&) = delete;
  AeroMapJournal& operator=(const AeroMapJournal&) = delete;

  /// Appends the record of point `index`, which must be the next one (records() before the call;
  /// std::logic_error otherwise), in one write. Throws std::runtime_error on failure.
  void append(std::size_t index, const AeroMapPoint& point);
  /// Points recorded so far (kept on opening plus appended).
  std::size_t records() const { return records_; }
  /// Reads every record back, in point order, into visit(index, point), one at a time. Throws
  /// std::runtime_error when the file cannot be read or a record does not read back.
  void replay(const std::function<void(std::size_t, const AeroMapPoint&)>& visit) const;
  /// Closes and deletes the journal (after the final outputs are written).
  void remove();

  const std::filesystem::path& path() const { return file_->path(); }

 private:
  std::size_t points_;
  std::size_t records_ = 0;
  std::optional<JournalFile> file_;  // set by the constructor
};

}  // namespace orni::studies
