#include "core/aero/mst_td_batch.hpp"

#include <algorithm>
#include <cmath>

#include "core/model/frames.hpp"

namespace orni::aero {

namespace {
constexpr double kTwoPi = 2.0 * kPi;
constexpr double kHalfPi = 0.5 * kPi;
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

namespace {
// atan2 without a branch: octant reduction to |u| <= tan(pi/16) and the odd Taylor series of
// atan to u^23 (|u|^25/25 < 1e-19). Only selects, so the strip loops vectorise with it inline.
// One division: with lo = min(|x|,|y|), hi = max(|x|,|y|) and a = lo/hi in [0, 1],
// atan(a) = atan(c) + atan((a - c)/(1 + a c)) = atan(c) + atan((lo - c hi)/(hi + c lo)) with c in
// {0, tan(pi/8), 1}, the octant chosen by comparing lo with tan(pi/16) hi and tan(3 pi/16) hi.
inline double atan2Poly(double y, double x) {
  const double t1 = 0.19891236737965800691;  // tan(pi/16)
  const double t3 = 0.66817863791929891999;  // tan(3 pi/16)
  const double c1 = 0.41421356237309504880;  // tan(pi/8)
  const double ax = std::abs(x), ay = std::abs(y);
  const double lo = std::min(ax, ay), hi = std::max(std::max(ax, ay), 1e-300);  // u = 0 at rest
  const bool low = lo < t1 * hi, mid = lo < t3 * hi;
  const double num = low ? lo : (mid ? lo - c1 * hi : lo - hi);
  const double den = low ? hi : (mid ? hi + c1 * lo : hi + lo);
  const double u = num / den;
  const double base = low ? 0.0 : (mid ? kPi / 8.0 : kPi / 4.0);
  // Estrin's scheme in u^2 (see sinPoly).
  const double u2 = u * u, u4 = u2 * u2, u8 = u4 * u4;
  const double p0 = 1.0 - u2 * (1.0 / 3), p1 = 1.0 / 5 - u2 * (1.0 / 7);
  const double p2 = 1.0 / 9 - u2 * (1.0 / 11), p3 = 1.0 / 13 - u2 * (1.0 / 15);
  const double p4 = 1.0 / 17 - u2 * (1.0 / 19), p5 = 1.0 / 21 - u2 * (1.0 / 23);
  const double q0 = p0 + u4 * p1, q1 = p2 + u4 * p3, q2 = p4 + u4 * p5;
  double r = base + u * (q0 + u8 * (q1 + u8 * q2));
  // Undo the octant reduction.
  r = ay > ax ? kHalfPi - r : r;
  r = x < 0.0 ? kPi - r : r;
  return y < 0.0 ? -r : r;
}
// sin of |x| <= 2 (the lagged 3/4-chord angle is clipped to +-pi/2, plus alpha0) without a
// call, so the strip loop still vectorises: the Taylor series to x^23 (remainder below
// 2^25/25! = 2e-18). Outside that range (never reached) the error grows.
inline double sinPoly(double x) {
  // Estrin's scheme in x^2 (the same polynomial; a short dependency chain instead of Horner's 12
  // steps, the strip loop's latency is the cost).
  const double x2 = x * x, x4 = x2 * x2, x8 = x4 * x4;
  const double p0 = 1.0 - x2 * (1.0 / 6), p1 = 1.0 / 120 - x2 * (1.0 / 5040);
  const double p2 = 1.0 / 362880 - x2 * (1.0 / 39916800);
  const double p3 = 1.0 / 6227020800.0 - x2 * (1.0 / 1307674368000.0);
  const double p4 = 1.0 / 355687428096000.0 - x2 * (1.0 / 121645100408832000.0);
  const double p5 = 1.0 / 51090942171709440000.0 - x2 * (1.0 / 25852016738884976640000.0);
  const double q0 = p0 + x4 * p1, q1 = p2 + x4 * p3, q2 = p4 + x4 * p5;
  return x * (q0 + x8 * (q1 + x8 * q2));
}
}  // namespace

ArrayXd& atan2Array(const ArrayXd& y, const ArrayXd& x, ArrayXd& out) {
  const Eigen::Index n = y.size();
  out.resize(n);
  const double* __restrict py = y.data();
  const double* __restrict px = x.data();
  double* __restrict po = out.data();
#pragma GCC ivdep
  for (Eigen::Index j = 0; j < n; ++j) po[j] = atan2Poly(py[j], px[j]);
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
  b.k_apparent = (rho * kPi * 0.25) * c * c * dy;  // apparentMassPerSpan_kgpm (mst_strip.hpp) dy
  b.k_couple1 = (rho * kPi / 16.0) * c * c * c * dy;
  b.k_couple2 = (rho * kPi / 128.0) * c * c * c * c * dy;
  if (params.skin_friction)
    b.k_friction = b.friction_coefficient * 0.5 * rho * c * dy;
  else
    b.k_friction.setZero();
  b.k_crossflow = params.crossflow_drag_coefficient * 0.5 * rho * c * dy;
  b.two_over_c = 2.0 / c;
}

namespace {

// kUniformFrame: e_c, n, w_s and wdot_s are the same for every strip (a rigid wing) and read from
// element 0 only, so that the compiler hoists what depends on them alone out of the strip loops.
template <bool kUniformFrame>
void evalBatch(const StripContext& context, StripBatch& b, const double* states,
               double* state_derivatives) {
  // Index of strip j's frame.
  const auto F = [](Eigen::Index j) { return kUniformFrame ? Eigen::Index{0} : j; };
  const AeroParameters& params = *context.params;
  const Eigen::Index n = b.size();
  const double alpha0 = params.zero_lift_angle_rad;
  const double C1 = context.constants.C1, C2 = context.constants.C2;
  const double J = context.constants.jones_factor;
  const double one_minus_J2 = 1.0 - J * J;
  const double min_speed = params.min_speed_mps;
  const double stall_max = params.stall_angle_max_rad, stall_min = params.stall_angle_min_rad;
  const double stall_mid = 0.5 * (stall_max + stall_min);
  const double stall_scale = 2.0 / params.stall_width_rad;
  const bool separation_lag = params.separation_lag_tf0 > 0.0;
  const double inv_tf0 = separation_lag ? 1.0 / params.separation_lag_tf0 : 0.0;
  const double suction_eff = params.suction_efficiency;
  const double cm_ac = params.moment_coefficient_ac;
  // Carried from the first pass to the second (scratch arrays of the batch).
  double* __restrict apx = b.t[0].data();
  double* __restrict apy = b.t[1].data();
  double* __restrict apz = b.t[2].data();
  double* __restrict thd_a = b.t[3].data();
  double* __restrict thdd_a = b.t[4].data();
  double* __restrict Vt_a = b.t[5].data();
  double* __restrict Vn50_a = b.t[6].data();
  double* __restrict vdot2_a = b.t[7].data();
  double* __restrict Vr_a = b.t[8].data();
  double* __restrict inv_Vr_a = b.t[9].data();
  double* __restrict fst_arg = b.t[10].data();  // then f_st
  double* __restrict zdot = b.t[11].data();
  double* __restrict f_state_a = b.t[12].data();
  double* __restrict speed_ratio_a = b.t[13].data();
  double* __restrict angle_b_a = b.t[14].data();
  const double* __restrict ecx = b.ecx.data();
  const double* __restrict ecy = b.ecy.data();
  const double* __restrict ecz = b.ecz.data();
  const double* __restrict nx = b.nx.data();
  const double* __restrict ny = b.ny.data();
  const double* __restrict nz = b.nz.data();
  const double* __restrict lever25 = b.lever25.data();
  const double* __restrict lever50 = b.lever50.data();
  const double* __restrict lever75 = b.lever75.data();
  const double* __restrict xP = b.ref_aft_of_le_m.data();
  const double* __restrict two_over_c = b.two_over_c.data();
  const double* __restrict airx = b.airx.data();
  const double* __restrict airy = b.airy.data();
  const double* __restrict airz = b.airz.data();
  const double* __restrict vx = b.vx.data();
  const double* __restrict vy = b.vy.data();
  const double* __restrict vz = b.vz.data();
  const double* __restrict aPx = b.ax.data();
  const double* __restrict aPy = b.ay.data();
  const double* __restrict aPz = b.az.data();
  const double* __restrict wsx = b.wx.data();
  const double* __restrict wsy = b.wy.data();
  const double* __restrict wsz = b.wz.data();
  const double* __restrict wdx = b.wdx.data();
  const double* __restrict wdy = b.wdy.data();
  const double* __restrict wdz = b.wdz.data();

  // Pass 1: kinematics (5.1), lag (5.7 option A), angles of the stall criterion (5.8).
#pragma GCC ivdep  // distinct arrays (GCC ignores restrict on local pointers)
  for (Eigen::Index j = 0; j < n; ++j) {
    // q = v_air - v_P, a_pitch = e_c x n, thetadot, thetaddot, V_t, Vn(x), vdot2.
    const double qx = airx[j] - vx[j], qy = airy[j] - vy[j], qz = airz[j] - vz[j];
    const double ax = ecy[F(j)] * nz[F(j)] - ecz[F(j)] * ny[F(j)];
    const double ay = ecz[F(j)] * nx[F(j)] - ecx[F(j)] * nz[F(j)];
    const double az = ecx[F(j)] * ny[F(j)] - ecy[F(j)] * nx[F(j)];
    const double wx = wsx[F(j)], wy = wsy[F(j)], wz = wsz[F(j)];
    const double thd = wx * ax + wy * ay + wz * az;
    const double thdd = wdx[F(j)] * ax + wdy[F(j)] * ay + wdz[F(j)] * az;
    const double Vt = -(qx * ecx[F(j)] + qy * ecy[F(j)] + qz * ecz[F(j)]);
    const double qn = qx * nx[F(j)] + qy * ny[F(j)] + qz * nz[F(j)];
    const double Vn34 = qn + thd * lever75[j];
    // vdot2 = -a_P.n + q.(w_s x n) + thetaddot (c/2 - x_P)
    const double vdot2 = -(aPx[j] * nx[F(j)] + aPy[j] * ny[F(j)] + aPz[j] * nz[F(j)]) +
                         qx * (wy * nz[F(j)] - wz * ny[F(j)]) + qy * (wz * nx[F(j)] - wx * nz[F(j)]) +
                         qz * (wx * ny[F(j)] - wy * nx[F(j)]) + thdd * lever50[j];
    // 5.9 steps 2-3: V_r floored; resultant 3/4-chord angle clipped to +-pi/2.
    const double Vr = std::max(std::sqrt(Vt * Vt + Vn34 * Vn34), min_speed);
    const double alpha34 = std::max(std::min(atan2Poly(Vn34, Vt), kHalfPi), -kHalfPi);
    // 5.7 option A: alpha_E = (1 - C1) alpha_34 + C1 z, dz/dt = sdot C2 (alpha_34 - z).
    const double z = states[2 * j];
    const double alpha_E = (1.0 - C1) * alpha34 + C1 * z;
    const double alpha_t = J * (alpha_E + alpha0) - alpha0;  // alpha'_t
    // Bounded attached flow (boundedAttachedFlow, mst_strip.hpp): J sin(alpha_E + alpha0) and
    // the speed ratio V_K / V_r = sqrt(cos^2 + (J sin)^2) = sqrt(1 - (1 - J^2) sin^2) of
    // DeLaurier's dynamic pressure.
    const double sE = sinPoly(alpha_E + alpha0);
    speed_ratio_a[j] = std::sqrt(1.0 - one_minus_J2 * (sE * sE));
    angle_b_a[j] = J * sE;
    const double inv_Vr = 1.0 / Vr;
    const double alpha_crit = alpha_t - (lever75[j] + xP[j]) * thd * inv_Vr;  // 5.8: 0.75 c
    // 5.8: f_st = 0.5 [1 - tanh(x)] = 1 / (1 + exp(2x)), split at the midpoint of the limits.
    const double x = alpha_crit >= stall_mid ? alpha_crit - stall_max : stall_min - alpha_crit;
    fst_arg[j] = std::min(stall_scale * x, 700.0);
    zdot[j] = (C2 * Vr) * two_over_c[j] * (alpha34 - z);
    f_state_a[j] = states[2 * j + 1];
    apx[j] = ax;
    apy[j] = ay;
    apz[j] = az;
    thd_a[j] = thd;
    thdd_a[j] = thdd;
    Vt_a[j] = Vt;
    Vn50_a[j] = qn + thd * lever50[j];
    vdot2_a[j] = vdot2;
    Vr_a[j] = Vr;
    inv_Vr_a[j] = inv_Vr;
  }
  {
    Eigen::Map<ArrayXd> arg(fst_arg, n);
    arg = (1.0 + arg.exp()).inverse();  // f_st (Eigen's vectorised exp)
  }
  const double* __restrict fst = fst_arg;

  // Pass 2: separation (5.8), attached and separated branches (5.9 step 5, M7-M17), loads (5.5).
  double* __restrict Fx = b.Fx.data();
  double* __restrict Fy = b.Fy.data();
  double* __restrict Fz = b.Fz.data();
  double* __restrict Mx = b.Mx.data();
  double* __restrict My = b.My.data();
  double* __restrict Mz = b.Mz.data();
  double* __restrict f_out = b.separation_f.data();
  const double* __restrict k_q = b.k_q.data();
  const double* __restrict k_apparent = b.k_apparent.data();
  const double* __restrict k_crossflow = b.k_crossflow.data();
  const double* __restrict k_friction = b.k_friction.data();
  const double* __restrict k_couple1 = b.k_couple1.data();
  const double* __restrict k_couple2 = b.k_couple2.data();
  const double* __restrict chord = b.chord_m.data();
#pragma GCC ivdep
  for (Eigen::Index j = 0; j < n; ++j) {
    const double f = separation_lag ? std::max(std::min(f_state_a[j], 1.0), 0.0) : fst[j];
    const double Vr = Vr_a[j], Vt = Vt_a[j], Vn50 = Vn50_a[j], thd = thd_a[j];
    const double angle_b = angle_b_a[j];
    // Attached branch (bounded, DeLaurier's dynamic pressure), separated branch (M15, 3-D).
    const double qcdy = Vr * Vr * k_q[j] * speed_ratio_a[j];
    const double qrcdy = Vr * Vr * k_q[j];
    const double dN4 = f * (kTwoPi * angle_b * qcdy);                       // f dNc (M7)
    const double dNa = k_apparent[j] * vdot2_a[j];                          // dNa (M8)
    const double dNs = k_crossflow[j] * std::sqrt(Vt * Vt + Vn50 * Vn50) * Vn50;  // dNc_s
    const double dN2 = (1.0 - f) * dNs + 0.5 * (1.0 + f) * dNa;
    // Chordwise: suction (off in reversed flow), camber, friction (M9-M12), blended (5.8).
    const double alpha_s = angle_b - alpha0 - (lever25[j] + xP[j]) * thd * inv_Vr_a[j];  // suction
    double dFx = Vt > 0.0 ? suction_eff * kTwoPi * alpha_s * alpha_s * qcdy : 0.0;  // dTs
    dFx += kTwoPi * alpha0 * (angle_b - alpha0) * qcdy;                        // - dDcamber
    dFx = std::sqrt(f) * dFx - f * (k_friction[j] * Vt * std::abs(Vt));
    // Couples (M17 with q_ref; V_r in the apparent-mass couple), blended.
    const double couple =
        f * (cm_ac * qrcdy * chord[j] - k_couple1[j] * Vr * thd - k_couple2[j] * thdd_a[j]);
    // 5.5: F = dN n + dFx e_c; moment about P along a_pitch.
    const double dN = dN4 + dN2;
    Fx[j] = dN * nx[F(j)] + dFx * ecx[F(j)];
    Fy[j] = dN * ny[F(j)] + dFx * ecy[F(j)];
    Fz[j] = dN * nz[F(j)] + dFx * ecz[F(j)];
    const double m = -lever25[j] * dN4 - lever50[j] * dN2 + couple;
    Mx[j] = m * apx[j];
    My[j] = m * apy[j];
    Mz[j] = m * apz[j];
    f_out[j] = f;
  }
  if (!state_derivatives) return;
  for (Eigen::Index j = 0; j < n; ++j) {  // interleaved [z, f] per strip
    state_derivatives[2 * j] = zdot[j];
    state_derivatives[2 * j + 1] =
        separation_lag ? (fst[j] - f_state_a[j]) * (Vr_a[j] * two_over_c[j] * inv_tf0) : 0.0;
  }
}

}  // namespace

void evalMstTdBatch(const StripContext& context, StripBatch& b, const double* states,
                    double* state_derivatives) {
  evalBatch<false>(context, b, states, state_derivatives);
}

void evalMstTdBatchUniformFrame(const StripContext& context, StripBatch& b, const double* states,
                                double* state_derivatives) {
  evalBatch<true>(context, b, states, state_derivatives);
}

}  // namespace orni::aero
