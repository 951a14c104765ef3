#include "studies/runner/output/optimize_journal.hpp"

#include <charconv>
#include <cmath>
#include <limits>
#include <system_error>

#include "studies/runner/output/aeromap_journal.hpp"
#include "studies/runner/output/atomic_file.hpp"

namespace orni::studies {

namespace {

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
                                 const OptimizeJournalShape& shape, OptimizeJournalResume* resume) {
  OptimizeJournalResume r;
  auto keep = [&](std::string_view line) {
    int start = 0, index = 0;
    JournaledEvaluation e;
    if (!parseOptimizeJournalRecord(line, shape, &start, &index, &e)) return false;
    r.evaluations[{start, index}] = std::move(e);  // a later record wins
    return true;
  };
  JournalFile::Reading reading;
  file_.emplace(std::move(file), header(fingerprint, shape), keep, &reading);
  r.existed = reading.existed;
  r.fingerprint_matched = reading.header_matched;
  r.rejected_lines = reading.rejected_lines;
  r.records = r.evaluations.size();
  if (resume) *resume = std::move(r);
}

void OptimizeJournal::append(const orni::opt::EvaluationRecord& record) {
  file_->append(optimizeJournalRecord(record));
}

void OptimizeJournal::remove() { file_->remove(); }

}  // namespace orni::studies
