// The trim solver: Ceres drives the residuals of paper Eq. (4) (trim_problem.hpp) to zero over
// the chosen unknowns (docs/design.md 1, data flow of a trim study), then hands a converged trim
// to the free-flight check (free_flight_check.hpp).
//
// Style (docs/design.md 7.5, Ceres): TrimOptions (trim_options.hpp) with documented defaults and
// IsValid(); TrimSummary with a status and a termination reason instead of exceptions for "did not
// converge", and a one-line BriefReport(). solveTrim() does no I/O and is thread-compatible (one
// model may be shared by solves on several threads; each solve owns its workspaces), so sweeps
// call it directly.
//
// Method: Levenberg-Marquardt (Ceres trust region, dense QR) with bounds on every unknown, in
// solver units (deg, m/s, deg, Hz). Derivatives: central differences with fixed absolute steps
// (0.05 deg, 0.02 m/s, 0.05 deg, 0.02 Hz), one-sided at a bound. Every periodic run uses rel_tol
// 1e-6: the cycle mean of an adaptive integrator is a noisy function of the point (the step
// sequence changes), about 2e-5 N at the default rel_tol 1e-4 and 3e-6 N at 1e-6 for efw_magpie,
// against differences of ~1e-2 N over a step. Residual runs stop at the periodic steady state
// (steady_tol 1e-5 of q S, i.e. ~3e-5 N, well below the 1e-4 W equilibrium tolerance); derivative
// runs use a fixed 3 cycles from the quasi-steady start, whose transient is a smooth function of
// the point and cancels in the difference (the derivative moves by ~0.1 % against fully periodic
// runs). A step that leaves the bounds is projected and line-searched by bisection on residual
// runs only (Ceres' default cubic search would evaluate a Jacobian per trial).
//
// Stopping: converged when max(|FV - W|, |FH|, |M| / c_mean) <= residual_tol * W at an accepted
// iterate (checked after every iteration). Otherwise not converged when the cost stalls (less than
// 1 % decrease over 8 iterations, typically creeping along a bound), at Ceres' own tolerances
// (function, gradient, parameter) or at the iteration limit; the summary says which and names any
// unknown left on a bound.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "core/dynamics/flight_core.hpp"
#include "core/model/vehicle_model.hpp"
#include "trim/free_flight_check.hpp"
#include "trim/trim_options.hpp"
#include "trim/trim_problem.hpp"

namespace orni {

enum class TrimStatus { kOk, kNotConverged };
/// "ok", "not_converged".
const char* toString(TrimStatus s);

/// Why the solve ended.
enum class TrimTermination {
  kResidualTolerance,  ///< equilibrium found (max scaled residual <= residual_tol)
  kCeresConvergence,   ///< Ceres' function/gradient/parameter tolerance, residual above tol
  kIterationLimit,     ///< max_iterations reached
  kStalled,            ///< the cost stopped falling (TrimOptions::stall_iterations)
  kSimulationFailure,  ///< the periodic core failed at the initial guess (Ceres could not start)
  kCeresFailure,       ///< any other Ceres failure
};
const char* toString(TrimTermination t);

/// One solver iteration (trim_progress.csv).
struct TrimIterationRecord {
  int iteration = 0;              ///< 0 = initial point
  OperatingPoint point;           ///< accepted iterate after this iteration, SI
  double cost = 0.0;              ///< Ceres cost 0.5 |r|^2 (scaled residuals)
  double scaled_max = 0.0;        ///< max |r_i| at the iterate
  double step_norm = 0.0;         ///< |dx| in solver units (0 for iteration 0)
  double trust_region_radius = 0.0;
  bool step_successful = false;
  int evaluations = 0;            ///< periodic runs so far
};

struct TrimSummary {
  TrimStatus status = TrimStatus::kNotConverged;
  TrimTermination termination = TrimTermination::kCeresFailure;
  bool converged = false;       ///< equilibrium within residual_tol (status ok)
  bool least_squares = false;   ///< fewer than 3 unknowns: least-squares solve
  std::string message;          ///< why it ended, in words (reason for not_converged)
  std::vector<TrimUnknown> unknowns;
  OperatingPoint solution;      ///< the final iterate (the trim point when converged), SI
  TrimReference reference;      ///< W and c_mean used for scaling
  CycleMeans mean;              ///< cycle means at the solution (gravity excluded)
  TrimResidual residual;        ///< dimensional residual at the solution: FV - W, FH, M
  std::array<double, kTrimResidualCount> scaled_residual{};  ///< (r_V, r_H, r_M)
  double scaled_residual_max = 0.0;
  std::vector<std::string> at_bound;  ///< "speed_mps at upper bound 30 m/s", ...
  int iterations = 0;           ///< Ceres iterations after the initial point (steps tried)
  int evaluations = 0;          ///< periodic runs (residual + derivative)
  int residual_evaluations = 0;
  int derivative_evaluations = 0;
  int failed_evaluations = 0;   ///< periodic runs that failed (treated as infeasible steps)
  double wall_time_s = 0.0;
  std::string ceres_message;    ///< Ceres Summary::message
  std::string ceres_report;     ///< Ceres Summary::BriefReport()
  std::vector<TrimEvaluationRecord> evaluation_log;
  std::vector<TrimIterationRecord> iteration_log;
  FreeFlightVerification free_flight;
  /// Two stages (TrimOptions::refine_in_free_flight, free_flight_trim.hpp): the Eq. (4) trim of
  /// the tethered means (stage 1; `residual` is its residual) and the tail angle of level settled
  /// free flight with the settled theta_mean and airspeed (stage 2; `solution`).
  bool refined_in_free_flight = false;
  OperatingPoint tethered_solution;     ///< stage 1 solution
  TrimResidual tethered_residual;       ///< stage 1 residual (tethered means)
  std::string free_flight_trim_message;
  int free_flight_trim_evaluations = 0; ///< settled free flights flown
  double free_flight_climb_angle_rad = 0.0;  ///< settled climb angle at the solution

  /// One line: status, solution, residual, iterations, evaluations, time.
  std::string BriefReport() const;
};

/// Solve the trim of `model` (paper Eq. 4) with the periodic tethered core. Throws
/// std::invalid_argument for invalid options or a vehicle without mass (no trim possible); every
/// numerical outcome is in the summary.
TrimSummary solveTrim(const FlightCoreModel& model, const TrimOptions& options);

/// The same with any cycle-mean function and reference (tests with analytic loads). The free-flight
/// check is not run (no model).
TrimSummary solveTrim(const TrimReference& reference, const MeanLoadsFunction& loads,
                      const TrimOptions& options);

}  // namespace orni
