#include "trim/trim_solver.hpp"

#include "trim/free_flight_trim.hpp"

#include <ceres/ceres.h>

#include <algorithm>
#include <exception>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <utility>

#include "core/model/cancellation.hpp"
#include "core/model/frames.hpp"
#include "trim/ceres_logging.hpp"
#include "trim/trim_unknowns.hpp"

namespace orni {

const char* toString(TrimStatus s) { return s == TrimStatus::kOk ? "ok" : "not_converged"; }

const char* toString(TrimTermination t) {
  switch (t) {
    case TrimTermination::kResidualTolerance: return "residual_tolerance";
    case TrimTermination::kCeresConvergence: return "ceres_convergence";
    case TrimTermination::kIterationLimit: return "iteration_limit";
    case TrimTermination::kStalled: return "stalled";
    case TrimTermination::kSimulationFailure: return "simulation_failure";
    case TrimTermination::kCeresFailure: return "ceres_failure";
  }
  return "ceres_failure";
}

namespace {

// "12.34 deg" etc. for messages.
std::string valueText(TrimUnknown u, double si) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.6g %s", si / trimUnknownScale(u), trimUnknownUnit(u));
  return buf;
}


}  // namespace

std::string TrimSummary::BriefReport() const {
  char buf[512];
  std::snprintf(buf, sizeof buf,
                "%s: %s; residual FV-W %.3e N, FH %.3e N, M %.3e N m (max %.2e W); %d iterations, "
                "%d periodic runs, %.3f s",
                toString(status), pointText(solution).c_str(), residual.FV_N, residual.FH_N,
                residual.M_Nm, scaled_residual_max, iterations, evaluations, wall_time_s);
  return buf;
}

// ------------------------------------------------------------------------------------------------
// Ceres side

namespace {

// Eq. (4) residuals and their finite-difference Jacobian (trim_problem.hpp) as a Ceres cost.
// `skip_tol` > 0 (TrimOptions::start_only): no Jacobian at a point whose max scaled residual is
// within it. Ceres asks for the Jacobian at every accepted point before its callbacks run, and
// TrimCallback then ends the solve at such a point, so that Jacobian (zeros here) is never used.
class TrimCostFunction final : public ceres::CostFunction {
 public:
  TrimCostFunction(TrimProblem* problem, std::exception_ptr* fatal, double skip_tol)
      : problem_(problem), fatal_(fatal), skip_tol_(skip_tol) {
    set_num_residuals(kTrimResidualCount);
    mutable_parameter_block_sizes()->push_back(problem->unknownCount());
  }
  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override {
    // A failed periodic run makes the point infeasible: Ceres shrinks the trust region. A
    // cancelled one too (Ceres is not left by an exception); solveTrim throws after Solve.
    if (*fatal_) return false;  // an earlier evaluation hit a programming error
    try {
      if (!problem_->residual(parameters[0], residuals)) return false;
      if (!jacobians || !jacobians[0]) return true;
      if (skip_tol_ > 0.0) {
        const TrimEvaluationRecord* e = problem_->findResidual(problem_->pointAt(parameters[0]));
        if (e && e->result.ok && e->scaled_max <= skip_tol_) {
          std::fill_n(jacobians[0], kTrimResidualCount * problem_->unknownCount(), 0.0);
          return true;
        }
      }
      return problem_->jacobian(parameters[0], jacobians[0]);
    } catch (const Cancelled&) {
      return false;
    } catch (...) {  // a programming error (core/model/invariant.hpp): solveTrim rethrows it
      if (!*fatal_) *fatal_ = std::current_exception();
      return false;
    }
    return true;
  }

