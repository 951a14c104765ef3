#include "trim/free_flight_trim.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <exception>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/analysis/periodic_shooting.hpp"
#include "core/dynamics/free_flight.hpp"
#include "trim/free_flight_period_map.hpp"
#include "trim/periodic_trim.hpp"
#include "trim/trim_options.hpp"
#include "core/model/invariant.hpp"

namespace orni {

namespace {

// The cycle means of a free flight as it is flown (theta, airspeed, climb angle; the altitude and
// time at each cycle boundary) and the settling test (SettledFlightOptions) after every cycle from
// options.cycles on: the run ends at the first cycle that passes.
class SettlingMonitor final : public FreeFlightObserver {
 public:
  SettlingMonitor(int samples_per_cycle, double freq_hz, const SettledFlightOptions& options)
      : spc_(samples_per_cycle), freq_hz_(freq_hz), options_(options) {}

  void onSample(double t_s, double, const BodyState& b, const FreeFlightSample*) override {
    if (index_ > 0 && index_ % spc_ == 0) {  // the end of a cycle: close its means
      const double V = airspeed_sum_ / spc_;
      theta_.push_back(theta_sum_ / spc_);
      airspeed_.push_back(V);
      const double climb_rate = (b.h_m - h_.back()) * freq_hz_;
      climb_.push_back(std::asin(std::max(-1.0, std::min(1.0, climb_rate / V))));
      theta_sum_ = airspeed_sum_ = 0.0;
    }
    if (index_ % spc_ == 0) {
      h_.push_back(b.h_m);
      t_.push_back(t_s);
    }
    theta_sum_ += b.theta_rad;
    airspeed_sum_ += std::hypot(b.U_mps, b.W_mps);
    ++index_;
  }

  bool endRunAfterCycle(int cycle) override {
    if (cycle < options_.cycles || cycles() != cycle) return false;
    return judge(cycle).ok;
  }

  int cycles() const { return static_cast<int>(theta_.size()); }

  static bool clean(const SlowMultiplierFit& f) {
    return f.ok && f.relative_residual <= kCleanSlowFitResidual;
  }
  // The `count` cycle means of y that end with cycle `last`.
  static std::vector<double> tail(const std::vector<double>& y, std::size_t last,
                                  std::size_t count) {
    return std::vector<double>(y.begin() + static_cast<std::ptrdiff_t>(last - count),
                               y.begin() + static_cast<std::ptrdiff_t>(last));
  }

  // The means over the window that ends with cycle `cycle` (>= window_cycles) and the settling
  // test: the slowest motion fitted over the flight's second half (at least the window); with a
  // clean decaying fit, the window's means against the values it predicts; without one, the
  // bands of the window's cycle means.
  SettledFlight judge(int cycle) const {
    SettledFlight r;
    const int W = options_.window_cycles;
    const std::size_t last = static_cast<std::size_t>(cycle);
    const std::size_t first = last - static_cast<std::size_t>(W);
    auto band = [&](const std::vector<double>& y) {
      const auto mm = std::minmax_element(y.begin() + first, y.begin() + last);
      return *mm.second - *mm.first;
    };
    double th = 0.0, V = 0.0, th1 = 0.0, th2 = 0.0;
    for (std::size_t j = first; j < last; ++j) {
      th += theta_[j];
      V += airspeed_[j];
    }
    const std::size_t half = static_cast<std::size_t>(W / 2);  // the middle cycle of an odd window
    for (std::size_t j = 0; j < half; ++j) {                   // is in neither half
      th1 += theta_[first + j];
      th2 += theta_[last - half + j];
    }
    r.cycles_flown = cycle;
    r.theta_mean_rad = th / W;
    r.airspeed_mps = V / W;
    r.theta_drift_rad = half > 0 ? (th2 - th1) / static_cast<double>(half) : 0.0;
    const double climb = (h_[last] - h_[first]) / (t_[last] - t_[first]);
    r.climb_angle_rad = std::asin(std::max(-1.0, std::min(1.0, climb / r.airspeed_mps)));
    r.theta_band_rad = band(theta_);
    r.airspeed_band = band(airspeed_) / r.airspeed_mps;
    r.climb_band_rad = band(climb_);
    const bool finite = std::isfinite(r.theta_mean_rad) && std::isfinite(r.airspeed_mps) &&
                        std::isfinite(r.climb_angle_rad);
    const double tol = options_.settled_tol_rad;

    const std::size_t fitted = std::max(static_cast<std::size_t>(W), last / 2);
    r.window_theta_rad = r.theta_mean_rad;
    r.window_airspeed_mps = r.airspeed_mps;
    r.window_climb_angle_rad = r.climb_angle_rad;
    r.slow = fitSlowMultipliers(tail(theta_, last, fitted));
    if (clean(r.slow)) {
      r.unstable = r.slow.modulus >= 1.0;
      if (!r.unstable) {
        r.settled_theta_rad = r.slow.limit;
        r.settled_airspeed_mps = settledValue(r.slow, tail(airspeed_, last, fitted));
        r.settled_climb_angle_rad = settledValue(r.slow, tail(climb_, last, fitted));
        r.remaining = std::max({std::abs(r.theta_mean_rad - r.settled_theta_rad),
                                std::abs(r.airspeed_mps / r.settled_airspeed_mps - 1.0),
                                std::abs(r.climb_angle_rad - r.settled_climb_angle_rad)});
        r.ok = finite && r.remaining <= tol;  // NaN fails
        if (!r.ok && options_.extrapolate) extrapolate(last, fitted, finite, &r);
      }
    } else {
      r.ok = finite && r.theta_band_rad <= tol && r.airspeed_band <= tol && r.climb_band_rad <= tol;
    }
    return r;
  }

