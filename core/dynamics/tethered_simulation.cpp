#include "core/dynamics/tethered_simulation.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "core/integrate/erk_integrator.hpp"

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

struct TetheredRhs {
  const FlightCoreModel* model;
  FlightCoreData* data;
  BodyMotion body;
  ControlInput control;
  int aero_states;
  LoadSample scratch;
};

int tetheredRhs(double t, const double* y, double* ydot, void* user) {
  auto* r = static_cast<TetheredRhs*>(user);
  evaluateLoads(*r->model, *r->data, r->body, r->control, t, y, ydot, &r->scratch);
  double* q = ydot + r->aero_states;
  q[0] = r->scratch.FV_N;
  q[1] = r->scratch.FH_N;
  q[2] = r->scratch.M_Nm;
  q[3] = r->scratch.power_aero_W;
  q[4] = r->scratch.power_hinge_W;
  return 0;
}

}  // namespace

SimulationSummary simulateTethered(const FlightCoreModel& model, const OperatingPoint& point,
                                   const SimulationOptions& options, TimeHistory* history) {
  std::string why;
  if (!options.IsValid(&why)) throw std::invalid_argument("simulation options: " + why);
  if (!(point.speed_mps > 0.0) || !(point.freq_hz > 0.0))
    throw std::invalid_argument("tethered simulation needs speed > 0 and frequency > 0");

  SimulationSummary summary;
  FlightCoreData data(model);
  TetheredRhs rhs{&model, &data, tetheredBodyMotion(point.speed_mps, point.theta_rad),
                  ControlInput{point.freq_hz, point.tail_angle_rad}, model.aeroStateCount(),
                  LoadSample{}};
  const int n_aero = rhs.aero_states;
  const int n = n_aero + kQuadratureChannels;
  const double period_s = 1.0 / point.freq_hz;

  // Scales for the steady-state test and the quadrature tolerances: dynamic pressure times wing
  // area (forces), times mean chord (moment), times speed (power).
  const double q_dyn = 0.5 * model.vehicle.air.density_kgpm3 * point.speed_mps * point.speed_mps;
  const double force_scale = q_dyn * model.wing_area_both_m2;
  const double scales[kQuadratureChannels] = {
      force_scale, force_scale, force_scale * model.mean_chord_m,
      force_scale * point.speed_mps, force_scale * point.speed_mps};

  IntegratorOptions iopt;
  iopt.rel_tol = options.rel_tol;
  iopt.abs_tol.assign(static_cast<std::size_t>(n), options.abs_tol);
  // The last state of each strip is its separation fraction f (aero-mst.md 9.4.2).
  const int per_strip = model.aero_states_per_strip;
  if (per_strip > 0)
    for (int i = per_strip - 1; i < n_aero; i += per_strip)
      iopt.abs_tol[static_cast<std::size_t>(i)] = options.separation_abs_tol;
  for (int c = 0; c < kQuadratureChannels; ++c)
    iopt.abs_tol[static_cast<std::size_t>(n_aero + c)] =
        0.1 * options.rel_tol * scales[c] * period_s;
  iopt.max_step = period_s / 8.0;  // never step over a whole flapping half-stroke
  ErkIntegrator integrator(n, &tetheredRhs, &rhs, iopt);

  std::vector<double> y0(static_cast<std::size_t>(n), 0.0);
  initialAeroStates(model, rhs.body, rhs.control, 0.0, y0.data());
  integrator.reset(0.0, y0.data());

  const int spc = options.record_history && history ? options.samples_per_cycle : 1;
  if (history) {
    history->t_s.clear();
    history->delta_M_rad.clear();
    history->loads.clear();
    const std::size_t total = static_cast<std::size_t>(options.cycles) *
                                  static_cast<std::size_t>(spc) + 1;
    history->t_s.reserve(total);
    history->delta_M_rad.reserve(total);
    history->loads.reserve(total);
  }
  auto record = [&](double t, const double* y) {
    if (!history || !options.record_history) return;
    LoadSample s;
    evaluateLoads(model, data, rhs.body, rhs.control, t, y, nullptr, &s);
    history->t_s.push_back(t);
    history->delta_M_rad.push_back(
        flapStateAt(model.vehicle.flapping.amplitude_rad, point.freq_hz, t).delta_rad);
    history->loads.push_back(s);
  };
  record(0.0, integrator.state());

  std::vector<double> prev_quad(kQuadratureChannels, 0.0);
  std::vector<double> prev_states(integrator.state(), integrator.state() + n_aero);
  summary.status = SimulationStatus::kNotConverged;
  for (int k = 1; k <= options.cycles; ++k) {
    for (int i = 1; i <= spc; ++i) {
      const double t = ((k - 1) * spc + i) * period_s / spc;
      if (integrator.advanceTo(t) != IntegratorStatus::kOk) {
        summary.status = SimulationStatus::kFailed;
        summary.message = integrator.lastError();
        summary.steps = integrator.steps();
        summary.rhs_evaluations = integrator.rhsEvaluations();
        return summary;
      }
      record(t, integrator.state());
    }
    const double* y = integrator.state();
    CycleMeans cm;
    double* fields[kQuadratureChannels] = {&cm.FV_N, &cm.FH_N, &cm.M_Nm, &cm.power_aero_W,
                                           &cm.power_hinge_W};
    double change = 0.0;
    bool finite = true;
    for (int c = 0; c < kQuadratureChannels; ++c) {
      const double q = y[n_aero + c];
      *fields[c] = (q - prev_quad[static_cast<std::size_t>(c)]) / period_s;
      prev_quad[static_cast<std::size_t>(c)] = q;
      finite = finite && std::isfinite(*fields[c]);
      if (k > 1) {
        const double prev = *(&summary.per_cycle.back().FV_N + c);
        change = std::max(change, std::abs(*fields[c] - prev) / scales[c]);
      }
    }
    // The aerodynamic states' cycle-to-cycle change is a diagnostic only: a separation state
    // sampled in a fast stall transition carries interpolation noise of order rel_tol there,
    // while the cycle means (what every analysis consumes) are integrals and converge cleanly.
    double state_change = 0.0;
    for (int i = 0; i < n_aero; ++i) {
      finite = finite && std::isfinite(y[i]);
      state_change = std::max(state_change, std::abs(y[i] - prev_states[static_cast<std::size_t>(i)]));
      prev_states[static_cast<std::size_t>(i)] = y[i];
    }
    summary.last_state_change = state_change;
    summary.per_cycle.push_back(cm);
    summary.cycles_run = k;
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
    }
  }
  summary.mean = summary.per_cycle.back();
  summary.steps = integrator.steps();
  summary.rhs_evaluations = integrator.rhsEvaluations();
  summary.step_attempts = integrator.stepAttempts();
  if (summary.status == SimulationStatus::kNotConverged) {
    if (summary.steady_state_cycle > 0) {
      summary.status = SimulationStatus::kOk;
      char buf[200];
      std::snprintf(buf, sizeof buf,
                    "periodic steady state reached at cycle %d (cycle-to-cycle change %.2e <= "
                    "%.2e)",
                    summary.steady_state_cycle, summary.last_cycle_change, options.steady_tol);
      summary.message = buf;
    } else {
      char buf[200];
      std::snprintf(buf, sizeof buf,
                    "periodic steady state not reached in %d cycles (last cycle-to-cycle change "
                    "%.2e > %.2e)",
                    summary.cycles_run, summary.last_cycle_change, options.steady_tol);
      summary.message = buf;
    }
  }
  return summary;
}

}  // namespace orni
