#include "studies/runner/output/point_journal.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <system_error>
#include <utility>

#include "studies/runner/output/atomic_file.hpp"

namespace orni::studies {

namespace {

constexpr double kSyncInterval_s = 1.0;

double nowSeconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

std::string hex16(std::uint64_t v) {
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(v));
  return buf;
}

std::string header(const std::string& label, std::uint64_t fingerprint, std::size_t points) {
  return "# ornithopter " + label + " journal v1 fingerprint=" + hex16(fingerprint) +
         " points=" + std::to_string(points);
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

}  // namespace

std::uint64_t fnv1a64(std::string_view text) {
  std::uint64_t h = 14695981039346656037ull;
  for (const char c : text) {
    h ^= static_cast<unsigned char>(c);
    h *= 1099511628211ull;
  }
  return h;
}

std::string pointJournalRecord(std::size_t index, std::string_view payload) {
  std::string line = std::to_string(index);
  line += ',';
  for (const char c : payload) line += (c == '\n' || c == '\r') ? ' ' : c;
  return hex16(fnv1a64(line)) + ' ' + line + '\n';
}

bool parsePointJournalRecord(std::string_view line, std::size_t points, std::size_t* index,
                             std::string_view* payload) {
  if (line.size() < 18 || line[16] != ' ') return false;
  const std::string_view rest = line.substr(17);
  if (hex16(fnv1a64(rest)) != line.substr(0, 16)) return false;
  const std::size_t comma = rest.find(',');
  if (comma == std::string_view::npos || comma == 0) return false;
  std::size_t i = 0;
  const auto r = std::from_chars(rest.data(), rest.data() + comma, i);
  if (r.ec != std::errc() || r.ptr != rest.data() + comma || i >= points) return false;
  *index = i;
  *payload = rest.substr(comma + 1);
  return true;
}

PointJournal::PointJournal(std::filesystem::path file, std::string label, std::uint64_t fingerprint,
                           std::size_t points, const JournalPayloadCheck& accept,
                           PointJournalResume* resume)
    : file_(std::move(file)) {
  PointJournalResume r;
  r.payloads.resize(points);
  const std::string head = header(label, fingerprint, points);
  std::string kept = head + '\n';

  std::error_code ec;
  if (std::filesystem::exists(file_, ec)) {
    r.existed = true;
    std::ifstream in(file_, std::ios::binary);
    std::ostringstream buf;
    buf << in.rdbuf();
    const std::string text = buf.str();
    const std::size_t first_nl = text.find('\n');
    if (first_nl != std::string::npos && std::string_view(text).substr(0, first_nl) == head) {
      r.fingerprint_matched = true;
      std::size_t start = first_nl + 1;
      while (start < text.size()) {
        const std::size_t nl = text.find('\n', start);
        if (nl == std::string::npos) {  // torn last line: no newline
          ++r.rejected_lines;
          break;
        }
        const std::string_view line = std::string_view(text).substr(start, nl - start);
        std::size_t index = 0;
        std::string_view payload;
        if (parsePointJournalRecord(line, points, &index, &payload) && !r.payloads[index] &&
            (!accept || accept(index, payload))) {
          r.payloads[index] = std::string(payload);
          ++r.records;
          kept.append(line.data(), line.size());
          kept += '\n';
        } else {
          ++r.rejected_lines;
        }
        start = nl + 1;
      }
    }
  }
  // Only trusted records survive: later appends never follow a torn fragment.
  writeFileAtomic(file_, kept);
  fd_ = ::open(file_.c_str(), O_WRONLY | O_APPEND | O_CLOEXEC);
  if (fd_ < 0)
    throw std::runtime_error("cannot open " + file_.string() + ": " + std::strerror(errno));
  last_sync_s_ = nowSeconds();
  if (resume) *resume = std::move(r);
}

PointJournal::~PointJournal() { close(); }

void PointJournal::close() {
  if (fd_ < 0) return;
  ::fdatasync(fd_);
  ::close(fd_);
  fd_ = -1;
}

void PointJournal::append(std::size_t index, std::string_view payload) {
  if (fd_ < 0) throw std::logic_error("PointJournal: append after remove");
  writeAll(fd_, pointJournalRecord(index, payload), file_);
  const double now = nowSeconds();
  if (now - last_sync_s_ >= kSyncInterval_s) {
    ::fdatasync(fd_);
    last_sync_s_ = now;
  }
}

void PointJournal::remove() {
  close();
  std::error_code ec;
  std::filesystem::remove(file_, ec);
}

}  // namespace orni::studies
