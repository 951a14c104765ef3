// Horizontal tail: seed paper Eq. (3) with the free-flight incidence of docs/theory.md section 7.
#include <cassert>

#include "core/aero/tail.hpp"
#include "core/model/frames.hpp"

namespace orni::aero {

namespace {
/// Floor of the airspeed in the pitch-rate term Q l_T/V (avoids a division by zero at rest).
constexpr double kMinTailSpeedMps = 0.5;
}  // namespace

TailLoads evalTail(const TailModel& tail, double density_kgpm3, const TailFlow& flow) {
  assert(tail.present && tail.aspect_ratio > 0.0);
  const double V = flow.airspeed_mps;
  const double V_floor = V > kMinTailSpeedMps ? V : kMinTailSpeedMps;
  TailLoads loads;
  // docs/theory.md 7: alpha_T = (theta_B - gamma) - delta_T + Q l_T/V - eps_w (delta_T > 0 reduces
  // it). eps_w is taken from the flow as given (the caller applies TailModel::downwash_factor).
  loads.alpha_rad = (flow.theta_body_rad - flow.flight_path_rad) - flow.tail_angle_rad +
                    flow.pitch_rate_radps * tail.arm_m / V_floor - flow.wing_downwash_rad;
  // Eq. (3): C_L,T = [AR_T/(2+AR_T)] 2 pi alpha_T; C_D,T = C_D0,T + C_L,T^2/(pi e AR_T).
  const double AR = tail.aspect_ratio;
  loads.CL = AR / (2.0 + AR) * 2.0 * kPi * loads.alpha_rad;
  loads.CD = tail.zero_lift_drag_coefficient +
             loads.CL * loads.CL / (kPi * tail.oswald_efficiency * AR);
  const double q_S = 0.5 * density_kgpm3 * V * V * tail.area_m2;
  loads.lift_N = loads.CL * q_S;
  loads.drag_N = loads.CD * q_S;
  return loads;
}

}  // namespace orni::aero
