#include "studies/runner/output/optimize_journal.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <system_error>

#include "studies/runner/output/aeromap_journal.hpp"
#include "studies/runner/output/atomic_file.hpp"

namespace orni::studies {

namespace {

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

std::string header(std::uint64_t fingerprint, const OptimizeJournalShape& s) {
  return "# ornithopter optimize journal v1 fingerprint=" + hex16(fingerprint) +
         " variables=" + std::to_string(s.variables) + " constraints=" +
         std::to_string(s.constraints) + " values=" + std::to_string(s.values);
}

bool parseNumber(std::string_view s, double* v) {
  if (s == "nan") {
    *v = std::numeric_limits<double>::quiet_NaN();
    return true;
  }
  if (s.empty()) return false;
  const auto r = std::from_chars(s.data(), s.data() + s.size(), *v);
  return r.ec == std::errc() && r.ptr == s.data() + s.size();
}

bool parseInt(std::string_view s, int* v) {
  if (s.empty()) return false;
  const auto r = std::from_chars(s.data(), s.data() + s.size(), *v);
  return r.ec == std::errc() && r.ptr == s.data() + s.size() && *v >= 0;
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

std::string optimizeJournalRecord(const orni::opt::EvaluationRecord& r) {
  std::string p = std::to_string(r.start) + ',' + std::to_string(r.index) + ',' +
                  orni::opt::toString(r.result.status);
  for (const double v : r.x) p += ',' + formatShortest(v);
  p += ',' + formatShortest(r.result.objective);
  for (const double v : r.result.constraints) p += ',' + formatShortest(v);
  for (const double v : r.result.values) p += ',' + formatShortest(v);
  p += ',';
  for (const char c : r.result.message) p += (c == '\n' || c == '\r') ? ' ' : c;
  return hex16(fnv1a64(p)) + ' ' + p + '\n';
}

bool parseOptimizeJournalRecord(std::string_view line, const OptimizeJournalShape& shape,
                                int* start, int* index, JournaledEvaluation* out) {
  if (line.size() < 18 || line[16] != ' ') return false;
  const std::string_view payload = line.substr(17);
  if (hex16(fnv1a64(payload)) != line.substr(0, 16)) return false;
  const std::size_t numbers =
      static_cast<std::size_t>(shape.variables + 1 + shape.constraints + shape.values);
  const std::size_t fields = 3 + numbers + 1;
  std::vector<std::string_view> f;
  std::size_t pos = 0;
  for (std::size_t i = 0; i + 1 < fields; ++i) {
    const std::size_t comma = payload.find(',', pos);
    if (comma == std::string_view::npos) return false;
    f.push_back(payload.substr(pos, comma - pos));
    pos = comma + 1;
  }
  f.push_back(payload.substr(pos));  // the message may contain commas
  JournaledEvaluation e;
  int s = 0, i = 0;
  if (!parseInt(f[0], &s) || !parseInt(f[1], &i)) return false;
  if (f[2] == "ok")
    e.result.status = orni::opt::EvaluationStatus::kOk;
  else if (f[2] == "failed")
    e.result.status = orni::opt::EvaluationStatus::kFailed;
  else
    return false;
  std::vector<double> v(numbers);
  for (std::size_t k = 0; k < numbers; ++k)
    if (!parseNumber(f[3 + k], &v[k])) return false;
  const auto nv = static_cast<std::size_t>(shape.variables);
  const auto nc = static_cast<std::size_t>(shape.constraints);
  e.x.assign(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(nv));
  e.result.objective = v[nv];
  e.result.constraints.assign(v.begin() + static_cast<std::ptrdiff_t>(nv + 1),
                              v.begin() + static_cast<std::ptrdiff_t>(nv + 1 + nc));
  e.result.values.assign(v.begin() + static_cast<std::ptrdiff_t>(nv + 1 + nc), v.end());
  e.result.message = std::string(f.back());
  *start = s;
  *index = i;
  *out = std::move(e);
  return true;
}

std::optional<orni::opt::Evaluation> OptimizeJournalResume::replay(
    int start, int index, const std::vector<double>& x) const {
  const auto it = evaluations.find({start, index});
  if (it == evaluations.end() || it->second.x != x) return std::nullopt;
  return it->second.result;
}

OptimizeJournal::OptimizeJournal(std::filesystem::path file, std::uint64_t fingerprint,
                                 const OptimizeJournalShape& shape, OptimizeJournalResume* resume)
    : file_(std::move(file)) {
  OptimizeJournalResume r;
  const std::string head = header(fingerprint, shape);
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
      std::size_t pos = first_nl + 1;
      while (pos < text.size()) {
        const std::size_t nl = text.find('\n', pos);
        if (nl == std::string::npos) {  // torn last line
          ++r.rejected_lines;
          break;
        }
        const std::string_view line = std::string_view(text).substr(pos, nl - pos);
        int start = 0, index = 0;
        JournaledEvaluation e;
        if (parseOptimizeJournalRecord(line, shape, &start, &index, &e)) {
          r.evaluations[{start, index}] = std::move(e);  // a later record wins
          kept.append(line.data(), line.size());
          kept += '\n';
        } else {
          ++r.rejected_lines;
        }
        pos = nl + 1;
      }
      r.records = r.evaluations.size();
    }
  }
  writeFileAtomic(file_, kept);
  fd_ = ::open(file_.c_str(), O_WRONLY | O_APPEND | O_CLOEXEC);
  if (fd_ < 0)
    throw std::runtime_error("cannot open " + file_.string() + ": " + std::strerror(errno));
  last_sync_s_ = nowSeconds();
  if (resume) *resume = std::move(r);
}

OptimizeJournal::~OptimizeJournal() { close(); }

void OptimizeJournal::close() {
  if (fd_ < 0) return;
  ::fdatasync(fd_);
  ::close(fd_);
  fd_ = -1;
}

void OptimizeJournal::append(const orni::opt::EvaluationRecord& record) {
  const std::string line = optimizeJournalRecord(record);
  std::lock_guard<std::mutex> lock(mutex_);
  if (fd_ < 0) throw std::logic_error("OptimizeJournal: append after remove");
  writeAll(fd_, line, file_);
  const double now = nowSeconds();
  if (now - last_sync_s_ >= kSyncInterval_s) {
    ::fdatasync(fd_);
    last_sync_s_ = now;
  }
}

void OptimizeJournal::remove() {
  std::lock_guard<std::mutex> lock(mutex_);
  close();
  std::error_code ec;
  std::filesystem::remove(file_, ec);
}

}  // namespace orni::studies
