// Horizontal tail: thin-airfoil lift with the finite-wing correction and a parabolic drag polar,
// paper Eq. (3), with the incidence generalised to free flight (docs/theory.md section 7).
#pragma once

#include "core/model/vehicle_model.hpp"

namespace orni::aero {

/// Flow state at the tail.
struct TailFlow {
  double theta_body_rad = 0.0;       ///< body pitch attitude theta_B
  double flight_path_rad = 0.0;      ///< flight-path angle gamma (climb +); 0 in the tunnel
  double pitch_rate_radps = 0.0;     ///< body pitch rate Q
  double airspeed_mps = 0.0;         ///< V at the tail, > 0
  double wing_downwash_rad = 0.0;    ///< eps_w (0 if unknown)
  double tail_angle_rad = 0.0;       ///< delta_T (paper sign: positive reduces incidence)
};

/// Tail coefficients and loads in the flight-path frame.
struct TailLoads {
  double alpha_rad = 0.0;  ///< alpha_T = (theta_B - gamma) - delta_T + Q l_T/V - eps_w
  double CL = 0.0;         ///< [AR_T/(2+AR_T)] 2 pi alpha_T
  double CD = 0.0;         ///< C_D0,T + CL^2/(pi e AR_T)
  double lift_N = 0.0;     ///< perpendicular to the flight path, up +
  double drag_N = 0.0;     ///< along the flight path, rearward +
};

/// Evaluate the tail (paper Eq. 3, docs/theory.md 7). Requires tail.present.
TailLoads evalTail(const TailModel& tail, double density_kgpm3, const TailFlow& flow);

}  // namespace orni::aero