 private:
  TrimProblem* problem_;
  std::exception_ptr* fatal_;
  double skip_tol_;
};

// Records every iteration, stops at the equilibrium tolerance (Ceres has no absolute residual
// test) and aborts a stalled solve (typically creeping along a bound, where the projected
// Levenberg-Marquardt steps shrink without reaching Ceres' own tolerances). Needs
// Solver::Options::update_state_every_iteration so that x is the accepted iterate.
class TrimCallback final : public ceres::IterationCallback {
 public:
  TrimCallback(TrimProblem* problem, const double* x, const TrimOptions& options,
               std::vector<TrimIterationRecord>* log, const std::exception_ptr* fatal)
      : fatal_(fatal),
        problem_(problem),
        x_(x),
        tol_(options.residual_tol),
        stall_iterations_(options.stall_iterations),
        stall_decrease_(options.stall_decrease),
        log_(log) {}
  bool stalled() const { return stalled_; }
  ceres::CallbackReturnType operator()(const ceres::IterationSummary& s) override {
    if (cancellationRequested()) return ceres::SOLVER_ABORT;  // solveTrim throws Cancelled
    if (*fatal_) return ceres::SOLVER_ABORT;                  // ... or the programming error
    TrimIterationRecord r;
    r.iteration = s.iteration;
    r.point = problem_->pointAt(x_);
    r.cost = s.cost;
    r.step_norm = s.step_norm;
    r.trust_region_radius = s.trust_region_radius;
    r.step_successful = s.step_is_successful;
    r.evaluations = static_cast<int>(problem_->log().size());
    const TrimEvaluationRecord* e = problem_->findResidual(r.point);
    r.scaled_max = e ? e->scaled_max : std::sqrt(2.0 * s.cost);
    log_->push_back(r);
    problem_->setIteration(s.iteration + 1);
    if (e && e->result.ok && e->scaled_max <= tol_) return ceres::SOLVER_TERMINATE_SUCCESSFULLY;
    const std::size_t k = log_->size() - 1;
    const std::size_t window = static_cast<std::size_t>(stall_iterations_);
    if (stall_iterations_ > 0 && k >= window) {
      const double before = (*log_)[k - window].cost;
      if (before - s.cost < stall_decrease_ * before) {
        stalled_ = true;  // USER_SUCCESS keeps the iterate (SOLVER_ABORT would restore x0)
        return ceres::SOLVER_TERMINATE_SUCCESSFULLY;
      }
    }
    return ceres::SOLVER_CONTINUE;
  }

 private:
  const std::exception_ptr* fatal_;  ///< set by TrimCostFunction: abort the solve
  TrimProblem* problem_;
  const double* x_;
  double tol_;
  int stall_iterations_;
  double stall_decrease_;
  std::vector<TrimIterationRecord>* log_;
  bool stalled_ = false;
};

}  // namespace

