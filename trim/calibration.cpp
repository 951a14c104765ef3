#include "trim/calibration.hpp"

#include <ceres/ceres.h>

#include <Eigen/Dense>

#include <algorithm>
#include <exception>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <utility>

#include "core/dynamics/flight_core.hpp"
#include "core/dynamics/modal_wing_cache.hpp"
#include "core/model/field_table.hpp"
#include "core/dynamics/tethered_simulation.hpp"
#include "core/model/cancellation.hpp"
#include "trim/ceres_logging.hpp"
#include "core/model/invariant.hpp"

namespace orni {

namespace {
struct CalibrationContext {
  const VehicleModel* base;
  const CalibrationOptions* options;
  std::vector<CalibrationEvaluation>* log;
  /// A programming error inside an evaluation (core/model/invariant.hpp): the solve aborts and
  /// calibrate rethrows it (Ceres is not left by an exception).
  std::shared_ptr<std::exception_ptr> fatal = std::make_shared<std::exception_ptr>();
  bool tethered = false;  ///< Eq. (4) residuals of the tethered means instead of settled flight
  /// The modal wings of the evaluations (calibrated parameters rarely touch the structure).
  std::shared_ptr<ModalWingCache> modal_wings = std::make_shared<ModalWingCache>();
};

// Appends an evaluation to the log and tells the caller (progress files of long calibrations).
void record(const CalibrationContext& c, const CalibrationEvaluation& e) {
  c.log->push_back(e);
  if (c.options->on_evaluation) c.options->on_evaluation(*c.log);
}

// Eq. (4) at the target: (mean FV - W)/W, mean FH/W, mean M/(W c_mean), x 100 (percent of W).
bool evaluateTethered(const CalibrationContext& c, const VehicleModel& v, double* r,
                      CalibrationEvaluation* e) {
  const FlightCoreModel model(v, FlightCoreModel::Checks::kRequired, c.modal_wings.get());
  SimulationOptions o;
  o.cycles = 40;
  o.stop_when_steady = true;
  o.steady_tol = 1e-5;
  o.rel_tol = 1e-6;
  o.record_history = false;
  const SimulationSummary s = simulateTethered(model, c.options->target, o, nullptr);
  const double W = v.body.mass_kg * v.air.gravity_mps2;
  e->residual[0] = 100.0 * (s.mean.FV_N - W) / W;
  e->residual[1] = 100.0 * s.mean.FH_N / W;
  e->residual[2] = 100.0 * s.mean.M_Nm / (W * model.mean_chord_m);
  e->settled.ok = s.status == SimulationStatus::kOk;
  e->settled.message = "tethered: " + s.message;
  for (int i = 0; i < 3; ++i) r[i] = e->residual[i];
  return e->settled.ok;
}

// A value whose component along a null direction of the scaled Jacobian exceeds this is reported
// undetermined (CalibrationConditioning::null_component): the null direction is mostly that
// value. Below it the value is determined up to that component times the free value's travel.
constexpr double kUndeterminedComponent = 0.5;

// A value from its position u in [1, 2] of the variable's range, u = 1 at the lower bound (the
// solver's unknowns: Ceres steps its central differences by a fraction of |u|, so 1-2 % of each
// range whatever the value's size, never a vanishing step at a bound at zero; a drag area of
// 4e-4 m^2 stepped by a fraction of itself would move the settled flight by less than the noise
// of its settled means).
double unscaled(const CalibrationVariable& v, double u) {
  return v.lower + (u - 1.0) * (v.upper - v.lower);
}
double scaled(const CalibrationVariable& v, double x) {
  return 1.0 + (x - v.lower) / (v.upper - v.lower);
}

// Settled free flight of the vehicle with the given scaled values at the target point.
bool evaluate(const CalibrationContext& c, const double* u, double* r,
              CalibrationStage stage = CalibrationStage::kFreeFlight) {
  VehicleModel v = *c.base;
  const CalibrationOptions& o = *c.options;
  CalibrationEvaluation e;
  e.stage = c.tethered ? CalibrationStage::kTethered : stage;
  for (std::size_t i = 0; i < o.variables.size(); ++i) {
    // Held inside the range: Ceres's central differences step past a bound the solution sits
    // on (the derivative there becomes one-sided, which is all a bounded fit can use).
    const double x = unscaled(o.variables[i], std::clamp(u[i], 1.0, 2.0));
    setValue(&v, o.variables[i].parameter, x);
    e.values.push_back(x);
  }
  // Ceres evaluates some points twice (with bounds its trust-region minimizer runs a projected
  // line search whose trial points evaluate the gradient, a full central-difference Jacobian, and
  // it may come back to the same point); runs are deterministic, so an earlier run at the same
  // values and kind is reused, not flown again (logged again, so the log still lists every
  // evaluation Ceres asked for).
  for (const CalibrationEvaluation& earlier : *c.log) {
    if (earlier.values != e.values ||
        (earlier.stage == CalibrationStage::kTethered) != c.tethered)
      continue;
    const CalibrationStage kind = e.stage;
    e = earlier;
    e.stage = kind;
    record(c, e);
    for (int i = 0; i < 3; ++i) r[i] = e.residual[i];
    return e.settled.ok;
  }
  try {
    if (c.tethered) {
      const bool ok = evaluateTethered(c, v, r, &e);
      record(c, e);
      return ok;
    }
    const FlightCoreModel model(v, FlightCoreModel::Checks::kRequired, c.modal_wings.get());
    SimulationOptions sim;
    sim.rel_tol = settledFlightRelTol(model);
    e.settled = settledFreeFlight(model, o.target, sim, o.settled);
  } catch (const std::exception& ex) {
    rethrowIfProgrammingError(ex);  // core/model/invariant.hpp
    e.settled.ok = false;
    e.settled.message = ex.what();
  }
  e.residual[0] = (e.settled.theta_mean_rad - o.target.theta_rad) * kRadToDeg;
  e.residual[1] = (e.settled.airspeed_mps - o.target.speed_mps) / 0.1;
  e.residual[2] = e.settled.climb_angle_rad * kRadToDeg;
  record(c, e);
  if (!e.settled.ok) return false;
  for (std::size_t i = 0; i < 3; ++i) r[i] = e.residual[i];
  return true;
}

// Stops Ceres as soon as an accepted iterate meets the tolerance (cost = 0.5 |r|^2 with the
// residuals in deg, 0.1 m/s and deg: |r_i| <= tolerance for all i when |r| <= tolerance).
class ToleranceCallback : public ceres::IterationCallback {
 public:
  ToleranceCallback(double tolerance, const std::exception_ptr* fatal)
      : tol_(tolerance), fatal_(fatal) {}
  ceres::CallbackReturnType operator()(const ceres::IterationSummary& s) override {
    if (cancellationRequested()) return ceres::SOLVER_ABORT;  // the caller throws Cancelled
    if (*fatal_) return ceres::SOLVER_ABORT;                  // ... or the programming error
    if (s.step_is_successful || s.iteration == 0)
      if (2.0 * s.cost <= tol_ * tol_) return ceres::SOLVER_TERMINATE_SUCCESSFULLY;
    return ceres::SOLVER_CONTINUE;
  }

