#include "studies/runner/output/journal_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <system_error>
#include <utility>

#include "studies/runner/output/atomic_file.hpp"
#include "studies/runner/output/console.hpp"

namespace orni::studies {

namespace {

constexpr double kSyncInterval_s = 1.0;

double nowSeconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

void writeAll(int fd, const std::string& text, const std::filesystem::path& file) {
  std::size_t done = 0;
  while (done < text.size()) {
    const ssize_t w = ::write(fd, text.data() + done, text.size() - done);
    if (w < 0) {
      if (errno == EINTR) continue;
      throw std::runtime_error("cannot append to " + file.string() + ": " + std::strerror(errno));
    }
    done += static_cast<std::size_t>(w);
  }
}

std::atomic<bool> g_fresh_run{false};

constexpr std::size_t kNotForeign = static_cast<std::size_t>(-1);

/// kNotForeign when `file` starts with the complete line `header` or holds nothing after its
/// first line (nothing to lose); otherwise the count of its lines after the first (the other
/// run's records).
std::size_t foreignRecords(const std::filesystem::path& file, const std::string& header) {
  std::ifstream in(file, std::ios::binary);
  std::string line;
  if (!std::getline(in, line) || (!in.eof() && line == header)) return kNotForeign;
  std::size_t records = 0;
  while (std::getline(in, line)) ++records;
  return records == 0 ? kNotForeign : records;
}

}  // namespace

std::string hex16(std::uint64_t v) {
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(v));
  return buf;
}

ForeignJournalError::ForeignJournalError(const std::filesystem::path& file, std::size_t records)
    : std::runtime_error(
          (file.has_parent_path() ? file.parent_path().string() : std::string(".")) +
          ": the folder holds " + file.filename().string() +
          ", the journal of another study, grid or version (" + std::to_string(records) +
          " finished record(s) of an interrupted run); run the same study again to resume it, "
          "run with --fresh to discard it, or choose another folder with -o") {}

void setFreshRun(bool fresh) noexcept { g_fresh_run.store(fresh); }
bool freshRun() noexcept { return g_fresh_run.load(); }

JournalFile::JournalFile(std::filesystem::path file, const std::string& header,
                         const KeepLine& keep, Reading* reading)
    : file_(std::move(file)) {
  Reading r;
  std::error_code ec;
  const bool existed = std::filesystem::exists(file_, ec);
  // Another run's journal is refused before anything is written (nothing is deleted).
  if (existed && !freshRun()) {
    const std::size_t records = foreignRecords(file_, header);
    if (records != kNotForeign) throw ForeignJournalError(file_, records);
  }
  // Line by line into the rewritten file: a journal of any length never sits in memory.
  AtomicFileWriter kept(file_);
  kept.write(header + '\n');
  if (existed && freshRun()) {
    r.existed = true;
  } else if (existed) {
    r.existed = true;
    std::ifstream in(file_, std::ios::binary);
    std::string line;
    // A complete line ends with a newline: getline reaching the end of the file without one
    // (eof) read a torn line.
    if (std::getline(in, line) && !in.eof() && line == header) {
      r.header_matched = true;
      while (std::getline(in, line)) {
        if (in.eof()) {  // torn last line: no newline
          ++r.rejected_lines;
          break;
        }
        if (keep(line)) {
          line += '\n';
          kept.write(line);
        } else {
          ++r.rejected_lines;
        }
      }
    }
  }
  // Only trusted records survive: later appends never follow a torn fragment.
  kept.commit();
  fd_ = ::open(file_.c_str(), O_WRONLY | O_APPEND | O_CLOEXEC);
  if (fd_ < 0)
    throw std::runtime_error("cannot open " + file_.string() + ": " + std::strerror(errno));
  last_sync_s_ = nowSeconds();
  if (reading) *reading = r;
}

JournalFile::~JournalFile() { close(); }

void JournalFile::close() {
  if (fd_ < 0) return;
  ::fdatasync(fd_);
  ::close(fd_);
  fd_ = -1;
}

void JournalFile::append(const std::string& line) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (fd_ < 0) throw std::logic_error("journal " + file_.string() + ": append after remove");
  writeAll(fd_, line, file_);
  const double now = nowSeconds();
  if (now - last_sync_s_ >= kSyncInterval_s) {
    ::fdatasync(fd_);
    last_sync_s_ = now;
  }
}

void JournalFile::remove() {
  std::lock_guard<std::mutex> lock(mutex_);
  close();
  std::error_code ec;
  std::filesystem::remove(file_, ec);
}

void noteJournalResume(std::string_view kind, const std::filesystem::path& path, bool existed,
                       bool fingerprint_matched, const std::string& done,
                       std::size_t rejected_lines) {
  if (!existed) return;
  if (!fingerprint_matched) {
    consoleErr() << kind << ": " << path.string() << " discarded: starting afresh\n";
    return;
  }
  consoleErr() << kind << ": resuming from " << path.string() << ": " << done
               << (rejected_lines ? " (" + std::to_string(rejected_lines) +
                                        " torn or corrupt line(s) dropped)"
                                  : std::string())
               << "\n";
}

}  // namespace orni::studies
