#include "core/dynamics/tethered_simulation.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "core/dynamics/flexible_tethered.hpp"
#include "core/dynamics/history_window.hpp"
#include "core/integrate/ode_integrator.hpp"
#include "core/model/cancellation.hpp"

namespace orni {

const char* toString(SimulationStatus s) {
  switch (s) {
    case SimulationStatus::kOk: return "ok";
    case SimulationStatus::kNotConverged: return "not_converged";
    case SimulationStatus::kDiverged: return "diverged";
    case SimulationStatus::kFailed: return "failed";
  }
  return "failed";
}

std::string SimulationSummary::BriefReport() const {
  char buf[256];
  std::snprintf(buf, sizeof buf,
                "%s: %d cycles, steady from cycle %d, mean FV %.6g N, FH %.6g N, M %.6g N m, "
                "power %.6g W (%ld steps)",
                toString(status), cycles_run, steady_state_cycle, mean.FV_N, mean.FH_N, mean.M_Nm,
                mean.power_aero_W, steps);
  return buf;
}

namespace {

// The rigid wing: aero states + quadratures; loads by evaluateLoads (flight_core.cpp).
class RigidTetheredSystem {
 public:
  RigidTetheredSystem(const FlightCoreModel& model, const BodyMotion& body,
                      const ControlInput& control)
      : model_(model), data_(model), body_(body), control_(control),
        n_aero_(model.aeroStateCount()) {}
  int stateCount() const { return n_aero_ + kQuadratureChannels; }
  int aeroOffset() const { return 0; }
  int quadratureOffset() const { return n_aero_; }
  void initialState(double t, double* y) const {
    initialAeroStates(model_, body_, control_, t, y);
    for (int c = 0; c < kQuadratureChannels; ++c) y[n_aero_ + c] = 0.0;
  }
  void absoluteTolerances(double rel_tol, double lag_abs_tol, double separation_abs_tol,
                          std::vector<double>* atol) const {
    atol->assign(static_cast<std::size_t>(stateCount()), lag_abs_tol);
    // The last state of each strip is its separation fraction f (docs/theory.md 5.8).
    const int per = model_.aero_states_per_strip;
    if (per > 0)
      for (int i = per - 1; i < n_aero_; i += per)
        (*atol)[static_cast<std::size_t>(i)] = separation_abs_tol;
    const auto scales = quadratureScales(model_, body_.v_P1_B.norm());
    const double T = 1.0 / control_.freq_hz;
    for (int c = 0; c < kQuadratureChannels; ++c)
      (*atol)[static_cast<std::size_t>(n_aero_ + c)] = 0.1 * rel_tol * scales[c] * T;
  }
  static int rhsCallback(double t, const double* y, double* ydot, void* self) {
    auto* r = static_cast<RigidTetheredSystem*>(self);
    evaluateLoads(r->model_, r->data_, r->body_, r->control_, t, y, ydot, &r->scratch_);
    double* q = ydot + r->n_aero_;
    q[0] = r->scratch_.FV_N;
    q[1] = r->scratch_.FH_N;
    q[2] = r->scratch_.M_Nm;
    q[3] = r->scratch_.power_aero_W;
    q[4] = r->scratch_.power_hinge_W;
    return 0;
  }
  void sample(double t, const double* y, LoadSample* out) {
    evaluateLoads(model_, data_, body_, control_, t, y, nullptr, out);
  }

 private:
  const FlightCoreModel& model_;
  FlightCoreData data_;
  BodyMotion body_;
  ControlInput control_;
  int n_aero_;
  LoadSample scratch_;
};

template <class System>
IntegratorOptions integratorOptions(const System& sys, const OperatingPoint& point,
                                    const SimulationOptions& options) {
  IntegratorOptions iopt;
  iopt.rel_tol = options.rel_tol;
  sys.absoluteTolerances(options.rel_tol, options.abs_tol, options.separation_abs_tol,
                         &iopt.abs_tol);
  iopt.max_step = 1.0 / point.freq_hz / 8.0;  // never step over a whole flapping half-stroke
  return iopt;
}

/// Keeps the last history->keep_cycles cycles of the samples (history_window.hpp) and streams
/// every sample to the observer.
class HistoryRecorder {
 public:
  HistoryRecorder(TimeHistory* history, TetheredRunObserver* observer, int samples_per_cycle)
      : history_(history), observer_(observer), spc_(static_cast<std::size_t>(samples_per_cycle)) {
    if (!history_) return;
    history_->t_s.clear();
    history_->delta_M_rad.clear();
    history_->loads.clear();
    const std::size_t most = 2 * static_cast<std::size_t>(history_->keep_cycles) * spc_ + 1;
    history_->t_s.reserve(most);
    history_->delta_M_rad.reserve(most);
    history_->loads.reserve(most);
  }
  bool active() const { return history_ != nullptr || observer_ != nullptr; }
  void add(double t_s, double delta_M_rad, const LoadSample& s) {
    if (observer_) observer_->onSample(t_s, delta_M_rad, s);
    if (!history_) return;
    history_->t_s.push_back(t_s);
    history_->delta_M_rad.push_back(delta_M_rad);
    history_->loads.push_back(s);
  }
  /// At a cycle boundary (amortised) and at the end of the run.
  void dropOld(bool amortised) {
    if (!history_) return;
    const std::size_t n =
        oldSamplesToDrop(history_->t_s.size(), spc_,
                         static_cast<std::size_t>(history_->keep_cycles), amortised);
    if (n == 0) return;
    dropFront(&history_->t_s, n);
    dropFront(&history_->delta_M_rad, n);
    dropFront(&history_->loads, n);
  }

