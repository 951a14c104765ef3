// MST-TD (docs/theory.md section 5.7-5.9): state-space equivalence O4, agreement with DeLaurier's
// MST for small harmonic motion, smooth separation, separated limit, reversed flow, zero speed,
// load resolution and power.
#include <cmath>
#include <limits>
#include <random>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "core/aero/mst_strip.hpp"

namespace orni::aero {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDeg = kPi / 180.0;
/// Identities evaluated in double precision on O(1e-3..10) values: a few ulps of the largest term.
constexpr double kRoundOffAbs = 1e-12;
/// The same, relative.
constexpr double kRoundOffRel = 1e-12;
/// An angle step far below any stall width (hard-switch edge test).
constexpr double kTinyAngle = 1e-12;
/// Values printed with 4 decimals (O2/O4): half a unit of the last digit.
constexpr double kFourDecimalTol = 5e-5;
/// Values printed with 3 decimals (section 9.3, 0.368): half a unit of the last digit.
constexpr double kThreeDecimalTol = 5e-4;
/// Mean lift of a zero-incidence plunge: zero by symmetry up to round-off of O(1e-2 N) samples.
constexpr double kZeroMeanLiftN = 1e-9;

/// Planar DeLaurier kinematics -> 3-D section kinematics (docs/theory.md 5.1). Frame: X forward
/// (upstream), Y, Z up; wind tunnel, v_air = -U X; reference point P at x_P aft of the LE. The
/// plunge (positive down) is normal to the flapping axis, which is at theta_a above U.
SectionKinematics toSection(const PlanarKinematics& p, double x_P) {
  SectionKinematics s;
  const double ct = std::cos(p.theta), st = std::sin(p.theta);
  s.e_c = Vec3(ct, 0.0, st);
  s.n = Vec3(-st, 0.0, ct);
  const Vec3 a_pitch = s.e_c.cross(s.n);
  s.w_s = p.thetadot * a_pitch;
  s.wdot_s = p.thetaddot * a_pitch;
  const Vec3 plunge_down(std::sin(p.theta_a), 0.0, -std::cos(p.theta_a));
  const Vec3 r_LE_P = -x_P * s.e_c;
  s.v_P = p.hdot * plunge_down + s.w_s.cross(r_LE_P);
  s.a_P = p.hddot * plunge_down + s.wdot_s.cross(r_LE_P) + s.w_s.cross(s.w_s.cross(r_LE_P));
  s.v_air = Vec3(-p.U, 0.0, 0.0);
  s.flight_speed_mps = p.U;
  return s;
}

/// MST-TD parameters with DeLaurier's hard switch and no separation lag.
AeroParameters hardSwitchParams() {
  AeroParameters p;
  p.model = AeroModelKind::kMstTd;
  p.lag = CirculationLag::kScherer1;
  p.zero_lift_angle_rad = 0.0;
  p.moment_coefficient_ac = 0.0;
  p.suction_efficiency = 0.98;
  p.skin_friction = false;
  p.stall_width_rad = 0.0;
  p.separation_lag_tf0 = 0.0;
  return p;
}

StripContext makeContext(const AeroParameters* params, double aspect_ratio) {
  StripContext ctx;
  ctx.params = params;
  ctx.constants = MstConstants::fromAspectRatio(aspect_ratio);
  return ctx;
}

bool allFinite(const SectionLoads& l) {
  return std::isfinite(l.dN_c4_N) && std::isfinite(l.dN_c2_N) && std::isfinite(l.dFx_N) &&
         std::isfinite(l.dM_couple_Nm) && std::isfinite(l.dP_W) && std::isfinite(l.alpha_eff_rad) &&
         std::isfinite(l.alpha_le_rad) && std::isfinite(l.separation_f);
}

// ---- O4 ---------------------------------------------------------------------------------------

/// O4: pass if below 1e-6 relative to the amplitude 0.3 (the spec's own run gave 3e-13).
constexpr double kO4RelTol = 1e-6;

TEST(AeroMstTd, O4StateSpaceEqualsDeLaurierOperator) {
  const MstConstants k = MstConstants::fromAspectRatio(5.58);
  const double c = 0.0968, U = 6.0, omega = 2.0 * kPi * 4.0, amplitude = 0.3;
  const double sdot = 2.0 * U / c;  // faithful variant: V_r = U
  const double k_red = omega * c / (2.0 * U);
  EXPECT_NEAR(k_red, 0.2027, kFourDecimalTol);
  const SchererFunction sc = schererFunction(k, k_red);
  auto alpha34 = [&](double t) { return amplitude * std::sin(omega * t); };
  auto dzdt = [&](double t, double z) { return sdot * k.C2 * (alpha34(t) - z); };  // 9.3 A
  const double dt = 1e-5;
  const double period = 2.0 * kPi / omega;
  const int steps_per_cycle = static_cast<int>(std::lround(period / dt));
  double z = alpha34(0.0), t = 0.0, max_error = 0.0;
  for (int i = 0; i < 6 * steps_per_cycle; ++i) {
    if (i >= 5 * steps_per_cycle) {  // after 5 cycles
      const double alpha_E = (1.0 - k.C1) * alpha34(t) + k.C1 * z;
      const double alphadot = amplitude * omega * std::cos(omega * t);
      const double delaurier = sc.F * alpha34(t) + c / (2.0 * U) * sc.G_over_k * alphadot;  // M5
      max_error = std::max(max_error, std::fabs(alpha_E - delaurier));
    }
    const double k1 = dzdt(t, z);
    const double k2 = dzdt(t + 0.5 * dt, z + 0.5 * dt * k1);
    const double k3 = dzdt(t + 0.5 * dt, z + 0.5 * dt * k2);
    const double k4 = dzdt(t + dt, z + dt * k3);
    z += dt / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
    t = (i + 1) * dt;
  }
  EXPECT_LT(max_error, kO4RelTol * amplitude) << "max |alpha_E - DeLaurier| = " << max_error;
}

// ---- (a) cycle means vs DeLaurier ---------------------------------------------------------------

struct CycleMeans {
  double lift_N = 0, thrust_N = 0, power_W = 0;
};

/// Harmonic plunge h = -h0 cos(omega t) (down +), constant pitch theta = thetabar, theta_a = 0.
PlanarKinematics plunge(double t, double U, double omega, double h0, double thetabar) {
  PlanarKinematics p;
  p.U = U;
  p.omega = omega;
  p.theta = p.thetabar = thetabar;
  p.theta_a = 0.0;
  p.hdot = h0 * omega * std::sin(omega * t);
  p.hddot = h0 * omega * omega * std::cos(omega * t);
  return p;
}

/// Cycle means of DeLaurier (M20 lift/thrust, M19 power) and of MST-TD (states integrated by RK4
/// to the periodic steady state; lift = F.Z, thrust = F.X; power converted to M19's by adding
/// U*thrust, since MST-TD's dP is taken relative to the air).
void cycleMeans(const AeroParameters& params, double thetabar, CycleMeans* delaurier,
                CycleMeans* td) {
  const double U = 6.0, c = 0.1, k_red = 0.2, h0 = 0.01 * c, x_P = 0.25 * c;
  const double omega = 2.0 * k_red * U / c;
  const double period = 2.0 * kPi / omega;
  const int n = 2000;
  const double dt = period / n;
  AeroParameters dl_params = params;
  dl_params.model = AeroModelKind::kDeLaurier1993;
  const StripContext ctx = makeContext(&params, 5.58);
  const StripContext dl_ctx = makeContext(&dl_params, 5.58);
  StripGeometry g;
  g.chord_m = c;
  g.width_m = 0.01;
  g.ref_aft_of_le_m = x_P;
  StripGeometry g_le = g;
  g_le.ref_aft_of_le_m = 0.0;

  double y[2];
  initialMstTdStates(ctx, g, toSection(plunge(0.0, U, omega, h0, thetabar), x_P), y);
  auto rhs = [&](double t, const double* s, double* ds) {
    evalMstTd(ctx, g, toSection(plunge(t, U, omega, h0, thetabar), x_P), s, ds);
  };
  const int spin_up_cycles = 10;  // z relaxes with c/(2 U C2) = 26 ms; 10 periods = 100 of them
  *delaurier = CycleMeans();
  *td = CycleMeans();
  for (int i = 0; i < (spin_up_cycles + 1) * n; ++i) {
    const double t = i * dt;
    if (i >= spin_up_cycles * n) {
      const PlanarKinematics p = plunge(t, U, omega, h0, thetabar);
      const SectionLoads dl = evalDeLaurier1993(dl_ctx, g_le, p);
      delaurier->lift_N += dl.dN_N() * std::cos(p.theta) + dl.dFx_N * std::sin(p.theta);
      delaurier->thrust_N += dl.dFx_N * std::cos(p.theta) - dl.dN_N() * std::sin(p.theta);
      delaurier->power_W += dl.dP_W;
      const SectionKinematics s = toSection(p, x_P);
      const SectionLoads l = evalMstTd(ctx, g, s, y, nullptr);
      Vec3 F, M;
      resolveSectionLoads(l, g, s.e_c, s.n, &F, &M);
      td->lift_N += F.z();
      td->thrust_N += F.x();
      td->power_W += l.dP_W + U * F.x();
    }
    double k1[2], k2[2], k3[2], k4[2], tmp[2];
    rhs(t, y, k1);
    for (int j = 0; j < 2; ++j) tmp[j] = y[j] + 0.5 * dt * k1[j];
    rhs(t + 0.5 * dt, tmp, k2);
    for (int j = 0; j < 2; ++j) tmp[j] = y[j] + 0.5 * dt * k2[j];
    rhs(t + 0.5 * dt, tmp, k3);
    for (int j = 0; j < 2; ++j) tmp[j] = y[j] + dt * k3[j];
    rhs(t + dt, tmp, k4);
    for (int j = 0; j < 2; ++j) y[j] += dt / 6.0 * (k1[j] + 2.0 * k2[j] + 2.0 * k3[j] + k4[j]);
  }
  for (CycleMeans* m : {delaurier, td}) {
    m->lift_N /= n;
    m->thrust_N /= n;
    m->power_W /= n;
  }
}

/// Small-amplitude plunge (h0/c = 0.01, k = 0.2) at zero mean incidence: the models differ only
/// by O(alpha^2) ~ (omega h0/U)^2 = 1.6e-5 relative (q_ref = rho V_r^2/2 vs rho U V/2, resultant
/// vs linear angle, sdot = 2 V_r/c vs 2U/c).
constexpr double kTdVsDeLaurierRelTol = 1e-3;

TEST(AeroMstTd, CycleMeansMatchDeLaurierSmallPlunge) {
  const AeroParameters params = hardSwitchParams();
  CycleMeans dl, td;
  cycleMeans(params, 0.0, &dl, &td);
  ASSERT_GT(dl.thrust_N, 0.0);
  EXPECT_NEAR(td.thrust_N / dl.thrust_N, 1.0, kTdVsDeLaurierRelTol);
  EXPECT_NEAR(td.power_W / dl.power_W, 1.0, kTdVsDeLaurierRelTol);
  EXPECT_NEAR(td.lift_N, 0.0, kZeroMeanLiftN);
  EXPECT_NEAR(dl.lift_N, 0.0, kZeroMeanLiftN);
}

TEST(AeroMstTd, CycleMeanLiftAtIncidenceMatchesDeLaurierUpToTheBoundedAngle) {
  // With a mean incidence thetabar the mean lift is first order. Both models use the dynamic
  // pressure rho U V/2 of the bound vortex (boundedAttachedFlow), so they differ only where
  // MST-TD's finite-wing angle is J sin(thetabar + alpha0) and DeLaurier's J (thetabar + alpha0):
  // ratio sin(x)/x at x = 5 deg (0.99873), and where the bound vortex's speed V_K/V_r =
  // |(cos x, J sin x)| (camber included in the normal flow) differs from DeLaurier's
  // V/U = |(cos thetabar, alpha'_t)| (M6: camber excluded): 0.99960 here.
  AeroParameters params = hardSwitchParams();
  params.zero_lift_angle_rad = 1.0 * kDeg;
  const double thetabar = 4.0 * kDeg;
  CycleMeans dl, td;
  cycleMeans(params, thetabar, &dl, &td);
  const double x = thetabar + params.zero_lift_angle_rad;
  // Residual: the second-order plunge terms, ~(omega h0/U)^2 and the hdot (1 - cos theta)/U
  // linearisation of M1 (2.4e-3 of a dynamic part that averages out).
  constexpr double kCorrectedLiftRelTol = 1e-4;
  const double J = MstConstants::fromAspectRatio(5.58).jones_factor;
  const double alpha_t = J * x - params.zero_lift_angle_rad;  // DeLaurier's alpha' + thetabar
  const double speed_ratio = std::hypot(std::cos(x), J * std::sin(x)) /
                             std::hypot(std::cos(thetabar), alpha_t);
  EXPECT_NEAR(td.lift_N / dl.lift_N, std::sin(x) / x * speed_ratio, kCorrectedLiftRelTol);
}

// ---- large relative angles (issue 13 item 7) ---------------------------------------------------

// Quasi-steady attached pure plunge (constant hdot, no pitch, lag states at equilibrium, no
// stall): MST-TD's circulatory normal force equals DeLaurier's M7 at every relative angle
// epsilon = atan(hdot/U) (boundedAttachedFlow), and its leading-edge suction is DeLaurier's times
// cos(epsilon) (sin^2 against tan^2 of the angle). Before the bounded form, MST-TD's normal force
// was 2 pi J epsilon rho V_r^2/2: 11 % above DeLaurier at 30 deg.
TEST(AeroMstTd, AttachedForceAgreesWithDeLaurierAtLargeRelativeAngles) {
  AeroParameters params = hardSwitchParams();
  params.stall_angle_max_rad = 1.5;  // attached at every angle of the sweep
  params.stall_angle_min_rad = -1.5;
  AeroParameters dl_params = params;
  dl_params.model = AeroModelKind::kDeLaurier1993;
  const StripContext ctx = makeContext(&params, 5.58);
  const StripContext dl_ctx = makeContext(&dl_params, 5.58);
  StripGeometry g;
  g.chord_m = 0.1;
  g.width_m = 0.01;
  g.ref_aft_of_le_m = 0.0;
  for (double eps_deg = 0.0; eps_deg <= 45.0; eps_deg += 5.0) {
    SCOPED_TRACE(eps_deg);
    const double eps = eps_deg * kDeg;
    PlanarKinematics p;
    p.U = 10.0;
    p.hdot = -p.U * std::tan(eps);  // plunging up: the flow comes from above, alpha > 0
    p.omega = 1e-9;                 // quasi-steady (k -> 0)
    const SectionLoads dl = evalDeLaurier1993(dl_ctx, g, p);
    const SectionKinematics s = toSection(p, 0.0);
    double states[2] = {0.0, 1.0};
    initialMstTdStates(ctx, g, s, states);  // z = alpha_34 (equilibrium), f = 1
    const SectionLoads td = evalMstTd(ctx, g, s, states, nullptr);
    ASSERT_EQ(td.separation_f, 1.0);
    EXPECT_NEAR(td.dN_c4_N, dl.dN_c4_N, kRoundOffRel * std::fabs(dl.dN_c4_N) + kRoundOffAbs);
    EXPECT_NEAR(td.dFx_N, dl.dFx_N * std::cos(eps), kRoundOffRel * std::fabs(dl.dFx_N) + kRoundOffAbs);
    // The criterion: the normal force within 3 % of DeLaurier up to 30 deg (here exact).
    if (eps_deg > 0.0 && eps_deg <= 30.0) {
      EXPECT_NEAR(td.dN_c4_N / dl.dN_c4_N, 1.0, 0.03);
    }
  }
}

// ---- (b) smooth separation ---------------------------------------------------------------------

TEST(AeroMstTd, StaticSeparationIsContinuousAndTendsToHardSwitch) {
  AeroParameters p;
  p.stall_angle_max_rad = 13.0 * kDeg;
  p.stall_angle_min_rad = -9.0 * kDeg;  // asymmetric on purpose
  p.stall_width_rad = 2.0 * kDeg;
  // Continuity: increments bounded by the maximum slope 1/(2 delta_s) times the step.
  const double step = 1e-5;
  const double max_slope = 1.0 / (2.0 * p.stall_width_rad);
  double previous = staticSeparation(p, -1.0), max_jump = 0.0;
  for (double a = -1.0 + step; a <= 1.0; a += step) {
    const double f = staticSeparation(p, a);
    EXPECT_GE(f, 0.0);
    EXPECT_LE(f, 1.0);
    max_jump = std::max(max_jump, std::fabs(f - previous));
    previous = f;
  }
  constexpr double kSlopeBoundSlack = 1e-6;  // the secant never exceeds the maximum slope
  EXPECT_LE(max_jump, max_slope * step * (1.0 + kSlopeBoundSlack));
  EXPECT_NEAR(staticSeparation(p, p.stall_angle_max_rad), 0.5, kRoundOffAbs);
  EXPECT_NEAR(staticSeparation(p, p.stall_angle_min_rad), 0.5, kRoundOffAbs);
  // Hard switch limit: with delta_s -> 0 the smooth function matches M14 away from the limits.
  AeroParameters hard = p;
  hard.stall_width_rad = 0.0;
  AeroParameters narrow = p;
  narrow.stall_width_rad = 1e-4;
  double max_difference = 0.0;
  constexpr double kExclusion = 20.0 * 1e-4;  // 20 widths: tanh(20) = 1 to 1e-17
  for (double a = -1.0; a <= 1.0; a += 1e-3) {
    if (std::fabs(a - p.stall_angle_max_rad) < kExclusion ||
        std::fabs(a - p.stall_angle_min_rad) < kExclusion)
      continue;
    const double difference = std::fabs(staticSeparation(narrow, a) - staticSeparation(hard, a));
    max_difference = std::max(max_difference, difference);
  }
  EXPECT_LT(max_difference, kRoundOffAbs);
  EXPECT_EQ(staticSeparation(hard, p.stall_angle_max_rad), 1.0);
  EXPECT_EQ(staticSeparation(hard, p.stall_angle_max_rad + kTinyAngle), 0.0);
}

TEST(AeroMstTd, SmoothSeparationGivesContinuousLoadsThroughStall) {
  // Sweep the pitch through the stall with T_f0 = 0 (f = f_st): the smooth switch gives small
  // increments, the hard switch one jump of the size of the attached-separated difference.
  AeroParameters smooth = hardSwitchParams();
  smooth.stall_width_rad = 2.0 * kDeg;
  const AeroParameters hard = hardSwitchParams();
  StripGeometry g;
  g.chord_m = 0.1;
  g.width_m = 0.01;
  auto max_increment = [&](const AeroParameters& params) {
    const StripContext ctx = makeContext(&params, 5.58);
    double states[2] = {0.0, 1.0}, previous = 0.0, max_inc = 0.0;
    for (int i = 0; i <= 4000; ++i) {
      PlanarKinematics p;
      p.U = 6.0;
      p.theta = p.thetabar = (10.0 + 20.0 * i / 4000.0) * kDeg;
      const SectionKinematics s = toSection(p, 0.0);
      initialMstTdStates(ctx, g, s, states);
      const double dN = evalMstTd(ctx, g, s, states, nullptr).dN_N();
      if (i > 0) max_inc = std::max(max_inc, std::fabs(dN - previous));
      previous = dN;
    }
    return max_inc;
  };
  const double smooth_inc = max_increment(smooth);
  const double hard_inc = max_increment(hard);
  // 4000 steps over 20 deg, width 2 deg: the smooth increment is ~1/100 of the jump.
  constexpr double kMaxIncrementFraction = 0.05;
  EXPECT_LT(smooth_inc, kMaxIncrementFraction * hard_inc) << smooth_inc << " vs " << hard_inc;
}

// ---- (c) separated limit -----------------------------------------------------------------------

TEST(AeroMstTd, FrozenSeparatedLimitEqualsDeLaurierSeparatedBranch) {
  AeroParameters params = hardSwitchParams();
  params.separation_lag_tf0 = 6.0;  // lag on, so the state f is used as given
  params.zero_lift_angle_rad = 2.0 * kDeg;
  params.moment_coefficient_ac = -0.05;
  params.skin_friction = true;
  params.stall_angle_max_rad = 13.0 * kDeg;
  params.stall_angle_min_rad = -13.0 * kDeg;
  AeroParameters dl_params = params;
  dl_params.model = AeroModelKind::kDeLaurier1993;
  const StripContext ctx = makeContext(&params, 5.58);
  const StripContext dl_ctx = makeContext(&dl_params, 5.58);
  StripGeometry g;
  g.chord_m = 0.1;
  g.width_m = 0.01;
  g.ref_aft_of_le_m = 0.3 * g.chord_m;
  StripGeometry g_le = g;
  g_le.ref_aft_of_le_m = 0.0;
  const double rho = ctx.density_kgpm3, c = g.chord_m, dy = g.width_m;

  for (const double thetadot : {0.0, -2.0}) {
    SCOPED_TRACE(thetadot);
    // O9 case B (separated in DeLaurier's model).
    PlanarKinematics p;
    p.U = 6.0;
    p.theta_a = 5.0 * kDeg;
    p.thetabar = 7.0 * kDeg;
    p.theta = 4.0 * kDeg;
    p.thetadot = thetadot;
    p.thetaddot = 30.0;
    p.hdot = 3.0;
    p.hddot = -40.0;
    p.omega = 2.0 * kPi * 4.0;
    DeLaurierTerms t;
    const SectionLoads dl = evalDeLaurier1993(dl_ctx, g_le, p, &t);
    ASSERT_FALSE(t.attached);
    const SectionKinematics s = toSection(p, g.ref_aft_of_le_m);
    const double states[2] = {0.3, 0.0};  // z arbitrary, f frozen at 0
    const SectionLoads td = evalMstTd(ctx, g, s, states, nullptr);
    // The 3-D vdot2 (2.3) has U thetadot cos(theta) where DeLaurier's linearised M8 has
    // U thetadot: the apparent-mass parts differ by rho pi c^2/4 * U thetadot (cos(theta) - 1).
    const double d_dNa = rho * kPi * c * c * 0.25 * p.U * thetadot * (std::cos(p.theta) - 1.0) * dy;
    const double expected_dN = t.dN + 0.5 * d_dNa;
    EXPECT_EQ(td.separation_f, 0.0);
    EXPECT_EQ(td.dN_c4_N, 0.0);
    EXPECT_NEAR(td.dN_c2_N, expected_dN, kRoundOffRel * std::fabs(expected_dN));
    EXPECT_EQ(td.dFx_N, 0.0);
    EXPECT_EQ(td.dM_couple_Nm, 0.0);
    EXPECT_NEAR(td.momentAboutLe(c), dl.momentAboutLe(c) - 0.5 * c * 0.5 * d_dNa, kRoundOffAbs);
    // Power: MST-TD's dP relative to the air plus U*thrust is M19 with the same dN.
    Vec3 F, M;
    resolveSectionLoads(td, g, s.e_c, s.n, &F, &M);
    const double M19 =
        td.dN_N() * (p.hdot * std::cos(p.theta - p.theta_a) + 0.5 * c * p.thetadot);
    EXPECT_NEAR(td.dP_W + p.U * F.x(), M19, kRoundOffAbs);
    if (thetadot == 0.0) {
      EXPECT_NEAR(td.dP_W + p.U * F.x(), dl.dP_W, kRoundOffAbs);
    }
  }
}

// ---- (d) reversed flow, (e) zero speed -------------------------------------------------------

TEST(AeroMstTd, ReversedFlowGivesFiniteOutputs) {
  AeroParameters params = hardSwitchParams();
  params.stall_width_rad = 2.0 * kDeg;
  params.separation_lag_tf0 = 6.0;
  params.skin_friction = true;
  params.zero_lift_angle_rad = 2.0 * kDeg;
  for (const CirculationLag lag : {CirculationLag::kScherer1, CirculationLag::kJones2}) {
    params.lag = lag;
    const StripContext ctx = makeContext(&params, 5.58);
    StripGeometry g;
    g.chord_m = 0.08;
    g.width_m = 0.01;
    g.ref_aft_of_le_m = 0.02;
    for (const double vn : {-2.0, -1e-9, 0.0, 1e-9, 2.0}) {
      SCOPED_TRACE(vn);
      SectionKinematics s;
      s.v_air = Vec3(4.0, 0.0, 0.0);  // flow from behind: V_t = -4 (e_c = X)
      s.v_P = Vec3(0.0, 0.0, vn);     // n = -Z: q.n = vn
      s.w_s = Vec3(0.0, 3.0, 0.0);
      s.flight_speed_mps = 6.0;
      double states[3] = {0.1, 0.05, 1.0}, d[3];
      const SectionLoads l = evalMstTd(ctx, g, s, states, d);
      EXPECT_TRUE(allFinite(l));
      for (int j = 0; j < statesPerStrip(params); ++j) EXPECT_TRUE(std::isfinite(d[j]));
      EXPECT_LE(std::fabs(l.alpha_eff_rad), 0.5 * kPi);  // clipped lagged angle
    }
  }
  // Friction drags towards the LE in reversed flow (V_t|V_t|), suction is off (pitfall 10).
  params.lag = CirculationLag::kScherer1;
  params.zero_lift_angle_rad = 0.0;
  const StripContext ctx = makeContext(&params, 5.58);
  StripGeometry g;
  g.chord_m = 0.08;
  g.width_m = 0.01;
  SectionKinematics s;
  s.v_air = Vec3(4.0, 0.0, 0.0);
  s.flight_speed_mps = 6.0;
  const double states[2] = {0.0, 1.0};
  const SectionLoads l = evalMstTd(ctx, g, s, states, nullptr);
  const double dDf = frictionCoefficient(6.0 * 0.08 / ctx.kinematic_viscosity_m2ps) * 0.5 *
                     ctx.density_kgpm3 * (-4.0) * 4.0 * 0.08 * 0.01;
  EXPECT_NEAR(l.dFx_N, -dDf, kRoundOffAbs);
  EXPECT_GT(l.dFx_N, 0.0);
}

TEST(AeroMstTd, CachedFrictionCoefficientGivesSameLoads) {
  AeroParameters params = hardSwitchParams();
  params.skin_friction = true;
  const StripContext ctx = makeContext(&params, 5.58);
  StripGeometry g;
  g.chord_m = 0.07;
  g.width_m = 0.01;
  PlanarKinematics p;
  p.U = 7.0;
  p.theta = p.thetabar = 0.1;
  p.hdot = 1.0;
  SectionKinematics s = toSection(p, 0.0);
  const double states[2] = {0.05, 1.0};
  const SectionLoads computed = evalMstTd(ctx, g, s, states, nullptr);
  s.friction_coefficient = frictionCoefficient(7.0 * 0.07 / ctx.kinematic_viscosity_m2ps);
  const SectionLoads cached = evalMstTd(ctx, g, s, states, nullptr);
  EXPECT_EQ(cached.dFx_N, computed.dFx_N);
  EXPECT_EQ(cached.dP_W, computed.dP_W);
  AeroParameters no_friction = params;
  no_friction.skin_friction = false;
  const StripContext ctx_nf = makeContext(&no_friction, 5.58);
  EXPECT_LT(computed.dFx_N, evalMstTd(ctx_nf, g, s, states, nullptr).dFx_N);  // friction drags
}

TEST(AeroMstTd, ZeroSpeedGivesFiniteStateDerivatives) {
  AeroParameters params = hardSwitchParams();
  params.stall_width_rad = 2.0 * kDeg;
  params.separation_lag_tf0 = 6.0;
  params.skin_friction = true;
  for (const CirculationLag lag : {CirculationLag::kScherer1, CirculationLag::kJones2}) {
    params.lag = lag;
    const StripContext ctx = makeContext(&params, 5.58);
    StripGeometry g;
    g.chord_m = 0.05;
    g.width_m = 0.01;
    g.ref_aft_of_le_m = 0.0125;
    for (const double thetadot : {0.0, 5.0}) {
      SectionKinematics s;  // everything at rest (flight speed 0: Re clamped)
      s.w_s = Vec3(0.0, thetadot, 0.0);
      double states[3] = {0.2, -0.1, 0.5}, d[3];
      initialMstTdStates(ctx, g, s, states);
      for (int j = 0; j < statesPerStrip(params); ++j) EXPECT_TRUE(std::isfinite(states[j]));
      states[0] = 0.2;
      const SectionLoads l = evalMstTd(ctx, g, s, states, d);
      EXPECT_TRUE(allFinite(l));
      for (int j = 0; j < statesPerStrip(params); ++j) EXPECT_TRUE(std::isfinite(d[j]));
      // V_r floored at V_min: the lag rate uses sdot = 2 V_min/c.
      if (lag == CirculationLag::kScherer1) {
        const double alpha_34 = std::atan2(thetadot * (0.75 * g.chord_m - g.ref_aft_of_le_m), 0.0);
        EXPECT_NEAR(d[0], 2.0 * params.min_speed_mps / g.chord_m * ctx.constants.C2 *
                              (std::min(alpha_34, 0.5 * kPi) - states[0]),
                    kRoundOffAbs);
      }
    }
  }
}

// ---- (f) load resolution and power -----------------------------------------------------------

/// Random orthonormal section frame (e_c, n), seeded.
void randomFrame(std::mt19937* rng, Vec3* e_c, Vec3* n) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const Vec3 a = Vec3(u(*rng), u(*rng), u(*rng)).normalized();
  Vec3 b = Vec3(u(*rng), u(*rng), u(*rng));
  b = (b - b.dot(a) * a).normalized();
  *e_c = a;
  *n = b;
}

