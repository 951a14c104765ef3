// TrimOptions: the options of one trim solve (docs/design.md 7.5: plain struct, documented
// defaults, IsValid). Light header (no core dynamics) so that the study files can hold them; the
// solver is trim_solver.hpp.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "core/dynamics/simulation_options.hpp"
#include "core/model/vehicle_model.hpp"
#include "trim/free_flight_check.hpp"
#include "trim/periodic_trim_options.hpp"
#include "trim/trim_unknowns.hpp"

namespace orni {

/// Options of one trim solve. Angles in SI (rad) like every model field; file and CLI units are
/// converted by the runner.
struct TrimOptions {
  /// Two stages (solveTrim, trim_solver.hpp) or the periodic orbit (solvePeriodicTrim,
  /// periodic_trim.hpp, which starts from the Eq. (4) stage of these options).
  TrimMethod method = TrimMethod::kTwoStage;
  PeriodicTrimOptions periodic;  ///< method periodic only

  /// The unknowns, 1 to 3 distinct (3: square solve; fewer: least squares). Default: theta_mean,
  /// U and delta_T at the given frequency.
  std::vector<TrimUnknown> unknowns = {TrimUnknown::kThetaMean, TrimUnknown::kSpeed,
                                       TrimUnknown::kTailAngle};
  /// Initial guess of the unknowns and the fixed value of every other quantity (e.g. the
  /// frequency). The runner fills it from the vehicle's operating point, the study and the CLI.
  /// speed > 0, freq > 0, every unknown inside its bounds.
  OperatingPoint initial;
  /// The vehicle file's design point ([operating_point], VehicleDefinition::design_point): the
  /// default of `initial`; the periodic orbit scales its tolerances by its speed (fixed over a
  /// continuation, FreeFlightPeriodMapOptions). Zero = none (10 m/s).
  OperatingPoint design_point;
  /// Bounds per unknown (indexed by TrimUnknown), SI; lower < upper, speed and frequency lower
  /// > 0. Defaults: theta [-10, 40] deg, U [2, 30] m/s, delta_T [-30, 45] deg, f [1, 40] Hz.
  std::array<TrimBounds, kTrimUnknownCount> bounds = defaultBounds();
  /// Central-difference steps per unknown, SI, > 0 and at most a quarter of the bound interval.
  /// Defaults 0.05 deg, 0.02 m/s, 0.05 deg, 0.02 Hz.
  std::array<double, kTrimUnknownCount> fd_steps = defaultSteps();

  int max_iterations = 50;      ///< Ceres iterations, [1, 1000]
  double residual_tol = 1e-4;   ///< equilibrium: max(|FV - W|, |FH|, |M| / c_mean) <= tol * W,
                                ///< (0, 0.1]
  double function_tol = 1e-12;  ///< Ceres function_tolerance (relative cost change), (0, 1)
  double gradient_tol = 1e-16;  ///< Ceres gradient_tolerance, [0, 1)
  double parameter_tol = 1e-10; ///< Ceres parameter_tolerance (relative step), [0, 1)
  /// Stall test: stop (not converged) when the cost fell by less than stall_decrease (relative)
  /// over the last stall_iterations iterations; 0 iterations = off. [0, 1000], (0, 1).
  int stall_iterations = 8;
  double stall_decrease = 0.01;

  /// Periodic runs of the residual (stop_when_steady; `cycles` is the maximum). Defaults tightened
  /// for trim: rel_tol 1e-6, steady_tol 1e-5, at most 40 cycles.
  SimulationOptions simulation = defaultSimulation();
  int derivative_cycles = 3;    ///< cycles of each finite-difference run, [1, 1000]

  /// Refine a converged Eq. (4) trim in free flight (free_flight_trim.hpp): the final trim is the
  /// tail angle of level settled free flight with its settled theta_mean and airspeed, as the
  /// paper refined its trim point (section 3.3).
  bool refine_in_free_flight = true;
  /// Eq. (4) only gives the refinement its release point: a stalled Eq. (4) solve (the cost
  /// stopped falling, no bound reached) whose max scaled residual is within this fraction of the
  /// weight is refined too, and the trim is then judged by its level settled flight alone. 1 % of
  /// the weight: the calibrated magpie's nonlinear wing stalls at 0.25 % (2 deg and 1.3 m/s from
  /// its settled flight, which any release within a few degrees reaches); the honest magpie's
  /// stalled sweep points stall at 1.4 % and more, far from any equilibrium.
  double refine_stalled_max_residual = 1e-2;
  int refine_cycles = 120;         ///< cycles of each settled free flight at least (last third
                                   ///< averaged; extended until settled, up to 10 times as
                                   ///< many), [6, 10000]
  bool verify_free_flight = true;  ///< run verifyFreeFlight() on a converged trim
  FreeFlightCheckOptions free_flight;
  /// Eq. (4) solved only as the start of another solve (the periodic orbit's, whose Newton
  /// iteration solves the trim anew, so the start's accuracy does not reach its result): the
  /// Jacobian by forward differences (one run per unknown instead of two) and none at a point that
  /// already meets residual_tol (Ceres asks for the Jacobian at an accepted point before the
  /// callback that ends the solve sees it). Set by solvePeriodicTrim for its stage 1; not a study
  /// key.
  bool start_only = false;
  /// Threads that run the periodic evaluations of one Eq. (4) Jacobian (its finite-difference
  /// columns) and, in the periodic trim, the columns of the orbit's Newton Jacobian, [1, 64]. The
  /// runs are independent and recorded in their sequential order, so every result and log is the
  /// same for any count. Set from `-j` for a single trim (`ornithopter trim`, a trim study run by
  /// `ornithopter run`); not a study key (optimize and the other studies use their threads over
  /// their own points).
  int jacobian_threads = 1;

  /// True when every field is inside its range; otherwise false with the reason in *why.
  bool IsValid(std::string* why) const;

  static std::array<TrimBounds, kTrimUnknownCount> defaultBounds();
  static std::array<double, kTrimUnknownCount> defaultSteps();
  static SimulationOptions defaultSimulation();
};

/// Default options with the vehicle file's design point ([operating_point]) as initial guess and
/// design point, and fixed values.
TrimOptions defaultTrimOptions(const OperatingPoint& design_point);

/// Switch `o` to the periodic method with that method's defaults of the Eq. (4) stage, which there
/// is only the start of Newton's iteration: residual_tol 1e-3, simulation.rel_tol 1e-4,
/// simulation.steady_tol 1e-3 (2.5 times faster than the two-stage defaults; the orbit found on
/// the magpie at 12 Hz is the same to 1e-4 deg and 1e-4 m/s, because Newton solves it anew).
void usePeriodicMethod(TrimOptions* o);

}  // namespace orni
