// Atomic file output (docs/design.md 4): write to a temporary file in the same folder, flush,
// then rename over the target, so an interrupted run never leaves a truncated file.
#pragma once

#include <cstdio>
#include <filesystem>
#include <string>
#include <string_view>

namespace orni::studies {

/// "PID.N": a tag unique to this process and call (N counts up from 1, thread-safe), for the names
/// of temporary files and folders (PATH.tmp.PID.N), so that two writers never share one.
std::string uniqueTempTag();

/// Write `content` to `path` atomically (through PATH.tmp.PID.N); creates parent folders. Throws
/// std::runtime_error.
void writeFileAtomic(const std::filesystem::path& path, const std::string& content);

/// A file written piece by piece and put in place atomically: the text goes to PATH.tmp.PID.N as
/// it comes (a long run's histories never sit in memory), commit() flushes, syncs and renames it
/// over PATH. Destroyed without commit() (a failed or abandoned run, an exception) it removes the
/// temporary file and leaves PATH as it was. Throws std::runtime_error (the messages of
/// writeFileAtomic).
class AtomicFileWriter {
 public:
  /// Creates the parent folders and opens the temporary file.
  explicit AtomicFileWriter(std::filesystem::path path);
  ~AtomicFileWriter();
  AtomicFileWriter(const AtomicFileWriter&) = delete;
  AtomicFileWriter& operator=(const AtomicFileWriter&) = delete;

  void write(std::string_view text);
  /// Puts the file in place; nothing may be written after it.
  void commit();
  const std::filesystem::path& path() const { return path_; }

 private:
  void discard();
  std::filesystem::path path_, tmp_;
  std::FILE* file_ = nullptr;
};

/// Shortest decimal text that reads back to exactly the same double (deterministic output).
std::string formatShortest(double value);

/// Appends formatShortest(value) to *out (no temporary string).
void appendShortest(std::string* out, double value);

/// formatShortest(value) for a finite value, "" (an empty CSV cell: no value) otherwise.
std::string formatCell(double value);

/// printf's "%.*f": `digits` digits after the point (labels and titles, not data).
std::string formatFixed(double value, int digits);

}  // namespace orni::studies