TEST(AeroMstTd, ResolvedMomentTransfersBetweenPoints) {
  std::mt19937 rng(20240607);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int trial = 0; trial < 20; ++trial) {
    Vec3 e_c, n;
    randomFrame(&rng, &e_c, &n);
    SectionLoads l;
    l.dN_c4_N = u(rng);
    l.dN_c2_N = u(rng);
    l.dFx_N = u(rng);
    l.dM_couple_Nm = 0.01 * u(rng);
    StripGeometry g;
    g.chord_m = 0.1;
    g.width_m = 0.01;
    g.ref_aft_of_le_m = 0.04;
    StripGeometry g2 = g;
    g2.ref_aft_of_le_m = 0.09;
    Vec3 F, M_P, F2, M_P2;
    resolveSectionLoads(l, g, e_c, n, &F, &M_P);
    resolveSectionLoads(l, g2, e_c, n, &F2, &M_P2);
    // Points on the chord: r = -x e_c from the LE. M_P' = M_P + (P - P') x F.
    const Vec3 P = -g.ref_aft_of_le_m * e_c, P2 = -g2.ref_aft_of_le_m * e_c;
    EXPECT_LT((F2 - F).norm(), kRoundOffAbs);
    EXPECT_LT((M_P2 - (M_P + (P - P2).cross(F))).norm(), kRoundOffAbs);
    // An arbitrary point off the chord, and the LE moment of M18 along a_pitch.
    const Vec3 Q(u(rng), u(rng), u(rng));
    const Vec3 M_Q = M_P + (P - Q).cross(F);
    const Vec3 M_LE = M_P + P.cross(F);
    EXPECT_NEAR(M_LE.dot(e_c.cross(n)), l.momentAboutLe(g.chord_m), kRoundOffAbs);
    EXPECT_LT((M_LE - l.momentAboutLe(g.chord_m) * e_c.cross(n)).norm(), kRoundOffAbs);
    EXPECT_LT((M_Q - (M_LE + (-Q).cross(F))).norm(), kRoundOffAbs);
    EXPECT_NEAR(F.dot(n), l.dN_N(), kRoundOffAbs);
    EXPECT_NEAR(F.dot(e_c), l.dFx_N, kRoundOffAbs);
  }
}

