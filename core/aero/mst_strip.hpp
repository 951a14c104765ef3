// Strip aerodynamics of one wing section: DeLaurier's (1993) modified strip theory and the
// time-domain MST-TD of docs/theory.md 5.7-5.9. Pure functions: no hidden state, no allocation,
// callable in any order by the integrator, the trim solver and the optimiser.
//
// Conventions (docs/theory.md 1.5): DeLaurier's. Plunge h positive DOWN, theta nose-up, normal
// force dN towards the upper surface, chordwise force dFx towards the leading edge (forward),
// moments nose-up positive. Angles in radians, SI units.
#pragma once

#include <cmath>

#include <Eigen/Core>

#include "core/model/frames.hpp"
#include "core/model/vehicle_model.hpp"

namespace orni::aero {

/// Apparent (added) air mass per unit span of a section of chord c: rho pi c^2 / 4 (kg/m;
/// DeLaurier 1993 M8, the air cylinder on the chord). The one definition for the strip kernels and
/// the wing's equations of motion (the batch kernel, mst_td_batch.cpp, hoists rho pi / 4 out of
/// its strip loop).
inline double apparentMassPerSpan_kgpm(double density_kgpm3, double chord_m) {
  return density_kgpm3 * kPi * chord_m * chord_m * 0.25;
}

using Vec3 = Eigen::Vector3d;

/// Constants derived from the aspect ratio (docs/theory.md 5.2 (M3), R.T. Jones' finite-wing factor).
struct MstConstants {
  double aspect_ratio = 0.0;  ///< AR = b^2/S of the wing pair
  double C1 = 0.0;            ///< 0.5 AR/(2.32 + AR)
  double C2 = 0.0;            ///< 0.181 + 0.772/AR
  double jones_factor = 0.0;  ///< AR/(2 + AR)
  /// Build from AR (> 0). AR = +infinity gives the 2-D limit C1 = 0.5, C2 = 0.181, factor 1.
  static MstConstants fromAspectRatio(double aspect_ratio);
};

/// Scherer's fit of the modified Theodorsen function (M3): F'(k), G'(k) and G'(k)/k (finite at
/// k = 0, docs/theory.md 5.11 (pitfall 4)).
struct SchererFunction {
  double F = 1.0, G = 0.0, G_over_k = 0.0;
};
SchererFunction schererFunction(const MstConstants& constants, double reduced_frequency);

/// The attached-flow circulatory force of MST-TD at large relative angles (docs/theory.md 5.9).
/// DeLaurier's M7 is dNc = 2 pi (alpha' + thetabar) rho U V/2 c dy, with the linear angle
/// alpha ~ hdot/U (= tan of the physical angle in pure plunge) and V the local speed at the bound
/// vortex, whose normal component U (alpha' + thetabar) is reduced by the finite-wing downwash.
/// MST-TD writes the same force with the resultant angle alpha_E and V_r = |(V_t, V_n)|:
///   angle = J sin(alpha_E + alpha0)            (the finite-wing angle, bounded)
///   speed_ratio = V_K / V_r = sqrt(cos^2(alpha_E + alpha0) + angle^2)
///   dNc = 2 pi angle (rho V_r V_K / 2) c dy = pi rho c dy J V_n sqrt(V_t^2 + J^2 V_n^2),
/// which is DeLaurier's M7 exactly in the quasi-steady attached limit (alpha_E = alpha_34, V_t in
/// place of U): the normal force grows like V_n V, not like alpha V_r^2 (the unbounded linear
/// angle times the resultant dynamic pressure, 11 % above DeLaurier at 30 deg, 26 % at 45 deg).
/// The leading-edge suction uses the same angle and dynamic pressure: 2 pi eta (J sin)^2 q_K, the
/// flat plate's sin^2 growth; DeLaurier's tan^2 U V exceeds it by 1/cos(relative angle). For
/// small angles both reduce to alpha'_t + alpha0 and rho V_r^2/2.
struct BoundedAttachedFlow {
  double angle = 0.0;        ///< J sin(alpha_E + alpha0), rad-like
  double speed_ratio = 1.0;  ///< V_K / V_r
};
inline BoundedAttachedFlow boundedAttachedFlow(double jones_factor, double alpha_rad) {
  const double s = jones_factor * std::sin(alpha_rad), c = std::cos(alpha_rad);
  return {s, std::sqrt(c * c + s * s)};
}

/// Hoerner turbulent flat-plate friction coefficient (M11), Re clamped to >= 1e3 (pitfall 11).
double frictionCoefficient(double reynolds_number);

/// Geometry of one strip.
struct StripGeometry {
  double chord_m = 0.0;          ///< c, > 0
  double width_m = 0.0;          ///< dy, > 0
  double ref_aft_of_le_m = 0.0;  ///< x_P: the kinematic reference point P, aft of the LE
};

/// Everything a strip evaluation needs besides geometry and kinematics.
struct StripContext {
  const AeroParameters* params = nullptr;
  MstConstants constants;
  double density_kgpm3 = 1.225;
  double kinematic_viscosity_m2ps = 1.5e-5;
};

/// DeLaurier's planar kinematic inputs of one strip (docs/theory.md 5.1), pitch axis at the LE.
struct PlanarKinematics {
  double U = 0.0;          ///< flight speed, m/s, > 0
  double theta_a = 0.0;    ///< incidence of the flapping axis relative to U, rad
  double thetabar = 0.0;   ///< mean chord pitch relative to U (theta_a + theta_w), rad
  double theta = 0.0;      ///< instantaneous chord pitch relative to U, rad
  double thetadot = 0.0;   ///< rad/s, nose-up +
  double thetaddot = 0.0;  ///< rad/s^2
  double hdot = 0.0;       ///< plunge velocity of the LE, positive DOWN, m/s
  double hddot = 0.0;      ///< plunge acceleration, positive down, m/s^2
  double omega = 0.0;      ///< flapping circular frequency, rad/s (for k = omega c/(2U))
};

/// 3-D section kinematics (docs/theory.md 5.1). All vectors in one common frame.
struct SectionKinematics {
  Vec3 e_c = Vec3::UnitX();   ///< unit chord vector, TE -> LE (forward)
  Vec3 n = -Vec3::UnitZ();    ///< unit chord normal towards the upper surface
  Vec3 v_P = Vec3::Zero();    ///< inertial velocity of the reference point P, m/s
  Vec3 a_P = Vec3::Zero();    ///< inertial acceleration of P (its u-dot-free part in a coupled
                              ///< solve, docs/theory.md 6.2), m/s^2
  Vec3 w_s = Vec3::Zero();    ///< angular velocity of the section, rad/s
  Vec3 wdot_s = Vec3::Zero(); ///< angular acceleration of the section, rad/s^2
  Vec3 v_air = Vec3::Zero();  ///< local air velocity (0 in still air), m/s
  double flight_speed_mps = 0.0;  ///< vehicle flight speed U (friction Reynolds number), > 0
  /// Cd_f of M11 precomputed by the caller for this strip and flight speed (it depends only on
  /// U c / nu; caching it keeps pow/log10 out of the right-hand side); < 0 = compute here.
  double friction_coefficient = -1.0;
};

/// Number of ODE states per strip in MST-TD: [z, f] for the Scherer lag (option A),
/// [x1, x2, f] for the Jones lag (option B). 0 for DeLaurier 1993.
int statesPerStrip(const AeroParameters& params);

/// Loads of one strip, in the section frame, with their points of action (docs/theory.md 5.4, 5.5).
/// The blend of MST-TD (5.8) is already applied to each component.
struct SectionLoads {
  double dN_c4_N = 0.0;     ///< normal force acting at the quarter chord (circulatory part)
  double dN_c2_N = 0.0;     ///< normal force acting at mid-chord (apparent mass + separated)
  double dFx_N = 0.0;       ///< chordwise force, + towards the LE, on the chord line
  double dM_couple_Nm = 0.0;  ///< pure couples dMac + dMa (nose-up +)
  double dP_W = 0.0;        ///< aerodynamic input power (positive = power into the air).
                            ///< DeLaurier mode: M19 (flapping power, freestream excluded).
                            ///< MST-TD: -(F.(v_P - v_air) + M_P.w_s), power relative to the
                            ///< air, = M19 - U*thrust for a steady freestream U.
  // Diagnostics.
  double alpha_eff_rad = 0.0;  ///< effective (lagged) angle alpha' + thetabar or alpha'_t
  double alpha_le_rad = 0.0;   ///< stall-criterion angle at the LE (M14 / alpha_crit)
  double separation_f = 1.0;   ///< 1 attached, 0 separated (DeLaurier: 0 or 1)
  double reduced_frequency = 0.0;  ///< k (DeLaurier mode only)

