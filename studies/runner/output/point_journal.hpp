// A journal that makes a many-point run resumable (aero maps, sweeps): DIR/<name>.journal holds
// one line per finished point, appended as soon as the point is done, so a killed run loses at
// most its in-flight points.
//
// Format (text, one record per line):
//   # ornithopter <label> journal v1 fingerprint=<16 hex digits> points=<N>
//   <16 hex digits FNV-1a of the rest> <index>,<payload>
// The payload is the caller's one-line encoding of the point's result (no newline). A record is
// trusted only when it ends with a newline, its checksum matches, the index is < N, it is the
// first record of that index and the caller's `accept` takes its payload: a torn last line (kill
// during a write) is dropped and recomputed. The fingerprint is a hash of whatever defines the
// results (version and resolved study); a journal with another label, fingerprint or point count
// is discarded. Each record is one write(2) to the kernel (survives a killed process at once);
// fdatasync runs at most once a second and when the journal is closed (an operating-system crash
// may lose the last second of points, never trust a bad one).
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "studies/runner/output/journal_file.hpp"

namespace orni::studies {

/// FNV-1a 64-bit hash of `text`.
std::uint64_t fnv1a64(std::string_view text);

/// One journal line (with its newline) for point `index` with `payload` (newlines and carriage
/// returns in the payload become spaces).
std::string pointJournalRecord(std::size_t index, std::string_view payload);

/// Splits one journal line (without its newline) into index and payload; false when the checksum
/// does not match, the line is malformed or index >= points.
bool parsePointJournalRecord(std::string_view line, std::size_t points, std::size_t* index,
                             std::string_view* payload);

/// The caller's check of a payload read back from a journal (true = trust and keep it).
using JournalPayloadCheck = std::function<bool(std::size_t index, std::string_view payload)>;

/// What reopening a journal found.
struct PointJournalResume {
  bool existed = false;              ///< a journal file was there
  bool fingerprint_matched = false;  ///< ... written by the same label, study and version
  std::size_t records = 0;           ///< valid records taken over
  std::size_t rejected_lines = 0;    ///< torn or corrupt lines dropped
  std::vector<std::optional<std::string>> payloads;  ///< one per point; set = finished
};

class PointJournal {
 public:
  /// Opens `file` for a run of `points` points. A journal with the same label, fingerprint and
  /// point count is resumed (its valid records go to *resume); anything else there is discarded.
  /// The file is then rewritten atomically with the header and the valid records only, and kept
  /// open for appending. Throws std::runtime_error when the file cannot be written.
  PointJournal(std::filesystem::path file, std::string label, std::uint64_t fingerprint,
               std::size_t points, const JournalPayloadCheck& accept, PointJournalResume* resume);
  PointJournal(const PointJournal&) = delete;
  PointJournal& operator=(const PointJournal&) = delete;

  /// Appends the record of point `index` (one write). Throws std::runtime_error on failure.
  void append(std::size_t index, std::string_view payload);
  /// Closes and deletes the journal (after the final outputs are written).
  void remove();

  const std::filesystem::path& path() const { return file_->path(); }

 private:
  std::optional<JournalFile> file_;  // set by the constructor
};

}  // namespace orni::studies