 private:
  double tol_;
  const std::exception_ptr* fatal_;
};

struct Functor {
  const CalibrationContext* c;
  bool operator()(const double* const x, double* r) const {
    if (*c->fatal) return false;  // an earlier evaluation hit a programming error
    try {
      return evaluate(*c, x, r);
    } catch (const Cancelled&) {  // Ceres is not left by an exception: the caller throws after
      return false;
    } catch (...) {  // a programming error: the solve aborts, the caller rethrows it
      if (!*c->fatal) *c->fatal = std::current_exception();
      return false;
    }
  }
};
}  // namespace

const std::vector<std::string_view>& calibrationKeys() {
  static const std::vector<std::string_view> keys = {
      "wing.member_diameter_scale", "body.drag_area_m2",       "kinematics.hinge_x_m",
      "kinematics.hinge_z_m",       "tail.arm_m",              "body.pitch_inertia_kgm2",
      "wing.p3_aft_of_le_m",        "aero.suction_efficiency", "wing.skin.pretension_N_per_m"};
  return keys;
}

std::string calibrationKeyList() {
  std::string list;
  for (const std::string_view k : calibrationKeys())
    list += (list.empty() ? "" : ", ") + std::string(k);
  return list;
}

std::string keyOf(CalibrationParameter p) { return p.number ? std::string(p.number->key) : "?"; }

bool parseCalibrationParameter(const std::string& key, CalibrationParameter* p) {
  for (const std::string_view k : calibrationKeys())
    if (key == k) {
      p->number = findVehicleNumber(k);
      return p->number != nullptr;
    }
  return false;
}

CalibrationParameter calibrationParameter(const std::string& key) {
  CalibrationParameter p;
  if (!parseCalibrationParameter(key, &p))
    throw std::invalid_argument("not a calibration key: " + key + " (one of " +
                                calibrationKeyList() + ")");
  return p;
}

double valueOf(const VehicleModel& v, CalibrationParameter p) { return p.number->get(v, 0); }

void setValue(VehicleModel* v, CalibrationParameter p, double value) {
  p.number->set(*v, 0, value);
}

bool CalibrationOptions::IsValid(std::string* why) const {
  auto fail = [why](const std::string& m) {
    if (why) *why = m;
    return false;
  };
  if (variables.empty() || variables.size() > 4) return fail("1 to 4 calibration variables");
  for (std::size_t i = 0; i < variables.size(); ++i) {
    const CalibrationVariable& v = variables[i];
    if (!v.parameter.number) return fail("a calibration variable without a key");
    if (!(v.lower < v.upper) || !(v.initial >= v.lower && v.initial <= v.upper))
      return fail(std::string("variable ") + keyOf(v.parameter) +
                  ": needs lower < upper and lower <= initial <= upper");
    for (std::size_t j = 0; j < i; ++j)
      if (variables[j].parameter == v.parameter)
        return fail(std::string("variable ") + keyOf(v.parameter) + " listed twice");
    const FieldSpec& f = field(keyOf(v.parameter));  // SI = file units for these keys
    if (!(f.range.contains(v.lower) && f.range.contains(v.upper)))
      return fail(std::string("variable ") + keyOf(v.parameter) + ": bounds must lie in " +
                  f.range.interval());
  }
  // The keys of [calibrate]: the field table's ranges (SI).
  const std::pair<const char*, double> keyed[] = {
      {"calibrate.theta_mean_deg", target.theta_rad},
      {"calibrate.speed_mps", target.speed_mps},
      {"calibrate.tail_angle_deg", target.tail_angle_rad},
      {"calibrate.freq_hz", target.freq_hz},
      {"calibrate.settled_cycles", settled.cycles},
      {"calibrate.window_cycles", settled.window_cycles},
      {"calibrate.tolerance", tolerance},
      {"calibrate.max_iterations", max_iterations}};
  for (const auto& [key, value] : keyed)
    if (!field(key).siRange().contains(value))
      return fail(std::string(key) + " must be in " + field(key).range.interval());
  if (settled.window_cycles >= settled.cycles) return fail("settled window < cycles");
  return true;
}

namespace {
// The Jacobian of the settled flight at the solution by central differences of 1 % of each range
// (one-sided at a bound), its singular values in band-per-range units and the half-width each
// value is determined to (calibration.hpp).
CalibrationConditioning conditioningAt(const CalibrationContext& ctx,
                                       const std::vector<double>& u) {
  const CalibrationOptions& o = *ctx.options;
  const int n = static_cast<int>(u.size());
  CalibrationConditioning k;
  Eigen::MatrixXd J(3, n);  // residual units (deg, 0.1 m/s, deg) per scaled value
  constexpr double kStep = 0.01;  // of the range: above the settled means' noise, below curvature
  for (int i = 0; i < n; ++i) {
    std::vector<double> up = u, um = u;
    up[static_cast<std::size_t>(i)] = std::min(2.0, u[static_cast<std::size_t>(i)] + kStep);
    um[static_cast<std::size_t>(i)] = std::max(1.0, u[static_cast<std::size_t>(i)] - kStep);
    double rp[3], rm[3];
    if (!evaluate(ctx, up.data(), rp, CalibrationStage::kConditioning) ||
        !evaluate(ctx, um.data(), rm, CalibrationStage::kConditioning)) {
      k.message = "a conditioning flight of " +
                  keyOf(o.variables[static_cast<std::size_t>(i)].parameter) +
                  " did not settle: " + ctx.log->back().settled.message;
      return k;
    }
    const double du = up[static_cast<std::size_t>(i)] - um[static_cast<std::size_t>(i)];
    for (int j = 0; j < 3; ++j) J(j, i) = (rp[j] - rm[j]) / du;
  }
  return conditioningOfJacobian(J, o.variables, o.band);
}
}  // namespace

CalibrationConditioning conditioningOfJacobian(const Eigen::MatrixXd& J,
                                               const std::vector<CalibrationVariable>& variables,
                                               const CalibrationBand& calibration_band) {
  const int n = static_cast<int>(J.cols());
  if (J.rows() != 3 || n != static_cast<int>(variables.size()) || n < 1)
    throw std::invalid_argument("conditioningOfJacobian: expected a 3 x n Jacobian, n values");
  CalibrationConditioning k;
  const double band[3] = {calibration_band.theta_deg, calibration_band.speed_mps / 0.1,
                          calibration_band.climb_deg};
  for (int i = 0; i < n; ++i) {
    const CalibrationVariable& v = variables[static_cast<std::size_t>(i)];
    const double range = v.upper - v.lower;
    k.jacobian.push_back({J(0, i) / range, J(1, i) * 0.1 / range, J(2, i) / range});
  }
  // Dimensionless: rows divided by the band, columns are already per range.
  Eigen::MatrixXd B = J;
  for (int j = 0; j < 3; ++j) B.row(j) /= band[j];
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(B, Eigen::ComputeFullU | Eigen::ComputeFullV);
  const Eigen::VectorXd sv = svd.singularValues();
  for (int i = 0; i < sv.size(); ++i) k.singular_values.push_back(sv(i));
  const double smax = sv.size() ? sv(0) : 0.0;
  const double tiny = 1e-9 * std::max(smax, 1e-300);
  int rank = 0;
  for (int i = 0; i < sv.size(); ++i) rank += sv(i) > tiny ? 1 : 0;
  k.condition_number = rank == n && rank > 0 ? smax / sv(rank - 1)
                                             : std::numeric_limits<double>::infinity();
  // J^+ in scaled units; a value with a component along a null direction is undetermined.
  const Eigen::MatrixXd V = svd.matrixV(), U = svd.matrixU();
  Eigen::MatrixXd pinv = Eigen::MatrixXd::Zero(n, 3);
  for (int r = 0; r < rank; ++r) pinv += V.col(r) * U.col(r).transpose() / sv(r);
  for (int i = 0; i < n; ++i) {
    const CalibrationVariable& v = variables[static_cast<std::size_t>(i)];
    double null_part = 0.0;
    for (int r = rank; r < n; ++r) null_part = std::max(null_part, std::abs(V(i, r)));
    // pinv maps band-scaled residuals (a box of half-width 1) to scaled values.
    const double half = pinv.row(i).cwiseAbs().sum() * (v.upper - v.lower);
    k.null_component.push_back(null_part);
    k.determined_within.push_back(null_part > kUndeterminedComponent
                                      ? std::numeric_limits<double>::infinity()
                                      : half);
  }
  k.ok = true;
  return k;
}

CalibrationSummary calibrate(const VehicleModel& base, const CalibrationOptions& options) {
  std::string why;
  if (!options.IsValid(&why)) throw std::invalid_argument("calibration options: " + why);
  const auto t0 = std::chrono::steady_clock::now();
  CalibrationSummary s;
  const int n = static_cast<int>(options.variables.size());
  std::vector<double> u;  // scaled to [1, 2] of each range (unscaled/scaled above)
  for (const CalibrationVariable& v : options.variables) u.push_back(scaled(v, v.initial));
  CalibrationContext ctx{&base, &options, &s.log};
  auto solve = [&](bool tethered) {
    ctx.tethered = tethered;
    Functor f{&ctx};
    ceres::NumericDiffOptions nd;
    nd.relative_step_size = 1e-2;  // of the scaled value: 1-2 % of the range (above the noise)
    ceres::CostFunction* cost = nullptr;
    if (n == 1)
      cost = new ceres::NumericDiffCostFunction<Functor, ceres::CENTRAL, 3, 1>(
          new Functor(f), ceres::TAKE_OWNERSHIP, 3, nd);
    else if (n == 2)
      cost = new ceres::NumericDiffCostFunction<Functor, ceres::CENTRAL, 3, 2>(
          new Functor(f), ceres::TAKE_OWNERSHIP, 3, nd);
    else if (n == 3)
      cost = new ceres::NumericDiffCostFunction<Functor, ceres::CENTRAL, 3, 3>(
          new Functor(f), ceres::TAKE_OWNERSHIP, 3, nd);
    else
      cost = new ceres::NumericDiffCostFunction<Functor, ceres::CENTRAL, 3, 4>(
          new Functor(f), ceres::TAKE_OWNERSHIP, 3, nd);
    ceres::Problem problem;
    problem.AddResidualBlock(cost, nullptr, u.data());
    for (int i = 0; i < n; ++i) {
      problem.SetParameterLowerBound(u.data(), i, 1.0);
      problem.SetParameterUpperBound(u.data(), i, 2.0);
    }
    ceres::Solver::Options so;
    so.linear_solver_type = ceres::DENSE_QR;
    so.max_num_iterations = options.max_iterations;
    // Both stages stop when the cost stalls (0.1 % a step) or the steps shrink below 1e-4 of the
    // ranges (a hundredth of the difference steps) instead of grinding on a minimum that is not
    // zero: measured, 558 tethered runs for the magpie's nonlinear wing against Table 3, the last
    // 400 within 1 %; in free flight each run costs seconds and the settled means carry noise of
    // about 1e-3 deg, so a closer minimum than 0.1 % of the cost is not resolved anyway. A
    // minimum inside the tolerance ends the fit earlier (ToleranceCallback); one outside it is
    // reported not calibrated, with the closest point and the values whose range binds.
    so.function_tolerance = 1e-3;
    so.gradient_tolerance = 1e-16;
    so.parameter_tolerance = 1e-4;
    so.logging_type = ceres::SILENT;
    so.num_threads = 1;
    // Tethered stage: 1e-3 % of W is plenty for a starting point of the free-flight stage.
    ToleranceCallback stop(tethered ? 1e-3 : options.tolerance, ctx.fatal.get());
    so.callbacks.push_back(&stop);
    quietCeresLogging();  // our summary says why the solve ended
    ceres::Solver::Summary cs;
    ceres::Solve(so, &problem, &cs);
    throwIfCancelled();  // core/model/cancellation.hpp
    if (*ctx.fatal) std::rethrow_exception(*ctx.fatal);
    s.iterations += static_cast<int>(cs.iterations.size()) - 1;
    s.ceres_report += (s.ceres_report.empty() ? "" : " | ") + cs.BriefReport();
    return cs.message;
  };
  if (options.tethered_first) solve(true);
  const std::string ceres_message = solve(false);
  s.evaluations = static_cast<int>(s.log.size());
  for (int i = 0; i < n; ++i) {
    const CalibrationVariable& v = options.variables[static_cast<std::size_t>(i)];
    s.values.push_back(unscaled(v, u[static_cast<std::size_t>(i)]));
    s.at_lower.push_back(u[static_cast<std::size_t>(i)] <= 1.0 + 1e-6);
    s.at_upper.push_back(u[static_cast<std::size_t>(i)] >= 2.0 - 1e-6);
  }
  // The settled flight at the solution (re-evaluated so the summary is consistent).
  double r[3] = {0, 0, 0};
  ctx.tethered = false;
  const bool ok = evaluate(ctx, u.data(), r);
  const CalibrationEvaluation at_solution = s.log.back();
  if (options.conditioning && ok) s.conditioning = conditioningAt(ctx, u);
  if (options.conditioning && !ok) s.conditioning.message = "no settled flight at the solution";
  s.settled = at_solution.settled;
  s.evaluations = static_cast<int>(s.log.size());
  s.theta_error_deg = at_solution.residual[0];
  s.speed_error_mps = at_solution.residual[1] * 0.1;
  s.climb_angle_deg = at_solution.residual[2];
  // Each residual within the tolerance in its own unit (deg, 0.1 m/s, deg), as the solver's stop
  // test: the speed to 0.1 tolerance m/s (it was compared in m/s, 10 times looser than documented).
  s.converged = ok && std::abs(at_solution.residual[0]) <= options.tolerance &&
                std::abs(at_solution.residual[1]) <= options.tolerance &&
                std::abs(at_solution.residual[2]) <= options.tolerance;
  char buf[400];
  std::snprintf(buf, sizeof buf,
                "%s after %d iterations, %d settled free flights: theta error %.4f deg, speed "
                "error %.4f m/s, climb angle %.4f deg (tolerance %.3g); Ceres: %s",
                s.converged ? "calibrated" : "not calibrated", s.iterations, s.evaluations,
                s.theta_error_deg, s.speed_error_mps, s.climb_angle_deg, options.tolerance,
                ceres_message.c_str());
  s.message = buf;
  s.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return s;
}

}  // namespace orni
