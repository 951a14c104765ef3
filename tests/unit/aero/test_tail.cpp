// Horizontal tail, seed paper Eq. (3) with the incidence of docs/theory.md section 7, and the
// trim-point numbers of O11.
#include <cmath>

#include <gtest/gtest.h>

#include "core/aero/tail.hpp"

namespace orni::aero {
namespace {

constexpr double kPi = 3.14159265358979323846;
/// Identities evaluated in double precision on O(1) values: a few ulps.
constexpr double kRoundOffAbs = 1e-14;
constexpr double kDeg = kPi / 180.0;
/// Hand-computed values below are evaluated in double precision: round-off only.
constexpr double kRoundOffRelTol = 1e-12;
/// O11 numbers are printed with 3-4 significant digits (L_T = -0.0727: rounding 5e-4 relative).
constexpr double kO11RelTol = 1e-3;

TailModel paperTail() {
  TailModel t;
  t.present = true;
  t.area_m2 = 0.007;
  t.aspect_ratio = 2.0;
  t.zero_lift_drag_coefficient = 0.02;
  t.oswald_efficiency = 0.9;
  t.arm_m = 0.15;
  return t;
}

TEST(AeroTail, HandComputedCase) {
  TailModel tail = paperTail();
  tail.aspect_ratio = 3.0;
  TailFlow flow;
  flow.theta_body_rad = 0.20;
  flow.flight_path_rad = 0.05;
  flow.pitch_rate_radps = 0.0;
  flow.airspeed_mps = 8.0;
  flow.tail_angle_rad = 0.10;
  const TailLoads l = evalTail(tail, 1.2, flow);
  const double alpha = 0.20 - 0.05 - 0.10;                       // 0.05 rad
  const double CL = 3.0 / 5.0 * 2.0 * kPi * alpha;                // 0.188496
  const double CD = 0.02 + CL * CL / (kPi * 0.9 * 3.0);           // 0.024189
  const double q_S = 0.5 * 1.2 * 64.0 * 0.007;                    // 0.2688 N
  EXPECT_NEAR(l.alpha_rad, alpha, kRoundOffRelTol);
  EXPECT_NEAR(l.CL, CL, kRoundOffRelTol * CL);
  EXPECT_NEAR(l.CL, 0.1884956, 1e-7);
  EXPECT_NEAR(l.CD, CD, kRoundOffRelTol * CD);
  EXPECT_NEAR(l.lift_N, CL * q_S, kRoundOffRelTol * CL * q_S);
  EXPECT_NEAR(l.drag_N, CD * q_S, kRoundOffRelTol * CD * q_S);
}

TEST(AeroTail, O11PaperTrimPoint) {
  // theta 9.2 deg, delta_T 11.85 deg, AR_T 2, S_T 0.007 m^2, U 10.8 m/s, rho 1.225:
  // C_L,T = pi (theta - delta_T) = -0.1453, q = 71.44 Pa, L_T = -0.0727 N.
  const TailModel tail = paperTail();
  TailFlow flow;
  flow.theta_body_rad = 9.2 * kDeg;
  flow.tail_angle_rad = 11.85 * kDeg;
  flow.airspeed_mps = 10.8;
  const TailLoads l = evalTail(tail, 1.225, flow);
  EXPECT_NEAR(l.CL, kPi * (9.2 - 11.85) * kDeg, kRoundOffRelTol);
  EXPECT_NEAR(l.CL / -0.1453, 1.0, kO11RelTol);
  EXPECT_NEAR(l.lift_N / -0.0727, 1.0, kO11RelTol);
  EXPECT_NEAR(l.lift_N / l.CL / tail.area_m2 / 71.44, 1.0, kO11RelTol);  // q
  // Tail drag = C_D,T q S_T = 0.500 N x C_D,T (O11).
  EXPECT_NEAR(l.drag_N / l.CD / 0.500, 1.0, kO11RelTol);
}

TEST(AeroTail, PitchRateAndDownwashShiftIncidence) {
  const TailModel tail = paperTail();
  TailFlow flow;
  flow.theta_body_rad = 0.1;
  flow.airspeed_mps = 10.0;
  const TailLoads base = evalTail(tail, 1.225, flow);
  TailFlow pitching = flow;
  pitching.pitch_rate_radps = 2.0;  // nose-up: the tail moves down, incidence + Q l_T/V
  const TailLoads with_q = evalTail(tail, 1.225, pitching);
  EXPECT_NEAR(with_q.alpha_rad - base.alpha_rad, 2.0 * tail.arm_m / 10.0, kRoundOffAbs);
  EXPECT_NEAR(with_q.CL - base.CL, 0.5 * 2.0 * kPi * 0.03, kRoundOffAbs);
  TailFlow downwash = flow;
  downwash.wing_downwash_rad = 0.02;
  EXPECT_NEAR(evalTail(tail, 1.225, downwash).alpha_rad - base.alpha_rad, -0.02, kRoundOffAbs);
  TailFlow climbing = flow;
  climbing.flight_path_rad = 0.04;
  EXPECT_NEAR(evalTail(tail, 1.225, climbing).alpha_rad - base.alpha_rad, -0.04, kRoundOffAbs);
  TailFlow elevated = flow;
  elevated.tail_angle_rad = 0.03;  // positive delta_T reduces the incidence (paper sign)
  EXPECT_NEAR(evalTail(tail, 1.225, elevated).alpha_rad - base.alpha_rad, -0.03, kRoundOffAbs);
  // Zero airspeed: finite (the Q l_T/V term uses a floored speed), zero loads.
  TailFlow at_rest = pitching;
  at_rest.airspeed_mps = 0.0;
  const TailLoads rest = evalTail(tail, 1.225, at_rest);
  EXPECT_TRUE(std::isfinite(rest.alpha_rad));
  EXPECT_EQ(rest.lift_N, 0.0);
  EXPECT_EQ(rest.drag_N, 0.0);
}

}  // namespace
}  // namespace orni::aero
