#include "studies/runner/points/sensitivity_point.hpp"

#include <exception>
#include <optional>
#include <stdexcept>
#include <utility>

#include "core/dynamics/flight_core.hpp"
#include "core/dynamics/free_flight.hpp"
#include "core/dynamics/tethered_simulation.hpp"
#include "core/dynamics/zero_moment_point.hpp"
#include "core/model/frames.hpp"
#include "core/model/invariant.hpp"
#include "studies/runner/output/atomic_file.hpp"
#include "trim/trim_solver.hpp"

namespace orni::studies {

namespace {

// Cell indices of sensitivityResultColumns().
enum Cell : std::size_t {
  kTheta,
  kSpeed,
  kTail,
  kHingePower,
  kPitchSwing,
  kAltitudeFlap,
  kAltitudeSlow,
  kNormRatio,
  kCFVMin,
  kCFVMax,
  kCFHMin,
  kCFHMax,
  kCMMin,
  kCMMax,
  kAeroPower,
  kHingePowerEq4,
  kBounded,
  kThetaMin,
  kThetaMax,
  kClimbRate,
  kCellCount
};

/// A number cell: shortest round-trip text, "" for a non-finite value (never NaN).
/// One line: control characters become spaces.
std::string oneLine(std::string s) {
  for (char& c : s)
    if (static_cast<unsigned char>(c) < 0x20) c = ' ';
  return s;
}

/// Severity of a status: the row takes the worst of its runs.
int severity(const std::string& status) {
  if (status == "failed") return 3;
  if (status == "diverged") return 2;
  if (status == "not_converged") return 1;
  return 0;
}

void worsen(SweepPointResult& r, const std::string& status) {
  if (severity(status) > severity(r.status)) r.status = status;
}

SweepPointResult runPoint(const Study& point, const SensitivitySettings& settings,
                          ModalWingCache* modal_wings) {
  SweepPointResult r;
  r.cells.assign(kCellCount, std::string());
  const FlightCoreModel model(point.vehicle, FlightCoreModel::Checks::kRequired, modal_wings);

  // The trim (its free-flight check is the free flight below).
  TrimOptions trim_options = point.trim;
  trim_options.verify_free_flight = false;
  const TrimSummary s = solveTrim(model, trim_options);
  r.status = toString(s.status);
  r.message = "trim: " + s.message;
  if (!s.converged) return r;
  const OperatingPoint& at = s.solution;
  r.cells[kTheta] = formatCell(at.theta_rad * kRadToDeg);
  r.cells[kSpeed] = formatCell(at.speed_mps);
  r.cells[kTail] = formatCell(at.tail_angle_rad * kRadToDeg);
  r.cells[kHingePowerEq4] = formatCell(s.mean.power_hinge_W);

  // Free flight from the trim point (paper Eq. 5, Figs. 6-8).
  SimulationOptions free_options;
  free_options.mode = FlightMode::kFree;
  free_options.cycles = settings.free_flight_cycles;
  free_options.free = settings.free;
  free_options.record_history = false;
  const FreeFlightSummary f = simulateFree(model, at, free_options, nullptr);
  r.message += "; free flight: " + f.message;
  if (f.status == SimulationStatus::kFailed) {
    worsen(r, "failed");
  } else if (!f.analysed) {
    worsen(r, "diverged");
    r.cells[kBounded] = "0";
  } else {
    const LimitCycleMetrics& m = f.limit_cycle;
    r.cells[kPitchSwing] = formatCell((m.theta_max_rad - m.theta_min_rad) * kRadToDeg);
    r.cells[kAltitudeFlap] = formatCell(m.altitude_p2p_fast_m);
    r.cells[kAltitudeSlow] = formatCell(m.altitude_p2p_slow_m);
    r.cells[kNormRatio] = formatCell(f.verdict.norm_ratio_max);
    r.cells[kBounded] = f.verdict.bounded ? "1" : "0";
    r.cells[kThetaMin] = formatCell(m.theta_min_rad * kRadToDeg);
    r.cells[kThetaMax] = formatCell(m.theta_max_rad * kRadToDeg);
    r.cells[kClimbRate] = formatCell(m.climb_rate_mps);
  }

  // Tethered at the trim point: the constrained flight test of the last cycle (paper Fig. 9).
  SimulationOptions tethered_options = point.trim.simulation;
  tethered_options.mode = FlightMode::kTethered;
  tethered_options.record_history = true;
  TimeHistory history;
  const SimulationSummary t = simulateTethered(model, at, tethered_options, &history);
  if (t.status == SimulationStatus::kOk || t.status == SimulationStatus::kNotConverged) {
    const std::optional<ConstrainedFlightTest> cft =
        lastCycleConstrainedFlightTest(model, at, history, tethered_options.samples_per_cycle);
    r.cells[kHingePower] = formatCell(t.mean.power_hinge_W);
    r.cells[kAeroPower] = formatCell(t.mean.power_aero_W);
    if (cft) {
      r.cells[kCFVMin] = formatCell(cft->CF_V.min);
      r.cells[kCFVMax] = formatCell(cft->CF_V.max);
      r.cells[kCFHMin] = formatCell(cft->CF_H.min);
      r.cells[kCFHMax] = formatCell(cft->CF_H.max);
      r.cells[kCMMin] = formatCell(cft->CM_CG.min);
      r.cells[kCMMax] = formatCell(cft->CM_CG.max);
    }
    if (t.status == SimulationStatus::kNotConverged) {
      worsen(r, "not_converged");
      r.message += "; tethered: " + t.message;
    } else if (!cft) {
      worsen(r, "failed");
      r.message += "; tethered: no whole last cycle to analyse";
    }
  } else {
    worsen(r, "failed");
    r.message += "; tethered: " + t.message;
  }
  return r;
}

}  // namespace

const std::vector<SensitivityColumn>& sensitivityResultColumns() {
  static const std::vector<SensitivityColumn> c = {
      {"theta_mean_deg", "deg", "trim: mean pitch attitude", true},
      {"speed_mps", "m/s", "trim: flight speed", true},
      {"tail_angle_deg", "deg", "trim: tail angle", true},
      {"hinge_power_W", "W", "flapping (hinge) power at the trim point", true},
      {"pitch_swing_deg", "deg", "free flight: pitch swing theta_max - theta_min", true},
      {"altitude_p2p_m", "m", "free flight: altitude peak-to-peak at the flapping frequency", true},
      {"altitude_p2p_slow_m", "m", "free flight: slow altitude oscillation peak-to-peak", true},
      {"norm_ratio_max", "-", "free flight: bounded-norm ratio (Eq. 5; bounded below 1)", true},
      {"CF_V_min", "-", "constrained flight test: minimum of C_F,V", true},
      {"CF_V_max", "-", "constrained flight test: maximum of C_F,V", true},
      {"CF_H_min", "-", "constrained flight test: minimum of C_F,H", true},
      {"CF_H_max", "-", "constrained flight test: maximum of C_F,H", true},
      {"CM_CG_min", "-", "constrained flight test: minimum of C_M,CG", true},
      {"CM_CG_max", "-", "constrained flight test: maximum of C_M,CG", true},
      {"power_aero_W", "W", "trim: aerodynamic power", false},
      {"hinge_power_eq4_W", "W", "trim: hinge power at the Eq. (4) point (stage 1)", false},
      {"bounded", "-", "free flight: bounded (1) or not (0)", false},
      {"theta_min_deg", "deg", "free flight: minimum pitch", false},
      {"theta_max_deg", "deg", "free flight: maximum pitch", false},
      {"climb_rate_mps", "m/s", "free flight: mean climb rate", false}};
  return c;
}

SweepPointResult runSensitivityPoint(const Study& point, const SensitivitySettings& settings,
                                     ModalWingCache* modal_wings) {
  static_assert(kCellCount == 20, "one cell per column of sensitivityResultColumns");
  SweepPointResult r;
  try {
    r = runPoint(point, settings, modal_wings);
  } catch (const std::exception& e) {
    rethrowIfProgrammingError(e);  // core/model/invariant.hpp: stops the run
    r = SweepPointResult();
    r.status = "failed";
    r.message = std::string("the run threw: ") + e.what();
    r.cells.assign(kCellCount, std::string());
  }
  if (r.cells.size() != sensitivityResultColumns().size())
    throw std::logic_error("runSensitivityPoint: one cell per result column expected");
  r.message = oneLine(std::move(r.message));
  return r;
}

}  // namespace orni::studies
