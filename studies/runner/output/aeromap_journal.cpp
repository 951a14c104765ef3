#include "studies/runner/output/aeromap_journal.hpp"

#include <charconv>
#include <fstream>
#include <stdexcept>
#include <string>
#include <system_error>
#include <utility>

#include "studies/runner/output/atomic_file.hpp"

namespace orni::studies {

namespace {

constexpr int kFields = 10;  // status ... message (after the index)

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

/// The record after "<index>,": status,cycles_run,steady_cycle,last_cycle_change,FV,FH,M,
/// power_aero,power_hinge,message.
std::string payloadOf(const AeroMapPoint& p) {
  std::string payload = toString(p.status);
  payload += ',' + std::to_string(p.cycles_run) + ',' + std::to_string(p.steady_state_cycle);
  for (const double v : {p.last_cycle_change, p.mean.FV_N, p.mean.FH_N, p.mean.M_Nm,
                         p.mean.power_aero_W, p.mean.power_hinge_W})
    payload += ',' + formatShortest(v);
  payload += ',';
  payload += p.message;
  return payload;
}

bool decodePayload(std::string_view payload, AeroMapPoint* point) {
  std::string_view field[kFields];
  std::size_t start = 0;
  for (int f = 0; f < kFields - 1; ++f) {
    const std::size_t comma = payload.find(',', start);
    if (comma == std::string_view::npos) return false;
    field[f] = payload.substr(start, comma - start);
    start = comma + 1;
  }
  field[kFields - 1] = payload.substr(start);  // the message may contain commas
  AeroMapPoint p;
  if (!parseStatus(field[0], &p.status)) return false;
  if (!parseWholeInt(field[1], &p.cycles_run) || !parseWholeInt(field[2], &p.steady_state_cycle))
    return false;
  double* numbers[] = {&p.last_cycle_change, &p.mean.FV_N,          &p.mean.FH_N,
                       &p.mean.M_Nm,         &p.mean.power_aero_W, &p.mean.power_hinge_W};
  for (int k = 0; k < 6; ++k)
    if (!parseWhole(field[3 + k], numbers[k])) return false;
  p.message = std::string(field[kFields - 1]);
  *point = std::move(p);
  return true;
}

}  // namespace

std::string journalRecord(std::size_t index, const AeroMapPoint& p) {
  return pointJournalRecord(index, payloadOf(p));
}

bool parseJournalRecord(std::string_view line, std::size_t points, std::size_t* index,
                        AeroMapPoint* point) {
  std::size_t i = 0;
  std::string_view payload;
  AeroMapPoint p;
  if (!parsePointJournalRecord(line, points, &i, &payload) || !decodePayload(payload, &p))
    return false;
  *index = i;
  *point = std::move(p);
  return true;
}

AeroMapJournal::AeroMapJournal(std::filesystem::path file, std::uint64_t fingerprint,
                               std::size_t points, JournalResume* resume)
    : points_(points) {
  JournalResume r;
  auto keep = [&](std::string_view line) {
    std::size_t index = 0;
    AeroMapPoint p;
    if (!parseJournalRecord(line, points_, &index, &p) || index != records_) return false;
    ++records_;
    return true;
  };
  JournalFile::Reading reading;
  file_.emplace(std::move(file),
                "# ornithopter aeromap journal v2 fingerprint=" + hex16(fingerprint) +
                    " points=" + std::to_string(points),
                keep, &reading);
  r.existed = reading.existed;
  r.fingerprint_matched = reading.header_matched;
  r.records = records_;
  r.rejected_lines = reading.rejected_lines;
  if (resume) *resume = r;
}

void AeroMapJournal::append(std::size_t index, const AeroMapPoint& point) {
  if (index != records_)
    throw std::logic_error("aeromap journal: point " + std::to_string(index) +
                           " appended where point " + std::to_string(records_) + " is next");
  file_->append(journalRecord(index, point));
  ++records_;
}

void AeroMapJournal::replay(
    const std::function<void(std::size_t, const AeroMapPoint&)>& visit) const {
  std::ifstream in(file_->path(), std::ios::binary);
  std::string line;
  if (!in || !std::getline(in, line))
    throw std::runtime_error("cannot read " + file_->path().string());
  for (std::size_t expected = 0; expected < records_; ++expected) {
    std::size_t index = 0;
    AeroMapPoint p;
    if (!std::getline(in, line) || !parseJournalRecord(line, points_, &index, &p) ||
        index != expected)
      throw std::runtime_error(file_->path().string() + ": record of point " +
                               std::to_string(expected) + " does not read back");
    visit(index, p);
  }
}

void AeroMapJournal::remove() { file_->remove(); }

}  // namespace orni::studies