 private:
  // SettledFlightOptions::extrapolate: the second fit, over the last third (at least 16 cycles,
  // at most the first fit's stretch), and the two fixed points' agreement. On agreement the
  // first fit's fixed point (the longer stretch: less noise) becomes the settled means.
  void extrapolate(std::size_t last, std::size_t fitted, bool finite, SettledFlight* r) const {
    const std::size_t third = std::min(fitted, std::max<std::size_t>(16, last / 3));
    if (third == fitted) return;  // no second stretch to confirm with
    const SlowMultiplierFit b = fitSlowMultipliers(tail(theta_, last, third));
    if (!clean(b) || !(b.modulus < 1.0)) return;
    const double theta_b = b.limit;
    const double airspeed_b = settledValue(b, tail(airspeed_, last, third));
    const double climb_b = settledValue(b, tail(climb_, last, third));
    r->extrapolation_spread =
        std::max({std::abs(r->settled_theta_rad - theta_b),
                  std::abs(r->settled_airspeed_mps / airspeed_b - 1.0),
                  std::abs(r->settled_climb_angle_rad - climb_b)});
    if (!(finite && r->extrapolation_spread <= options_.settled_tol_rad)) return;  // NaN fails
    r->ok = true;
    r->extrapolated = true;
    r->theta_mean_rad = r->settled_theta_rad;
    r->airspeed_mps = r->settled_airspeed_mps;
    r->climb_angle_rad = r->settled_climb_angle_rad;
  }

