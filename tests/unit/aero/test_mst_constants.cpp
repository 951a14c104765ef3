// Finite-wing constants, Scherer's function and the friction coefficient of DeLaurier's MST:
// docs/theory.md 5.2 (M3), M11 and the oracles O1 (last column), O2 and O8.
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "core/aero/mst_strip.hpp"

namespace orni::aero {
namespace {

constexpr double kPi = 3.14159265358979323846;
/// Identities evaluated in double precision on O(1) values: a few ulps.
constexpr double kRoundOffAbs = 1e-14;
/// O1/O2 tables are printed with 4 decimals: half a unit of the last printed digit.
constexpr double kFourDecimalTol = 5e-5;
/// O8 friction table printed with 5 decimals: half a unit of the last printed digit.
constexpr double kFiveDecimalTol = 5e-6;

TEST(AeroMstConstants, O2ConstantsTable) {
  struct Row {
    double AR, C1, C2, factor, slope, high_k, g_over_k0;
  };
  const double inf = std::numeric_limits<double>::infinity();
  const Row rows[] = {
      {2.0, 0.2315, 0.5670, 0.5000, 3.1416, 0.3843, -0.4083},
      {4.0, 0.3165, 0.3740, 0.6667, 4.1888, 0.4557, -0.8461},
      {5.58, 0.3532, 0.3194, 0.7361, 4.6254, 0.4762, -1.1059},
      {6.0, 0.3606, 0.3097, 0.7500, 4.7124, 0.4796, -1.1644},
      {10.0, 0.4058, 0.2582, 0.8333, 5.2360, 0.4951, -1.5718},
      {inf, 0.5000, 0.1810, 1.0000, 6.2832, 0.5000, -2.7624},
  };
  for (const Row& r : rows) {
    SCOPED_TRACE(r.AR);
    const MstConstants k = MstConstants::fromAspectRatio(r.AR);
    EXPECT_NEAR(k.C1, r.C1, kFourDecimalTol);
    EXPECT_NEAR(k.C2, r.C2, kFourDecimalTol);
    EXPECT_NEAR(k.jones_factor, r.factor, kFourDecimalTol);
    EXPECT_NEAR(2.0 * kPi * k.jones_factor, r.slope, kFourDecimalTol);
    EXPECT_NEAR((1.0 - k.C1) * k.jones_factor, r.high_k, kFourDecimalTol);
    const SchererFunction s0 = schererFunction(k, 0.0);
    EXPECT_NEAR(s0.G_over_k, r.g_over_k0, kFourDecimalTol);
    EXPECT_EQ(s0.F, 1.0);
    EXPECT_EQ(s0.G, 0.0);
  }
}

TEST(AeroMstConstants, O2SchererAtAr558) {
  const MstConstants k = MstConstants::fromAspectRatio(5.58);
  const struct {
    double k, F, G;
  } rows[] = {{0.1, 0.9685, -0.1007}, {0.2, 0.9005, -0.1589}, {0.5, 0.7492, -0.1602},
              {1.0, 0.6795, -0.1023}};
  for (const auto& r : rows) {
    SCOPED_TRACE(r.k);
    const SchererFunction s = schererFunction(k, r.k);
    EXPECT_NEAR(s.F, r.F, kFourDecimalTol);
    EXPECT_NEAR(s.G, r.G, kFourDecimalTol);
    EXPECT_NEAR(s.G_over_k * r.k, s.G, kRoundOffAbs);
  }
}

TEST(AeroMstConstants, O1SchererTwoDimensionalColumn) {
  const MstConstants k = MstConstants::fromAspectRatio(std::numeric_limits<double>::infinity());
  const struct {
    double k, F, G;
  } rows[] = {{0.01, 0.9985, -0.0275}, {0.05, 0.9646, -0.1283}, {0.10, 0.8831, -0.2116},
              {0.20, 0.7251, -0.2488}, {0.30, 0.6334, -0.2212}, {0.50, 0.5579, -0.1600},
              {0.80, 0.5243, -0.1076}, {1.00, 0.5159, -0.0876}, {2.00, 0.5041, -0.0449},
              {5.00, 0.5007, -0.0181}, {10.0, 0.5002, -0.0090}};
  for (const auto& r : rows) {
    SCOPED_TRACE(r.k);
    const SchererFunction s = schererFunction(k, r.k);
    EXPECT_NEAR(s.F, r.F, kFourDecimalTol);
    EXPECT_NEAR(s.G, r.G, kFourDecimalTol);
  }
}

TEST(AeroMstConstants, O8FrictionTable) {
  const struct {
    double Re, Cd;
  } rows[] = {{1e4, 0.02489}, {2e4, 0.02064}, {3.87e4, 0.01748}, {5e4, 0.01643},
              {1e5, 0.01400}, {3e5, 0.01106}, {1e6, 0.00874}};
  for (const auto& r : rows) {
    SCOPED_TRACE(r.Re);
    EXPECT_NEAR(frictionCoefficient(r.Re), r.Cd, kFiveDecimalTol);
  }
}

TEST(AeroMstConstants, FrictionClampsReynoldsAt1e3) {
  // Pitfall 11: tip strips with c -> 0 give Re -> 0 and log10(Re) <= 0.
  const double at_clamp = frictionCoefficient(1e3);
  EXPECT_EQ(frictionCoefficient(0.0), at_clamp);
  EXPECT_EQ(frictionCoefficient(1.0), at_clamp);
  EXPECT_EQ(frictionCoefficient(-5.0), at_clamp);
  EXPECT_TRUE(std::isfinite(at_clamp));
  EXPECT_NEAR(at_clamp, 0.89 / std::pow(3.0, 2.58), kRoundOffAbs);
}

}  // namespace
}  // namespace orni::aero