  double dN_N() const { return dN_c4_N + dN_c2_N; }
  /// Moment about the leading edge, nose-up + (M18).
  double momentAboutLe(double chord_m) const {
    return -0.25 * chord_m * dN_c4_N - 0.5 * chord_m * dN_c2_N + dM_couple_Nm;
  }
};

/// Detailed intermediate values of DeLaurier's model, for term-by-term tests (docs/theory.md 5.10, O9).
struct DeLaurierTerms {
  double k = 0, F = 0, G_over_k = 0, alpha = 0, alphadot = 0, w0_over_U = 0, alpha_prime = 0;
  double Vx = 0, Vy = 0, V = 0, Cn = 0, dNc = 0, vdot2 = 0, dNa = 0;
  double dTs = 0, dDcamber = 0, Cd_f = 0, dDf = 0, alpha_le = 0;
  bool attached = true;
  double Vn_mid = 0, Vhat = 0, dN = 0, dFx = 0, dMac = 0, dMa = 0, dM_le = 0, dP = 0;
};

/// DeLaurier (1993) algebraic MST, docs/theory.md 5.2-5.4 (M1-M19), hard stall switch (stall_width
/// ignored). If `terms` is not null it receives every intermediate value.
SectionLoads evalDeLaurier1993(const StripContext& context, const StripGeometry& geometry,
                               const PlanarKinematics& kinematics,
                               DeLaurierTerms* terms = nullptr);

/// MST-TD (docs/theory.md 5.9). `states` holds statesPerStrip() values of this strip; their time
/// derivatives are written to `state_derivatives` (may be null when not needed).
SectionLoads evalMstTd(const StripContext& context, const StripGeometry& geometry,
                       const SectionKinematics& kinematics, const double* states,
                       double* state_derivatives);

/// Quasi-steady initial states of MST-TD for the given kinematics (docs/theory.md 5.7: z =
/// alpha_34, f = f_st), written to `states`.
void initialMstTdStates(const StripContext& context, const StripGeometry& geometry,
                        const SectionKinematics& kinematics, double* states);

/// Static separation function f_st (docs/theory.md 5.8), with asymmetric stall limits; a hard
/// switch (0 or 1) when stall_width_rad == 0.
double staticSeparation(const AeroParameters& params, double alpha_crit_rad);

/// Resolve section loads into a force and a moment about the reference point P, in the frame of
/// the section vectors (docs/theory.md 5.5): F = dN n + dFx e_c; normal components at c/4 and c/2
/// with their lever arms from P, couples about a_pitch = e_c x n.
void resolveSectionLoads(const SectionLoads& loads, const StripGeometry& geometry,
                         const Vec3& e_c, const Vec3& n, Vec3* force_N, Vec3* moment_P_Nm);

}  // namespace orni::aero