  int spc_;
  double freq_hz_;
  SettledFlightOptions options_;
  long index_ = 0;  // of the next sample in the run
  double theta_sum_ = 0.0, airspeed_sum_ = 0.0;
  std::vector<double> theta_, airspeed_, climb_;  // cycle means, cycle 1 first
  std::vector<double> h_, t_;                     // at the cycle boundaries, t = 0 first
};

// How the slowest motion moves: "grows by a factor 1.0089 a cycle, an oscillation of period 3.9 s"
// or "decays by ...", empty without a clean fit.
std::string slowMotionText(const SettledFlight& r, double period_s) {
  const SlowMultiplierFit& f = r.slow;
  if (!f.ok || !(f.relative_residual <= kCleanSlowFitResidual)) return std::string();
  const double arg = std::abs(std::arg(f.mu[0]));
  char osc[80] = "";
  if (arg > 1e-3)
    std::snprintf(osc, sizeof osc, ", an oscillation of period %.2f s", 2.0 * kPi / arg * period_s);
  char buf[200];
  std::snprintf(buf, sizeof buf, "%s by a factor %.4f a cycle%s", r.unstable ? "grows" : "decays",
                f.modulus, osc);
  return buf;
}

// The periodic orbit at `point`'s tail angle and frequency (the altitude free: it may climb or
// sink), by shooting from the body at (theta, airspeed) on a path climbing at `climb` with the
// wing in its tethered periodic state, the skin friction frozen at point.speed_mps like the
// flight's; its cycle means and Floquet multipliers into r. False (with r->orbit_message) when
// Newton does not converge from there.
bool periodicOrbitNear(const FlightCoreModel& model, const OperatingPoint& point, double theta_rad,
                       double airspeed_mps, double climb_rad, SettledFlight* r) {
  FreeFlightPeriodMapOptions mo;
  mo.rel_tol = PeriodicTrimOptions{}.rel_tol;
  mo.friction_speed_mps = point.speed_mps;
  mo.design_point = point;  // scales only
  FreeFlightPeriodMap map(model, mo);
  OperatingPoint guess = point;
  guess.theta_rad = theta_rad;
  guess.speed_mps = airspeed_mps;
  std::vector<double> x = periodicStartState(model, map, guess, TrimOptions::defaultSimulation());
  const double alpha = theta_rad - climb_rad;
  x[1] = airspeed_mps * std::cos(alpha);
  x[2] = airspeed_mps * std::sin(alpha);
  ShootingOptions so;
  so.first_jacobian_states = {0, 1, 2, 3};  // as the periodic trim: the wing decays in a period
  so.jacobian_at_solution = true;           // the monodromy
  ShootingSummary s;
  try {
    s = solveShooting(map, x, FreeFlightPeriodMap::parameters(point), so);
  } catch (const std::invalid_argument& e) {  // a point the period map cannot take
    r->orbit_message = std::string("no periodic orbit: ") + e.what();
    return false;
  }
  if (s.status != ShootingStatus::kConverged || !s.jacobian_valid) {
    r->orbit_message = "no periodic orbit found from theta " +
                       std::to_string(theta_rad * kRadToDeg) + " deg, airspeed " +
                       std::to_string(airspeed_mps) + " m/s: " + s.message;
    return false;
  }
  OrbitHistory h;
  std::string why;
  const double T = 1.0 / point.freq_hz;
  if (!map.sampleOrbit(s.x.data(), s.p.data(), 64, &h, &why)) {
    r->orbit_message = "the orbit's period could not be sampled: " + why;
    return false;
  }
  const PeriodicCycleMeans m = cycleMeans(h, T);
  r->orbit_found = true;
  r->orbit_floquet = analyseFloquet(s.monodromy, T, map.stateInfo());
  r->orbit_theta_rad = m.theta_rad;
  r->orbit_airspeed_mps = m.airspeed_mps;
  r->orbit_climb_angle_rad =
      std::asin(std::max(-1.0, std::min(1.0, h.body.back().h_m / T / m.airspeed_mps)));
  return true;
}

// "mu = 0.9715 +- 0.0978i (|mu| 0.9764, phugoid-like: theta, U)"
std::string multiplierText(const FloquetMultiplier& m) {
  char buf[200];
  if (m.mu.imag() != 0.0)
    std::snprintf(buf, sizeof buf, "mu = %.4f +- %.4fi (|mu| %.4f, %s)", m.mu.real(),
                  std::abs(m.mu.imag()), m.modulus, m.label.c_str());
  else
    std::snprintf(buf, sizeof buf, "mu = %.4f (%s)", m.mu.real(), m.label.c_str());
  return buf;
}

}  // namespace

SettledFlight settledFreeFlight(const FlightCoreModel& model, const OperatingPoint& point,
                                const SimulationOptions& simulation,
                                const SettledFlightOptions& options) {
  SettledFlight r;
  SimulationOptions o = simulation;
  o.mode = FlightMode::kFree;
  o.cycles = std::max(options.cycles, options.max_cycles);
  o.record_history = false;
  o.stop_when_steady = false;
  o.free.divergence_ratio = 1e6;       // a settling vehicle may leave the bounds on the way
  o.free.initial_altitude_m = 1e4;     // no ground in a trim run
  o.free.transient_fraction = 0.0;
  if (o.free.periodic_start_cycles == 0) o.free.periodic_start_cycles = 40;
  const double period_s = 1.0 / point.freq_hz;
  try {
    SettlingMonitor monitor(o.samples_per_cycle, point.freq_hz, options);
    const FreeFlightSummary s = simulateFree(model, point, o, nullptr, &monitor);
    const int flown = monitor.cycles();
    if (s.status == SimulationStatus::kFailed) {
      r.message = s.message;
      return r;
    }
    if (flown >= options.window_cycles) r = monitor.judge(flown);
    r.cycles_flown = flown;
    const std::string slow = slowMotionText(r, period_s);
    char buf[600];
    if (s.status == SimulationStatus::kOk && r.ok && r.extrapolated) {
      std::snprintf(buf, sizeof buf,
                    "settled means predicted after %d cycles by the decay of the slowest motion "
                    "(fits over the flight's second half and last third agree to %.4f deg): "
                    "theta %.3f deg, airspeed %.3f m/s, climb angle %.3f deg (the last %d "
                    "cycles: theta %.3f deg, climb angle %.3f deg)%s%s",
                    flown, r.extrapolation_spread * kRadToDeg, r.theta_mean_rad * kRadToDeg,
                    r.airspeed_mps, r.climb_angle_rad * kRadToDeg, options.window_cycles,
                    r.window_theta_rad * kRadToDeg, r.window_climb_angle_rad * kRadToDeg,
                    slow.empty() ? "" : "; the slowest motion ", slow.c_str());
      r.message = buf;
      return r;
    }
    if (s.status == SimulationStatus::kOk && r.ok) {
      std::snprintf(buf, sizeof buf,
                    "settled means over the last %d of %d cycles: theta %.3f deg, airspeed %.3f "
                    "m/s, climb angle %.3f deg, theta drift %.3f deg%s%s",
                    options.window_cycles, flown, r.theta_mean_rad * kRadToDeg, r.airspeed_mps,
                    r.climb_angle_rad * kRadToDeg, r.theta_drift_rad * kRadToDeg,
                    slow.empty() ? "" : "; the slowest motion ", slow.c_str());
      r.message = buf;
      return r;
    }
    r.ok = false;
    // The flight alone.
    std::string flight;
    if (flown < options.window_cycles) {
      std::snprintf(buf, sizeof buf, "the flight ended after %d cycles (%s)", flown,
                    s.message.c_str());
      flight = buf;
    } else {
      char how[300];
      if (!slow.empty() && r.unstable)
        std::snprintf(how, sizeof how, "its slowest motion %s", slow.c_str());
      else if (!slow.empty())
        std::snprintf(how, sizeof how,
                      "its slowest motion %s (e-folding in %.0f cycles; theta heads for %.3f deg, "
                      "%.4f deg from the window's mean)",
                      slow.c_str(), -1.0 / std::log(r.slow.modulus),
                      r.settled_theta_rad * kRadToDeg, r.remaining * kRadToDeg);
      else
        std::snprintf(how, sizeof how,
                      "no single slow motion in its cycle means; over the last %d cycles theta "
                      "spans %.4f deg, the airspeed %.4f %%, the climb angle %.4f deg",
                      options.window_cycles, r.theta_band_rad * kRadToDeg, 100.0 * r.airspeed_band,
                      r.climb_band_rad * kRadToDeg);
      if (s.status == SimulationStatus::kOk)
        std::snprintf(buf, sizeof buf, "not settled within %d cycles (tolerance %.4f deg): %s",
                      flown, options.settled_tol_rad * kRadToDeg, how);
      else
        std::snprintf(buf, sizeof buf, "the flight ended after %d cycles (%s); %s", flown,
                      s.message.c_str(), how);
      flight = buf;
    }
    // The periodic orbit here and its multipliers: from where the flight was heading (the fit's
    // fixed point, else the window's means), else from the release.
    bool found = false;
    if (flown >= options.window_cycles) {
      const bool fixed = std::isfinite(r.settled_theta_rad) &&
                         std::isfinite(r.settled_airspeed_mps) &&
                         std::isfinite(r.settled_climb_angle_rad);
      found = periodicOrbitNear(model, point, fixed ? r.settled_theta_rad : r.theta_mean_rad,
                                fixed ? r.settled_airspeed_mps : r.airspeed_mps,
                                fixed ? r.settled_climb_angle_rad : r.climb_angle_rad, &r);
    }
    if (!found) found = periodicOrbitNear(model, point, point.theta_rad, point.speed_mps, 0.0, &r);
    if (!found) {
      r.message = (r.unstable ? "unstable: " : "not settled: ") + flight + "; " + r.orbit_message;
      return r;
    }
    const FloquetAnalysis& fa = r.orbit_floquet;
    std::snprintf(buf, sizeof buf,
                  "the periodic orbit at this tail angle (theta %.3f deg, airspeed %.3f m/s, climb "
                  "angle %.3f deg)",
                  r.orbit_theta_rad * kRadToDeg, r.orbit_airspeed_mps,
                  r.orbit_climb_angle_rad * kRadToDeg);
    const std::string orbit = buf;
    r.unstable = !fa.stable;
    if (fa.multipliers.empty()) {
      r.message = "not settled: " + flight + "; " + orbit + " has no multipliers";
    } else if (r.unstable) {
      r.message = "unstable: " + orbit + " has the Floquet multiplier " +
                  multiplierText(fa.multipliers.front()) +
                  " outside the unit circle: the released vehicle leaves it (" + flight + ")";
    } else {
      std::snprintf(buf, sizeof buf, " is Floquet-stable (largest multiplier %s, e-folding in %.0f "
                    "cycles) but ", multiplierText(fa.multipliers.front()).c_str(),
                    -1.0 / std::log(fa.max_modulus));
      r.message = "not settled: " + orbit + buf +
                  (s.status == SimulationStatus::kOk
                       ? "the flight did not reach it: " + flight
                       : "the flight released here did not reach it: " + flight);
    }
  } catch (const std::exception& ex) {
    rethrowIfProgrammingError(ex);  // core/model/invariant.hpp
    r.ok = false;
    r.message = ex.what();
  }
  return r;
}

double settledFlightRelTol(const FlightCoreModel& model) {
  const bool nonlinear = model.flexible != nullptr && model.flexible->nonlinear();
  return nonlinear ? kNonlinearWingFreeFlightRelTol : SimulationOptions{}.rel_tol;
}

FreeFlightTrim solveFreeFlightTrim(const FlightCoreModel& model, const OperatingPoint& start,
                                   const SimulationOptions& simulation,
                                   const FreeFlightTrimOptions& options) {
  FreeFlightTrim t;
  OperatingPoint p = start;
  // Each flight is released at the latest settled flight's means (the first at `start`): as the
  // secant converges the release comes ever closer to the orbit the flight settles on, and the
  // skin friction, frozen at the release speed, to the settled airspeed.
  OperatingPoint release = start;
  double tail_lo = start.tail_angle_rad, tail_hi = tail_lo;
  double climb_lo = 0.0, climb_hi = 0.0;
  auto fly = [&](double tail) {
    OperatingPoint q = release;
    q.tail_angle_rad = tail;
    ++t.evaluations;
    SettledFlight f = settledFreeFlight(model, q, simulation, options.settled);
    if (f.ok) {
      release.theta_rad = f.theta_mean_rad;
      release.speed_mps = f.airspeed_mps;
      if (t.evaluations == 1) climb_lo = climb_hi = f.climb_angle_rad;
      tail_lo = std::min(tail_lo, tail);
      tail_hi = std::max(tail_hi, tail);
      climb_lo = std::min(climb_lo, f.climb_angle_rad);
      climb_hi = std::max(climb_hi, f.climb_angle_rad);
    }
    return f;
  };
  auto failed = [&](double tail, const SettledFlight& f) {
    char where[120];
    if (t.evaluations == 1)
      std::snprintf(where, sizeof where, "free flight from the Eq. (4) trim");
    else
      std::snprintf(where, sizeof where, "free flight at tail angle %.3f deg", tail * kRadToDeg);
    t.message = std::string(where) + ": " + f.message;
    t.settled = f;
    return t;
  };
  double x0 = start.tail_angle_rad;
  SettledFlight f0 = fly(x0);
  if (!f0.ok) return failed(x0, f0);
  double x1 = x0 + options.tail_step_rad;
  for (int it = 0; it < options.max_iterations; ++it) {
    if (std::abs(f0.climb_angle_rad) <= options.climb_angle_tol_rad) break;
    SettledFlight f1 = fly(x1);
    if (!f1.ok) return failed(x1, f1);
    const double d = f1.climb_angle_rad - f0.climb_angle_rad;
    double x2 = d != 0.0 ? x1 - f1.climb_angle_rad * (x1 - x0) / d : x1;
    x2 = std::max(x1 - options.max_tail_step_rad, std::min(x1 + options.max_tail_step_rad, x2));
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
  char buf[900];
  if (t.converged)
    std::snprintf(buf, sizeof buf, "level free flight found after %d settled free flights: tail "
                  "%.3f deg gives %s", t.evaluations, x0 * kRadToDeg, f0.message.c_str());
  else
    std::snprintf(buf, sizeof buf,
                  "no level free flight after %d settled free flights: their climb angles span "
                  "%.3f to %.3f deg over tail angles %.3f to %.3f deg; tail %.3f deg gives %s",
                  t.evaluations, climb_lo * kRadToDeg, climb_hi * kRadToDeg,
                  tail_lo * kRadToDeg, tail_hi * kRadToDeg, x0 * kRadToDeg, f0.message.c_str());
  t.message = buf;
  return t;
}

}  // namespace orni
