#include "core/dynamics/free_flight.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "core/analysis/harmonics.hpp"
#include "core/dynamics/flapping.hpp"
#include "core/dynamics/flight_path_frame.hpp"
#include "core/dynamics/history_window.hpp"
#include "core/integrate/ode_integrator.hpp"
#include "core/model/cancellation.hpp"

namespace orni {

BodyState trimmedBodyState(const OperatingPoint& point, double altitude_m) {
  BodyState b;
  b.h_m = altitude_m;
  b.theta_rad = point.theta_rad;
  b.U_mps = point.speed_mps * std::cos(point.theta_rad);
  b.W_mps = point.speed_mps * std::sin(point.theta_rad);
  return b;
}

namespace {

constexpr double kThetaLimit_rad = 85.0 * kDegToRad;

BodyState bodyOf(const double* y) {
  return BodyState{y[0], y[1], y[2], y[3], y[4], y[5]};
}

// Scaled deviation norm of [U W theta Q h] and the worst state; empty name when finite.
double scaledNorm(const BodyState& s, const BodyState& ref, const FreeFlightBounds& b,
                  double R_Q, const char** worst) {
  const double d[5] = {(s.U_mps - ref.U_mps) / b.U_mps, (s.W_mps - ref.W_mps) / b.W_mps,
                       (s.theta_rad - ref.theta_rad) / b.theta_rad, (s.Q_radps - ref.Q_radps) / R_Q,
                       (s.h_m - ref.h_m) / b.h_m};
  static const char* names[5] = {"U", "W", "theta", "Q", "h"};
  double sq = 0.0, big = -1.0;
  for (int i = 0; i < 5; ++i) {
    sq += d[i] * d[i];
    if (std::abs(d[i]) > big) {
      big = std::abs(d[i]);
      *worst = names[i];
    }
  }
  return std::sqrt(sq);
}

// Release in the periodic state instead of from rest (FreeFlightOptions::periodic_start_cycles):
// the wing's modes and aerodynamic states from a tethered run at the same point (end of a cycle,
// flap phase 0), and the body's periodic oscillation to first order: the zero-mean parts of the
// tethered loads over that cycle integrated once (U, W, Q) and twice (theta), with the vehicle's
// mass and pitch inertia. Without it the release at Q = 0 starts a pitch and phugoid transient
// (a zero-mean moment integrated from one phase has a non-zero mean rate). Returns why the
// tethered run could not give the periodic state (it failed or diverged), empty on success.
std::string startFromPeriodicState(const FlightCoreModel& model, const OperatingPoint& point,
                                   const SimulationOptions& options, const FreeFlightSystem& sys,
                                   FreeFlightSummary* summary, double* y0) {
  SimulationOptions t = options;
  t.mode = FlightMode::kTethered;
  t.cycles = options.free.periodic_start_cycles;
  t.stop_when_steady = true;
  t.record_history = true;
  // 32 samples per cycle integrate the periodic loads to well below the release's own first-order
  // error; the flexible wing's loads are nodal sums over the mesh, so fewer samples are cheaper.
  t.samples_per_cycle = 32;
  TimeHistory hist;
  const SimulationSummary ts = simulateTethered(model, point, t, &hist);
  if (ts.status != SimulationStatus::kOk && ts.status != SimulationStatus::kNotConverged)
    return std::string(toString(ts.status)) + ": " + ts.message;
  const int M = sys.modeCount();
  const std::vector<double>& w = ts.final_wing_state;
  if (ts.final_mode_count != M ||
      static_cast<int>(w.size()) != 2 * M + (sys.powerOffset() - sys.aeroOffset()))
    throw std::logic_error("free flight: tethered periodic state has another layout");
  std::copy(w.begin(), w.end(), y0 + FreeFlightSystem::kBody);

  // Body oscillation over the last cycle (uniform samples, endpoint = the release point).
  const std::size_t spc = static_cast<std::size_t>(t.samples_per_cycle);
  if (hist.loads.size() < spc + 1) return std::string();
  const std::size_t first = hist.loads.size() - 1 - spc;
  const double dt = 1.0 / (point.freq_hz * static_cast<double>(spc));
  const double m = model.vehicle.body.mass_kg, I = model.vehicle.body.pitch_inertia_kgm2;
  const BodyMotion bm = tetheredBodyMotion(point.speed_mps, point.theta_rad);
  const FlightPathFrame path = flightPathFrame(bm.v_P1_B);
  const Vec3& e_v = path.e_v_B;
  const Vec3& e_L = path.e_L_B;
  // Accelerations a_k (k = 0..spc) with their cycle mean removed, integrated by trapezoids, the
  // result made zero-mean: the periodic velocity; once more: the periodic displacement.
  auto periodic = [&](const std::vector<double>& a) {
    std::vector<double> v(spc + 1, 0.0);
    double mean_a = 0.0;
    for (std::size_t k = 0; k < spc; ++k) mean_a += a[k];
    mean_a /= static_cast<double>(spc);
    for (std::size_t k = 1; k <= spc; ++k)
      v[k] = v[k - 1] + 0.5 * dt * ((a[k - 1] - mean_a) + (a[k] - mean_a));
    double mean_v = 0.0;
    for (std::size_t k = 0; k < spc; ++k) mean_v += v[k];
    mean_v /= static_cast<double>(spc);
    for (double& x : v) x -= mean_v;
    return v;
  };
  std::vector<double> ax(spc + 1), az(spc + 1), aq(spc + 1);
  for (std::size_t k = 0; k <= spc; ++k) {
    const LoadSample& l = hist.loads[first + k];
    const Vec3 F = l.FH_N * e_v + l.FV_N * e_L;
    ax[k] = F.x() / m;
    az[k] = F.z() / m;
    aq[k] = l.M_Nm / I;
  }
  const std::vector<double> U = periodic(ax), W = periodic(az), Q = periodic(aq);
  const std::vector<double> theta = periodic(Q);
  BodyState& b = summary->initial;
  y0[2] = b.theta_rad + theta[spc];
  y0[3] = b.U_mps + U[spc];
  y0[4] = b.W_mps + W[spc];
  y0[5] = Q[spc];
  return std::string();
}

}  // namespace

FreeFlightSummary simulateFree(const FlightCoreModel& model, const OperatingPoint& point,
                               const SimulationOptions& options, FreeFlightHistory* history,
                               FreeFlightObserver* observer) {
  std::string why;
  if (!options.IsValid(&why)) throw std::invalid_argument("simulation options: " + why);
  if (!(point.speed_mps > 0.0) || !(point.freq_hz > 0.0))
    throw std::invalid_argument("free flight needs speed > 0 and frequency > 0");
  if (history && history->keep_cycles < 1)
    throw std::invalid_argument("free flight: history keep_cycles must be >= 1");
  const FreeFlightOptions& fo = options.free;
  const ControlInput control{point.freq_hz, point.tail_angle_rad};
  FreeFlightSystem sys(model, model.flexible.get(), control, point.speed_mps);

  FreeFlightSummary summary;
  summary.initial = trimmedBodyState(point, fo.initial_altitude_m);
  const double R_Q = fo.bounds.Q_radps > 0.0
                         ? fo.bounds.Q_radps
                         : 2.0 * kPi * point.freq_hz * fo.bounds.theta_rad;

  const int n = sys.stateCount();
  std::vector<double> y0(static_cast<std::size_t>(n), 0.0);
  sys.initialState(0.0, summary.initial, y0.data());
  if (fo.periodic_start_cycles > 0) {
    const std::string why_not =
        startFromPeriodicState(model, point, options, sys, &summary, y0.data());
    if (!why_not.empty()) {  // no periodic state to release from: the run has no result
      summary.status = SimulationStatus::kFailed;
      summary.message = "the periodic start (a tethered run at the release point) " + why_not;
      if (history) {
        const int keep = history->keep_cycles;
        *history = FreeFlightHistory{};
        history->keep_cycles = keep;
      }
      return summary;
    }
  }
  const double period_s = 1.0 / point.freq_hz;
  IntegratorOptions iopt;
  iopt.rel_tol = options.rel_tol;
  sys.absoluteTolerances(options.rel_tol, options.abs_tol, options.separation_abs_tol,
                         &iopt.abs_tol);
  iopt.max_step = period_s / 8.0;
  // Flexible wing: the modal stiffness implicit (modal_implicit_split.hpp) unless the options ask
  // for the explicit table; explicit steps are stability-limited, where ARK4(3)6L needs fewer
  // evaluations than Dormand-Prince (integration_method.hpp). The rigid wing: ARK4(3)6L too.
  using Imex = ModalImex<FreeFlightSystem>;
  const bool implicit =
      sys.hasModes() && options.modal_integration == ModalIntegration::kImplicit;
  OdeIntegrator integrator(n, Imex::rhs(implicit), &sys, Imex::method(implicit), iopt);
  integrator.reset(0.0, y0.data());

  // What the run keeps (history_window.hpp): the caller's last cycles (at least the last one, for
  // the mean loads) and the limit-cycle window (the last cycles after the transient,
  // limit_cycle.hpp); the bounded-norm verdict and the theta extremes run on every sample after
  // the transient. The windows are known in advance: the analysis runs only on a flight that
  // completed every cycle.
  FreeFlightHistory local;
  FreeFlightHistory& h = history ? *history : local;
  const int keep = history ? history->keep_cycles : 1;
  h = FreeFlightHistory{};
  h.keep_cycles = keep;
  const int spc = options.samples_per_cycle;
  const std::size_t spc_n = static_cast<std::size_t>(spc);
  {
    const std::size_t most = 2 * static_cast<std::size_t>(keep) * spc_n + 1;
    h.t_s.reserve(most);
    h.delta_M_rad.reserve(most);
    h.body.reserve(most);
    if (options.record_history) h.samples.reserve(most);
  }
  std::size_t h_first = 0;  // index of h's first sample in the run
  auto dropOld = [&](bool amortised) {
    const std::size_t d =
        oldSamplesToDrop(h.t_s.size(), spc_n, static_cast<std::size_t>(keep), amortised);
    if (d == 0) return;
    dropFront(&h.t_s, d);
    dropFront(&h.delta_M_rad, d);
    dropFront(&h.body, d);
    if (!h.samples.empty()) dropFront(&h.samples, d);
    h_first += d;
  };

  const int skip = std::min(options.cycles - 1,
                            static_cast<int>(std::floor(fo.transient_fraction * options.cycles)));
  const std::size_t first = static_cast<std::size_t>(skip) * spc_n;
  const int window_cycles =
      limitCycleWindowCycles(options.cycles - skip, spc, fo.limit_cycle_window_samples);
  const std::size_t window_first =
      static_cast<std::size_t>(options.cycles - window_cycles) * spc_n;
  const std::size_t analysed_end = static_cast<std::size_t>(options.cycles) * spc_n;
  std::vector<double> win_t, win_delta, win_theta, win_h;
  for (std::vector<double>* v : {&win_t, &win_delta, &win_theta, &win_h})
    v->reserve(static_cast<std::size_t>(window_cycles) * spc_n + 1);
  BoundedNormMonitor monitor({{summary.initial.U_mps, fo.bounds.U_mps, "U"},
                              {summary.initial.W_mps, fo.bounds.W_mps, "W"},
                              {summary.initial.theta_rad, fo.bounds.theta_rad, "theta"},
                              {summary.initial.Q_radps, R_Q, "Q"},
                              {summary.initial.h_m, fo.bounds.h_m, "h"}},
                             first, spc);
  double theta_min = 0.0, theta_max = 0.0;  // over [first, analysed_end)

  const bool loads = options.record_history;  // the loads need one more RHS evaluation
  std::size_t index = 0;                      // of the next sample in the run
  auto record = [&](double t, const double* y) {
    const double delta =
        flapStateAt(model.vehicle.flapping.amplitude_rad, point.freq_hz, t).delta_rad;
    const BodyState b = bodyOf(y);
    FreeFlightSample s;
    if (loads) sys.sample(t, y, &s, false);
    if (observer) observer->onSample(t, delta, b, loads ? &s : nullptr);
    h.t_s.push_back(t);
    h.delta_M_rad.push_back(delta);
    h.body.push_back(b);
    if (loads) h.samples.push_back(s);
    const double judged[5] = {b.U_mps, b.W_mps, b.theta_rad, b.Q_radps, b.h_m};
    monitor.add(index, t, judged);
    if (index >= first && index < analysed_end) {
      if (index == first || b.theta_rad < theta_min) theta_min = b.theta_rad;
      if (index == first || b.theta_rad > theta_max) theta_max = b.theta_rad;
    }
    if (index >= window_first) {
      win_t.push_back(t);
      win_delta.push_back(delta);
      win_theta.push_back(b.theta_rad);
      win_h.push_back(b.h_m);
    }
    summary.end_time_s = t;
    ++index;
  };
  record(0.0, integrator.state());

  summary.status = SimulationStatus::kOk;
  double power_prev = 0.0;
  char buf[320];
  for (int k = 1; k <= options.cycles && summary.status == SimulationStatus::kOk; ++k) {
    throwIfCancelled();  // a cancellation point per cycle (core/model/cancellation.hpp)
    for (int i = 1; i <= spc; ++i) {
      const double t = ((k - 1) * spc + i) * period_s / spc;
      if (integrator.advanceTo(t) != IntegratorStatus::kOk) {
        summary.status = SimulationStatus::kDiverged;
        std::snprintf(buf, sizeof buf, "integration stopped at t = %.4f s: %s", integrator.time(),
                      integrator.lastError().c_str());
        summary.message = buf;
        break;
      }
      const double* y = integrator.state();
      bool finite = true;
      for (int j = 0; j < n; ++j) finite = finite && std::isfinite(y[j]);
      const BodyState b = bodyOf(y);
      const char* worst = "";
      const double norm = finite ? scaledNorm(b, summary.initial, fo.bounds, R_Q, &worst) : 0.0;
      if (!finite) {
        std::snprintf(buf, sizeof buf, "non-finite state at t = %.4f s", t);
      } else if (std::abs(b.theta_rad) >= kThetaLimit_rad) {
        std::snprintf(buf, sizeof buf,
                      "pitch attitude %.1f deg beyond +-85 deg at t = %.4f s (the longitudinal "
                      "model does not cover it)",
                      b.theta_rad * kRadToDeg, t);
      } else if (b.h_m <= 0.0) {
        std::snprintf(buf, sizeof buf,
                      "ground contact at t = %.4f s (started %.3g m above ground, x = %.3g m)", t,
                      fo.initial_altitude_m, b.x_I_m);
      } else if (norm > fo.divergence_ratio) {
        std::snprintf(buf, sizeof buf,
                      "scaled state norm %.3g > %.3g at t = %.4f s (largest deviation: %s)",
                      norm, fo.divergence_ratio, t, worst);
      } else {
        record(t, y);
        continue;
      }
      if (finite) record(t, y);
      summary.status = SimulationStatus::kDiverged;
      summary.message = buf;
      break;
    }
    if (summary.status != SimulationStatus::kOk) break;
    summary.cycles_run = k;
    dropOld(true);
    const double power = integrator.state()[sys.powerOffset()];
    summary.mean.power_aero_W = (power - power_prev) / period_s;
    power_prev = power;
  }
  dropOld(false);
  summary.steps = integrator.steps();
  summary.rhs_evaluations = integrator.rhsEvaluations();
  summary.integrator_method = integrator.methodName();

  // Last whole cycle means of the aerodynamic loads (trapezoid on the periodic samples).
  if (summary.cycles_run >= 1 && loads) {
    const std::size_t start =
        static_cast<std::size_t>(summary.cycles_run - 1) * spc_n - h_first;
    const std::size_t stride = sizeof(FreeFlightSample) / sizeof(double);
    summary.mean.FV_N = periodMean(&h.samples[start].loads.FV_N, spc_n, stride);
    summary.mean.FH_N = periodMean(&h.samples[start].loads.FH_N, spc_n, stride);
    summary.mean.M_Nm = periodMean(&h.samples[start].loads.M_Nm, spc_n, stride);
  }
  if (summary.status != SimulationStatus::kOk) return summary;

  // Verdict over the cycles after the transient; limit cycle over its window.
  summary.first_analysed_cycle = skip + 1;
  summary.limit_cycle_first_cycle = options.cycles - window_cycles + 1;
  summary.verdict = monitor.result();
  summary.limit_cycle =
      analyseLimitCycle(win_t, win_delta, win_theta, win_h, 0, spc, point.freq_hz);
  summary.limit_cycle.theta_min_rad = theta_min;
  summary.limit_cycle.theta_max_rad = theta_max;
  summary.analysed = true;
  std::snprintf(buf, sizeof buf, "%d cycles of free flight; %s", summary.cycles_run,
                summary.verdict.reason.c_str());
  summary.message = buf;
  return summary;
}

}  // namespace orni
