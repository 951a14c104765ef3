#include "core/dynamics/simulation_options.hpp"

#include "core/model/field_table.hpp"

namespace orni {

namespace {

/// False with "<key> must be in <range>" when `value` (SI) is outside the key's range.
bool inRange(const char* key, double value_si, std::string* why) {
  const FieldSpec& f = field(key);
  if (f.siRange().contains(value_si)) return true;
  const std::size_t dot = f.key.rfind('.');
  if (why) *why = std::string(f.key.substr(dot + 1)) + " must be in " + f.range.interval();
  return false;
}

}  // namespace

bool SimulationOptions::IsValid(std::string* why) const {
  const FreeFlightBounds& b = free.bounds;
  if (!(inRange("simulate.cycles", cycles, why) && inRange("simulate.rel_tol", rel_tol, why) &&
        inRange("simulate.abs_tol", abs_tol, why) &&
        inRange("simulate.separation_abs_tol", separation_abs_tol, why) &&
        inRange("simulate.steady_tol", steady_tol, why) &&
        inRange("simulate.samples_per_cycle", samples_per_cycle, why) &&
        inRange("simulate.free.bound_speed_mps", b.U_mps, why) &&
        inRange("simulate.free.bound_W_mps", b.W_mps, why) &&
        inRange("simulate.free.bound_theta_deg", b.theta_rad, why) &&
        inRange("simulate.free.bound_Q_degps", b.Q_radps, why) &&
        inRange("simulate.free.bound_h_m", b.h_m, why) &&
        inRange("simulate.free.transient_fraction", free.transient_fraction, why) &&
        inRange("simulate.free.divergence_ratio", free.divergence_ratio, why) &&
        inRange("simulate.free.initial_altitude_m", free.initial_altitude_m, why)))
    return false;
  if (free.periodic_start_cycles < 0 || free.periodic_start_cycles > 1000) {
    if (why) *why = "periodic_start_cycles must be in [0, 1000]";
    return false;
  }
  if (free.limit_cycle_window_samples < 1 || free.limit_cycle_window_samples > 10000000) {
    if (why) *why = "limit_cycle_window_samples must be in [1, 10^7]";
    return false;
  }
  return true;
}

}  // namespace orni
