// MST-TD: time-domain modified strip theory per strip (docs/theory.md 5.7-5.9): circulatory lag as
// ODE states (5.7 option A Scherer [z, f] or option B Jones [x1, x2, f]), resultant angle of attack
// from the 3-D section kinematics (5.1), smooth lagged separation (5.8), per-step
// algorithm 5.9. Pure functions, no allocation.
#include <cassert>
#include <cmath>

#include <Eigen/Geometry>

#include "core/aero/mst_strip.hpp"
#include "core/model/frames.hpp"

namespace orni::aero {

namespace {

constexpr double kTwoPi = 2.0 * kPi;
constexpr double kHalfPi = 0.5 * kPi;

// R.T. Jones' two-term Wagner approximation (5.7 option B).
constexpr double kJonesA1 = 0.165;
constexpr double kJonesB1 = 0.0455;
constexpr double kJonesA2 = 0.335;
constexpr double kJonesB2 = 0.3;

/// Number of circulatory-lag states before the separation state f.
inline int lagStateCount(const AeroParameters& params) {
  return params.lag == CirculationLag::kScherer1 ? 1 : 2;
}

/// Section quantities of docs/theory.md 5.1, 5.9 steps 1-3.
struct FlowAtSection {
  double V_t_mps;        ///< chordwise flow, LE -> TE positive
  double qn_P_mps;       ///< q . n at P
  double thetadot_radps;
  double thetaddot_radps2;
  double Vn_34_mps;      ///< normal flow at 3/4 chord
  double Vn_50_mps;      ///< normal flow at mid-chord
  double vdot2_mps2;     ///< d/dt Vn_50
  double V_r_mps;        ///< reference speed, floored at V_min
  double alpha_34_rad;   ///< resultant 3/4-chord angle, clipped to +-pi/2
};

inline FlowAtSection extractFlow(const AeroParameters& params, const StripGeometry& geometry,
                                 const SectionKinematics& kin) {
  const double c = geometry.chord_m;
  const double x_P = geometry.ref_aft_of_le_m;
  FlowAtSection flow;
  // 5.1: q = v_air - v_P; a_pitch = e_c x n; V_t = -q.e_c; Vn(x) = q.n + thetadot (x - x_P).
  const Vec3 q = kin.v_air - kin.v_P;
  const Vec3 a_pitch = kin.e_c.cross(kin.n);
  flow.thetadot_radps = kin.w_s.dot(a_pitch);
  flow.thetaddot_radps2 = kin.wdot_s.dot(a_pitch);  // rotation rate of a_pitch neglected
  const double thetaddot = flow.thetaddot_radps2;
  flow.V_t_mps = -q.dot(kin.e_c);
  flow.qn_P_mps = q.dot(kin.n);
  flow.Vn_34_mps = flow.qn_P_mps + flow.thetadot_radps * (0.75 * c - x_P);
  flow.Vn_50_mps = flow.qn_P_mps + flow.thetadot_radps * (0.5 * c - x_P);
  // vdot2 = -a_P.n + q.(w_s x n) + thetaddot (c/2 - x_P)
  flow.vdot2_mps2 =
      -kin.a_P.dot(kin.n) + q.dot(kin.w_s.cross(kin.n)) + thetaddot * (0.5 * c - x_P);
  // 5.9 step 2: V_r = max(|(V_t, Vn_34)|, V_min).
  const double V_r = std::sqrt(flow.V_t_mps * flow.V_t_mps + flow.Vn_34_mps * flow.Vn_34_mps);
  flow.V_r_mps = V_r > params.min_speed_mps ? V_r : params.min_speed_mps;
  // 5.9 step 3: resultant angle, clipped to +-pi/2 (pitfall 10: no atan2 wrap into the lag).
  // At rest (both components exactly zero, possibly signed zeros) the angle is 0, not atan2's +-pi.
  double alpha_34 = (flow.V_t_mps == 0.0 && flow.Vn_34_mps == 0.0)
                        ? 0.0
                        : std::atan2(flow.Vn_34_mps, flow.V_t_mps);
  if (alpha_34 > kHalfPi) alpha_34 = kHalfPi;
  if (alpha_34 < -kHalfPi) alpha_34 = -kHalfPi;
  flow.alpha_34_rad = alpha_34;
  return flow;
}

/// 5.7: alpha'_t = [AR/(2+AR)] (alpha_E + alpha0) - alpha0.
inline double finiteWingAngle(const StripContext& context, double alpha_E_rad) {
  const double alpha0 = context.params->zero_lift_angle_rad;
  return context.constants.jones_factor * (alpha_E_rad + alpha0) - alpha0;
}

}  // namespace

int statesPerStrip(const AeroParameters& params) {
  if (params.model == AeroModelKind::kDeLaurier1993) return 0;
  return lagStateCount(params) + 1;
}

double staticSeparation(const AeroParameters& params, double alpha_crit_rad) {
  const double a_max = params.stall_angle_max_rad;
  const double a_min = params.stall_angle_min_rad;
  const double width = params.stall_width_rad;
  if (!(width > 0.0)) {  // hard switch, M14
    return (alpha_crit_rad >= a_min && alpha_crit_rad <= a_max) ? 1.0 : 0.0;
  }
  // 5.8: f_st = 0.5 [1 - tanh((|a| - alpha_s)/delta_s)], with alpha_s = a_max on the upper
  // side and -a_min on the lower side. The two sides meet at the midpoint of the limits, where
  // both give the same value (continuous; for symmetric limits exactly the |a| form).
  const double midpoint = 0.5 * (a_max + a_min);
  const double excess =
      alpha_crit_rad >= midpoint ? alpha_crit_rad - a_max : a_min - alpha_crit_rad;
  // 0.5 [1 - tanh(x)] == 1 / (1 + exp(2 x)) exactly; one exp is several times cheaper than
  // glibc's tanh (expm1 path), and this runs per strip in every right-hand side.
  const double two_x = 2.0 * excess / width;
  if (two_x > 700.0) return 0.0;  // exp overflow guard; the value is 0 to double precision
  return 1.0 / (1.0 + std::exp(two_x));
}

void initialMstTdStates(const StripContext& context, const StripGeometry& geometry,
                        const SectionKinematics& kinematics, double* states) {
  assert(context.params != nullptr && states != nullptr);
  const AeroParameters& params = *context.params;
  const FlowAtSection flow = extractFlow(params, geometry, kinematics);
  // Quasi-steady: lag states at their equilibrium, so alpha_E = alpha_34 (5.7).
  const int n_lag = lagStateCount(params);
  if (params.lag == CirculationLag::kScherer1) {
    states[0] = flow.alpha_34_rad;
  } else {
    states[0] = kJonesA1 * flow.alpha_34_rad;
    states[1] = kJonesA2 * flow.alpha_34_rad;
  }
  const double alpha_t = finiteWingAngle(context, flow.alpha_34_rad);
  const double alpha_crit = alpha_t - 0.75 * geometry.chord_m * flow.thetadot_radps / flow.V_r_mps;
  states[n_lag] = staticSeparation(params, alpha_crit);
}

SectionLoads evalMstTd(const StripContext& context, const StripGeometry& geometry,
                       const SectionKinematics& kinematics, const double* states,
                       double* state_derivatives) {
  assert(context.params != nullptr && states != nullptr);
  const AeroParameters& params = *context.params;
  const double rho = context.density_kgpm3;
  const double c = geometry.chord_m;
  const double dy = geometry.width_m;
  const double x_P = geometry.ref_aft_of_le_m;
  const double alpha0 = params.zero_lift_angle_rad;

  // 5.9 steps 1-3.
  const FlowAtSection flow = extractFlow(params, geometry, kinematics);
  const double V_r = flow.V_r_mps;
  const double inv_V_r = 1.0 / V_r;
  const double thetadot = flow.thetadot_radps;
  const double sdot = 2.0 * V_r / c;  // reduced-time rate, 1/s (5.7)

  // 5.9 step 4: lagged angle alpha_E (5.7), finite-wing angle alpha'_t, stall angle alpha_crit.
  const int n_lag = lagStateCount(params);
  double alpha_E = 0.0;
  if (params.lag == CirculationLag::kScherer1) {
    const double C1 = context.constants.C1;
    alpha_E = (1.0 - C1) * flow.alpha_34_rad + C1 * states[0];  // option A
    if (state_derivatives != nullptr)
      state_derivatives[0] = sdot * context.constants.C2 * (flow.alpha_34_rad - states[0]);
  } else {
    alpha_E = (1.0 - kJonesA1 - kJonesA2) * flow.alpha_34_rad + states[0] + states[1];  // option B
    if (state_derivatives != nullptr) {
      state_derivatives[0] = sdot * kJonesB1 * (kJonesA1 * flow.alpha_34_rad - states[0]);
      state_derivatives[1] = sdot * kJonesB2 * (kJonesA2 * flow.alpha_34_rad - states[1]);
    }
  }
  const double alpha_t = finiteWingAngle(context, alpha_E);
  const double alpha_crit = alpha_t - 0.75 * c * thetadot * inv_V_r;  // 5.8 (M14 form)

  // 5.8: separation state. T_f0 = 0: f follows f_st instantly, derivative 0.
  const double f_st = staticSeparation(params, alpha_crit);
  double f = f_st;
  if (params.separation_lag_tf0 > 0.0) {
    const double f_state = states[n_lag];
    f = f_state < 0.0 ? 0.0 : (f_state > 1.0 ? 1.0 : f_state);
    if (state_derivatives != nullptr) {
      const double T_f = params.separation_lag_tf0 * c * 0.5 * inv_V_r;  // T_f0 c/(2 V_r)
      state_derivatives[n_lag] = (f_st - f_state) / T_f;
    }
  } else if (state_derivatives != nullptr) {
    state_derivatives[n_lag] = 0.0;
  }

  // 5.9 step 5: attached branch, bounded at large angles (boundedAttachedFlow: the finite-wing
  // angle as J sin(alpha_E + alpha0) and DeLaurier's Kutta-Joukowski dynamic pressure).
  const BoundedAttachedFlow bounded =
      boundedAttachedFlow(context.constants.jones_factor, alpha_E + alpha0);
  const double q_ref_c_dy = 0.5 * rho * V_r * V_r * c * dy;
  const double q_K_c_dy = q_ref_c_dy * bounded.speed_ratio;
  const double dNc = kTwoPi * bounded.angle * q_K_c_dy;                          // M7
  const double dNa = apparentMassPerSpan_kgpm(rho, c) * flow.vdot2_mps2 * dy;              // M8
  // M9 with the suction angle (bounded) - c thetadot/(4 V_r); off in reversed flow (pitfall 10).
  const double suction_angle = bounded.angle - alpha0 - 0.25 * c * thetadot * inv_V_r;
  const double dTs = flow.V_t_mps > 0.0
                         ? params.suction_efficiency * kTwoPi * suction_angle * suction_angle *
                               q_K_c_dy
                         : 0.0;
  const double dDcamber = -kTwoPi * alpha0 * (bounded.angle - alpha0) * q_K_c_dy;  // M10
  double dDf = 0.0;
  if (params.skin_friction) {
    // M11 with Re = U c/nu (flight speed) and V_t|V_t| (pitfall 10).
    const double Cd_f =
        kinematics.friction_coefficient >= 0.0
            ? kinematics.friction_coefficient
            : frictionCoefficient(kinematics.flight_speed_mps * c /
                                  context.kinematic_viscosity_m2ps);
    dDf = Cd_f * 0.5 * rho * flow.V_t_mps * std::fabs(flow.V_t_mps) * c * dy;
  }
  // M17 with q_ref, and V_r in place of U in the apparent-mass couple.
  const double dMac = params.moment_coefficient_ac * q_ref_c_dy * c;
  const double dMa = -(rho * kPi * c * c * c * V_r * thetadot * (1.0 / 16.0) +
                       rho * kPi * c * c * c * c * flow.thetaddot_radps2 * (1.0 / 128.0)) * dy;
  // Separated branch (M15 with the 3-D mid-chord normal flow).
  const double Vn_50 = flow.Vn_50_mps;
  const double Vhat = std::sqrt(flow.V_t_mps * flow.V_t_mps + Vn_50 * Vn_50);
  const double dNc_s = params.crossflow_drag_coefficient * 0.5 * rho * Vhat * Vn_50 * c * dy;

  // 5.9 step 6: blend with f (5.8), points of action per component (5.4, 5.5).
  SectionLoads loads;
  loads.dN_c4_N = f * dNc;
  loads.dN_c2_N = (1.0 - f) * dNc_s + 0.5 * (1.0 + f) * dNa;  // (f + 0.5 (1 - f)) dNa
  loads.dFx_N = std::sqrt(f) * (dTs - dDcamber) - f * dDf;
  loads.dM_couple_Nm = f * (dMac + dMa);

  // Power of the wing on the air, in the air's rest frame:
  //   dP = -(F . (v_P - v_air) + M_P . w_s) = F . q - M_P . w_s,
  // with F and M_P as resolveSectionLoads gives them (F in span{n, e_c}, M_P along a_pitch), so
  // dP = dN (q.n) - dFx V_t - m_P thetadot. For a steady freestream U this is DeLaurier's M19
  // minus the propulsive power: dP = dP_M19 - U dT (dT = thrust along U).
  const double m_P = -(0.25 * c - x_P) * loads.dN_c4_N - (0.5 * c - x_P) * loads.dN_c2_N +
                     loads.dM_couple_Nm;
  loads.dP_W = loads.dN_N() * flow.qn_P_mps - loads.dFx_N * flow.V_t_mps - m_P * thetadot;

  loads.alpha_eff_rad = alpha_t;
  loads.alpha_le_rad = alpha_crit;
  loads.separation_f = f;
  loads.reduced_frequency = 0.0;
  return loads;
}

}  // namespace orni::aero
