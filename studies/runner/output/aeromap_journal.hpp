// The journal that makes an aero map resumable: DIR/aeromap.journal holds one line per finished
// point, appended as soon as the point is done, so a killed run loses at most its in-flight points.
// The file mechanics (checksums, torn lines, fingerprint, appends) are PointJournal's
// (point_journal.hpp); this file adds the aero-map record.
//
// Format (text, one record per line):
//   # ornithopter aeromap journal v1 fingerprint=<16 hex digits> points=<N>
//   <16 hex digits FNV-1a of the rest> <index>,<status>,<cycles_run>,<steady_cycle>,
//       <last_cycle_change>,<FV_N>,<FH_N>,<M_Nm>,<power_aero_W>,<power_hinge_W>,<message>
// (one line; numbers in shortest round-trip form, so a resumed point is bit-identical to a computed
// one). A record is trusted only when it ends with a newline, its checksum matches, every field
// parses and the index is < N: a torn last line (kill during a write) is dropped and recomputed.
// The fingerprint is a hash of the version and the resolved study; a journal with another
// fingerprint or point count is discarded. Each record is one write(2) to the kernel (survives a
// killed process at once); fdatasync runs at most once a second and when the journal is closed
// (an operating-system crash may lose the last second of points, never trust a bad one).
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "studies/runner/output/point_journal.hpp"
#include "trim/aero_map.hpp"

namespace orni::studies {

/// One journal line (with its newline) for point `index`.
std::string journalRecord(std::size_t index, const trim::AeroMapPoint& point);
/// Parses one journal line (without its newline); false when it is not a valid record of a map of
/// `points` points.
bool parseJournalRecord(std::string_view line, std::size_t points, std::size_t* index,
                        trim::AeroMapPoint* point);

/// What reopening a journal found.
struct JournalResume {
  bool existed = false;               ///< a journal file was there
  bool fingerprint_matched = false;   ///< ... written by the same study and version
  std::size_t records = 0;            ///< valid records taken over
  std::size_t rejected_lines = 0;     ///< torn or corrupt lines dropped
  std::vector<std::optional<trim::AeroMapPoint>> points;  ///< one per point; set = finished
};

class AeroMapJournal {
 public:
  /// Opens `file` for a map of `points` points. A journal with the same fingerprint and point
  /// count is resumed (its valid records go to *resume); anything else there is discarded. The file
  /// is then rewritten atomically with the header and the valid records only, and kept open for
  /// appending. Throws std::runtime_error when the file cannot be written.
  AeroMapJournal(std::filesystem::path file, std::uint64_t fingerprint, std::size_t points,
                 JournalResume* resume);
  AeroMapJournal(const AeroMapJournal&) = delete;
  AeroMapJournal& operator=(const AeroMapJournal&) = delete;

  /// Appends the record of point `index` (one write). Throws std::runtime_error on failure.
  void append(std::size_t index, const trim::AeroMapPoint& point);
  /// Closes and deletes the journal (after the final outputs are written).
  void remove();

  const std::filesystem::path& path() const { return journal_.path(); }

 private:
  PointJournalResume opened_;  ///< what the journal found (declared before journal_: it fills it)
  PointJournal journal_;
};

}  // namespace orni::studies
