// The append-only file under every resumable run's journal (point_journal.hpp for aero maps and
// sweeps, optimize_journal.hpp for optimisations): a header line that names the run, then one
// record per line.
//
// Opening reads an existing file: when its first line is the expected header, each complete line
// is offered to the caller's `keep` (which parses and stores it); a torn last line (no newline)
// and every line `keep` refuses are dropped. A file with another header and records after it is
// the journal of another study, grid or version (the finished points of an interrupted run):
// opening refuses it (ForeignJournalError, bad input for the CLI: exit 2, naming the folder and
// --fresh) and leaves it untouched, unless the run was started fresh (setFreshRun(true), the
// CLI's --fresh): then any journal there is discarded and the run starts afresh. The file is then
// rewritten atomically with the header and the kept lines only, so that later appends never
// follow a torn fragment, and kept open for appending. Each append is one write(2) (a killed
// process loses nothing written); fdatasync runs at most once a second and at close (an
// operating-system crash may lose the last second). Appends are thread-safe.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <mutex>
#include <stdexcept>
#include <string>
#include <string_view>

namespace orni::studies {

/// 16 lower-case hex digits of v (the journals' checksums and fingerprints).
std::string hex16(std::uint64_t v);

/// A folder holds the journal of another study, grid or version (bad input for the CLI: exit 2).
class ForeignJournalError : public std::runtime_error {
 public:
  ForeignJournalError(const std::filesystem::path& file, std::size_t records);
};

/// Process-wide (the CLI's --fresh): every journal opened afterwards starts empty, whatever the
/// file held. Off by default: another run's journal is refused, never deleted.
void setFreshRun(bool fresh) noexcept;
bool freshRun() noexcept;

/// The console note (stderr) of a run that reopened its journal at `path`: "KIND: PATH discarded:
/// starting afresh" when it belonged to another run (!fingerprint_matched), "KIND: resuming from
/// PATH: DONE" (and how many torn or corrupt lines were dropped) when it is resumed; nothing when
/// there was none. `done` says what the journal held ("12 of 180 points already done").
void noteJournalResume(std::string_view kind, const std::filesystem::path& path, bool existed,
                       bool fingerprint_matched, const std::string& done,
                       std::size_t rejected_lines);

class JournalFile {
 public:
  /// What opening found.
  struct Reading {
    bool existed = false;         ///< a file was there
    bool header_matched = false;  ///< ... with the expected header line
    std::size_t rejected_lines = 0;  ///< torn or refused lines dropped
  };
  /// Called for every complete line after a matching header (without its newline); true keeps it.
  using KeepLine = std::function<bool(std::string_view line)>;

  /// Opens `file` with `header` (one line, no newline). Throws ForeignJournalError when the file
  /// holds another header (and the run is not fresh), std::runtime_error when the file cannot be
  /// written.
  JournalFile(std::filesystem::path file, const std::string& header, const KeepLine& keep,
              Reading* reading);
  ~JournalFile();
  JournalFile(const JournalFile&) = delete;
  JournalFile& operator=(const JournalFile&) = delete;

  /// Appends `line` (which ends with its newline) in one write. Throws std::runtime_error on
  /// failure, std::logic_error after remove().
  void append(const std::string& line);
  /// Closes and deletes the file.
  void remove();
  const std::filesystem::path& path() const { return file_; }

 private:
  void close();
  std::filesystem::path file_;
  std::mutex mutex_;
  int fd_ = -1;
  double last_sync_s_ = 0.0;
};

}  // namespace orni::studies
