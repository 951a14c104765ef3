#include "trim/trim_options.hpp"

#include <cmath>

#include "core/model/frames.hpp"

namespace orni {

std::array<TrimBounds, kTrimUnknownCount> TrimOptions::defaultBounds() {
  std::array<TrimBounds, kTrimUnknownCount> b{};
  b[trimIndex(TrimUnknown::kThetaMean)] = {-10.0 * kDegToRad, 40.0 * kDegToRad};
  b[trimIndex(TrimUnknown::kSpeed)] = {2.0, 30.0};
  b[trimIndex(TrimUnknown::kTailAngle)] = {-30.0 * kDegToRad, 45.0 * kDegToRad};
  b[trimIndex(TrimUnknown::kFreq)] = {1.0, 40.0};
  return b;
}

std::array<double, kTrimUnknownCount> TrimOptions::defaultSteps() {
  std::array<double, kTrimUnknownCount> h{};
  h[trimIndex(TrimUnknown::kThetaMean)] = 0.05 * kDegToRad;
  h[trimIndex(TrimUnknown::kSpeed)] = 0.02;
  h[trimIndex(TrimUnknown::kTailAngle)] = 0.05 * kDegToRad;
  h[trimIndex(TrimUnknown::kFreq)] = 0.02;
  return h;
}

SimulationOptions TrimOptions::defaultSimulation() {
  SimulationOptions s;
  s.cycles = 40;
  s.rel_tol = 1e-6;
  s.steady_tol = 1e-5;
  s.record_history = false;
  s.stop_when_steady = true;
  return s;
}

bool TrimOptions::IsValid(std::string* why) const {
  auto fail = [why](const std::string& m) {
    if (why) *why = m;
    return false;
  };
  if (unknowns.empty() || unknowns.size() > static_cast<std::size_t>(kTrimResidualCount))
    return fail("unknowns must name 1 to 3 distinct unknowns (3 for a square solve)");
  for (std::size_t i = 0; i < unknowns.size(); ++i)
    for (std::size_t k = i + 1; k < unknowns.size(); ++k)
      if (unknowns[i] == unknowns[k])
        return fail(std::string("unknowns must be distinct (") + trimUnknownName(unknowns[i]) +
                    " twice)");
  for (TrimUnknown u : kAllTrimUnknowns) {
    const std::size_t i = static_cast<std::size_t>(trimIndex(u));
    const TrimBounds& b = bounds[i];
    const std::string name = trimUnknownName(u);
    if (!(std::isfinite(b.lower) && std::isfinite(b.upper) && b.lower < b.upper))
      return fail("bounds must have finite lower < upper (" + name + ")");
    if ((u == TrimUnknown::kSpeed || u == TrimUnknown::kFreq) && !(b.lower > 0.0))
      return fail("bounds must have a lower bound > 0 for " + name);
    if ((u == TrimUnknown::kThetaMean || u == TrimUnknown::kTailAngle) &&
        !(b.lower > -0.5 * kPi && b.upper < 0.5 * kPi))
      return fail("bounds must lie inside (-90, 90) deg for " + name);
    if (!(fd_steps[i] > 0.0 && fd_steps[i] <= 0.25 * (b.upper - b.lower)))
      return fail("fd_steps must be > 0 and at most a quarter of the bound interval (" + name +
                  ")");
  }
  if (!(initial.speed_mps > 0.0)) return fail("initial speed must be > 0");
  if (!(initial.freq_hz > 0.0)) return fail("initial frequency must be > 0");
  if (!(std::abs(initial.theta_rad) < 0.5 * kPi && std::abs(initial.tail_angle_rad) < 0.5 * kPi))
    return fail("initial angles must lie inside (-90, 90) deg");
  for (TrimUnknown u : unknowns) {
    const TrimBounds& b = bounds[static_cast<std::size_t>(trimIndex(u))];
    const double v = unknownValue(initial, u);
    if (!(v >= b.lower && v <= b.upper))
      return fail(std::string("initial ") + trimUnknownName(u) + " must lie inside its bounds");
  }
  if (max_iterations < 1 || max_iterations > 1000)
    return fail("max_iterations must be in [1, 1000]");
  if (!(residual_tol > 0.0 && residual_tol <= 0.1)) return fail("residual_tol must be in (0, 0.1]");
  if (!(function_tol > 0.0 && function_tol < 1.0)) return fail("function_tol must be in (0, 1)");
  if (!(gradient_tol >= 0.0 && gradient_tol < 1.0)) return fail("gradient_tol must be in [0, 1)");
  if (!(parameter_tol >= 0.0 && parameter_tol < 1.0))
    return fail("parameter_tol must be in [0, 1)");
  if (stall_iterations < 0 || stall_iterations > 1000)
    return fail("stall_iterations must be in [0, 1000]");
  if (!(stall_decrease > 0.0 && stall_decrease < 1.0))
    return fail("stall_decrease must be in (0, 1)");
  if (derivative_cycles < 1 || derivative_cycles > 1000)
    return fail("derivative_cycles must be in [1, 1000]");
  if (refine_cycles < 6 || refine_cycles > 10000)
    return fail("refine_cycles must be in [6, 10000]");
  std::string sim_why;
  if (!simulation.IsValid(&sim_why)) return fail("simulation: " + sim_why);
  if (!periodic.IsValid(&sim_why)) return fail(sim_why);
  return true;
}

TrimOptions defaultTrimOptions(const VehicleModel& vehicle) {
  TrimOptions o;
  o.initial = vehicle.operating_point;
  return o;
}

void usePeriodicMethod(TrimOptions* o) {
  o->method = TrimMethod::kPeriodic;
  o->residual_tol = 1e-3;
  o->simulation.rel_tol = 1e-4;
  o->simulation.steady_tol = 1e-3;
}

}  // namespace orni
