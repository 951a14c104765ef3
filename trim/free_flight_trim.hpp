// Free-flight refinement of a trim (the paper's procedure, section 3.3: the Eq. (4) trim from the
// aero map is refined "during the heuristic flight simulation constrained to Eq. (5)", which fixed
// the tail angle and refined theta and U). Solved here: released at the Eq. (4) trim, the vehicle
// flies freely until its motion has settled into the flapping limit cycle; the settled means give
// the free-flight trim (theta_mean, airspeed) at that tail angle, and the tail angle is found by a
// secant iteration so that the settled flight is level (mean climb angle zero).
//
// Why it is needed: the tethered means of Eq. (4) miss the effect of the body's own oscillation on
// the mean aerodynamic loads, so the Eq. (4) point is not exactly the free vehicle's equilibrium;
// released there a statically stable vehicle settles to a nearby steady flight that climbs or
// sinks (the committed magpie: by a fraction of a degree; with a rigid wing and a suction
// efficiency of 0.35 by 7.7 deg).
//
// Settled: the vehicle converges on the periodic orbit at its controls (periodic_trim.hpp) at the
// rate of the orbit's slowest Floquet multiplier, the phugoid's (|mu| 0.976-0.985 a cycle on the
// magpie: e-folding in 40-70 cycles, a 60-150-cycle period, longer than the averaged window). So
// the flight goes on, cycle by cycle, until the window's means are within tolerance of the values
// the flight settles to, which the decay of that slowest motion predicts (fitted to the cycle
// means, core/analysis/slow_multipliers.hpp); where nothing is left to fit, until the cycle means
// over the window lie within the tolerance. A flight that does not settle is reported with the
// periodic orbit at its controls and that orbit's multipliers: unstable (a multiplier outside the
// unit circle, named), or stable but too slow for the cycles allowed, or not reached from the
// release. By default (SettledFlightOptions::extrapolate) the flight stops earlier, as soon as the
// values it settles to are known: the fits of the slowest motion over the flight's second half
// and over its last third predict the same settled means within the tolerance. Measured on the
// rigid magpie at eta_s 0.35 (test_settled_free_flight.cpp): predicted after 121 cycles, 0.003
// deg from the periodic orbit's means, against 276 cycles and 0.005 deg flown until settled.
#pragma once

#include <limits>
#include <string>

#include "core/analysis/floquet.hpp"
#include "core/analysis/slow_multipliers.hpp"
#include "core/dynamics/flight_core.hpp"
#include "core/dynamics/simulation_options.hpp"
#include "core/model/vehicle_model.hpp"
#include "trim/settled_flight_options.hpp"

