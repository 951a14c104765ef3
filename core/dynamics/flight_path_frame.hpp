// The flight-path frame (paper Eq. 2): e_v along the velocity of P1, e_L perpendicular to it and
// up, both resolved in body axes B (x forward, z down). Loads FH (along e_v, forward +) and FV
// (along e_L, up +) are the paper's. One definition for the tethered, free-flight and trim paths.
#pragma once

#include "core/dynamics/load_sample.hpp"
#include "core/model/frames.hpp"

namespace orni {

struct FlightPathFrame {
  Vec3 e_v_B = Vec3::UnitX();   ///< along the flight path (velocity of P1)
  Vec3 e_L_B = -Vec3::UnitZ();  ///< perpendicular to it, up
};

/// The frame of P1's velocity `v_P1_B`; at rest (|v| = 0) the body's own (e_v = x_B).
inline FlightPathFrame flightPathFrame(const Vec3& v_P1_B) {
  const double speed_mps = v_P1_B.norm();
  FlightPathFrame f;
  f.e_v_B = speed_mps > 0.0 ? Vec3(v_P1_B / speed_mps) : Vec3::UnitX();
  f.e_L_B = Vec3(f.e_v_B.z(), 0.0, -f.e_v_B.x());
  return f;
}

/// One wing's loads (forces in B, moments about P1 in B; aerodynamic and inertial parts) doubled
/// for the mirrored pair (their lateral parts cancel) and resolved in `f`: the wing fields of
/// `out` (FV, FH, M of each part). The other fields of `out` are left alone.
inline void setWingPairLoads(const FlightPathFrame& f, const Vec3& F_aero_B,
                             const Vec3& M_aero_P1_B, const Vec3& F_inertial_B,
                             const Vec3& M_inertial_P1_B, LoadSample* out) {
  out->FV_wing_aero_N = 2.0 * F_aero_B.dot(f.e_L_B);
  out->FH_wing_aero_N = 2.0 * F_aero_B.dot(f.e_v_B);
  out->M_wing_aero_Nm = 2.0 * M_aero_P1_B.y();
  out->FV_wing_inertial_N = 2.0 * F_inertial_B.dot(f.e_L_B);
  out->FH_wing_inertial_N = 2.0 * F_inertial_B.dot(f.e_v_B);
  out->M_wing_inertial_Nm = 2.0 * M_inertial_P1_B.y();
}

}  // namespace orni
