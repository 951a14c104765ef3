// The trim problem: paper Eq. (4), the time-averaged force and moment equilibrium of level flight,
// as three residuals of the operating point, evaluated by the periodic tethered core.
//
//   sum FV = (FV_M)_mean + (FV_T)_mean - m g = 0     r_V = (mean FV - W) / W
//   sum FH = (FH_M)_mean + (FH_T)_mean       = 0     r_H =  mean FH      / W
//   sum M  = (M_M)_mean  + (M_T)_mean        = 0     r_M =  mean M       / (W c_mean)
//
// W = m g is the weight, c_mean = S / b the mean chord of the wing pair (paper Eq. 7). The means
// are the tethered core's cycle means (tethered_simulation.hpp): wings (aerodynamic + inertial)
// plus tail, about P1 = the CG, in the flight-path frame of level flight (FV up, FH forward),
// gravity not included. The weight acts at the CG, so it enters r_V only. Eq. (4) has no fuselage
// term; the vehicle model adds the fuselage's parasite drag (body.drag_area_m2, at the CG against
// the flight path; the paper omits it), so FH is the wings' mean thrust minus the tail and body drag.
//
// The unknowns are a subset of (theta_mean, U, delta_T, f); the others are held at their given
// values. The solver works in "solver units" (deg, m/s, deg, Hz), in which all four are O(1-10)
// and the finite-difference steps are fixed absolute numbers.
//
// No Ceres type appears here (docs/design.md 1): the Ceres side is in trim_solver.cpp.
#pragma once

#include <array>
#include <functional>
#include <string>
#include <vector>

#include "core/dynamics/flight_core.hpp"
#include "core/dynamics/simulation_options.hpp"
#include "core/dynamics/tethered_simulation.hpp"
#include "core/model/vehicle_model.hpp"
#include "trim/trim_unknowns.hpp"

namespace orni {

/// The scales of Eq. (4): weight and moment length.
struct TrimReference {
  double weight_N = 0.0;  ///< W = m g, > 0
  double length_m = 0.0;  ///< moment reference length (c_mean = S / b), > 0
};

/// W = body.mass_kg * air.gravity_mps2 and c_mean of the model. Throws std::invalid_argument when
/// the vehicle has no body mass or no gravity (a wind-tunnel rig cannot be trimmed).
TrimReference trimReference(const FlightCoreModel& model);

/// Dimensional equilibrium residual of Eq. (4): mean FV - W, mean FH, mean M (about the CG).
struct TrimResidual {
  double FV_N = 0.0;
  double FH_N = 0.0;
  double M_Nm = 0.0;
};

/// Scaled residual (r_V, r_H, r_M) = ((FV - W)/W, FH/W, M/(W l)).
std::array<double, kTrimResidualCount> scaledResidual(const TrimReference& ref,
                                                      const TrimResidual& r);
/// max_i |r_i| of the scaled residual (the equilibrium test: below TrimOptions::residual_tol).
double scaledResidualMax(const TrimReference& ref, const TrimResidual& r);

/// What a periodic evaluation is for: the residual at a solver iterate, or a finite-difference
/// neighbour for the Jacobian.
enum class TrimEvaluationPurpose { kResidual = 0, kDerivative = 1 };

/// Outcome of one periodic evaluation (one run of the periodic core).
struct PeriodicEvaluation {
  bool ok = false;       ///< false: the run failed or diverged (the point is infeasible)
  bool steady = false;   ///< periodic steady state detected (residual runs)
  int cycles = 0;        ///< flapping cycles run
  CycleMeans mean;       ///< cycle means of the last cycle (gravity excluded)
  std::string message;   ///< the simulation's message
};

/// Cycle-mean loads at an operating point: the periodic core (tetheredMeanLoads) or, in tests, an
/// analytic stand-in.
using MeanLoadsFunction =
    std::function<PeriodicEvaluation(const OperatingPoint&, TrimEvaluationPurpose)>;

/// The tethered periodic core as a MeanLoadsFunction. Residual runs use `residual_options` (with
/// stop_when_steady: `cycles` is the maximum); derivative runs use the same tolerances but exactly
/// `derivative_cycles` cycles from the same quasi-steady start, so that the start-up transient is
/// the same smooth function of the point on both sides of a difference and cancels; for the
/// geometrically nonlinear wing, whose transient is not smooth in the point, derivative runs are
/// periodic runs like the residual runs. `model` must outlive the returned function.
MeanLoadsFunction tetheredMeanLoads(const FlightCoreModel& model,
                                    const SimulationOptions& residual_options,
                                    int derivative_cycles);

/// One periodic evaluation as recorded by TrimProblem (trim_iterations.csv).
struct TrimEvaluationRecord {
  int index = 0;          ///< 0-based, in call order
  int iteration = 0;      ///< solver iteration during which it ran (0 = initial point)
  TrimEvaluationPurpose purpose = TrimEvaluationPurpose::kResidual;
  OperatingPoint point;   ///< SI
  PeriodicEvaluation result;
  TrimResidual residual;  ///< dimensional (meaningful when result.ok)
  double scaled_max = 0.0;  ///< max |r_i| (meaningful when result.ok)
};

/// Residual and central-difference Jacobian of Eq. (4) in solver units, with a log of every
/// periodic evaluation. Not thread-safe (one per solve).
class TrimProblem {
 public:
  /// `base` holds the fixed values of the quantities that are not unknowns. `steps` and `bounds`
  /// are per unknown (indexed by TrimUnknown), SI.
  /// `forward_differences`: the Jacobian from the residual at x and one run per unknown (see
  /// jacobian()).
  TrimProblem(const TrimReference& reference, MeanLoadsFunction loads, const OperatingPoint& base,
              std::vector<TrimUnknown> unknowns,
              const std::array<double, kTrimUnknownCount>& steps,
              const std::array<TrimBounds, kTrimUnknownCount>& bounds,
              bool forward_differences = false);

