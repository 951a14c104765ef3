// One writer per output folder: a run holds an exclusive flock(2) on DIR/.ornithopter.lock for
// its whole life, and the file holds the holder's pid for the message a second run prints. The
// kernel drops the lock when the holder ends, however it ends, so a lock file left behind by a
// killed run (a stale lock) is simply taken over. The lock file descriptor is close-on-exec:
// gnuplot and other children never keep a folder locked. Releasing deletes the file.
//
// Taking the lock also clears what a killed writer of the folder may have left (only this
// program's temporary names: FILE.tmp.PID.N from atomic_file.hpp and the drawing folders
// .plot-STEM-PID.N from gnuplot.hpp), so a folder never keeps a partial file.
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>

namespace orni::studies {

/// Lock file name inside an output folder.
inline constexpr const char* kFolderLockName = ".ornithopter.lock";

/// Another process holds the folder (bad input for the CLI: exit 2).
class FolderBusyError : public std::runtime_error {
 public:
  FolderBusyError(const std::filesystem::path& dir, long holder_pid);
  /// The holder's pid, 0 when it has not written it yet.
  long holderPid() const noexcept { return holder_pid_; }

 private:
  long holder_pid_ = 0;
};

class OutputFolderLock {
 public:
  /// Creates `dir` when needed and locks it. Throws FolderBusyError when another process holds
  /// it, std::runtime_error when the folder or the lock file cannot be created.
  explicit OutputFolderLock(const std::filesystem::path& dir);
  ~OutputFolderLock();
  OutputFolderLock(const OutputFolderLock&) = delete;
  OutputFolderLock& operator=(const OutputFolderLock&) = delete;

  const std::filesystem::path& folder() const { return dir_; }

 private:
  std::filesystem::path dir_;
  std::filesystem::path file_;
  int fd_ = -1;
};

}  // namespace orni::studies
