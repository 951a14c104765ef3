// DeLaurier (1993) MST: term-by-term oracle O9, steady limit and induced drag O5, Garrick plunge
// propulsion O6 and Theodorsen plunge normal force O7 (docs/theory.md section 5.10).
#include <cmath>
#include <complex>
#include <limits>

#include <gtest/gtest.h>

#include "core/aero/mst_strip.hpp"

namespace orni::aero {
namespace {

constexpr double kPi = 3.14159265358979323846;
/// Identities evaluated in double precision on O(1) values: a few ulps.
constexpr double kRoundOffAbs = 1e-14;
constexpr double kDeg = kPi / 180.0;

/// O9 values are printed with 6 significant digits (a few with 5): worst-case rounding 5e-6
/// relative; every printed value, including the 5-digit ones, is met within 1e-5.
constexpr double kO9RelTol = 1e-5;

void expectRel(double actual, double expected, double rel_tol, const char* what) {
  EXPECT_NEAR(actual, expected, rel_tol * std::fabs(expected)) << what;
}

/// The O9 strip (docs/theory.md 5.10, O9).
struct O9Setup {
  AeroParameters params;
  StripContext context;
  StripGeometry geometry;
  PlanarKinematics kin;
  O9Setup(double hdot, double hddot) {
    params.model = AeroModelKind::kDeLaurier1993;
    params.zero_lift_angle_rad = 2.0 * kDeg;
    params.moment_coefficient_ac = -0.05;
    params.suction_efficiency = 0.98;
    params.crossflow_drag_coefficient = 1.98;
    params.skin_friction = true;
    params.stall_angle_max_rad = 13.0 * kDeg;
    params.stall_angle_min_rad = -13.0 * kDeg;
    context.params = &params;
    context.constants = MstConstants::fromAspectRatio(5.58);
    context.density_kgpm3 = 1.225;
    context.kinematic_viscosity_m2ps = 1.5e-5;
    geometry.chord_m = 0.10;
    geometry.width_m = 0.01;
    kin.U = 6.0;
    kin.theta_a = 5.0 * kDeg;
    kin.thetabar = 7.0 * kDeg;
    kin.theta = kin.thetabar - 3.0 * kDeg;
    kin.thetadot = -2.0;
    kin.thetaddot = 30.0;
    kin.hdot = hdot;
    kin.hddot = hddot;
    kin.omega = 2.0 * kPi * 4.0;
  }
};

TEST(AeroDeLaurier, O9CaseAAttachedTermByTerm) {
  O9Setup s(1.5, 20.0);
  DeLaurierTerms t;
  const SectionLoads loads = evalDeLaurier1993(s.context, s.geometry, s.kin, &t);
  expectRel(t.k, 0.209440, kO9RelTol, "k");
  expectRel(t.F, 0.893785, kO9RelTol, "F'");
  expectRel(t.G_over_k, -0.773284, kO9RelTol, "G'/k");
  expectRel(t.alpha, 0.172602, kO9RelTol, "alpha");
  expectRel(t.alphadot, 1.69910, kO9RelTol, "alphadot");
  expectRel(t.w0_over_U, 0.0414458, kO9RelTol, "w0/U");
  expectRel(t.alpha_prime, 0.0640589, kO9RelTol, "alpha'");
  expectRel(t.Vx, 6.01156, kO9RelTol, "Vx");
  expectRel(t.Vy, 1.21739, kO9RelTol, "Vy");
  expectRel(t.V, 6.13359, kO9RelTol, "V");
  expectRel(t.Cn, 1.38945, kO9RelTol, "Cn");
  expectRel(t.dNc, 0.0313196, kO9RelTol, "dNc");
  expectRel(t.vdot2, 9.44460, kO9RelTol, "vdot2");
  expectRel(t.dNa, 9.08677e-4, kO9RelTol, "dNa");
  expectRel(t.dTs, 5.25423e-3, kO9RelTol, "dTs");
  expectRel(t.dDcamber, -9.2069e-4, kO9RelTol, "dDcamber");  // 5 digits, rounding 5.4e-6
  expectRel(t.Cd_f, 0.017337, kO9RelTol, "Cd_f");  // 5 digits; actual rounding 1.9e-6
  expectRel(t.dDf, 3.83755e-4, kO9RelTol, "dDf");
  expectRel(t.alpha_le, 12.1027 * kDeg, kO9RelTol, "alpha_LE");
  EXPECT_TRUE(t.attached);
  expectRel(t.Vn_mid, 1.81831, kO9RelTol, "Vn mid");
  expectRel(t.Vhat, 6.28054, kO9RelTol, "Vhat");
  expectRel(t.dN, 0.0322283, kO9RelTol, "dN");
  expectRel(t.dFx, 5.79116e-3, kO9RelTol, "dFx");
  expectRel(t.dMac, -1.12705e-4, kO9RelTol, "dMac");
  expectRel(t.dMa, 2.79614e-5, kO9RelTol, "dMa");
  expectRel(t.dM_le, -9.13167e-4, kO9RelTol, "dM_LE");
  expectRel(t.dP, 0.0463571, kO9RelTol, "dP");
  // M20 (before cos Gamma).
  const double dL = t.dN * std::cos(s.kin.theta) + t.dFx * std::sin(s.kin.theta);
  const double dT = t.dFx * std::cos(s.kin.theta) - t.dN * std::sin(s.kin.theta);
  expectRel(dL, 0.0325538, kO9RelTol, "dL");
  expectRel(dT, 3.52892e-3, kO9RelTol, "dT");
  // SectionLoads carry the same loads with their points of action (M13, M17, M18).
  EXPECT_DOUBLE_EQ(loads.dN_c4_N, t.dNc);
  EXPECT_DOUBLE_EQ(loads.dN_c2_N, t.dNa);
  EXPECT_DOUBLE_EQ(loads.dFx_N, t.dFx);
  EXPECT_DOUBLE_EQ(loads.dM_couple_Nm, t.dMac + t.dMa);
  EXPECT_DOUBLE_EQ(loads.dP_W, t.dP);
  EXPECT_EQ(loads.separation_f, 1.0);
}

TEST(AeroDeLaurier, O9CaseBSeparatedTermByTerm) {
  O9Setup s(3.0, -40.0);
  DeLaurierTerms t;
  const SectionLoads loads = evalDeLaurier1993(s.context, s.geometry, s.kin, &t);
  expectRel(t.k, 0.209440, kO9RelTol, "k");
  expectRel(t.F, 0.893785, kO9RelTol, "F'");
  expectRel(t.G_over_k, -0.773284, kO9RelTol, "G'/k");
  expectRel(t.alpha, 0.422564, kO9RelTol, "alpha");
  expectRel(t.alphadot, -8.30810, kO9RelTol, "alphadot");
  expectRel(t.w0_over_U, 0.0414458, kO9RelTol, "w0/U");
  expectRel(t.alpha_prime, 0.275995, kO9RelTol, "alpha'");
  expectRel(t.Vx, 6.03774, kO9RelTol, "Vx");
  expectRel(t.Vy, 2.48901, kO9RelTol, "Vy");
  expectRel(t.V, 6.53066, kO9RelTol, "V");
  expectRel(t.Cn, 2.72109, kO9RelTol, "Cn");
  expectRel(t.dNc, 0.0653066, kO9RelTol, "dNc (unused)");
  expectRel(t.vdot2, -50.5986, kO9RelTol, "vdot2");
  expectRel(t.dNa, -4.86816e-3, kO9RelTol, "dNa");
  expectRel(t.alpha_le, 24.2457 * kDeg, kO9RelTol, "alpha_LE");
  EXPECT_FALSE(t.attached);
  expectRel(t.Vn_mid, 3.31808, kO9RelTol, "Vn mid");
  expectRel(t.Vhat, 6.88941, kO9RelTol, "Vhat");
  expectRel(t.dN, 0.0252889, kO9RelTol, "dN");
  EXPECT_EQ(t.dFx, 0.0);
  expectRel(t.dM_le, -1.26445e-3, kO9RelTol, "dM_LE");
  expectRel(t.dP, 0.0733264, kO9RelTol, "dP");
  const double dL = t.dN * std::cos(s.kin.theta) + t.dFx * std::sin(s.kin.theta);
  const double dT = t.dFx * std::cos(s.kin.theta) - t.dN * std::sin(s.kin.theta);
  expectRel(dL, 0.0252273, kO9RelTol, "dL");
  expectRel(dT, -1.76407e-3, kO9RelTol, "dT");
  // M16: everything at mid-chord, no couples, no chordwise force.
  EXPECT_EQ(loads.dN_c4_N, 0.0);
  EXPECT_DOUBLE_EQ(loads.dN_c2_N, t.dN);
  EXPECT_EQ(loads.dM_couple_Nm, 0.0);
  EXPECT_EQ(loads.separation_f, 0.0);
}

/// Steady, motionless strip at mean pitch thetabar (O5 settings).
struct SteadySetup {
  AeroParameters params;
  StripContext context;
  StripGeometry geometry;
  SteadySetup() {
    params.model = AeroModelKind::kDeLaurier1993;
    params.zero_lift_angle_rad = 0.0;
    params.suction_efficiency = 1.0;
    params.skin_friction = false;
    context.params = &params;
    context.constants = MstConstants::fromAspectRatio(5.58);
    geometry.chord_m = 0.1;
    geometry.width_m = 0.01;
  }
  /// (C_L, C_D) from M20 for a motionless strip at thetabar.
  std::pair<double, double> coefficients(double thetabar) const {
    PlanarKinematics kin;
    kin.U = 6.0;
    kin.theta = kin.thetabar = kin.theta_a = thetabar;
    const SectionLoads l = evalDeLaurier1993(context, geometry, kin);
    const double dL = l.dN_N() * std::cos(thetabar) + l.dFx_N * std::sin(thetabar);
    const double dT = l.dFx_N * std::cos(thetabar) - l.dN_N() * std::sin(thetabar);
    const double q_c_dy = 0.5 * context.density_kgpm3 * kin.U * kin.U * geometry.chord_m *
                          geometry.width_m;
    return {dL / q_c_dy, -dT / q_c_dy};
  }
};

/// O5 C_L printed with 5 significant digits (rounding <= 6.2e-5 relative at 0.08073): 1e-4.
constexpr double kO5LiftRelTol = 1e-4;
/// O5 C_D printed with 3 significant digits; the brief asks for 1 %.
constexpr double kO5DragRelTol = 1e-2;
/// Lift slope printed with 4 decimals.
constexpr double kLiftSlopeTol = 5e-5;
/// Induced-drag identity at 1 deg: the O(thetabar^2) remainder there is 1.6e-4.
constexpr double kInducedDragRelTolAt1Deg = 5e-4;

TEST(AeroDeLaurier, O5SteadyLimitAndInducedDrag) {
  const SteadySetup s;
  const double thetas_deg[] = {1.0, 3.0, 5.0};
  const double CL_expected[] = {0.08073, 0.24219, 0.40366};
  const double CD_expected[] = {0.000372, 0.003351, 0.009332};
  for (int i = 0; i < 3; ++i) {
    SCOPED_TRACE(thetas_deg[i]);
    const auto [CL, CD] = s.coefficients(thetas_deg[i] * kDeg);
    expectRel(CL, CL_expected[i], kO5LiftRelTol, "C_L");
    expectRel(CD, CD_expected[i], kO5DragRelTol, "C_D");
  }
  // Section 8.3: induced drag is C_L^2/(pi AR) to small-angle order; the higher-order part grows
  // as thetabar^2 (ratio 1.0002 at 1 deg, 1.004 at 5 deg), hence the check at 1 deg only.
  const auto [CL1, CD1] = s.coefficients(1.0 * kDeg);
  expectRel(CD1, CL1 * CL1 / (kPi * 5.58), kInducedDragRelTolAt1Deg, "C_D vs C_L^2/(pi AR)");
}

TEST(AeroDeLaurier, O5LiftSlope) {
  const SteadySetup s;
  const double d_theta = 1e-5;
  const double slope =
      (s.coefficients(d_theta).first - s.coefficients(-d_theta).first) / (2.0 * d_theta);
  EXPECT_NEAR(slope, 4.6254, kLiftSlopeTol);
}

// ---- O6: Garrick pure plunge ------------------------------------------------------------------

/// 2-D flat plate, no friction, full suction, no stall (O6 settings).
struct TwoDPlateSetup {
  AeroParameters params;
  StripContext context;
  StripGeometry geometry;
  TwoDPlateSetup() {
    params.model = AeroModelKind::kDeLaurier1993;
    params.zero_lift_angle_rad = 0.0;
    params.moment_coefficient_ac = 0.0;
    params.suction_efficiency = 1.0;
    params.skin_friction = false;
    params.stall_angle_max_rad = 0.5 * kPi - 1e-9;
    params.stall_angle_min_rad = -(0.5 * kPi - 1e-9);
    context.params = &params;
    context.constants = MstConstants::fromAspectRatio(std::numeric_limits<double>::infinity());
    geometry.chord_m = 0.1;
    geometry.width_m = 0.01;
  }
};

/// Samples per period: the integrand is periodic and smooth, so the trapezoid rule (the plain
/// mean of equispaced samples) converges spectrally; 4000 samples resolve it to round-off.
constexpr int kSamplesPerPeriod = 4000;
/// Issue acceptance for Garrick with F', G' substituted.
constexpr double kGarrickIssueRelTol = 1e-3;
/// Spec O6: the remaining V/U effect is ~1e-5 (1.3e-5 at k = 0.5).
constexpr double kGarrickSpecRelTol = 1e-4;

TEST(AeroGarrick, O6PurePlungeThrustAndPower) {
  const TwoDPlateSetup s;
  const double U = 6.0, c = s.geometry.chord_m, h0 = 0.01 * c;
  const double q_c_dy = 0.5 * s.context.density_kgpm3 * U * U * c * s.geometry.width_m;
  // Exact Garrick (Theodorsen C(k)) table, O6, and the tolerance against it: the Scherer fit
  // differs from C(k) (O1): |C'|^2/|C|^2 = 1.142, 1.040, 0.886 and F'/F = 1.062, 0.997, 0.933 at
  // k = 0.1, 0.2, 0.5. Tolerances sit just above these known fit errors.
  const struct {
    double k, CT_exact, CP_exact, tol_T, tol_P;
  } rows[] = {{0.1, 0.09070, 0.10454, 0.15, 0.07},
              {0.2, 0.28398, 0.36572, 0.06, 0.01},
              {0.5, 1.19456, 1.87847, 0.12, 0.07}};
  for (const auto& r : rows) {
    SCOPED_TRACE(r.k);
    const double omega = 2.0 * r.k * U / c;
    const double period = 2.0 * kPi / omega;
    double thrust_sum = 0.0, power_sum = 0.0;
    for (int i = 0; i < kSamplesPerPeriod; ++i) {
      const double t = period * i / kSamplesPerPeriod;
      PlanarKinematics kin;  // h = -h0 cos(omega t), positive down; theta = theta_a = 0
      kin.U = U;
      kin.omega = omega;
      kin.hdot = h0 * omega * std::sin(omega * t);
      kin.hddot = h0 * omega * omega * std::cos(omega * t);
      const SectionLoads l = evalDeLaurier1993(s.context, s.geometry, kin);
      thrust_sum += l.dFx_N * std::cos(kin.theta) - l.dN_N() * std::sin(kin.theta);  // M20
      power_sum += l.dP_W;
    }
    const double CT = thrust_sum / kSamplesPerPeriod / q_c_dy;
    const double CP = power_sum / kSamplesPerPeriod / (q_c_dy * U);
    const SchererFunction sc = schererFunction(s.context.constants, r.k);
    const double scale = 4.0 * kPi * r.k * r.k * (h0 / c) * (h0 / c);
    const double CT_scherer = scale * (sc.F * sc.F + sc.G * sc.G);
    const double CP_scherer = scale * sc.F;
    EXPECT_NEAR(CT / CT_scherer, 1.0, kGarrickIssueRelTol);
    EXPECT_NEAR(CP / CP_scherer, 1.0, kGarrickIssueRelTol);
    EXPECT_NEAR(CT / CT_scherer, 1.0, kGarrickSpecRelTol);
    EXPECT_NEAR(CP / CP_scherer, 1.0, kGarrickSpecRelTol);
    // Exact Garrick, loosely (Scherer fit error, see above).
    const double h_sq = (h0 / c) * (h0 / c);
    EXPECT_NEAR(CT / h_sq / r.CT_exact, 1.0, r.tol_T);
    EXPECT_NEAR(CP / h_sq / r.CP_exact, 1.0, r.tol_P);
  }
}

// ---- O7: Theodorsen plunge normal force -------------------------------------------------------

/// Amplitude against C_N = pi (h0/b)[-k^2 + 2ik C'(k)] (Scherer C' substituted): 1e-3 relative
/// (the residual is the V/U effect, O(alpha^2) ~ 1e-5 at h0/c = 0.01).
constexpr double kO7AmplitudeRelTol = 1e-3;
constexpr double kO7PhaseTolDeg = 0.1;
/// Against the exact-Theodorsen table: the Scherer fit itself is off by up to 6.8 % in
/// amplitude (k = 0.1 and 0.5) and 4.7 deg in phase (k = 0.2) over k = 0.05..1 (O1 columns).
constexpr double kO7ExactAmplitudeRelTol = 0.08;
constexpr double kO7ExactPhaseTolDeg = 5.0;

TEST(AeroTheodorsen, O7PlungeNormalForceAmplitudeAndPhase) {
  const TwoDPlateSetup s;
  const double U = 6.0, c = s.geometry.chord_m, h0 = 0.01 * c;
  const double q_c_dy = 0.5 * s.context.density_kgpm3 * U * U * c * s.geometry.width_m;
  const struct {
    double k, amp_exact, phase_exact_deg;
  } rows[] = {{0.05, 0.5750, 83.37}, {0.10, 1.0567, 81.64}, {0.20, 1.8421, 83.06},
              {0.50, 3.8084, 99.43}, {1.00, 8.4370, 126.54}};
  for (const auto& r : rows) {
    SCOPED_TRACE(r.k);
    const double omega = 2.0 * r.k * U / c;
    double sin_sum = 0.0, cos_sum = 0.0;
    for (int i = 0; i < kSamplesPerPeriod; ++i) {
      const double phase = 2.0 * kPi * i / kSamplesPerPeriod;
      PlanarKinematics kin;  // h = h0 sin(omega t), positive down
      kin.U = U;
      kin.omega = omega;
      kin.hdot = h0 * omega * std::cos(phase);
      kin.hddot = -h0 * omega * omega * std::sin(phase);
      const double CN = evalDeLaurier1993(s.context, s.geometry, kin).dN_N() / q_c_dy;
      sin_sum += CN * std::sin(phase);
      cos_sum += CN * std::cos(phase);
    }
    // C_N(t) = A sin(omega t + phi): A cos(phi) = sin projection, A sin(phi) = cos projection.
    const double a = 2.0 * sin_sum / kSamplesPerPeriod, b = 2.0 * cos_sum / kSamplesPerPeriod;
    const double amp = std::hypot(a, b) / (h0 / c);
    const double phase_deg = std::atan2(b, a) / kDeg;
    const SchererFunction sc = schererFunction(s.context.constants, r.k);
    const std::complex<double> C_prime(sc.F, sc.G);
    const std::complex<double> CN_expected =
        kPi * 2.0 * (-r.k * r.k + std::complex<double>(0.0, 2.0 * r.k) * C_prime);  // per h0/c
    EXPECT_NEAR(amp / std::abs(CN_expected), 1.0, kO7AmplitudeRelTol);
    EXPECT_NEAR(phase_deg, std::arg(CN_expected) / kDeg, kO7PhaseTolDeg);
    EXPECT_NEAR(amp / r.amp_exact, 1.0, kO7ExactAmplitudeRelTol);
    EXPECT_NEAR(phase_deg, r.phase_exact_deg, kO7ExactPhaseTolDeg);
  }
}

TEST(AeroDeLaurier, ZeroFrequencyKeepsPitchRateLag) {
  // Pitfall 4: omega = 0 with alphadot != 0 must use G'/k = -C1/C2, not 0. Round-off only.
  SteadySetup s;
  PlanarKinematics kin;
  kin.U = 6.0;
  kin.thetadot = 1.0;
  DeLaurierTerms t;
  evalDeLaurier1993(s.context, s.geometry, kin, &t);
  EXPECT_EQ(t.k, 0.0);
  EXPECT_NEAR(t.G_over_k, -s.context.constants.C1 / s.context.constants.C2, kRoundOffAbs);
  const double expected_alpha_prime =
      s.context.constants.jones_factor *
      (t.alpha + s.geometry.chord_m / (2.0 * kin.U) * t.G_over_k * t.alphadot);
  EXPECT_NEAR(t.alpha_prime, expected_alpha_prime, kRoundOffAbs);
}

}  // namespace
}  // namespace orni::aero
