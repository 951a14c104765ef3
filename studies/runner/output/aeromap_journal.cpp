#include "studies/runner/output/aeromap_journal.hpp"

#include <charconv>
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
std::string payloadOf(const trim::AeroMapPoint& p) {
  std::string payload = toString(p.status);
  payload += ',' + std::to_string(p.cycles_run) + ',' + std::to_string(p.steady_state_cycle);
  for (const double v : {p.last_cycle_change, p.mean.FV_N, p.mean.FH_N, p.mean.M_Nm,
                         p.mean.power_aero_W, p.mean.power_hinge_W})
    payload += ',' + formatShortest(v);
  payload += ',';
  payload += p.message;
  return payload;
}

bool decodePayload(std::string_view payload, trim::AeroMapPoint* point) {
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

std::string journalRecord(std::size_t index, const trim::AeroMapPoint& p) {
  return pointJournalRecord(index, payloadOf(p));
}

bool parseJournalRecord(std::string_view line, std::size_t points, std::size_t* index,
                        trim::AeroMapPoint* point) {
  std::size_t i = 0;
  std::string_view payload;
  trim::AeroMapPoint p;
  if (!parsePointJournalRecord(line, points, &i, &payload) || !decodePayload(payload, &p))
    return false;
  *index = i;
  *point = std::move(p);
  return true;
}

AeroMapJournal::AeroMapJournal(std::filesystem::path file, std::uint64_t fingerprint,
                               std::size_t points, JournalResume* resume)
    : journal_(
          std::move(file), "aeromap", fingerprint, points,
          [](std::size_t, std::string_view payload) {
            trim::AeroMapPoint p;
            return decodePayload(payload, &p);
          },
          &opened_) {
  JournalResume r;
  r.existed = opened_.existed;
  r.fingerprint_matched = opened_.fingerprint_matched;
  r.records = opened_.records;
  r.rejected_lines = opened_.rejected_lines;
  r.points.resize(points);
  for (std::size_t i = 0; i < points; ++i) {
    if (!opened_.payloads[i]) continue;
    trim::AeroMapPoint p;
    if (decodePayload(*opened_.payloads[i], &p)) r.points[i] = std::move(p);  // always (accepted)
  }
  opened_ = PointJournalResume();
  if (resume) *resume = std::move(r);
}

void AeroMapJournal::append(std::size_t index, const trim::AeroMapPoint& point) {
  journal_.append(index, payloadOf(point));
}

void AeroMapJournal::remove() { journal_.remove(); }

}  // namespace orni::studies
