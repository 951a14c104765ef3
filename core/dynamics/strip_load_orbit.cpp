#include "core/dynamics/strip_load_orbit.hpp"

#include <stdexcept>

#include "core/dynamics/flexible_tethered.hpp"
#include "core/dynamics/modal_implicit_split.hpp"
#include "core/dynamics/simulation_options.hpp"
#include "core/integrate/ode_integrator.hpp"

namespace orni {

StripLoadOrbit recordStripLoadOrbit(const FlightCoreModel& model, const OperatingPoint& point,
                                    int settle_cycles, int samples) {
  if (!model.flexible) throw std::invalid_argument("strip load orbit: the wing is rigid");
  if (settle_cycles < 0 || samples < 1)
    throw std::invalid_argument("strip load orbit: cycles >= 0 and samples >= 1");
  const BodyMotion body = tetheredBodyMotion(point.speed_mps, point.theta_rad);
  FlexibleTetheredSystem sys(model, *model.flexible, body,
                             ControlInput{point.freq_hz, point.tail_angle_rad});
  // The integration of simulateTethered (tethered_simulation.cpp): the same options and method.
  const SimulationOptions so;
  IntegratorOptions iopt;
  iopt.rel_tol = so.rel_tol;
  sys.absoluteTolerances(so.rel_tol, so.abs_tol, so.separation_abs_tol, &iopt.abs_tol);
  const double period = 1.0 / point.freq_hz;
  iopt.max_step = period / 8.0;
  using Imex = ModalImex<FlexibleTetheredSystem>;
  OdeIntegrator integ(sys.stateCount(), Imex::rhs(true), &sys,
                      Imex::method(true, sys.nonlinearWing()), iopt);
  std::vector<double> y0(static_cast<std::size_t>(sys.stateCount()), 0.0);
  sys.initialState(0.0, y0.data());
  integ.reset(0.0, y0.data());
  const int m = model.flexible->mode_count;
  StripLoadOrbit orbit;
  const double t0 = settle_cycles * period;
  for (int i = 0; i <= samples; ++i) {
    const double t = t0 + period * i / samples;
    if (t > 0.0 && integ.advanceTo(t) != IntegratorStatus::kOk)
      throw std::runtime_error("strip load orbit: the tethered run failed: " + integ.lastError());
    const double* y = integ.state();
    LoadSample ls;
    sys.sample(t, y, &ls);  // evaluates the strips at (t, y)
    Eigen::Matrix3Xd f;
    Eigen::VectorXd mom, sep;
    sys.lastStripLoads(&f, &mom, &sep);
    orbit.t_s.push_back(t);
    orbit.q.emplace_back(Eigen::Map<const Eigen::VectorXd>(y, m));
    orbit.qd.emplace_back(Eigen::Map<const Eigen::VectorXd>(y + m, m));
    orbit.force_W.push_back(f);
    orbit.moment_Nm.push_back(mom);
    orbit.separation_f.push_back(sep);
  }
  return orbit;
}

}  // namespace orni
