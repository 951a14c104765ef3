// DeLaurier (1993) modified strip theory, algebraic, per strip: docs/theory.md 5.2-5.4 (M1-M19)
// with DeLaurier's instantaneous (hard) stall switch. Pitch axis at the leading edge; plunge h
// positive down; SI units, radians.
#include <cassert>
#include <cmath>

#include "core/aero/mst_strip.hpp"
#include "core/model/frames.hpp"

namespace orni::aero {

namespace {
constexpr double kTwoPi = 2.0 * kPi;
}  // namespace

SectionLoads evalDeLaurier1993(const StripContext& context, const StripGeometry& geometry,
                               const PlanarKinematics& kinematics, DeLaurierTerms* terms) {
  assert(context.params != nullptr);
  const AeroParameters& params = *context.params;
  const MstConstants& constants = context.constants;
  const double rho = context.density_kgpm3;
  const double c = geometry.chord_m;
  const double dy = geometry.width_m;

  // Division by U (M1, M9, M14): floor at V_min (pitfall 7). No effect for U >= V_min.
  const double U = kinematics.U > params.min_speed_mps ? kinematics.U : params.min_speed_mps;
  const double inv_U = 1.0 / U;
  const double theta = kinematics.theta;
  const double thetabar = kinematics.thetabar;
  const double thetadot = kinematics.thetadot;
  const double thetaddot = kinematics.thetaddot;
  const double hdot = kinematics.hdot;
  const double hddot = kinematics.hddot;
  const double alpha0 = params.zero_lift_angle_rad;

  const double cos_rel = std::cos(theta - kinematics.theta_a);  // plunge projection (pitfall 3)
  const double sin_rel = std::sin(theta - kinematics.theta_a);
  const double hdot_normal = hdot * cos_rel;  // plunge velocity normal to the chord

  // M1, M2: dynamic relative angle at 3/4 chord and its rate.
  const double alpha = (hdot_normal + 0.75 * c * thetadot + U * (theta - thetabar)) * inv_U;
  const double alphadot = (hddot * cos_rel - hdot * thetadot * sin_rel + 0.75 * c * thetaddot +
                           U * thetadot) * inv_U;

  // M4, M3: reduced frequency and Scherer's fit (G'/k form, pitfall 4).
  const double k = kinematics.omega * c * 0.5 * inv_U;
  const SchererFunction scherer = schererFunction(constants, k);

  // M5: mean-lift downwash, 2/(2+AR) = 1 - AR/(2+AR) (also valid for AR = inf), and alpha'.
  const double w0_over_U = (1.0 - constants.jones_factor) * (alpha0 + thetabar);
  const double alpha_prime =
      constants.jones_factor * (scherer.F * alpha + c * 0.5 * inv_U * scherer.G_over_k * alphadot) -
      w0_over_U;
  const double alpha_flow = alpha_prime + thetabar;  // (alpha' + thetabar)

  // M6: flow at the 1/4 chord.
  const double Vx = U * std::cos(theta) - hdot * sin_rel;
  const double Vy = U * alpha_flow - 0.5 * c * thetadot;
  const double V = std::sqrt(Vx * Vx + Vy * Vy);
  const double q_mixed_c_dy = 0.5 * rho * U * V * c * dy;  // (rho U V/2) c dy, M7 mixed pressure

  // M7: circulatory normal force at c/4.
  const double Cn = kTwoPi * (alpha_flow + alpha0);
  const double dNc = Cn * q_mixed_c_dy;

  // M8: apparent-mass normal force at c/2.
  const double vdot2 = U * alphadot - 0.25 * c * thetaddot;
  const double apparent_mass_per_span = apparentMassPerSpan_kgpm(rho, c);
  const double dNa = apparent_mass_per_span * vdot2 * dy;

  // M9-M12: chordwise forces (+ towards the LE).
  const double suction_angle = alpha_flow - c * thetadot * 0.25 * inv_U;
  const double dTs =
      params.suction_efficiency * kTwoPi * suction_angle * suction_angle * q_mixed_c_dy;
  const double dDcamber = -kTwoPi * alpha0 * alpha_flow * q_mixed_c_dy;
  double Cd_f = 0.0;
  double dDf = 0.0;
  if (params.skin_friction) {
    Cd_f = frictionCoefficient(U * c / context.kinematic_viscosity_m2ps);  // M11, Re = U c/nu
    dDf = Cd_f * 0.5 * rho * Vx * std::fabs(Vx) * c * dy;                  // Vx|Vx| (pitfall 10)
  }
  const double dFx_att = dTs - dDcamber - dDf;

  // M14: stall criterion at the LE, hard switch.
  const double alpha_le = alpha_flow - 0.75 * c * thetadot * inv_U;
  const bool attached =
      alpha_le >= params.stall_angle_min_rad && alpha_le <= params.stall_angle_max_rad;

  // M15, M16: separated flow (cross-flow drag at c/2, apparent mass halved, no chordwise force).
  const double Vn_mid = hdot_normal + 0.5 * c * thetadot + U * std::sin(theta);
  const double Vhat = std::sqrt(Vx * Vx + Vn_mid * Vn_mid);
  const double dNc_s = params.crossflow_drag_coefficient * 0.5 * rho * Vhat * Vn_mid * c * dy;
  const double dN_sep = dNc_s + 0.5 * dNa;

  // M17: couples (nose-up +), dropped when separated.
  const double dMac = params.moment_coefficient_ac * q_mixed_c_dy * c;
  const double dMa = -(rho * kPi * c * c * c * U * thetadot * (1.0 / 16.0) +
                       rho * kPi * c * c * c * c * thetaddot * (1.0 / 128.0)) * dy;

  SectionLoads loads;
  double dP = 0.0;
  if (attached) {
    loads.dN_c4_N = dNc;
    loads.dN_c2_N = dNa;
    loads.dFx_N = dFx_att;
    loads.dM_couple_Nm = dMac + dMa;
    // M19 attached.
    dP = dFx_att * hdot * sin_rel + dNc * (hdot_normal + 0.25 * c * thetadot) +
         dNa * (hdot_normal + 0.5 * c * thetadot) - (dMac + dMa) * thetadot;
  } else {
    loads.dN_c4_N = 0.0;
    loads.dN_c2_N = dN_sep;
    loads.dFx_N = 0.0;
    loads.dM_couple_Nm = 0.0;
    dP = dN_sep * (hdot_normal + 0.5 * c * thetadot);  // M19 separated
  }
  loads.dP_W = dP;
  loads.alpha_eff_rad = alpha_flow;
  loads.alpha_le_rad = alpha_le;
  loads.separation_f = attached ? 1.0 : 0.0;
  loads.reduced_frequency = k;

  if (terms != nullptr) {
    // Every term as computed; dMac, dMa and dNc are filled even when separated (unused then).
    terms->k = k;
    terms->F = scherer.F;
    terms->G_over_k = scherer.G_over_k;
    terms->alpha = alpha;
    terms->alphadot = alphadot;
    terms->w0_over_U = w0_over_U;
    terms->alpha_prime = alpha_prime;
    terms->Vx = Vx;
    terms->Vy = Vy;
    terms->V = V;
    terms->Cn = Cn;
    terms->dNc = dNc;
    terms->vdot2 = vdot2;
    terms->dNa = dNa;
    terms->dTs = dTs;
    terms->dDcamber = dDcamber;
    terms->Cd_f = Cd_f;
    terms->dDf = dDf;
    terms->alpha_le = alpha_le;
    terms->attached = attached;
    terms->Vn_mid = Vn_mid;
    terms->Vhat = Vhat;
    terms->dN = loads.dN_N();
    terms->dFx = loads.dFx_N;
    terms->dMac = dMac;
    terms->dMa = dMa;
    terms->dM_le = loads.momentAboutLe(c);  // M18
    terms->dP = dP;
  }
  return loads;
}

}  // namespace orni::aero