TEST(AeroMstTd, PowerIsLoadPowerRelativeToAir) {
  // dP_W = -(F.(v_P - v_air) + M_P.w_s) with F, M_P from resolveSectionLoads, general 3-D.
  AeroParameters params = hardSwitchParams();
  params.stall_width_rad = 2.0 * kDeg;
  params.separation_lag_tf0 = 6.0;
  params.zero_lift_angle_rad = 1.5 * kDeg;
  params.moment_coefficient_ac = -0.04;
  params.skin_friction = true;
  const StripContext ctx = makeContext(&params, 5.58);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  StripGeometry g;
  g.chord_m = 0.09;
  g.width_m = 0.012;
  g.ref_aft_of_le_m = 0.03;
  for (int trial = 0; trial < 20; ++trial) {
    SectionKinematics s;
    randomFrame(&rng, &s.e_c, &s.n);
    s.v_air = Vec3(u(rng), u(rng), u(rng));
    s.v_P = 8.0 * s.e_c + 1.5 * Vec3(u(rng), u(rng), u(rng));  // mostly V_t > 0
    s.a_P = 50.0 * Vec3(u(rng), u(rng), u(rng));
    s.w_s = 5.0 * Vec3(u(rng), u(rng), u(rng));
    s.wdot_s = 100.0 * Vec3(u(rng), u(rng), u(rng));
    s.flight_speed_mps = 8.0;
    const double states[2] = {0.1 * u(rng), 0.5 + 0.5 * u(rng)};
    const SectionLoads l = evalMstTd(ctx, g, s, states, nullptr);
    Vec3 F, M_P;
    resolveSectionLoads(l, g, s.e_c, s.n, &F, &M_P);
    const double expected = -(F.dot(s.v_P - s.v_air) + M_P.dot(s.w_s));
    EXPECT_NEAR(l.dP_W, expected, kRoundOffRel * (1.0 + std::fabs(expected)));
  }
}

