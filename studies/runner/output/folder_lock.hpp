// One writer per output folder: a run holds an exclusive flock(2) on DIR/.ornithopter.lock for
// its whole life, and the file holds the holder's pid for the message a second run prints. The
// kernel drops the lock when the holder ends, however it ends, so a lock file left behind by a
// killed run (a stale lock) is simply taken over. The lock file descriptor is close-on-exec:
// gnuplot and other children never keep a folder locked. Releasing deletes the file.
//
// The folder is checked first: a path that is a file, a symbolic link loop or a dangling link,
// or a folder that cannot be created or written is an OutputPathError naming the path.
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

/// An output folder that cannot be one: a file, a symbolic link loop, a dangling symbolic link, a
/// path through a file, a folder that cannot be created or written (bad input for the CLI:
/// exit 2). The message starts with the path as given.
class OutputPathError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Another process holds the folder (bad input for the CLI: exit 2).
class FolderBusyError : public std::runtime_error {
 public:
  FolderBusyError(const std::filesystem::path& dir, long holder_pid);
  /// The holder's pid, 0 when it has not written it yet.
  long holderPid() const noexcept { return holder_pid_; }

 private:
  long holder_pid_ = 0;
};

/// What the lock is taken for: a run (which owns the folder: its first write removes an earlier
/// run's outputs, run_outputs.hpp) or a redraw of a finished run's figures (`plot`).
enum class FolderUse { kRun, kRedraw };

class OutputFolderLock {
 public:
  /// Creates `dir` when needed and locks it. Throws FolderBusyError when another process holds
  /// it, OutputPathError when the folder or the lock file cannot be created.
  /// `kind`: the run's kind (summary.json's), for the summary of an interrupted run.
  explicit OutputFolderLock(const std::filesystem::path& dir, FolderUse use = FolderUse::kRun,
                            std::string kind = {});
  /// Released while a cancellation (SIGINT, SIGTERM) unwinds a running run: the run owns the
  /// folder (an earlier run's outputs are removed if it wrote nothing yet) and its summary.json
  /// is marked "interrupted" first (interrupted_run.hpp).
  ~OutputFolderLock();
  OutputFolderLock(const OutputFolderLock&) = delete;
  OutputFolderLock& operator=(const OutputFolderLock&) = delete;

  const std::filesystem::path& folder() const { return dir_; }
  /// Whether the folder's run is running (true from the start): a multi-study run locks every
  /// folder first and runs one study at a time; only the running one is interrupted.
  void setRunning(bool running) { running_ = running; }

 private:
  std::filesystem::path dir_;
  std::filesystem::path file_;
  FolderUse use_ = FolderUse::kRun;
  std::string kind_;
  bool running_ = true;
  int fd_ = -1;
};

}  // namespace orni::studies