TrimSummary solveTrim(const TrimReference& reference, const MeanLoadsFunction& loads,
                      const TrimOptions& options) {
  const auto t0 = std::chrono::steady_clock::now();
  std::string why;
  if (!options.IsValid(&why)) throw std::invalid_argument("trim options: " + why);
  if (!(reference.weight_N > 0.0 && reference.length_m > 0.0))
    throw std::invalid_argument("trim reference: weight and length must be > 0");

  TrimSummary summary;
  summary.unknowns = options.unknowns;
  summary.reference = reference;
  summary.least_squares = options.unknowns.size() < static_cast<std::size_t>(kTrimResidualCount);

  TrimProblem problem(reference, loads, options.initial, options.unknowns, options.fd_steps,
                      options.bounds, options.start_only);
  problem.setJacobianThreads(options.jacobian_threads);
  std::vector<double> x = problem.solverValues(options.initial);
  const int n = problem.unknownCount();

  ceres::Problem::Options problem_options;
  problem_options.cost_function_ownership = ceres::TAKE_OWNERSHIP;
  ceres::Problem ceres_problem(problem_options);
  std::exception_ptr fatal;  // a programming error inside an evaluation, rethrown after Solve
  const double skip_tol = options.start_only ? options.residual_tol : 0.0;
  ceres_problem.AddResidualBlock(new TrimCostFunction(&problem, &fatal, skip_tol), nullptr,
                                 x.data());
  for (int j = 0; j < n; ++j) {
    const TrimUnknown u = options.unknowns[static_cast<std::size_t>(j)];
    const TrimBounds& b = options.bounds[static_cast<std::size_t>(trimIndex(u))];
    ceres_problem.SetParameterLowerBound(x.data(), j, b.lower / trimUnknownScale(u));
    ceres_problem.SetParameterUpperBound(x.data(), j, b.upper / trimUnknownScale(u));
  }

  TrimCallback callback(&problem, x.data(), options, &summary.iteration_log, &fatal);
  ceres::Solver::Options so;
  so.minimizer_type = ceres::TRUST_REGION;
  so.trust_region_strategy_type = ceres::LEVENBERG_MARQUARDT;
  so.linear_solver_type = ceres::DENSE_QR;
  // A step that leaves the bounds is projected and followed by a line search (Ceres trust-region
  // minimizer). With the default cubic interpolation every trial there costs a Jacobian, i.e. six
  // periodic runs, and it may bisect 20 times; bisection on function values only and at most four
  // trials cut the runs of a solve that ends on a bound by 2-5x (no change when none is active).
  so.line_search_interpolation_type = ceres::BISECTION;
  so.max_num_line_search_step_size_iterations = 4;
  so.max_num_iterations = options.max_iterations;
  so.function_tolerance = options.function_tol;
  so.gradient_tolerance = options.gradient_tol;
  so.parameter_tolerance = options.parameter_tol;
  so.num_threads = 1;
  so.logging_type = ceres::SILENT;
  so.minimizer_progress_to_stdout = false;
  so.update_state_every_iteration = true;
  so.callbacks.push_back(&callback);

  ceres::Solver::Summary cs;
  quietCeresLogging();  // our summary says why the solve ended
  ceres::Solve(so, &ceres_problem, &cs);
  throwIfCancelled();  // core/model/cancellation.hpp: the solve above stopped early for it
  if (fatal) std::rethrow_exception(fatal);

  summary.ceres_message = cs.message;
  summary.ceres_report = cs.BriefReport();
  // The last iteration index the callback saw (Ceres counts iteration 0, the initial point, as a
  // successful step).
  summary.iterations = summary.iteration_log.empty() ? 0 : summary.iteration_log.back().iteration;

  // The final iterate and its residual (normally already evaluated).
  summary.solution = problem.pointAt(x.data());
  const TrimEvaluationRecord* final_rec = problem.findResidual(summary.solution);
  bool final_ok = final_rec && final_rec->result.ok;
  if (!final_rec) {
    std::array<double, kTrimResidualCount> r{};
    final_ok = problem.residual(x.data(), r.data());
    final_rec = problem.findResidual(summary.solution);
  }
  if (final_ok) {
    summary.mean = final_rec->result.mean;
    summary.residual = final_rec->residual;
    summary.scaled_residual = scaledResidual(reference, summary.residual);
    summary.scaled_residual_max = final_rec->scaled_max;
  } else {
    summary.scaled_residual_max = std::numeric_limits<double>::quiet_NaN();
  }
  summary.converged = final_ok && summary.scaled_residual_max <= options.residual_tol;
  summary.status = summary.converged ? TrimStatus::kOk : TrimStatus::kNotConverged;

  // Unknowns on a bound (within a thousandth of a step).
  for (TrimUnknown u : options.unknowns) {
    const std::size_t i = static_cast<std::size_t>(trimIndex(u));
    const double v = unknownValue(summary.solution, u);
    const double eps = 1e-3 * options.fd_steps[i];
    if (v <= options.bounds[i].lower + eps)
      summary.at_bound.push_back(std::string(trimUnknownName(u)) + " at its lower bound " +
                                 valueText(u, options.bounds[i].lower));
    else if (v >= options.bounds[i].upper - eps)
      summary.at_bound.push_back(std::string(trimUnknownName(u)) + " at its upper bound " +
                                 valueText(u, options.bounds[i].upper));
  }

  // Termination reason and message.
  char tolerance_text[200];
  std::snprintf(tolerance_text, sizeof tolerance_text,
                "max scaled residual %.3e %s tolerance %.1e (|FV-W|, |FH|, |M|/c_mean vs W)",
                summary.scaled_residual_max, summary.converged ? "<=" : ">",
                options.residual_tol);
  std::string msg;
  if (summary.converged) {
    summary.termination = TrimTermination::kResidualTolerance;
    msg = std::string("equilibrium found: ") + tolerance_text;
  } else if (problem.log().size() == 1 && !problem.log().front().result.ok) {
    summary.termination = TrimTermination::kSimulationFailure;
    msg = "the periodic simulation failed at the initial guess (" + pointText(options.initial) +
          "): " + problem.log().front().result.message;
  } else if (callback.stalled()) {
    summary.termination = TrimTermination::kStalled;
    char buf[160];
    std::snprintf(buf, sizeof buf,
                  "stalled: the cost fell by less than %g %% over the last %d iterations; ",
                  100.0 * options.stall_decrease, options.stall_iterations);
    msg = buf + std::string(tolerance_text);
  } else if (cs.termination_type == ceres::NO_CONVERGENCE) {
    summary.termination = TrimTermination::kIterationLimit;
    msg = "iteration limit (" + std::to_string(options.max_iterations) + ") reached; " +
          tolerance_text;
  } else if (cs.termination_type == ceres::CONVERGENCE) {
    summary.termination = TrimTermination::kCeresConvergence;
    msg = std::string(summary.least_squares ? "least-squares minimum" : "Ceres stopped") +
          " without equilibrium (" + cs.message + "); " + tolerance_text;
  } else {
    summary.termination = TrimTermination::kCeresFailure;
    msg = "Ceres failure (" + cs.message + "); " + tolerance_text;
  }
  if (!summary.converged && !summary.at_bound.empty()) {
    msg += "; ";
    for (std::size_t i = 0; i < summary.at_bound.size(); ++i)
      msg += (i ? ", " : "") + summary.at_bound[i];
    msg += ": no equilibrium inside the bounds was found";
  }
  if (!summary.converged && summary.least_squares)
    msg += "; least-squares solve with " + std::to_string(n) +
           " unknown(s) for 3 equations: an exact equilibrium needs 3 unknowns in general";
  if (problem.failedEvaluations() > 0 && !summary.converged)
    msg += "; " + std::to_string(problem.failedEvaluations()) +
           " periodic run(s) failed, last: " + problem.lastFailure();
  summary.message = msg;

  summary.evaluation_log = problem.log();
  summary.evaluations = static_cast<int>(summary.evaluation_log.size());
  for (const TrimEvaluationRecord& r : summary.evaluation_log) {
    if (r.purpose == TrimEvaluationPurpose::kResidual)
      ++summary.residual_evaluations;
    else
      ++summary.derivative_evaluations;
  }
  summary.failed_evaluations = problem.failedEvaluations();
  summary.free_flight.status = FreeFlightStatus::kSkipped;
  summary.free_flight.message = "not run";
  summary.wall_time_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return summary;
}