// ---- states -----------------------------------------------------------------------------------

TEST(AeroMstTd, StatesPerStripAndQuasiSteadyInitialState) {
  AeroParameters params = hardSwitchParams();
  params.stall_width_rad = 2.0 * kDeg;
  params.separation_lag_tf0 = 6.0;
  params.zero_lift_angle_rad = 1.0 * kDeg;
  EXPECT_EQ(statesPerStrip(params), 2);
  params.model = AeroModelKind::kDeLaurier1993;
  EXPECT_EQ(statesPerStrip(params), 0);
  params.model = AeroModelKind::kMstTd;
  StripGeometry g;
  g.chord_m = 0.1;
  g.width_m = 0.01;
  g.ref_aft_of_le_m = 0.025;
  PlanarKinematics p;
  p.U = 6.0;
  p.theta = p.thetabar = 12.0 * kDeg;
  p.theta_a = 3.0 * kDeg;
  p.thetadot = 1.0;
  p.hdot = 0.4;
  const SectionKinematics s = toSection(p, g.ref_aft_of_le_m);
  for (const CirculationLag lag : {CirculationLag::kScherer1, CirculationLag::kJones2}) {
    params.lag = lag;
    EXPECT_EQ(statesPerStrip(params), lag == CirculationLag::kScherer1 ? 2 : 3);
    const StripContext ctx = makeContext(&params, 5.58);
    double states[3], d[3];
    initialMstTdStates(ctx, g, s, states);
    const SectionLoads l = evalMstTd(ctx, g, s, states, d);
    for (int j = 0; j < statesPerStrip(params); ++j) {
      EXPECT_NEAR(d[j], 0.0, kRoundOffAbs);
    }
    // alpha_E = alpha_34 at equilibrium: alpha'_t = [AR/(2+AR)](alpha_34 + alpha0) - alpha0,
    // with Vn_34 and V_t of 2.3 (checked against their planar forms).
    const Vec3 q = s.v_air - s.v_P;
    const double Vn_34 = q.dot(s.n) + p.thetadot * (0.75 * g.chord_m - g.ref_aft_of_le_m);
    const double V_t = -q.dot(s.e_c);
    EXPECT_NEAR(V_t, p.U * std::cos(p.theta) - p.hdot * std::sin(p.theta - p.theta_a),
                kRoundOffAbs);
    EXPECT_NEAR(Vn_34,
                p.U * std::sin(p.theta) + p.hdot * std::cos(p.theta - p.theta_a) +
                    0.75 * g.chord_m * p.thetadot,
                kRoundOffAbs);
    const double alpha0 = params.zero_lift_angle_rad;
    EXPECT_NEAR(l.alpha_eff_rad,
                ctx.constants.jones_factor * (std::atan2(Vn_34, V_t) + alpha0) - alpha0,
                kRoundOffAbs);
    EXPECT_NEAR(l.separation_f, staticSeparation(params, l.alpha_le_rad), kRoundOffAbs);
  }
}

