#include "trim/free_flight_check.hpp"

#include "core/dynamics/flight_core.hpp"
#include "core/analysis/limit_cycle.hpp"
#include "core/dynamics/free_flight.hpp"

namespace orni {

const char* toString(FreeFlightStatus s) {
  switch (s) {
    case FreeFlightStatus::kNotAvailable: return "not_available";
    case FreeFlightStatus::kSkipped: return "skipped";
    case FreeFlightStatus::kBounded: return "bounded";
    case FreeFlightStatus::kUnbounded: return "unbounded";
    case FreeFlightStatus::kFailed: return "failed";
  }
  return "failed";
}

FreeFlightVerification verifyFreeFlight(const FlightCoreModel& model, const OperatingPoint& trim,
                                        const FreeFlightCheckOptions& options) {
  FreeFlightVerification v;
  SimulationOptions o;
  o.mode = FlightMode::kFree;
  o.cycles = options.cycles;
  o.free = options.free;
  o.record_history = false;
  const FreeFlightSummary s = simulateFree(model, trim, o, nullptr);
  v.message = s.message;
  v.horizon_s = options.cycles / trim.freq_hz;
  if (s.status == SimulationStatus::kFailed) {
    v.status = FreeFlightStatus::kFailed;
    return v;
  }
  v.flown_s = s.end_time_s;
  if (!s.analysed) {  // diverged
    v.status = FreeFlightStatus::kUnbounded;
    v.bounded = false;
    return v;
  }
  v.bounded = s.verdict.bounded;
  v.status = v.bounded ? FreeFlightStatus::kBounded : FreeFlightStatus::kUnbounded;
  v.norm_ratio_max = s.verdict.norm_ratio_max;
  v.drift = s.verdict.drift_per_window;
  v.drift_limit = kDefaultDriftLimit;  // simulateFree judges with boundedNorm's default
  v.theta_min_rad = s.limit_cycle.theta_min_rad;
  v.theta_max_rad = s.limit_cycle.theta_max_rad;
  v.altitude_p2p_m = s.limit_cycle.altitude_p2p_fast_m;
  v.dominant_freq_hz = s.limit_cycle.dominant_freq_theta_hz;
  return v;
}

}  // namespace orni
