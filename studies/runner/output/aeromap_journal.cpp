#include "studies/runner/output/aeromap_journal.hpp"

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

#include "studies/runner/output/atomic_file.hpp"

namespace orni::studies {

namespace {

constexpr int kFields = 11;  // index ... message
constexpr double kSyncInterval_s = 1.0;

double nowSeconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

std::string hex16(std::uint64_t v) {
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(v));
  return buf;
}

std::string header(std::uint64_t fingerprint, std::size_t points) {
  return "# ornithopter aeromap journal v1 fingerprint=" + hex16(fingerprint) +
         " points=" + std::to_string(points);
}

bool parseWhole(std::string_view s, double* v) {
  if (s.empty()) return false;
  const auto r = std::from_chars(s.data(), s.data() + s.size(), *v);
  return r.ec == std::errc() && r.ptr == s.data() + s.size();
}

template <typename Int>
bool parseWholeInt(std::string_view s, Int* v) {
  if (s.empty()) return false;
  const auto r = std::from_chars(s.data(), s.data() + s.size(), *v);
  return r.ec == std::errc() && r.ptr == s.data() + s.size();
}

bool parseStatus(std::string_view s, SimulationStatus* status) {
  for (const SimulationStatus k : {SimulationStatus::kOk, SimulationStatus::kNotConverged,
                                   SimulationStatus::kDiverged, SimulationStatus::kFailed}) {
    if (s == toString(k)) {
      *status = k;
      return true;
    }
  }
  return false;
}

void writeAll(int fd, const std::string& text, const std::filesystem::path& file) {
  std::size_t done = 0;
  while (done < text.size()) {
    const ssize_t w = ::write(fd, text.data() + done, text.size() - done);
    if (w < 0) {
      if (errno == EINTR) continue;
      throw std::runtime_error("cannot append to " + file.string() + ": " +
                               std::strerror(errno));
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

std::string journalRecord(std::size_t index, const trim::AeroMapPoint& p) {
  std::string payload = std::to_string(index);
  payload += ',';
  payload += toString(p.status);
  payload += ',' + std::to_string(p.cycles_run) + ',' + std::to_string(p.steady_state_cycle);
  for (const double v : {p.last_cycle_change, p.mean.FV_N, p.mean.FH_N, p.mean.M_Nm,
                         p.mean.power_aero_W, p.mean.power_hinge_W})
    payload += ',' + formatShortest(v);
  payload += ',';
  for (const char c : p.message) payload += (c == '\n' || c == '\r') ? ' ' : c;
  return hex16(fnv1a64(payload)) + ' ' + payload + '\n';
}

bool parseJournalRecord(std::string_view line, std::size_t points, std::size_t* index,
                        trim::AeroMapPoint* point) {
  if (line.size() < 18 || line[16] != ' ') return false;
  const std::string_view payload = line.substr(17);
  if (hex16(fnv1a64(payload)) != line.substr(0, 16)) return false;
  std::string_view field[kFields];
  std::size_t start = 0;
  for (int f = 0; f < kFields - 1; ++f) {
    const std::size_t comma = payload.find(',', start);
    if (comma == std::string_view::npos) return false;
    field[f] = payload.substr(start, comma - start);
    start = comma + 1;
  }
  field[kFields - 1] = payload.substr(start);  // the message may contain commas
  trim::AeroMapPoint p;
  std::size_t i = 0;
  if (!parseWholeInt(field[0], &i) || i >= points) return false;
  if (!parseStatus(field[1], &p.status)) return false;
  if (!parseWholeInt(field[2], &p.cycles_run) || !parseWholeInt(field[3], &p.steady_state_cycle))
    return false;
  double* numbers[] = {&p.last_cycle_change, &p.mean.FV_N,          &p.mean.FH_N,
                       &p.mean.M_Nm,         &p.mean.power_aero_W, &p.mean.power_hinge_W};
  for (int k = 0; k < 6; ++k)
    if (!parseWhole(field[4 + k], numbers[k])) return false;
  p.message = std::string(field[kFields - 1]);
  *index = i;
  *point = std::move(p);
  return true;
}

AeroMapJournal::AeroMapJournal(std::filesystem::path file, std::uint64_t fingerprint,
                               std::size_t points, JournalResume* resume)
    : file_(std::move(file)) {
  JournalResume r;
  r.points.resize(points);
  const std::string head = header(fingerprint, points);
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
        trim::AeroMapPoint p;
        if (parseJournalRecord(line, points, &index, &p) && !r.points[index]) {
          r.points[index] = std::move(p);
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

AeroMapJournal::~AeroMapJournal() { close(); }

void AeroMapJournal::close() {
  if (fd_ < 0) return;
  ::fdatasync(fd_);
  ::close(fd_);
  fd_ = -1;
}

void AeroMapJournal::append(std::size_t index, const trim::AeroMapPoint& point) {
  if (fd_ < 0) throw std::logic_error("AeroMapJournal: append after remove");
  writeAll(fd_, journalRecord(index, point), file_);
  const double now = nowSeconds();
  if (now - last_sync_s_ >= kSyncInterval_s) {
    ::fdatasync(fd_);
    last_sync_s_ = now;
  }
}

void AeroMapJournal::remove() {
  close();
  std::error_code ec;
  std::filesystem::remove(file_, ec);
}

}  // namespace orni::studies