TEST(AeroMstTd, ImpulsiveStartValuesOfTheTwoLags) {
  // 9.3: the circulatory response just after a step in alpha_34 (lag states still 0) is
  // (1 - C1) AR/(2+AR) = 0.476 for option A and 0.5 AR/(2+AR) = 0.368 for option B (AR 5.58).
  AeroParameters params = hardSwitchParams();
  params.stall_angle_max_rad = 1.5;
  StripGeometry g;
  g.chord_m = 0.1;
  g.width_m = 0.01;
  PlanarKinematics p;
  p.U = 6.0;
  p.theta = p.thetabar = 0.1;
  const SectionKinematics s = toSection(p, 0.0);
  const double zeros[3] = {0.0, 0.0, 1.0};
  params.lag = CirculationLag::kScherer1;
  StripContext ctx = makeContext(&params, 5.58);
  EXPECT_NEAR(evalMstTd(ctx, g, s, zeros, nullptr).alpha_eff_rad / 0.1, 0.4762, kFourDecimalTol);
  params.lag = CirculationLag::kJones2;
  ctx = makeContext(&params, 5.58);
  EXPECT_NEAR(evalMstTd(ctx, g, s, zeros, nullptr).alpha_eff_rad / 0.1, 0.368, kThreeDecimalTol);
}

