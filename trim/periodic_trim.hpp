// Periodic-orbit trim of the free-flying vehicle and its Floquet stability (docs/theory.md 10.3-10.4).
//
// A flapping vehicle in trimmed flight flies a periodic orbit, not an equilibrium. Found here
// directly: the state at flap phase 0 (body theta, U, W, Q; modal q, q'; every MST-TD state) and
// one control (the tail angle by default; the frequency or the CG position) such that one flapping
// period T = 1/f later every state is back and the altitude gained is zero (level flight), by
// Newton on the single-shooting residual (core/analysis/periodic_shooting.hpp) of the free-flight
// period map (free_flight_period_map.hpp), from the Eq. (4) trim of the tethered means (stage 1 of
// solveTrim, trim_solver.hpp, with the tolerances of `options`: usePeriodicMethod makes them
// loose, the orbit does not depend on them) with the wing in its tethered periodic state. The skin
// friction is frozen (it must not depend on the unknowns): pass 1 at the Eq. (4) speed, pass 2 at
// pass 1's mean airspeed, from pass 1's orbit and Jacobian. At the orbit: the Floquet multipliers
// (core/analysis/floquet.hpp; the leading periodic.multipliers by Arnoldi, or all from the full
// monodromy, core/analysis/monodromy.hpp), the cycle means, the histories of one period, an
// independent check of the orbit with the production integrator (ARKODE, adaptive), and the
// bounded-norm free-flight check (paper Eq. 5) like every trim.
//
// The trim point reported is the orbit's cycle means: theta_mean, the mean airspeed |v_P1| (the
// two-stage trim's settled means), the control found and the frequency. No I/O; thread-compatible
// like solveTrim.
#pragma once

#include <limits>
#include <string>
#include <vector>

#include "core/analysis/floquet.hpp"
#include "core/analysis/periodic_shooting.hpp"
#include "core/dynamics/flight_core.hpp"
#include "trim/free_flight_period_map.hpp"
#include "trim/trim_options.hpp"
#include "trim/trim_solver.hpp"

namespace orni {

/// Cycle means of the orbit (uniform samples of one period, periodic rectangle rule).
struct PeriodicCycleMeans {
  double theta_rad = 0.0;
  double airspeed_mps = 0.0;    ///< mean |v_P1|
  double U_mps = 0.0, W_mps = 0.0, Q_radps = 0.0;  ///< body axes
  double power_aero_W = 0.0;    ///< aerodynamic power of both wings (exact integral)
  double FV_N = 0.0, FH_N = 0.0, M_Nm = 0.0;  ///< aerodynamic loads (wings incl. apparent mass,
                                              ///< tail, fuselage drag), flight-path frame
  double theta_min_rad = 0.0, theta_max_rad = 0.0;
  double altitude_p2p_m = 0.0;  ///< altitude swing within the period
};

struct PeriodicTrimSummary {
  TrimStatus status = TrimStatus::kNotConverged;
  bool converged = false;
  std::string message;
  PeriodicControl control = PeriodicControl::kTailAngle;
  TrimSummary stage1;                ///< the Eq. (4) start (no free-flight refinement or check)
  OperatingPoint solution;           ///< cycle-mean theta and airspeed, tail angle, frequency
  double cg_shift_m = 0.0;           ///< CG forward of the vehicle file's (control cg only)
  std::vector<double> orbit_start;   ///< x at flap phase 0 (FreeFlightPeriodMap layout, SI)
  std::vector<FloquetStateInfo> states;
  std::vector<std::string> state_units;
  std::vector<double> state_scales;  ///< the scaled residual's units
  PeriodicCycleMeans mean;
  ShootingSummary shooting;          ///< the last pass; counts summed over both passes
  /// Newton iterations of both passes (pass 1: skin friction frozen at the Eq. (4) speed; pass
  /// 2: at the first orbit's mean airspeed), newton_pass[i] = 1 or 2.
  std::vector<ShootingIteration> newton_log;
  std::vector<int> newton_pass;
  bool floquet_valid = false;
  FloquetAnalysis floquet;
  std::string floquet_message;       ///< why there is no Floquet analysis (floquet_valid false)
  long floquet_maps = 0;             ///< period maps of the Floquet analysis (Arnoldi or the
                                     ///< fallback, and the multiplier check's; the full matrix
                                     ///< of multipliers = 0 is in shooting.period_maps)
  OrbitHistory history;              ///< one period from orbit_start
  /// One period from orbit_start with ARKODE (the free-flight integrator, adaptive, at
  /// periodic.rel_tol): max |x(T) - x(0)| in scales. The orbit's integration error, independent of
  /// the shooting's fixed grid; NaN when not run.
  double orbit_check = std::numeric_limits<double>::quiet_NaN();
  double friction_speed_mps = 0.0;   ///< skin friction frozen at this speed (the orbit's mean
                                     ///< airspeed after the second pass)
  int grid_steps = 0;                ///< steps of the period map's grid
  long rhs_evaluations = 0;          ///< right-hand sides of all period maps
  std::string integrator;
  FreeFlightVerification free_flight;
  double stage1_time_s = 0.0, orbit_time_s = 0.0, floquet_time_s = 0.0, wall_time_s = 0.0;

  std::string BriefReport() const;
};

/// Periodic trim with `options` (its Eq. (4) settings for stage 1, options.periodic for the
/// orbit, verify_free_flight and free_flight for the check). Throws std::invalid_argument for
/// invalid options; every numerical outcome is in the summary.
PeriodicTrimSummary solvePeriodicTrim(const FlightCoreModel& model, const TrimOptions& options);

/// Initial guess of the orbit at an operating point: the body on the level path at (theta, U)
/// with Q = 0, the wing (modes and MST-TD states) in its tethered periodic state at phase 0 (a
/// tethered run with the `tethered` settings, stopped when steady).
std::vector<double> periodicStartState(const FlightCoreModel& model,
                                       const FreeFlightPeriodMap& map, const OperatingPoint& point,
                                       const SimulationOptions& tethered);

/// Cycle means of a sampled period (samples + 1 rows, the last = the first period's end).
PeriodicCycleMeans cycleMeans(const OrbitHistory& history, double period_s);

}  // namespace orni
