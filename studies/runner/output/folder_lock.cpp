#include "studies/runner/output/folder_lock.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <regex>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

#include "core/model/cancellation.hpp"
#include "studies/runner/output/interrupted_run.hpp"
#include "studies/runner/output/run_outputs.hpp"

namespace orni::studies {

namespace fs = std::filesystem;

namespace {

/// The pid written in the lock file, 0 when there is none (yet).
long pidIn(int fd) {
  char buf[32] = {};
  const ssize_t n = ::pread(fd, buf, sizeof buf - 1, 0);
  if (n <= 0) return 0;
  char* end = nullptr;
  const long pid = std::strtol(buf, &end, 10);
  return end != buf && pid > 0 ? pid : 0;
}

/// True when `fd` is still the file at `path` (a releasing holder deletes the file; a lock taken
/// on the deleted file would guard nothing).
bool sameFile(int fd, const fs::path& path) {
  struct stat held {}, now {};
  return ::fstat(fd, &held) == 0 && ::stat(path.c_str(), &now) == 0 &&
         held.st_dev == now.st_dev && held.st_ino == now.st_ino;
}

/// Removes the temporary files and drawing folders a killed writer left in `dir`.
void clearLeftovers(const fs::path& dir) {
  static const std::regex kTempFile(R"(.+\.tmp\.\d+\.\d+)");
  static const std::regex kDrawingFolder(R"(\.plot-.+-\d+\.\d+)");
  std::vector<fs::path> stale;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(dir, ec)) {
    const std::string name = e.path().filename().string();
    if (std::regex_match(name, kTempFile) || std::regex_match(name, kDrawingFolder))
      stale.push_back(e.path());
  }
  for (const fs::path& p : stale) fs::remove_all(p, ec);
}

/// Creates `dir` (and its parents) or throws OutputPathError saying what is in the way.
void makeOutputFolder(const fs::path& dir) {
  const std::string name = dir.string();
  std::error_code ec;
  const fs::file_status link = fs::symlink_status(dir, ec);
  if (!ec && fs::is_symlink(link)) {
    std::error_code target_ec;
    const fs::file_status target = fs::status(dir, target_ec);
    if (target_ec.value() == ELOOP)
      throw OutputPathError(name + ": the output folder is a symbolic link loop");
    if (!fs::exists(target)) {
      std::error_code read_ec;
      const fs::path to = fs::read_symlink(dir, read_ec);
      throw OutputPathError(name + ": the output folder is a symbolic link to a missing target" +
                            (read_ec ? std::string() : " (" + to.string() + ")") +
                            "; create the target or choose another folder with -o");
    }
  }
  ec.clear();
  const fs::file_status st = fs::status(dir, ec);
  if (ec && ec.value() == ELOOP)
    throw OutputPathError(name + ": the output folder is a symbolic link loop");
  if (!ec && fs::exists(st) && !fs::is_directory(st))
    throw OutputPathError(name + ": the output folder exists and is not a folder (" +
                          (fs::is_regular_file(st) ? "a file" : "not a folder") +
                          "); choose another folder with -o");
  ec.clear();
  fs::create_directories(dir, ec);
  if (ec || !fs::is_directory(dir))
    throw OutputPathError(name + ": cannot create the output folder: " +
                          (ec ? ec.message() : std::string("not a folder")) +
                          "; choose another folder with -o");
}

}  // namespace

FolderBusyError::FolderBusyError(const fs::path& dir, long holder_pid)
    : std::runtime_error(
          dir.string() + ": the output folder is in use by another ornithopter run (" +
          (holder_pid > 0 ? "pid " + std::to_string(holder_pid) : std::string("pid unknown")) +
          "); wait for it to finish or choose another folder with -o"),
      holder_pid_(holder_pid) {}

OutputFolderLock::OutputFolderLock(const fs::path& dir, FolderUse use, std::string kind)
    : dir_(dir), file_(dir / kFolderLockName), use_(use), kind_(std::move(kind)) {
  makeOutputFolder(dir_);
  for (int attempt = 0; fd_ < 0; ++attempt) {
    const int fd = ::open(file_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd < 0)
      throw OutputPathError(dir_.string() + ": the output folder is not writable (cannot create " +
                            "the lock file " + file_.filename().string() + ": " +
                            std::strerror(errno) + ")");
    if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
      const int err = errno;
      const long holder = pidIn(fd);
      ::close(fd);
      if (err == EWOULDBLOCK) throw FolderBusyError(dir_, holder);
      throw std::runtime_error("cannot lock " + file_.string() + ": " + std::strerror(err));
    }
    if (sameFile(fd, file_)) {
      fd_ = fd;
    } else {
      ::close(fd);
      if (attempt >= 100)
        throw std::runtime_error("cannot lock " + file_.string() + ": it keeps being replaced");
    }
  }
  const std::string pid = std::to_string(::getpid()) + "\n";
  if (::ftruncate(fd_, 0) != 0 ||
      ::pwrite(fd_, pid.data(), pid.size(), 0) != static_cast<ssize_t>(pid.size())) {
    const int err = errno;
    ::unlink(file_.c_str());
    ::close(fd_);
    throw std::runtime_error("cannot write the lock file " + file_.string() + ": " +
                             std::strerror(err));
  }
  clearLeftovers(dir_);
  if (use_ == FolderUse::kRun) expectRunFolder(dir_);
}

OutputFolderLock::~OutputFolderLock() {
  if (use_ == FolderUse::kRun) {
    if (running_ && std::uncaught_exceptions() > 0 && cancellationRequested()) {
      claimRunFolder(dir_ / "summary.json");  // the interrupted run's folder, not an earlier one's
      markRunInterrupted(dir_, kind_);
    }
    forgetRunFolder(dir_);
  }
  // Unlink while still holding the lock: a waiting opener of the old file sees it is gone.
  ::unlink(file_.c_str());
  ::close(fd_);
}

}  // namespace orni::studies
