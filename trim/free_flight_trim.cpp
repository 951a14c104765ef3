#include "trim/free_flight_trim.hpp"

#include <cmath>
#include <cstdio>
#include <exception>
#include <stdexcept>

#include "core/dynamics/free_flight.hpp"

namespace orni {

SettledFlight settledFreeFlight(const FlightCoreModel& model, const OperatingPoint& point,
                                const SimulationOptions& simulation,
                                const SettledFlightOptions& options) {
  SettledFlight r;
  SimulationOptions o = simulation;
  o.mode = FlightMode::kFree;
  o.cycles = options.cycles;
  o.record_history = false;
  o.stop_when_steady = false;
  o.free.divergence_ratio = 1e6;       // a settling vehicle may leave the bounds on the way
  o.free.initial_altitude_m = 1e4;     // no ground in a trim run
  o.free.transient_fraction = 0.0;
  if (o.free.periodic_start_cycles == 0) o.free.periodic_start_cycles = 40;
  try {
    FreeFlightHistory h;
    h.keep_cycles = options.window_cycles;  // the averaged window: the last cycles
    const FreeFlightSummary s = simulateFree(model, point, o, &h);
    r.message = s.message;
    if (s.status != SimulationStatus::kOk || s.cycles_run != options.cycles) return r;
    const std::size_t spc = static_cast<std::size_t>(o.samples_per_cycle);
    const std::size_t n = spc * static_cast<std::size_t>(options.window_cycles);
    if (h.body.size() != n + 1) throw std::logic_error("settled free flight: history window");
    const std::size_t end = n;  // h holds the last window_cycles cycles and their end sample
    const std::size_t first = 0;
    double th = 0, th1 = 0, th2 = 0, V = 0;
    for (std::size_t i = first; i < end; ++i) {
      const BodyState& b = h.body[i];
      th += b.theta_rad;
      (i < first + n / 2 ? th1 : th2) += b.theta_rad;
      V += std::hypot(b.U_mps, b.W_mps);
    }
    r.theta_mean_rad = th / static_cast<double>(n);
    r.airspeed_mps = V / static_cast<double>(n);
    r.theta_drift_rad = (th2 - th1) / static_cast<double>(n / 2);
    const double climb = (h.body[end].h_m - h.body[first].h_m) / (h.t_s[end] - h.t_s[first]);
    r.climb_angle_rad = std::asin(std::max(-1.0, std::min(1.0, climb / r.airspeed_mps)));
    const bool finite = std::isfinite(r.theta_mean_rad) && std::isfinite(r.airspeed_mps) &&
                        std::isfinite(r.climb_angle_rad);
    r.ok = finite && std::abs(r.theta_drift_rad) <= options.settled_theta_drift_rad;
    char buf[200];
    std::snprintf(buf, sizeof buf,
                  "settled means over the last %d of %d cycles: theta %.3f deg, airspeed %.3f "
                  "m/s, climb angle %.3f deg, theta drift %.3f deg%s",
                  options.window_cycles, options.cycles, r.theta_mean_rad * kRadToDeg,
                  r.airspeed_mps, r.climb_angle_rad * kRadToDeg, r.theta_drift_rad * kRadToDeg,
                  r.ok ? "" : " (not settled)");
    r.message = buf;
  } catch (const std::exception& ex) {
    r.ok = false;
    r.message = ex.what();
  }
  return r;
}

FreeFlightTrim solveFreeFlightTrim(const FlightCoreModel& model, const OperatingPoint& start,
                                   const SimulationOptions& simulation,
                                   const FreeFlightTrimOptions& options) {
  FreeFlightTrim t;
  OperatingPoint p = start;
  auto fly = [&](double tail) {
    OperatingPoint q = start;
    q.tail_angle_rad = tail;
    ++t.evaluations;
    return settledFreeFlight(model, q, simulation, options.settled);
  };
  double x0 = start.tail_angle_rad;
  SettledFlight f0 = fly(x0);
  if (!f0.ok) {
    t.message = "free flight from the Eq. (4) trim did not settle: " + f0.message;
    t.settled = f0;
    return t;
  }
  double x1 = x0 + options.tail_step_rad;
  for (int it = 0; it < options.max_iterations; ++it) {
    if (std::abs(f0.climb_angle_rad) <= options.climb_angle_tol_rad) break;
    SettledFlight f1 = fly(x1);
    if (!f1.ok) {
      t.message = "free flight did not settle at tail angle " +
                  std::to_string(x1 * kRadToDeg) + " deg: " + f1.message;
      t.settled = f1;
      return t;
    }
    const double d = f1.climb_angle_rad - f0.climb_angle_rad;
    const double x2 = d != 0.0 ? x1 - f1.climb_angle_rad * (x1 - x0) / d : x1;
    x0 = x1;
    f0 = f1;
    x1 = std::max(-1.2, std::min(1.2, x2));
  }
  t.settled = f0;
  p.tail_angle_rad = x0;
  p.theta_rad = f0.theta_mean_rad;
  p.speed_mps = f0.airspeed_mps;
  t.solution = p;
  t.converged = std::abs(f0.climb_angle_rad) <= options.climb_angle_tol_rad;
  char buf[240];
  std::snprintf(buf, sizeof buf,
                "%s after %d settled free flights: tail %.3f deg gives %s",
                t.converged ? "level free flight found" : "no level free flight",
                t.evaluations, x0 * kRadToDeg, f0.message.c_str());
  t.message = buf;
  return t;
}

}  // namespace orni