namespace orni {

/// Means of a settled free flight.
struct SettledFlight {
  bool ok = false;             ///< finished, finite and settled
  std::string message;
  /// The settled means: over the last window_cycles cycles, or, when `extrapolated`, the values
  /// the flight's slowest motion decays to.
  double theta_mean_rad = 0.0;
  double airspeed_mps = 0.0;   ///< mean |v_P1|
  double climb_angle_rad = 0.0;  ///< asin(mean dh/dt / airspeed): the flight-path angle
  double theta_drift_rad = 0.0;  ///< change of the theta mean between the window's halves
  /// max - min of the window's cycle means: theta (rad), airspeed (over the mean airspeed), climb
  /// angle (rad).
  double theta_band_rad = 0.0, airspeed_band = 0.0, climb_band_rad = 0.0;
  int cycles_flown = 0;          ///< whole cycles flown (options.cycles up to max_cycles)
  /// The slowest motion, fitted to the cycle means of theta over the flight's second half (at
  /// least the window; core/analysis/slow_multipliers.hpp): with a clean fit (relative residual <=
  /// 0.01) its multiplier is the flight's estimate of the leading Floquet multiplier.
  SlowMultiplierFit slow;
  /// The flight cannot settle: the periodic orbit at this point is unstable (orbit_floquet), or,
  /// without an orbit found, the clean fit's multiplier is on or outside the unit circle.
  bool unstable = false;
  /// With a clean decaying fit: the values theta, airspeed and climb angle settle to (the fit's
  /// fixed point) and the largest distance of the window's means from them (rad; the airspeed as
  /// a fraction); NaN otherwise.
  double settled_theta_rad = std::numeric_limits<double>::quiet_NaN();
  double settled_airspeed_mps = std::numeric_limits<double>::quiet_NaN();
  double settled_climb_angle_rad = std::numeric_limits<double>::quiet_NaN();
  double remaining = std::numeric_limits<double>::quiet_NaN();
  /// Settled by prediction (SettledFlightOptions::extrapolate): theta_mean_rad, airspeed_mps and
  /// climb_angle_rad are the fitted fixed point of the slowest motion over the flight's second
  /// half, confirmed by the fit over its last third to within extrapolation_spread (rad; the
  /// airspeed as a fraction), not the window's means (those are window_*).
  bool extrapolated = false;
  double extrapolation_spread = std::numeric_limits<double>::quiet_NaN();
  double window_theta_rad = std::numeric_limits<double>::quiet_NaN();
  double window_airspeed_mps = std::numeric_limits<double>::quiet_NaN();
  double window_climb_angle_rad = std::numeric_limits<double>::quiet_NaN();
  /// Not settled: the periodic orbit at this point's controls (tail angle, frequency), found by
  /// shooting (core/analysis/periodic_shooting.hpp) from where the flight was heading, and its
  /// Floquet multipliers (floquet.hpp), which decide `unstable` when it is found: the verdict of
  /// `ornithopter stability` on the orbit the flight did not settle on.
  bool orbit_found = false;
  std::string orbit_message;     ///< why no orbit was found
  FloquetAnalysis orbit_floquet;
  double orbit_theta_rad = std::numeric_limits<double>::quiet_NaN();  ///< cycle means
  double orbit_airspeed_mps = std::numeric_limits<double>::quiet_NaN();
  double orbit_climb_angle_rad = std::numeric_limits<double>::quiet_NaN();
};

/// Fly freely from `point` (released in its periodic state) until the motion has settled (at least
/// options.cycles, at most options.max_cycles cycles; SettledFlightOptions::settled_tol_rad) and
/// average the last window. Not settled: ok false with the reason, from the periodic orbit at this
/// point and its Floquet multipliers when it is found (unstable: a multiplier outside the unit
/// circle, named; stable: the slowest decays too slowly for max_cycles, or the flight left the
/// model's range from a release outside the orbit's reach), else from the flight alone.
SettledFlight settledFreeFlight(const FlightCoreModel& model, const OperatingPoint& point,
                                const SimulationOptions& simulation,
                                const SettledFlightOptions& options);

/// Result of the free-flight trim: the tail angle of level settled flight and the settled state.
struct FreeFlightTrim {
  bool converged = false;
  std::string message;
  OperatingPoint solution;     ///< settled theta_mean and airspeed, the level-flight tail angle
  SettledFlight settled;       ///< at the solution
  int evaluations = 0;         ///< settled free flights flown
};

struct FreeFlightTrimOptions {
  SettledFlightOptions settled;
  double climb_angle_tol_rad = 1.7e-4;  ///< |mean climb angle| at the solution (0.01 deg)
  double tail_step_rad = 0.0174533;     ///< first secant step of the tail angle (1 deg)
  /// Largest secant step (5 deg): the secant is a local model, and the settled climb angle is far
  /// from linear in the tail angle over more (magpie, rigid wing, suction efficiency 0.35: its
  /// slope changes sign between tail angles of 15 and 8 deg); a longer step lands where the
  /// released vehicle flips over.
  double max_tail_step_rad = 0.0872665;
  int max_iterations = 12;
};

/// The integrator's relative tolerance for settled free flights of this model: the default
/// (SimulationOptions, 1e-4) for the linear and the rigid wing, 1e-5 for the geometrically
/// nonlinear wing, whose cycle means scatter from cycle to cycle with the integration error:
/// measured on the magpie (P3 35 mm, eta_s 0.001), tethered, cycle-mean FV 1e-3 N at 1e-4, 5e-5 N
/// at 1e-5, 1e-6 N at 1e-6 (the linear wing: 2e-5 N at 1e-4); free, the fit of the slowest motion
/// to the cycle means of theta leaves 1 % of it at 1e-4 (at the limit of a clean fit), 0.1 % at
/// 1e-5; the run costs 25 % more. The Eq. 5 check flies at it too (free_flight_check.cpp).
double settledFlightRelTol(const FlightCoreModel& model);

/// Secant iteration on the tail angle from `start` (an Eq. (4) trim) for level settled flight.
FreeFlightTrim solveFreeFlightTrim(const FlightCoreModel& model, const OperatingPoint& start,
                                   const SimulationOptions& simulation,
                                   const FreeFlightTrimOptions& options);

}  // namespace orni
