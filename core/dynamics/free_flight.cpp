#include "core/dynamics/free_flight.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "core/analysis/harmonics.hpp"
#include "core/dynamics/flight_path_frame.hpp"
#include "core/dynamics/free_flight_recorder.hpp"
#include "core/integrate/ode_integrator.hpp"
#include "core/model/cancellation.hpp"
#include "core/model/invariant.hpp"

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
  // error.
  t.samples_per_cycle = 32;
  TimeHistory hist;
  const SimulationSummary ts = simulateTethered(model, point, t, &hist);
  if (ts.status != SimulationStatus::kOk && ts.status != SimulationStatus::kNotConverged)
    return std::string(toString(ts.status)) + ": " + ts.message;
  const int M = sys.modeCount();
  const std::vector<double>& w = ts.final_wing_state;
  ORNI_DEMAND(ts.final_mode_count == M &&
                  static_cast<int>(w.size()) == 2 * M + (sys.powerOffset() - sys.aeroOffset()),
              "free flight: the tethered periodic state has the free flight's layout");
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

// The std::invalid_argument cases of simulateFree (free_flight.hpp).
void checkArguments(const OperatingPoint& point, const SimulationOptions& options,
                    const FreeFlightHistory* history) {
  std::string why;
  if (!options.IsValid(&why)) throw std::invalid_argument("simulation options: " + why);
  if (!(point.speed_mps > 0.0) || !(point.freq_hz > 0.0))
    throw std::invalid_argument("free flight needs speed > 0 and frequency > 0");
  if (history && history->keep_cycles < 1)
    throw std::invalid_argument("free flight: history keep_cycles must be >= 1");
}

// The pitch-rate bound R_Q of the bounded-norm criterion: the options' own, else the rate of a
// pitch oscillation of amplitude R_theta at the flapping frequency.
double pitchRateBound(const FreeFlightBounds& bounds, double freq_hz) {
  return bounds.Q_radps > 0.0 ? bounds.Q_radps : 2.0 * kPi * freq_hz * bounds.theta_rad;
}

// No periodic state to release from: the run has no result (and the history no samples).
FreeFlightSummary failedPeriodicStart(const std::string& why_not, FreeFlightSummary* summary,
                                      FreeFlightHistory* history) {
  summary->status = SimulationStatus::kFailed;
  summary->message = "the periodic start (a tethered run at the release point) " + why_not;
  if (history) clearFreeFlightHistory(history);
  return *summary;
}

// The integrator of a run of `sys`: the options' tolerances (free_flight_system.hpp's absolute
// ones), at most an eighth of a period per step. Flexible wing: the modal stiffness implicit
// (modal_implicit_split.hpp) unless the options ask for the explicit table; explicit steps are
// stability-limited, where ARK4(3)6L needs fewer evaluations than Dormand-Prince
// (integration_method.hpp). The rigid wing: ARK4(3)6L too.
OdeIntegrator freeFlightIntegrator(FreeFlightSystem& sys, const SimulationOptions& options,
                                   double period_s) {
  IntegratorOptions iopt;
  iopt.rel_tol = options.rel_tol;
  sys.absoluteTolerances(options.rel_tol, options.abs_tol, options.separation_abs_tol,
                         &iopt.abs_tol);
  iopt.max_step = period_s / 8.0;
  using Imex = ModalImex<FreeFlightSystem>;
  const bool implicit =
      sys.hasModes() && options.modal_integration == ModalIntegration::kImplicit;
  return OdeIntegrator(sys.stateCount(), Imex::rhs(implicit), &sys, Imex::method(implicit, sys.nonlinearWing()), iopt);
}

bool allFinite(const double* y, int n) {
  bool finite = true;
  for (int j = 0; j < n; ++j) finite = finite && std::isfinite(y[j]);
  return finite;
}

// Why the sample y (n states) at t ends the run: a non-finite state, |theta| beyond the
// longitudinal model, ground contact, or the scaled state norm about `initial` above the
// divergence ratio; empty when the flight goes on.
std::string divergenceReason(double t, const double* y, int n, const BodyState& initial,
                             const FreeFlightOptions& fo, double Q_bound_radps) {
  const bool finite = allFinite(y, n);
  const BodyState b = bodyOf(y);
  const char* worst = "";
  const double norm = finite ? scaledNorm(b, initial, fo.bounds, Q_bound_radps, &worst) : 0.0;
  char buf[320];
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
                  "scaled state norm %.3g > %.3g at t = %.4f s (largest deviation: %s)", norm,
                  fo.divergence_ratio, t, worst);
  } else {
    return std::string();
  }
  return buf;
}

