#include "studies/runner/points/sweep_point.hpp"

#include <exception>
#include <stdexcept>
#include <utility>

#include "core/dynamics/flight_core.hpp"
#include "core/dynamics/free_flight.hpp"
#include "core/dynamics/tethered_simulation.hpp"
#include "core/model/frames.hpp"
#include "core/model/invariant.hpp"
#include "studies/runner/output/atomic_file.hpp"
#include "trim/periodic_trim.hpp"
#include "trim/trim_solver.hpp"

namespace orni::studies {

namespace {

const std::vector<SweepColumn>& trimColumns() {
  static const std::vector<SweepColumn> c = {
      {"theta_mean_deg", "deg", true},  {"speed_mps", "m/s", true},
      {"tail_angle_deg", "deg", true},  {"freq_hz", "Hz", true},
      {"power_aero_W", "W", true},      {"power_hinge_W", "W", false},
      {"residual_FV_N", "N", false},    {"residual_FH_N", "N", false},
      {"residual_M_Nm", "N m", false},  {"residual_scaled_max", "-", false},
      {"iterations", "-", false},       {"evaluations", "-", false},
      {"free_flight", "-", false},      {"bounded", "-", false},
      {"norm_ratio_max", "-", true},    {"theta_min_deg", "deg", false},
      {"theta_max_deg", "deg", false},  {"altitude_p2p_m", "m", false},
      {"dominant_freq_hz", "Hz", false}};
  return c;
}

// A periodic trim's row: the trim's columns (power_hinge_W empty: the orbit's hinge power is not
// integrated; iterations = Newton iterations, evaluations = period maps; residual_* the orbit's
// mean fuselage loads minus the weight, residual_scaled_max the periodic residual) and its
// Floquet verdict.
const std::vector<SweepColumn>& periodicTrimColumns() {
  static const std::vector<SweepColumn> c = [] {
    std::vector<SweepColumn> v = trimColumns();
    v.push_back({"max_modulus", "-", true});
    v.push_back({"floquet_stable", "-", false});
    return v;
  }();
  return c;
}

const std::vector<SweepColumn>& tetheredColumns() {
  static const std::vector<SweepColumn> c = {
      {"FV_mean_N", "N", true},     {"FH_mean_N", "N", true},         {"M_mean_Nm", "N m", true},
      {"power_aero_W", "W", true},  {"power_hinge_W", "W", false},    {"cycles_run", "-", false},
      {"steady_cycle", "-", false}, {"last_cycle_change", "-", false}};
  return c;
}

const std::vector<SweepColumn>& freeColumns() {
  static const std::vector<SweepColumn> c = {
      {"FV_mean_N", "N", false},       {"FH_mean_N", "N", false},
      {"M_mean_Nm", "N m", false},     {"power_aero_W", "W", true},
      {"cycles_run", "-", false},      {"bounded", "-", false},
      {"norm_ratio_max", "-", true},   {"theta_min_deg", "deg", true},
      {"theta_max_deg", "deg", true},  {"altitude_p2p_m", "m", true},
      {"dominant_freq_hz", "Hz", true}};
  return c;
}

const std::vector<SweepColumn>& columnsOf(StudyKind run, FlightMode mode, TrimMethod method) {
  if (run == StudyKind::kTrim)
    return method == TrimMethod::kPeriodic ? periodicTrimColumns() : trimColumns();
  return mode == FlightMode::kFree ? freeColumns() : tetheredColumns();
}

/// The columns of a point of a sweep that runs `run` (a trim point has no [simulate]).
const std::vector<SweepColumn>& pointColumns(const Study& point, StudyKind run) {
  const FlightMode mode =
      run == StudyKind::kSimulate ? point.simulate().options.mode : FlightMode::kTethered;
  return columnsOf(run, mode, point.trim.method);
}

/// A number cell: shortest round-trip text, "" for a non-finite value (never NaN).
/// One line: control characters become spaces.
std::string oneLine(std::string s) {
  for (char& c : s)
    if (static_cast<unsigned char>(c) < 0x20) c = ' ';
  return s;
}

/// The free-flight check's cells of a trim row (free_flight ... dominant_freq_hz).
void appendFreeFlightCells(const FreeFlightVerification& f, std::vector<std::string>* cells) {
  const bool verdict =
      f.status == FreeFlightStatus::kBounded || f.status == FreeFlightStatus::kUnbounded;
  for (std::string c : {std::string(toString(f.status)),
                        std::string(verdict ? (f.bounded ? "1" : "0") : ""),
                        formatCell(f.norm_ratio_max), formatCell(f.theta_min_rad * kRadToDeg),
                        formatCell(f.theta_max_rad * kRadToDeg), formatCell(f.altitude_p2p_m),
                        formatCell(f.dominant_freq_hz)})
    cells->push_back(std::move(c));
}

SweepPointResult trimPoint(const Study& point, ModalWingCache* modal_wings) {
  const FlightCoreModel model(point.vehicle, FlightCoreModel::Checks::kRequired, modal_wings);
  const TrimSummary s = solveTrim(model, point.trim);
  SweepPointResult r;
  r.status = toString(s.status);
  r.message = s.message;
  r.cells.assign(trimColumns().size(), std::string());
  if (!s.converged) return r;
  const FreeFlightVerification& f = s.free_flight;
  r.cells = {formatCell(s.solution.theta_rad * kRadToDeg),
             formatCell(s.solution.speed_mps),
             formatCell(s.solution.tail_angle_rad * kRadToDeg),
             formatCell(s.solution.freq_hz),
             formatCell(s.mean.power_aero_W),
             formatCell(s.mean.power_hinge_W),
             formatCell(s.residual.FV_N),
             formatCell(s.residual.FH_N),
             formatCell(s.residual.M_Nm),
             formatCell(s.scaled_residual_max),
             std::to_string(s.iterations),
             std::to_string(s.evaluations),
};
  appendFreeFlightCells(f, &r.cells);
  if (f.status != FreeFlightStatus::kSkipped) r.message += "; free flight: " + f.message;
  return r;
}

SweepPointResult periodicTrimPoint(const Study& point, ModalWingCache* modal_wings) {
  const FlightCoreModel model(point.vehicle, FlightCoreModel::Checks::kRequired, modal_wings);
  const PeriodicTrimSummary s = solvePeriodicTrim(model, point.trim);
  SweepPointResult r;
  r.status = toString(s.status);
  r.message = s.message;
  r.cells.assign(periodicTrimColumns().size(), std::string());
  if (!s.converged) return r;
  const FreeFlightVerification& f = s.free_flight;
  const double W = point.vehicle.body.mass_kg * point.vehicle.air.gravity_mps2;
  r.cells = {formatCell(s.solution.theta_rad * kRadToDeg),
             formatCell(s.solution.speed_mps),
             formatCell(s.solution.tail_angle_rad * kRadToDeg),
             formatCell(s.solution.freq_hz),
             formatCell(s.mean.power_aero_W),
             "",
             formatCell(s.mean.FV_N - W),
             formatCell(s.mean.FH_N),
             formatCell(s.mean.M_Nm),
             formatCell(s.shooting.residual_max),
             std::to_string(s.shooting.iterations),
             std::to_string(s.shooting.period_maps)};
  appendFreeFlightCells(f, &r.cells);
  r.cells.push_back(s.floquet_valid ? formatCell(s.floquet.max_modulus) : "");
  r.cells.push_back(s.floquet_valid ? (s.floquet.stable ? "1" : "0") : "");
  if (s.floquet_valid) r.message += "; Floquet: " + s.floquet.BriefReport();
  if (f.status != FreeFlightStatus::kSkipped) r.message += "; free flight: " + f.message;
  return r;
}

SweepPointResult tetheredPoint(const Study& point, ModalWingCache* modal_wings) {
  // The options and history of `ornithopter simulate` (simulate_command.cpp): the sampled history
  // sets the integrator's output times, so the means are bit-identical to a direct run's (the
  // history keeps only the last cycle).
  const FlightCoreModel model(point.vehicle, FlightCoreModel::Checks::kRequired, modal_wings);
  SimulationOptions opts = point.simulate().options;
  opts.record_history = true;
  TimeHistory history;
  const SimulationSummary s = simulateTethered(model, point.point, opts, &history);
  SweepPointResult r;
  r.status = toString(s.status);
  r.message = s.message;
  r.cells.assign(tetheredColumns().size(), std::string());
  if (s.status != SimulationStatus::kOk && s.status != SimulationStatus::kNotConverged) return r;
  r.cells = {formatCell(s.mean.FV_N),
             formatCell(s.mean.FH_N),
             formatCell(s.mean.M_Nm),
             formatCell(s.mean.power_aero_W),
             formatCell(s.mean.power_hinge_W),
             std::to_string(s.cycles_run),
             s.steady_state_cycle > 0 ? std::to_string(s.steady_state_cycle) : "",
             s.cycles_run > 1 ? formatCell(s.last_cycle_change) : ""};
  return r;
}

SweepPointResult freePoint(const Study& point, ModalWingCache* modal_wings) {
  // As `ornithopter simulate --mode free` (free_flight_command.cpp).
  const FlightCoreModel model(point.vehicle, FlightCoreModel::Checks::kRequired, modal_wings);
  const FreeFlightSummary s = simulateFree(model, point.point, point.simulate().options, nullptr);
  SweepPointResult r;
  r.status = toString(s.status);
  r.message = s.message;
  r.cells.assign(freeColumns().size(), std::string());
  if (s.status == SimulationStatus::kDiverged) {
    r.cells[4] = std::to_string(s.cycles_run);
    r.cells[5] = "0";
    return r;
  }
  if (s.status != SimulationStatus::kOk || !s.analysed) return r;
  const LimitCycleMetrics& m = s.limit_cycle;
  r.cells = {formatCell(s.mean.FV_N),
             formatCell(s.mean.FH_N),
             formatCell(s.mean.M_Nm),
             formatCell(s.mean.power_aero_W),
             std::to_string(s.cycles_run),
             s.verdict.bounded ? "1" : "0",
             formatCell(s.verdict.norm_ratio_max),
             formatCell(m.theta_min_rad * kRadToDeg),
             formatCell(m.theta_max_rad * kRadToDeg),
             formatCell(m.altitude_p2p_fast_m),
             formatCell(m.dominant_freq_theta_hz)};
  return r;
}

}  // namespace

std::vector<SweepColumn> sweepResultColumns(const Study& sweep) {
  return columnsOf(sweep.sweep().run, sweep.sweep().base_simulate.options.mode, sweep.trim.method);
}

SweepPointResult runSweepPoint(const Study& point, StudyKind run, ModalWingCache* modal_wings) {
  SweepPointResult r;
  try {
    if (run == StudyKind::kTrim && point.trim.method == TrimMethod::kPeriodic)
      r = periodicTrimPoint(point, modal_wings);
    else if (run == StudyKind::kTrim)
      r = trimPoint(point, modal_wings);
    else if (point.simulate().options.mode == FlightMode::kFree)
      r = freePoint(point, modal_wings);
    else
      r = tetheredPoint(point, modal_wings);
  } catch (const std::exception& e) {
    rethrowIfProgrammingError(e);  // core/model/invariant.hpp: stops the run
    r = SweepPointResult();
    r.status = "failed";
    r.message = std::string("the run threw: ") + e.what();
    r.cells.assign(pointColumns(point, run).size(), std::string());
  }
  if (r.cells.size() != pointColumns(point, run).size())
    throw std::logic_error("runSweepPoint: one cell per result column expected");
  r.message = oneLine(std::move(r.message));
  return r;
}

std::string encodeSweepPoint(const SweepPointResult& r) {
  std::string payload = r.status;
  for (const std::string& c : r.cells) payload += ',' + c;
  payload += ',';
  payload += r.message;
  return payload;
}

bool decodeSweepPoint(std::string_view payload, std::size_t columns, SweepPointResult* result) {
  SweepPointResult r;
  std::size_t start = 0;
  auto field = [&](std::string* out) {
    const std::size_t comma = payload.find(',', start);
    if (comma == std::string_view::npos) return false;
    *out = std::string(payload.substr(start, comma - start));
    start = comma + 1;
    return true;
  };
  if (!field(&r.status)) return false;
  if (r.status != "ok" && r.status != "not_converged" && r.status != "diverged" &&
      r.status != "failed")
    return false;
  r.cells.resize(columns);
  for (std::string& c : r.cells)
    if (!field(&c)) return false;
  r.message = std::string(payload.substr(start));  // the message may contain commas
  *result = std::move(r);
  return true;
}

}  // namespace orni::studies