TrimSummary solveTrim(const FlightCoreModel& model, const TrimOptions& options) {
  const auto t0 = std::chrono::steady_clock::now();
  std::string why;
  if (!options.IsValid(&why)) throw std::invalid_argument("trim options: " + why);
  const TrimReference reference = trimReference(model);
  TrimSummary s = solveTrim(reference,
                            tetheredMeanLoads(model, options.simulation, options.derivative_cycles),
                            options);
  const bool stalled_near =
      !s.converged && s.termination == TrimTermination::kStalled &&
      s.scaled_residual_max <= options.refine_stalled_max_residual;
  SlowMultiplierFit slow_motion;  // of the settled flight at the refined trim, when flown
  if (options.refine_in_free_flight && (s.converged || stalled_near)) {
    // Stage 2: level settled free flight from the Eq. (4) trim (free_flight_trim.hpp).
    SimulationOptions sim;  // default tolerances for the free flights, tighter for the
    sim.rel_tol = settledFlightRelTol(model);  // nonlinear wing (free_flight_trim.hpp)
    FreeFlightTrimOptions fo;
    fo.settled.cycles = options.refine_cycles;
    fo.settled.window_cycles = std::max(1, options.refine_cycles / 3);
    fo.settled.max_cycles = 10 * options.refine_cycles;
    const FreeFlightTrim ft = solveFreeFlightTrim(model, s.solution, sim, fo);
    s.refined_in_free_flight = true;
    s.tethered_solution = s.solution;
    s.tethered_residual = s.residual;
    s.free_flight_trim_message = ft.message;
    s.free_flight_trim_evaluations = ft.evaluations;
    s.free_flight_climb_angle_rad = ft.settled.climb_angle_rad;
    if (ft.converged) slow_motion = ft.settled.slow;
    if (ft.converged) {
      s.solution = ft.solution;
      if (stalled_near) {
        // Judged by the level settled flight alone (TrimOptions::refine_stalled_max_residual).
        char buf[200];
        std::snprintf(buf, sizeof buf,
                      "Eq. (4) stalled within %.0e of the weight (max scaled residual %.3e), "
                      "released there; ",
                      options.refine_stalled_max_residual, s.scaled_residual_max);
        s.status = TrimStatus::kOk;
        s.converged = true;
        s.message = std::string(buf) + "free-flight refinement: " + ft.message + " (Eq. (4): " +
                    s.message + ")";
      } else {
        s.message = "Eq. (4) " + s.message + "; free-flight refinement: " + ft.message;
      }
    } else {
      s.status = TrimStatus::kNotConverged;
      s.converged = false;
      s.message = "Eq. (4) " + s.message + "; free-flight refinement failed: " + ft.message;
    }
  }
  if (!options.verify_free_flight) {
    s.free_flight.status = FreeFlightStatus::kSkipped;
    s.free_flight.message = "free-flight check not requested";
  } else if (!s.converged) {
    s.free_flight.status = FreeFlightStatus::kSkipped;
    s.free_flight.message = "trim not converged: no free-flight check";
  } else {
    // Eq. (5) over a window long enough for the slowest motion the refinement measured.
    std::string horizon_note;
    s.free_flight = verifyFreeFlight(
        model, s.solution, coveringSlowMotion(options.free_flight, slow_motion, &horizon_note));
    if (!horizon_note.empty()) s.free_flight.message += " (" + horizon_note + ")";
  }
  s.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return s;
}

}  // namespace orni