// The cycles of the run, sample by sample, until the last or the first divergence (status
// diverged with the reason; a finite diverged sample is still recorded); after each whole cycle
// the history window is trimmed and the cycle's mean aerodynamic power kept.
void flyCycles(const FreeFlightSystem& sys, double freq_hz, const SimulationOptions& options,
               double Q_bound_radps, OdeIntegrator& integrator, FreeFlightRecorder& recorder,
               FreeFlightObserver* observer, FreeFlightSummary* summary) {
  const int n = sys.stateCount();
  const int spc = options.samples_per_cycle;
  const double period_s = 1.0 / freq_hz;
  summary->status = SimulationStatus::kOk;
  double power_prev = 0.0;
  for (int k = 1; k <= options.cycles && summary->status == SimulationStatus::kOk; ++k) {
    throwIfCancelled();  // a cancellation point per cycle (core/model/cancellation.hpp)
    for (int i = 1; i <= spc; ++i) {
      const double t = ((k - 1) * spc + i) * period_s / spc;
      if (integrator.advanceTo(t) != IntegratorStatus::kOk) {
        char buf[320];
        std::snprintf(buf, sizeof buf, "integration stopped at t = %.4f s: %s", integrator.time(),
                      integrator.lastError().c_str());
        summary->status = SimulationStatus::kDiverged;
        summary->message = buf;
        break;
      }
      const double* y = integrator.state();
      const std::string why = divergenceReason(t, y, n, summary->initial, options.free,
                                               Q_bound_radps);
      if (why.empty() || allFinite(y, n)) recorder.record(t, y, integrator.derivative());
      if (!why.empty()) {
        summary->status = SimulationStatus::kDiverged;
        summary->message = why;
        break;
      }
    }
    if (summary->status != SimulationStatus::kOk) break;
    summary->cycles_run = k;
    recorder.dropOld(true);
    const double power = integrator.state()[sys.powerOffset()];
    summary->mean.power_aero_W = (power - power_prev) / period_s;
    power_prev = power;
    if (observer && k < options.cycles && observer->endRunAfterCycle(k)) break;
  }
}

// Mean aerodynamic FV, FH and M of the last whole cycle `cycle` (1-based; trapezoid on its
// periodic samples, the endpoint excluded) from the recorder's history window.
void lastCycleMeanLoads(const FreeFlightRecorder& recorder, int samples_per_cycle, int cycle,
                        CycleMeans* mean) {
  const std::size_t n = static_cast<std::size_t>(samples_per_cycle);
  const std::vector<FreeFlightSample>& samples = recorder.history().samples;
  const std::size_t start = static_cast<std::size_t>(cycle - 1) * n - recorder.historyFirst();
  std::vector<double> x(n);  // one channel of the cycle, contiguous
  auto channel = [&](double LoadSample::*field) -> const double* {
    for (std::size_t i = 0; i < n; ++i) x[i] = samples[start + i].loads.*field;
    return x.data();
  };
  mean->FV_N = periodMean(channel(&LoadSample::FV_N), n);
  mean->FH_N = periodMean(channel(&LoadSample::FH_N), n);
  mean->M_Nm = periodMean(channel(&LoadSample::M_Nm), n);
}

// The verdict over the cycles after the transient and the limit cycle over its window, of a run
// that completed all `cycles`.
void analyse(const FreeFlightRecorder& recorder, int cycles, FreeFlightSummary* summary) {
  const FreeFlightWindows& w = recorder.windows();
  summary->first_analysed_cycle = w.transient_cycles + 1;
  summary->limit_cycle_first_cycle = cycles - w.limit_cycle_cycles + 1;
  summary->verdict = recorder.verdict();
  summary->limit_cycle = recorder.limitCycle();
  summary->analysed = true;
  char buf[320];
  std::snprintf(buf, sizeof buf, "%d cycles of free flight; %s", summary->cycles_run,
                summary->verdict.reason.c_str());
  summary->message = buf;
}

}  // namespace

FreeFlightSummary simulateFree(const FlightCoreModel& model, const OperatingPoint& point,
                               const SimulationOptions& options, FreeFlightHistory* history,
                               FreeFlightObserver* observer) {
  checkArguments(point, options, history);
  FreeFlightSystem sys(model, model.flexible.get(),
                       ControlInput{point.freq_hz, point.tail_angle_rad}, point.speed_mps);
  FreeFlightSummary summary;
  summary.initial = trimmedBodyState(point, options.free.initial_altitude_m);
  const double Q_bound_radps = pitchRateBound(options.free.bounds, point.freq_hz);

  std::vector<double> y0(static_cast<std::size_t>(sys.stateCount()), 0.0);
  sys.initialState(0.0, summary.initial, y0.data());
  if (options.free.periodic_start_cycles > 0) {
    const std::string why_not =
        startFromPeriodicState(model, point, options, sys, &summary, y0.data());
    if (!why_not.empty()) return failedPeriodicStart(why_not, &summary, history);
  }
  OdeIntegrator integrator = freeFlightIntegrator(sys, options, 1.0 / point.freq_hz);
  integrator.reset(0.0, y0.data());

  FreeFlightRecorder recorder(sys, point.freq_hz, options, summary.initial, Q_bound_radps,
                              history, observer);
  recorder.record(0.0, integrator.state());
  flyCycles(sys, point.freq_hz, options, Q_bound_radps, integrator, recorder, observer, &summary);
  recorder.dropOld(false);
  summary.end_time_s = recorder.lastTime_s();
  summary.steps = integrator.steps();
  summary.rhs_evaluations = integrator.rhsEvaluations();
  summary.integrator_method = integrator.methodName();
  if (summary.cycles_run >= 1 && options.record_history)
    lastCycleMeanLoads(recorder, options.samples_per_cycle, summary.cycles_run, &summary.mean);
  if (summary.status != SimulationStatus::kOk) return summary;
  if (summary.cycles_run < options.cycles) {  // ended by the observer: no verdict
    char buf[160];
    std::snprintf(buf, sizeof buf, "%d of %d cycles of free flight (ended by the observer)",
                  summary.cycles_run, options.cycles);
    summary.message = buf;
    return summary;
  }
  analyse(recorder, options.cycles, &summary);
  return summary;
}

}  // namespace orni