  int unknownCount() const { return static_cast<int>(unknowns_.size()); }
  const std::vector<TrimUnknown>& unknowns() const { return unknowns_; }
  const TrimReference& reference() const { return reference_; }

  /// The operating point at x (solver units, unknownCount() values).
  OperatingPoint pointAt(const double* x) const;
  /// x (solver units) of a point.
  std::vector<double> solverValues(const OperatingPoint& point) const;

  /// Scaled residual r (3 values) at x. Reuses the residual evaluation of an identical point.
  /// False when the periodic evaluation failed.
  bool residual(const double* x, double* r);
  /// Jacobian dr/dx at x, row-major 3 x unknownCount(): central differences with the fixed steps,
  /// one-sided (both ends at derivative accuracy) where x -/+ step would leave the bounds; with
  /// forward_differences, r(x + step) - r(x) (x - step at the upper bound) over the step, r(x)
  /// being the residual run at x (made when missing). False when a periodic evaluation failed.
  bool jacobian(const double* x, double* jacobian_row_major);

  /// The residual record of exactly this point, or nullptr.
  const TrimEvaluationRecord* findResidual(const OperatingPoint& point) const;

  /// Threads for the runs of one Jacobian (TrimOptions::jacobian_threads), >= 1. The runs are
  /// independent (a MeanLoadsFunction keeps no state between calls) and recorded in the order the
  /// sequential loop makes them, up to and including the first that fails, so the log and the
  /// Jacobian are the same for any count; only the work after a failed run differs (it is run and
  /// dropped). `loads` must then be callable from several threads at once.
  void setJacobianThreads(int threads);

  /// Tag the following evaluations with this solver iteration.
  void setIteration(int iteration) { iteration_ = iteration; }
  const std::vector<TrimEvaluationRecord>& log() const { return log_; }
  /// Message of the most recent failed evaluation ("" when none failed).
  const std::string& lastFailure() const { return last_failure_; }
  int failedEvaluations() const { return failed_; }

 private:
  const TrimEvaluationRecord& run(const OperatingPoint& point, TrimEvaluationPurpose purpose);
  const TrimEvaluationRecord& record(const OperatingPoint& point, TrimEvaluationPurpose purpose,
                                     PeriodicEvaluation result);
  /// The derivative runs at `points`, recorded in order up to the first failure; their scaled
  /// residuals in *r. False when one failed.
  bool runDerivatives(const std::vector<OperatingPoint>& points,
                      std::vector<std::array<double, kTrimResidualCount>>* r);
  bool forwardJacobian(const double* x, double* jacobian_row_major);

  TrimReference reference_;
  MeanLoadsFunction loads_;
  OperatingPoint base_;
  std::vector<TrimUnknown> unknowns_;
  std::array<double, kTrimUnknownCount> steps_;
  std::array<TrimBounds, kTrimUnknownCount> bounds_;
  bool forward_differences_ = false;
  int jacobian_threads_ = 1;
  std::vector<TrimEvaluationRecord> log_;
  int iteration_ = 0;
  int failed_ = 0;
  std::string last_failure_;
};

}  // namespace orni