TEST(AeroMstTd, LaggedSeparationRelaxesWithTf) {
  AeroParameters params = hardSwitchParams();
  params.stall_width_rad = 2.0 * kDeg;
  params.separation_lag_tf0 = 6.0;
  const StripContext ctx = makeContext(&params, 5.58);
  StripGeometry g;
  g.chord_m = 0.1;
  g.width_m = 0.01;
  PlanarKinematics p;
  p.U = 6.0;
  p.theta = p.thetabar = 25.0 * kDeg;  // well past stall: f_st ~ 0
  const SectionKinematics s = toSection(p, 0.0);
  double states[2] = {0.0, 0.0}, d[2];
  initialMstTdStates(ctx, g, s, states);
  states[1] = 0.7;
  const SectionLoads l = evalMstTd(ctx, g, s, states, d);
  const double f_st = staticSeparation(params, l.alpha_le_rad);
  const double T_f = 6.0 * g.chord_m / (2.0 * 6.0);  // V_r = U (no motion)
  EXPECT_NEAR(d[1], (f_st - 0.7) / T_f, kRoundOffAbs);
  EXPECT_EQ(l.separation_f, 0.7);
  // T_f0 = 0: f follows f_st, derivative 0.
  params.separation_lag_tf0 = 0.0;
  const SectionLoads l0 = evalMstTd(ctx, g, s, states, d);
  EXPECT_EQ(d[1], 0.0);
  EXPECT_EQ(l0.separation_f, staticSeparation(params, l0.alpha_le_rad));
}

}  // namespace
}  // namespace orni::aero
