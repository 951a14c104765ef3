#include "trim/periodic_trim.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "core/dynamics/free_flight.hpp"
#include "core/dynamics/modal_implicit_split.hpp"
#include "core/dynamics/tethered_simulation.hpp"
#include "core/analysis/monodromy.hpp"
#include "core/integrate/ode_integrator.hpp"
#include "core/model/frames.hpp"
#include "trim/trim_unknowns.hpp"

namespace orni {

namespace {

double seconds(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

int parameterIndex(PeriodicControl c) {
  switch (c) {
    case PeriodicControl::kTailAngle: return kPeriodTailAngle;
    case PeriodicControl::kFrequency: return kPeriodFrequency;
    case PeriodicControl::kCgPosition: return kPeriodCgShift;
  }
  return kPeriodTailAngle;
}

// One period from x with ARKODE (the free-flight integrator: IMEX ARK4(3)7L[2]SA for the flexible
// wing, the explicit ARK4(3)6L table for the rigid one), max |x(T) - x| in scales.
double orbitCheck(const FlightCoreModel& model, const std::vector<double>& x,
                  const std::vector<double>& p, double friction_speed_mps, double rel_tol,
                  const FreeFlightPeriodMap& map, const OperatingPoint& design_point) {
  FreeFlightSystem sys(model, model.flexible.get(),
                       ControlInput{p[kPeriodFrequency], p[kPeriodTailAngle]},
                       orbitScaleSpeed_mps(design_point));
  sys.setFrictionSpeed(friction_speed_mps);
  const int n = sys.stateCount();
  std::vector<double> y0(static_cast<std::size_t>(n), 0.0);
  std::copy(x.begin(), x.end(), y0.begin() + 2);
  IntegratorOptions io;
  io.rel_tol = rel_tol;
  sys.absoluteTolerances(rel_tol, 0.1 * rel_tol, 0.1 * rel_tol, &io.abs_tol);
  const double T = 1.0 / p[kPeriodFrequency];
  io.max_step = T / 8.0;
  using Imex = ModalImex<FreeFlightSystem>;
  OdeIntegrator integ(n, Imex::rhs(sys.hasModes()), &sys, Imex::method(sys.hasModes(), sys.nonlinearWing()), io);
  integ.reset(0.0, y0.data());
  if (integ.advanceTo(T) != IntegratorStatus::kOk) return std::numeric_limits<double>::quiet_NaN();
  double worst = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i)
    worst = std::max(worst, std::abs(integ.state()[i + 2] - x[i]) /
                                map.stateScale(static_cast<int>(i)));
  return worst;
}

// PeriodicTrimOptions::multiplier_check: the full monodromy again at the orbit start on a grid
// kMultiplierCheckTolFactor times finer, and each multiplier paired with its counterpart there.
void checkMultipliers(const FlightCoreModel& model, FreeFlightPeriodMapOptions mo,
                      const FreeFlightPeriodMap& map, const std::vector<double>& x,
                      const std::vector<double>& p, double fd_step, PeriodicTrimSummary* s) {
  mo.rel_tol *= kMultiplierCheckTolFactor;
  mo.friction_speed_mps = map.frictionSpeed_mps();
  FreeFlightPeriodMap fine(model, mo);
  Eigen::MatrixXd M;
  long used = 0;
  std::string why;
  if (!fine.refreshDiscretisation(x.data(), p.data(), &why) ||
      !monodromyByDifferences(fine, x, p, fd_step, &M, &used, &why)) {
    s->floquet.check_method = "not checked: the finer grid's monodromy failed: " + why;
  } else {
    char how[200];
    std::snprintf(how, sizeof how,
                  "each multiplier against the full monodromy on a grid at rel_tol %g (%d steps "
                  "a period, against %d)",
                  mo.rel_tol, fine.gridSteps(), map.gridSteps());
    compareWithRefined(&s->floquet, eigenOfMonodromy(M), how);
  }
  s->floquet_maps += used;
}

}  // namespace

std::string PeriodicTrimSummary::BriefReport() const {
  char buf[512];
  std::snprintf(buf, sizeof buf,
                "%s: %s; periodic residual %.2e, %d Newton iterations, %ld period maps; %s; %.3f s",
                toString(status), pointText(solution, "theta_mean", "airspeed").c_str(),
                shooting.residual_max, shooting.iterations, shooting.period_maps,
                floquet_valid ? floquet.BriefReport().c_str() : "no Floquet analysis",
                wall_time_s);
  return buf;
}

std::vector<double> periodicStartState(const FlightCoreModel& model,
                                       const FreeFlightPeriodMap& map, const OperatingPoint& point,
                                       const SimulationOptions& tethered) {
  SimulationOptions t = tethered;
  t.mode = FlightMode::kTethered;
  t.stop_when_steady = true;
  t.record_history = false;
  const SimulationSummary ts = simulateTethered(model, point, t, nullptr);
  std::vector<double> wing = ts.final_wing_state;
  if (ts.status != SimulationStatus::kOk && ts.status != SimulationStatus::kNotConverged)
    wing.clear();
  if (static_cast<int>(wing.size()) != map.stateCount() - 4) {
    // No tethered periodic state: the wing undeformed, quasi-steady aerodynamic states.
    FreeFlightSystem sys(model, model.flexible.get(),
                         ControlInput{point.freq_hz, point.tail_angle_rad}, point.speed_mps);
    std::vector<double> y(static_cast<std::size_t>(sys.stateCount()));
    sys.initialState(0.0, trimmedBodyState(point, 0.0), y.data());
    wing.assign(y.begin() + FreeFlightSystem::kBody, y.begin() + sys.powerOffset());
  }
  return map.reducedState(trimmedBodyState(point, 0.0), wing);
}

PeriodicCycleMeans cycleMeans(const OrbitHistory& h, double period_s) {
  PeriodicCycleMeans m;
  const std::size_t N = h.t_s.size() > 1 ? h.t_s.size() - 1 : 0;
  if (N == 0) return m;
  double hmin = h.body[0].h_m, hmax = hmin;
  m.theta_min_rad = m.theta_max_rad = h.body[0].theta_rad;
  for (std::size_t k = 0; k < N; ++k) {
    const BodyState& b = h.body[k];
    m.theta_rad += b.theta_rad;
    m.airspeed_mps += std::hypot(b.U_mps, b.W_mps);
    m.U_mps += b.U_mps;
    m.W_mps += b.W_mps;
    m.Q_radps += b.Q_radps;
    m.FV_N += h.samples[k].loads.FV_N;
    m.FH_N += h.samples[k].loads.FH_N;
    m.M_Nm += h.samples[k].loads.M_Nm;
    m.theta_min_rad = std::min(m.theta_min_rad, b.theta_rad);
    m.theta_max_rad = std::max(m.theta_max_rad, b.theta_rad);
    hmin = std::min(hmin, b.h_m);
    hmax = std::max(hmax, b.h_m);
  }
  const double inv = 1.0 / static_cast<double>(N);
  m.theta_rad *= inv;
  m.airspeed_mps *= inv;
  m.U_mps *= inv;
  m.W_mps *= inv;
  m.Q_radps *= inv;
  m.FV_N *= inv;
  m.FH_N *= inv;
  m.M_Nm *= inv;
  m.power_aero_W = h.power_integral_J.back() / period_s;
  m.altitude_p2p_m = hmax - hmin;
  return m;
}

PeriodicTrimSummary solvePeriodicTrim(const FlightCoreModel& model, const TrimOptions& options) {
  const auto t0 = std::chrono::steady_clock::now();
  std::string why;
  if (!options.IsValid(&why)) throw std::invalid_argument("trim options: " + why);
  PeriodicTrimSummary s;
  s.control = options.periodic.control;

  // Stage 1: paper Eq. (4) on the tethered means, the start of the orbit search.
  TrimOptions o1 = options;
  o1.method = TrimMethod::kTwoStage;
  o1.refine_in_free_flight = false;
  o1.verify_free_flight = false;
  o1.start_only = true;  // forward differences, no Jacobian at the converged point
  s.stage1 = solveTrim(model, o1);
  s.stage1_time_s = seconds(t0);
  s.solution = s.stage1.solution;
  s.free_flight.status = FreeFlightStatus::kSkipped;
  s.free_flight.message = "periodic trim not converged: no free-flight check";
  if (!s.stage1.converged) {
    s.message = "no Eq. (4) start for the periodic orbit: " + s.stage1.message;
    s.wall_time_s = seconds(t0);
    return s;
  }

  // The orbit. The skin friction is frozen at a speed (it must not depend on the unknowns): first
  // the Eq. (4) speed, then the orbit's own mean airspeed, solved again from the first orbit with
  // its Jacobian, so that the result does not depend on how tightly stage 1 was solved.
  const auto t1 = std::chrono::steady_clock::now();
  FreeFlightPeriodMapOptions mo;
  mo.rel_tol = options.periodic.rel_tol;
  mo.friction_speed_mps = s.stage1.solution.speed_mps;
  mo.design_point = options.design_point;
  FreeFlightPeriodMap map(model, mo);
  s.states = map.stateInfo();
  s.state_units = map.stateUnits();
  for (int i = 0; i < map.stateCount(); ++i) s.state_scales.push_back(map.stateScale(i));
  std::vector<double> x = periodicStartState(model, map, s.stage1.solution, options.simulation);
  std::vector<double> p = FreeFlightPeriodMap::parameters(s.stage1.solution);
  ShootingOptions so;
  so.free_parameters = {parameterIndex(options.periodic.control)};
  so.conditions = {kPeriodAltitudeGain};
  so.residual_tol = options.periodic.residual_tol;
  so.max_iterations = options.periodic.max_iterations;
  // The first Jacobian differences the body states only: the modal and aerodynamic states decay
  // within a period (multipliers below 0.4 on the magpie); Broyden supplies the rest.
  so.first_jacobian_states = {0, 1, 2, 3};
  // Its columns on the trim's threads (each on a copy of the map: the same bits for any count).
  so.jacobian_threads = options.jacobian_threads;
  const bool full_floquet = options.periodic.floquet && options.periodic.multipliers == 0;
  long maps = 0;
  int iterations = 0, jacobians = 0, partial = 0, broyden = 0, refreshes = 0;
  std::string sample_why;
  for (int pass = 0; pass < 2; ++pass) {
    // The full monodromy is the Jacobian at the solution of the last pass.
    so.jacobian_at_solution = pass == 1 && full_floquet;
    try {
      s.shooting = solveShooting(map, x, p, so);
    } catch (const std::invalid_argument& e) {  // a parameter the vehicle cannot take (f <= 0)
      s.shooting = ShootingSummary{};
      s.shooting.status = ShootingStatus::kFailed;
      s.shooting.message = e.what();
    }
    for (const ShootingIteration& r : s.shooting.log) {
      s.newton_log.push_back(r);
      s.newton_log.back().period_maps += maps;
      s.newton_pass.push_back(pass + 1);
    }
    maps += s.shooting.period_maps;
    iterations += s.shooting.iterations;
    jacobians += s.shooting.jacobians;
    partial += s.shooting.partial_jacobians;
    broyden += s.shooting.broyden_updates;
    refreshes += s.shooting.refreshes;
    if (s.shooting.status != ShootingStatus::kConverged) break;
    x = s.shooting.x;
    p = s.shooting.p;
    // Histories and cycle means of this orbit; the first pass only needs the mean airspeed (the
    // friction speed of the second), for which 16 uniform samples of the smooth periodic airspeed
    // are plenty (the rectangle rule is spectrally accurate on a periodic function).
    sample_why.clear();
    const int samples = pass == 1 ? options.periodic.history_samples
                                  : std::min(16, options.periodic.history_samples);
    if (!map.sampleOrbit(x.data(), p.data(), samples, &s.history, &sample_why)) {
      s.shooting.status = ShootingStatus::kFailed;
      s.shooting.message = "the orbit's histories could not be integrated: " + sample_why;
      break;
    }
    s.mean = cycleMeans(s.history, 1.0 / p[kPeriodFrequency]);
    if (pass == 1 || !(s.mean.airspeed_mps > 0.0)) break;
    map.setFrictionSpeed(s.mean.airspeed_mps);
    so.initial_jacobian = s.shooting.jacobian;
  }
  s.shooting.period_maps = maps;
  s.shooting.iterations = iterations;
  s.shooting.jacobians = jacobians;
  s.shooting.partial_jacobians = partial;
  s.shooting.broyden_updates = broyden;
  s.shooting.refreshes = refreshes;
  s.friction_speed_mps = map.frictionSpeed_mps();
  s.grid_steps = map.gridSteps();
  s.integrator = map.methodName();
  s.converged = s.shooting.status == ShootingStatus::kConverged;
  s.orbit_time_s = seconds(t1);
  if (!s.converged) {
    s.rhs_evaluations = map.rhsEvaluations();
    s.message = "Eq. (4) " + s.stage1.message + "; periodic orbit not found: " + s.shooting.message;
    s.wall_time_s = seconds(t0);
    return s;
  }
  const double T = 1.0 / p[kPeriodFrequency];
  s.orbit_start = x;
  s.cg_shift_m = p[kPeriodCgShift];

  // Floquet multipliers: the full monodromy (the Jacobian at the solution) or the leading ones by
  // Arnoldi, with the full matrix as the fallback when Arnoldi does not converge.
  if (options.periodic.floquet) {
    const auto t2 = std::chrono::steady_clock::now();
    MonodromyEigen eigen;
    std::string fallback;
    if (full_floquet && s.shooting.jacobian_valid) {
      eigen = eigenOfMonodromy(s.shooting.monodromy);
    } else if (!full_floquet) {
      ArnoldiOptions ao;
      ao.count = options.periodic.multipliers;
      eigen = leadingMultipliers(map, x, p, ao);
      s.floquet_maps += eigen.period_maps;
      if (!eigen.ok) fallback = eigen.message;
    }
    if (!eigen.ok) {
      Eigen::MatrixXd M;
      long used = 0;
      std::string why_m;
      const bool ok = monodromyByDifferences(map, x, p, so.fd_step, &M, &used, &why_m);
      s.floquet_maps += used;
      eigen = ok ? eigenOfMonodromy(M) : MonodromyEigen{};
      if (!ok) eigen.message = "the monodromy matrix could not be formed: " + why_m;
      if (!fallback.empty()) eigen.message += " (" + fallback + ")";
    }
    if (eigen.ok) {
      s.floquet = analyseFloquet(eigen, T, map.stateInfo());
      s.floquet_valid = true;
      if (options.periodic.multiplier_check) checkMultipliers(model, mo, map, x, p, so.fd_step, &s);
    } else {
      s.floquet_message = eigen.message;
    }
    s.floquet_time_s = seconds(t2);
  }
  s.rhs_evaluations = map.rhsEvaluations();
  s.solution.theta_rad = s.mean.theta_rad;
  s.solution.speed_mps = s.mean.airspeed_mps;
  s.solution.tail_angle_rad = p[kPeriodTailAngle];
  s.solution.freq_hz = p[kPeriodFrequency];
  const FlightCoreModel& solved = map.modelAt(p.data());
  s.orbit_check =
      orbitCheck(solved, x, p, s.friction_speed_mps, mo.rel_tol, map, options.design_point);

  s.status = TrimStatus::kOk;
  char buf[400];
  std::snprintf(buf, sizeof buf,
                "periodic orbit found from the Eq. (4) trim (theta %.3f deg, U %.3f m/s, tail %.3f "
                "deg): %s",
                s.stage1.solution.theta_rad * kRadToDeg, s.stage1.solution.speed_mps,
                s.stage1.solution.tail_angle_rad * kRadToDeg, s.shooting.message.c_str());
  s.message = buf;
  if (!options.verify_free_flight) {
    s.free_flight.message = "free-flight check not requested";
  } else {
    s.free_flight = verifyFreeFlight(solved, s.solution, options.free_flight);
  }
  s.wall_time_s = seconds(t0);
  return s;
}

}  // namespace orni
