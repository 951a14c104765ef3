#include "trim/trim_options.hpp"

#include <cmath>
#include <utility>

#include "core/model/field_table.hpp"
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
    const FieldSpec& f = field("trim.bounds." + name);
    if (!(f.siRange().contains(b.lower) && f.siRange().contains(b.upper)))
      return fail("bounds must lie in " + f.range.interval() + " " + std::string(f.unit) +
                  " for " + name);
    if (!(fd_steps[i] > 0.0 && fd_steps[i] <= 0.25 * (b.upper - b.lower)))
      return fail("fd_steps must be > 0 and at most a quarter of the bound interval (" + name +
                  ")");
  }
  const std::pair<const char*, double> initial_values[] = {
      {"trim.initial.theta_mean_deg", initial.theta_rad},
      {"trim.initial.speed_mps", initial.speed_mps},
      {"trim.initial.tail_angle_deg", initial.tail_angle_rad},
      {"trim.freq_hz", initial.freq_hz}};
  for (const auto& [key, value] : initial_values)
    if (!field(key).siRange().contains(value))
      return fail(std::string(key) + " must be in " + field(key).range.interval());
  for (TrimUnknown u : unknowns) {
    const TrimBounds& b = bounds[static_cast<std::size_t>(trimIndex(u))];
    const double v = unknownValue(initial, u);
    if (!(v >= b.lower && v <= b.upper))
      return fail(std::string("initial ") + trimUnknownName(u) + " must lie inside its bounds");
  }
  // The keys of [trim]: the field table's ranges.
  const std::pair<const char*, double> keyed[] = {
      {"trim.max_iterations", max_iterations}, {"trim.residual_tol", residual_tol},
      {"trim.function_tol", function_tol},     {"trim.derivative_cycles", derivative_cycles},
      {"trim.refine_cycles", refine_cycles}};
  for (const auto& [key, value] : keyed)
    if (!field(key).range.contains(value))
      return fail(std::string(key).substr(5) + " must be in " + field(key).range.interval());
  if (!(gradient_tol >= 0.0 && gradient_tol < 1.0)) return fail("gradient_tol must be in [0, 1)");
  if (!(parameter_tol >= 0.0 && parameter_tol < 1.0))
    return fail("parameter_tol must be in [0, 1)");
  if (stall_iterations < 0 || stall_iterations > 1000)
    return fail("stall_iterations must be in [0, 1000]");
  if (!(stall_decrease > 0.0 && stall_decrease < 1.0))
    return fail("stall_decrease must be in (0, 1)");
  if (!(refine_stalled_max_residual >= 0.0 && refine_stalled_max_residual <= 1.0))
    return fail("refine_stalled_max_residual must be in [0, 1]");
  if (jacobian_threads < 1 || jacobian_threads > 64)
    return fail("jacobian_threads must be in [1, 64]");
  std::string sim_why;
  if (!simulation.IsValid(&sim_why)) return fail("simulation: " + sim_why);
  if (!periodic.IsValid(&sim_why)) return fail(sim_why);
  return true;
}

TrimOptions defaultTrimOptions(const OperatingPoint& design_point) {
  TrimOptions o;
  o.initial = design_point;
  o.design_point = design_point;
  return o;
}

void usePeriodicMethod(TrimOptions* o) {
  o->method = TrimMethod::kPeriodic;
  o->residual_tol = 1e-3;
  o->simulation.rel_tol = 1e-4;
  o->simulation.steady_tol = 1e-3;
}

}  // namespace orni
