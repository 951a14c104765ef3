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
// sinks.
#pragma once

#include <string>

#include "core/dynamics/flight_core.hpp"
#include "core/dynamics/simulation_options.hpp"
#include "core/model/vehicle_model.hpp"
#include "trim/settled_flight_options.hpp"

namespace orni {

/// Means of a settled free flight.
struct SettledFlight {
  bool ok = false;             ///< finished, finite and settled
  std::string message;
  double theta_mean_rad = 0.0;
  double airspeed_mps = 0.0;   ///< mean |v_P1|
  double climb_angle_rad = 0.0;  ///< asin(mean dh/dt / airspeed): the flight-path angle
  double theta_drift_rad = 0.0;  ///< change of the theta mean between the window's halves
};


/// Fly freely from `point` (released in its periodic state) and average the settled motion.
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
  int max_iterations = 12;
};

/// Secant iteration on the tail angle from `start` (an Eq. (4) trim) for level settled flight.
FreeFlightTrim solveFreeFlightTrim(const FlightCoreModel& model, const OperatingPoint& start,
                                   const SimulationOptions& simulation,
                                   const FreeFlightTrimOptions& options);

}  // namespace orni