 private:
  TimeHistory* history_;
  TetheredRunObserver* observer_;
  std::size_t spc_;
};

// The loads of a history sample at the integrator's present (t, y). The flexible wing takes them
// from the dense output's derivative where it can (FlexibleTetheredSystem::sampleFromDerivative:
// no strip evaluation); every other system, and the start (no step taken yet), evaluates them.
template <class System>
void sampleLoads(System& sys, OdeIntegrator&, double t, const double* y, bool, LoadSample* s) {
  sys.sample(t, y, s);
}
void sampleLoads(FlexibleTetheredSystem& sys, OdeIntegrator& integrator, double t,
                 const double* y, bool interpolate, LoadSample* s) {
  const double* ydot = interpolate ? integrator.derivative() : nullptr;
  if (ydot == nullptr || !sys.sampleFromDerivative(t, y, ydot, s)) sys.sample(t, y, s);
}

template <class System>
SimulationSummary runCycles(System& sys, OdeIntegrator& integrator, const FlightCoreModel& model,
                            const OperatingPoint& point, const SimulationOptions& options,
                            TimeHistory* history, TetheredRunObserver* observer) {
  SimulationSummary summary;
  const int n = sys.stateCount();
  const int n_aero0 = sys.aeroOffset();
  const int n_aero1 = sys.quadratureOffset();
  const int n_quad = sys.quadratureOffset();
  const double period_s = 1.0 / point.freq_hz;

  // Scales for the steady-state test (the same as for the quadrature tolerances).
  const auto scales = quadratureScales(model, point.speed_mps);

  std::vector<double> y0(static_cast<std::size_t>(n), 0.0);
  sys.initialState(0.0, y0.data());
  integrator.reset(0.0, y0.data());

  const bool record = (history != nullptr || observer != nullptr) && options.record_history;
  const int spc = record ? options.samples_per_cycle : 1;
  HistoryRecorder recorder(record ? history : nullptr, record ? observer : nullptr, spc);
  auto recordSample = [&](double t, const double* y) {
    if (!record) return;
    LoadSample s;
    sampleLoads(sys, integrator, t, y, options.interpolate_sampled_loads && t > 0.0, &s);
    recorder.add(t, flapStateAt(model.vehicle.flapping.amplitude_rad, point.freq_hz, t).delta_rad,
                 s);
  };
  recordSample(0.0, integrator.state());

  std::vector<double> prev_quad(kQuadratureChannels, 0.0);
  CycleMeans prev_cm;
  std::vector<double> prev_states(integrator.state() + n_aero0, integrator.state() + n_aero1);
  summary.status = SimulationStatus::kNotConverged;
  for (int k = 1; k <= options.cycles; ++k) {
    throwIfCancelled();  // a cancellation point per cycle (core/model/cancellation.hpp)
    for (int i = 1; i <= spc; ++i) {
      const double t = ((k - 1) * spc + i) * period_s / spc;
      if (integrator.advanceTo(t) != IntegratorStatus::kOk) {
        recorder.dropOld(false);
        summary.status = SimulationStatus::kFailed;
        summary.message = integrator.lastError();
        summary.steps = integrator.steps();
        summary.rhs_evaluations = integrator.rhsEvaluations();
        return summary;
      }
      recordSample(t, integrator.state());
    }
    recorder.dropOld(true);
    const double* y = integrator.state();
    CycleMeans cm;
    double* fields[kQuadratureChannels] = {&cm.FV_N, &cm.FH_N, &cm.M_Nm, &cm.power_aero_W,
                                           &cm.power_hinge_W};
    double change = 0.0;
    bool finite = true;
    for (int c = 0; c < kQuadratureChannels; ++c) {
      const double q = y[n_quad + c];
      *fields[c] = (q - prev_quad[static_cast<std::size_t>(c)]) / period_s;
      prev_quad[static_cast<std::size_t>(c)] = q;
      finite = finite && std::isfinite(*fields[c]);
      if (k > 1) {
        const double prev = *(&prev_cm.FV_N + c);
        change = std::max(change, std::abs(*fields[c] - prev) / scales[c]);
      }
    }
    // The aerodynamic states' cycle-to-cycle change is a diagnostic only: a separation state
    // sampled in a fast stall transition carries interpolation noise of order rel_tol there,
    // while the cycle means (what every analysis consumes) are integrals and converge cleanly.
    double state_change = 0.0;
    for (int i = 0; i < n; ++i) finite = finite && std::isfinite(y[i]);
    for (int i = n_aero0; i < n_aero1; ++i) {
      const std::size_t s = static_cast<std::size_t>(i - n_aero0);
      state_change = std::max(state_change, std::abs(y[i] - prev_states[s]));
      prev_states[s] = y[i];
    }
    summary.last_state_change = state_change;
    prev_cm = cm;
    summary.cycles_run = k;
    if (observer) observer->onCycle(k, cm);
    if (!finite) {
      summary.status = SimulationStatus::kDiverged;
      char buf[160];
      std::snprintf(buf, sizeof buf, "non-finite loads or states in cycle %d (t = %.6g s)", k,
                    k * period_s);
      summary.message = buf;
      break;
    }
    if (k > 1) {
      summary.last_cycle_change = change;
      if (change <= options.steady_tol && summary.steady_state_cycle < 0)
        summary.steady_state_cycle = k;
      if (change > options.steady_tol) summary.steady_state_cycle = -1;
      if (options.stop_when_steady && summary.steady_state_cycle > 0) break;
    }
  }
  recorder.dropOld(false);
  summary.mean = prev_cm;
  summary.final_wing_state.assign(integrator.state(), integrator.state() + n_quad);
  summary.steps = integrator.steps();
  summary.rhs_evaluations = integrator.rhsEvaluations();
  summary.step_attempts = integrator.stepAttempts();
  summary.integrator_method = integrator.methodName();
  if (summary.status == SimulationStatus::kNotConverged) {
    char buf[200];
    if (summary.steady_state_cycle > 0) {
      summary.status = SimulationStatus::kOk;
      std::snprintf(buf, sizeof buf,
                    "periodic steady state reached at cycle %d (cycle-to-cycle change %.2e <= "
                    "%.2e)",
                    summary.steady_state_cycle, summary.last_cycle_change, options.steady_tol);
    } else if (summary.cycles_run < 2) {
      // No cycle-to-cycle change exists after one cycle (the message would
      // otherwise report a meaningless "0.00e+00 >").
      std::snprintf(buf, sizeof buf,
                    "periodic steady state not reached: %d cycle run; the test compares two "
                    "consecutive cycles (run at least 2)",
                    summary.cycles_run);
    } else {
      std::snprintf(buf, sizeof buf,
                    "periodic steady state not reached in %d cycles (last cycle-to-cycle change "
                    "%.2e > %.2e)",
                    summary.cycles_run, summary.last_cycle_change, options.steady_tol);
    }
    summary.message = buf;
  }
  return summary;
}

// A stateless strip model (the algebraic delaurier1993 model on the rigid wing) makes the loads an
// explicit periodic function of time: the solution is periodic from the first cycle, so nothing
// is integrated. The cycle means are the periodic rectangle rule over kStatelessMeanSamples
// uniform samples, spectrally accurate for smooth loads and deterministic across a hard stall
// switch; the samples come in pairs half a period apart, so a load that is odd under the
// half-period shift (FV at theta 0 of a symmetric stroke) averages to zero up to rounding.
constexpr int kStatelessMeanSamples = 4096;

SimulationSummary sampleStatelessCycles(const FlightCoreModel& model, const OperatingPoint& point,
                                        const SimulationOptions& options, TimeHistory* history,
                                        TetheredRunObserver* observer) {
  RigidTetheredSystem sys(model, tetheredBodyMotion(point.speed_mps, point.theta_rad),
                          ControlInput{point.freq_hz, point.tail_angle_rad});
  const double period_s = 1.0 / point.freq_hz;
  SimulationSummary summary;
  CycleMeans cm;
  LoadSample s;
  bool finite = true;
  for (int i = 0; i < kStatelessMeanSamples; ++i) {
    sys.sample(i * period_s / kStatelessMeanSamples, nullptr, &s);
    cm.FV_N += s.FV_N;
    cm.FH_N += s.FH_N;
    cm.M_Nm += s.M_Nm;
    cm.power_aero_W += s.power_aero_W;
    cm.power_hinge_W += s.power_hinge_W;
    finite = finite && std::isfinite(s.FV_N) && std::isfinite(s.FH_N) && std::isfinite(s.M_Nm) &&
             std::isfinite(s.power_aero_W) && std::isfinite(s.power_hinge_W);
  }
  for (double* v : {&cm.FV_N, &cm.FH_N, &cm.M_Nm, &cm.power_aero_W, &cm.power_hinge_W})
    *v /= kStatelessMeanSamples;
  const bool record = (history != nullptr || observer != nullptr) && options.record_history;
  const int spc = record ? options.samples_per_cycle : 1;
  HistoryRecorder recorder(record ? history : nullptr, record ? observer : nullptr, spc);
  // The same phase gives the same sample in every cycle: evaluate the first cycle only.
  std::vector<LoadSample> cycle(record ? static_cast<std::size_t>(spc) : 0);
  for (std::size_t i = 0; i < cycle.size(); ++i)
    sys.sample(static_cast<double>(i) * period_s / spc, nullptr, &cycle[i]);
  auto recordSample = [&](std::size_t i) {
    if (!record) return;
    const double t = static_cast<double>(i) * period_s / spc;
    recorder.add(t, flapStateAt(model.vehicle.flapping.amplitude_rad, point.freq_hz, t).delta_rad,
                 cycle[i % static_cast<std::size_t>(spc)]);
  };
  recordSample(0);
  for (int k = 1; k <= options.cycles; ++k) {
    for (int i = 1; i <= spc; ++i)
      recordSample(static_cast<std::size_t>(k - 1) * static_cast<std::size_t>(spc) +
                   static_cast<std::size_t>(i));
    recorder.dropOld(true);
    if (observer) observer->onCycle(k, cm);
  }
  recorder.dropOld(false);
  summary.cycles_run = options.cycles;
  summary.mean = cm;
  if (!finite) {
    summary.status = SimulationStatus::kDiverged;
    summary.message = "non-finite loads in the first cycle (stateless strip model)";
    return summary;
  }
  summary.status = SimulationStatus::kOk;
  summary.steady_state_cycle = 1;
  summary.message =
      "stateless strip model: periodic from the first cycle; cycle means from " +
      std::to_string(kStatelessMeanSamples) + " uniform samples per period";
  summary.integrator_method = "none (stateless strip model, sampled directly)";
  return summary;
}

}  // namespace

SimulationSummary simulateTethered(const FlightCoreModel& model, const OperatingPoint& point,
                                   const SimulationOptions& options, TimeHistory* history,
                                   TetheredRunObserver* observer) {
  std::string why;
  if (!options.IsValid(&why)) throw std::invalid_argument("simulation options: " + why);
  if (history && history->keep_cycles < 1)
    throw std::invalid_argument("tethered simulation: history keep_cycles must be >= 1");
  if (history) {  // empty without options.record_history
    history->t_s.clear();
    history->delta_M_rad.clear();
    history->loads.clear();
  }
  if (!(point.speed_mps > 0.0) || !(point.freq_hz > 0.0))
    throw std::invalid_argument("tethered simulation needs speed > 0 and frequency > 0");
  const BodyMotion body = tetheredBodyMotion(point.speed_mps, point.theta_rad);
  const ControlInput control{point.freq_hz, point.tail_angle_rad};
  if (model.flexible) {
    FlexibleTetheredSystem sys(model, *model.flexible, body, control);
    IntegratorOptions iopt = integratorOptions(sys, point, options);
    using Imex = ModalImex<FlexibleTetheredSystem>;
    const bool implicit = options.modal_integration == ModalIntegration::kImplicit;
    OdeIntegrator integrator(sys.stateCount(), Imex::rhs(implicit), &sys, Imex::method(implicit, sys.nonlinearWing()),
                             iopt);
    SimulationSummary s = runCycles(sys, integrator, model, point, options, history, observer);
    s.final_mode_count = model.flexible->mode_count;
    return s;
  }
  if (model.aeroStateCount() == 0)
    return sampleStatelessCycles(model, point, options, history, observer);
  RigidTetheredSystem sys(model, body, control);
  IntegratorOptions iopt = integratorOptions(sys, point, options);
  OdeIntegrator integrator(sys.stateCount(), &RigidTetheredSystem::rhsCallback, &sys,
                           IntegrationMethod::explicitRungeKutta(ErkMethod::kDormandPrince5), iopt);
  return runCycles(sys, integrator, model, point, options, history, observer);
}

}  // namespace orni
