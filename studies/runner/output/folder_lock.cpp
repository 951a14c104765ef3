#include "studies/runner/output/folder_lock.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <regex>
#include <string>
#include <system_error>
#include <vector>

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

}  // namespace

FolderBusyError::FolderBusyError(const fs::path& dir, long holder_pid)
    : std::runtime_error(
          dir.string() + ": the output folder is in use by another ornithopter run (" +
          (holder_pid > 0 ? "pid " + std::to_string(holder_pid) : std::string("pid unknown")) +
          "); wait for it to finish or choose another folder with -o"),
      holder_pid_(holder_pid) {}

OutputFolderLock::OutputFolderLock(const fs::path& dir)
    : dir_(dir), file_(dir / kFolderLockName) {
  std::error_code ec;
  fs::create_directories(dir_, ec);
  if (ec || !fs::is_directory(dir_))
    throw std::runtime_error("cannot create the output folder " + dir_.string() +
                             (ec ? ": " + ec.message() : std::string(": not a folder")));
  for (int attempt = 0; fd_ < 0; ++attempt) {
    const int fd = ::open(file_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd < 0)
      throw std::runtime_error("cannot create the lock file " + file_.string() + ": " +
                               std::strerror(errno));
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
}

OutputFolderLock::~OutputFolderLock() {
  // Unlink while still holding the lock: a waiting opener of the old file sees it is gone.
  ::unlink(file_.c_str());
  ::close(fd_);
}

}  // namespace orni::studies
