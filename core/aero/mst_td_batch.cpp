#include "core/aero/mst_td_batch.hpp"

#include <cmath>

namespace orni::aero {

namespace {
constexpr double kPi = 3.14159265358979323846;
constexpr double kTwoPi = 2.0 * kPi;
constexpr double kHalfPi = 0.5 * kPi;
using StateMap = Eigen::Map<const ArrayXd, 0, Eigen::InnerStride<2>>;
using DerivMap = Eigen::Map<ArrayXd, 0, Eigen::InnerStride<2>>;
}  // namespace

bool batchKernelApplies(const AeroParameters& params) {
  return params.model == AeroModelKind::kMstTd && params.lag == CirculationLag::kScherer1 &&
         params.stall_width_rad > 0.0;
}

void StripBatch::resize(int n) {
  for (ArrayXd* a : {&chord_m, &width_m, &ref_aft_of_le_m, &friction_coefficient, &ecx, &ecy,
                     &ecz, &nx, &ny, &nz, &vx, &vy, &vz, &ax, &ay, &az, &wx, &wy, &wz, &wdx, &wdy,
                     &wdz, &airx, &airy, &airz, &Fx, &Fy, &Fz, &Mx, &My, &Mz, &separation_f,
                     &lever25, &lever50, &lever75, &k_q, &k_apparent, &k_couple1, &k_couple2,
                     &k_friction, &k_crossflow, &two_over_c})
    a->setZero(n);
  for (ArrayXd& s : t) s.setZero(n);
}

ArrayXd& atan2Array(const ArrayXd& y, const ArrayXd& x, ArrayXd& out, ArrayXd& a, ArrayXd& u,
                    ArrayXd& base) {
  const double t1 = 0.19891236737965800691;  // tan(pi/16)
  const double t3 = 0.66817863791929891999;  // tan(3 pi/16)
  const double c1 = 0.41421356237309504880;  // tan(pi/8)
  // a = min(|x|,|y|) / max(|x|,|y|) in [0, 1] (0 when both are 0).
  a = x.abs().min(y.abs()) / x.abs().max(y.abs()).max(1e-300);
  // atan(a) = atan(c) + atan((a - c)/(1 + a c)) with c in {0, tan(pi/8), 1}: |u| <= tan(pi/16).
  u = (a < t1).select(a, (a < t3).select((a - c1) / (1.0 + a * c1), (a - 1.0) / (a + 1.0)));
  base = (a < t3).select(ArrayXd::Constant(a.size(), kPi / 8.0), kPi / 4.0);
  base = (a < t1).select(0.0, base);
  // atan(u) = u p(u^2), p the odd Taylor series to u^23 (|u|^25/25 < 1e-19), one fused pass.
  a = u * u;
  out = base + u * (1.0 + a * (-1.0 / 3 + a * (1.0 / 5 + a * (-1.0 / 7 + a * (1.0 / 9 + a * (
                    -1.0 / 11 + a * (1.0 / 13 + a * (-1.0 / 15 + a * (1.0 / 17 + a * (
                    -1.0 / 19 + a * (1.0 / 21 + a * (-1.0 / 23))))))))))));
  // Undo the octant reduction.
  out = (y.abs() > x.abs()).select(kHalfPi - out, out);
  out = (x < 0.0).select(kPi - out, out);
  out = (y < 0.0).select(-out, out);
  return out;
}

void prepareStripBatch(const StripContext& context, StripBatch& b) {
  const AeroParameters& params = *context.params;
  const double rho = context.density_kgpm3;
  const ArrayXd& c = b.chord_m;
  const ArrayXd& dy = b.width_m;
  b.lever25 = 0.25 * c - b.ref_aft_of_le_m;
  b.lever50 = 0.5 * c - b.ref_aft_of_le_m;
  b.lever75 = 0.75 * c - b.ref_aft_of_le_m;
  b.k_q = 0.5 * rho * c * dy;
  b.k_apparent = (rho * kPi * 0.25) * c * c * dy;
  b.k_couple1 = (rho * kPi / 16.0) * c * c * c * dy;
  b.k_couple2 = (rho * kPi / 128.0) * c * c * c * c * dy;
  if (params.skin_friction)
    b.k_friction = b.friction_coefficient * 0.5 * rho * c * dy;
  else
    b.k_friction.setZero();
  b.k_crossflow = params.crossflow_drag_coefficient * 0.5 * rho * c * dy;
  b.two_over_c = 2.0 / c;
}

void evalMstTdBatch(const StripContext& context, StripBatch& b, const double* states,
                    double* state_derivatives) {
  const AeroParameters& params = *context.params;
  const int n = b.size();
  const double alpha0 = params.zero_lift_angle_rad;
  const double C1 = context.constants.C1, C2 = context.constants.C2;
  const double J = context.constants.jones_factor;
  ArrayXd* t = b.t;
  ArrayXd &qx = t[0], &qy = t[1], &qz = t[2], &apx = t[3], &apy = t[4], &apz = t[5];
  ArrayXd &thd = t[6], &thdd = t[7], &Vt = t[8], &qn = t[9], &Vn34 = t[10], &Vn50 = t[11];
  ArrayXd &vdot2 = t[12], &Vr = t[13], &alpha34 = t[14], &invVr = t[15], &alpha_t = t[16];
  ArrayXd &f = t[17], &qcdy = t[18], &s1 = t[19], &s2 = t[20], &s3 = t[21], &dN4 = t[22];
  ArrayXd& dN2 = t[23];
  const ArrayXd& c = b.chord_m;
  const ArrayXd& xP = b.ref_aft_of_le_m;

  // 2.3: q = v_air - v_P, a_pitch = e_c x n, thetadot, thetaddot, V_t, Vn(x), vdot2.
  qx = b.airx - b.vx;
  qy = b.airy - b.vy;
  qz = b.airz - b.vz;
  apx = b.ecy * b.nz - b.ecz * b.ny;
  apy = b.ecz * b.nx - b.ecx * b.nz;
  apz = b.ecx * b.ny - b.ecy * b.nx;
  thd = b.wx * apx + b.wy * apy + b.wz * apz;
  thdd = b.wdx * apx + b.wdy * apy + b.wdz * apz;
  Vt = -(qx * b.ecx + qy * b.ecy + qz * b.ecz);
  qn = qx * b.nx + qy * b.ny + qz * b.nz;
  Vn34 = qn + thd * b.lever75;
  Vn50 = qn + thd * b.lever50;
  // vdot2 = -a_P.n + q.(w_s x n) + thetaddot (c/2 - x_P)
  vdot2 = -(b.ax * b.nx + b.ay * b.ny + b.az * b.nz) +
          qx * (b.wy * b.nz - b.wz * b.ny) + qy * (b.wz * b.nx - b.wx * b.nz) +
          qz * (b.wx * b.ny - b.wy * b.nx) + thdd * b.lever50;
  // 9.5 steps 2-3: V_r floored; resultant 3/4-chord angle clipped to +-pi/2.
  Vr = (Vt * Vt + Vn34 * Vn34).sqrt().max(params.min_speed_mps);
  atan2Array(Vn34, Vt, alpha34, s1, s2, s3);
  alpha34 = alpha34.min(kHalfPi).max(-kHalfPi);
  invVr = Vr.inverse();

  // 9.3 option A: alpha_E = (1 - C1) alpha_34 + C1 z, dz/dt = sdot C2 (alpha_34 - z).
  const StateMap z(states, n), f_state(states + 1, n);
  s1 = (1.0 - C1) * alpha34 + C1 * z;                      // alpha_E
  alpha_t = J * (s1 + alpha0) - alpha0;                     // alpha'_t
  s2 = alpha_t - (b.lever75 + xP) * thd * invVr;           // alpha_crit (9.4.2): 0.75 c
  // 9.4.1: f_st = 0.5 [1 - tanh(x)] = 1 / (1 + exp(2x)), split at the midpoint of the limits.
  const double mid = 0.5 * (params.stall_angle_max_rad + params.stall_angle_min_rad);
  s3 = (s2 >= mid).select(s2 - params.stall_angle_max_rad, params.stall_angle_min_rad - s2);
  s3 = (2.0 / params.stall_width_rad * s3).min(700.0);
  s3 = (1.0 + s3.exp()).inverse();                          // f_st
  if (params.separation_lag_tf0 > 0.0) {
    f = f_state.max(0.0).min(1.0);
    if (state_derivatives) {
      DerivMap(state_derivatives, n) = (C2 * Vr) * b.two_over_c * (alpha34 - z);
      DerivMap(state_derivatives + 1, n) =
          (s3 - f_state) * (Vr * b.two_over_c * (1.0 / params.separation_lag_tf0));
    }
  } else {
    f = s3;
    if (state_derivatives) {
      DerivMap(state_derivatives, n) = (C2 * Vr) * b.two_over_c * (alpha34 - z);
      DerivMap(state_derivatives + 1, n).setZero();
    }
  }

  // 9.5 step 5: attached branch with q_ref = 0.5 rho V_r^2, separated branch (M15, 3-D).
  qcdy = Vr * Vr * b.k_q;
  dN4 = f * (kTwoPi * (alpha_t + alpha0) * qcdy);                                  // f dNc (M7)
  s1 = b.k_apparent * vdot2;                                                         // dNa (M8)
  s2 = b.k_crossflow * (Vt * Vt + Vn50 * Vn50).sqrt() * Vn50;                        // dNc_s
  dN2 = (1.0 - f) * s2 + 0.5 * (1.0 + f) * s1;
  // Chordwise: suction (off in reversed flow), camber, friction (M9-M12), blended (9.4.2).
  s2 = alpha_t - (b.lever25 + xP) * thd * invVr;                                    // suction angle
  s2 = (Vt > 0.0).select(params.suction_efficiency * kTwoPi * s2 * s2 * qcdy, 0.0); // dTs
  s2 += kTwoPi * alpha0 * alpha_t * qcdy;                                            // - dDcamber
  s2 = f.sqrt() * s2 - f * (b.k_friction * Vt * Vt.abs());                           // dFx
  // Couples (M17 with q_ref; V_r in the apparent-mass couple), blended.
  s3 = f * (params.moment_coefficient_ac * qcdy * c - b.k_couple1 * Vr * thd - b.k_couple2 * thdd);
  // 6.3: F = dN n + dFx e_c; moment about P along a_pitch.
  s1 = dN4 + dN2;
  b.Fx = s1 * b.nx + s2 * b.ecx;
  b.Fy = s1 * b.ny + s2 * b.ecy;
  b.Fz = s1 * b.nz + s2 * b.ecz;
  s1 = -b.lever25 * dN4 - b.lever50 * dN2 + s3;
  b.Mx = s1 * apx;
  b.My = s1 * apy;
  b.Mz = s1 * apz;
  b.separation_f = f;
}

}  // namespace orni::aero
