// The slowest motion of a sequence sampled once a period (core/analysis/slow_multipliers.hpp)
// against sequences whose multipliers and limits are known exactly: a decaying and a growing
// oscillation (a complex pair), two real modes, a second quantity of the same motion; what it
// refuses (too few values, a constant) and how a sequence with a third mode or noise shows in the
// relative residual.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <random>
#include <vector>

#include "core/analysis/slow_multipliers.hpp"

namespace orni {
namespace {

// y_k = c + A rho^k cos(k phi + psi): the pair rho e^(+-i phi), the limit c.
std::vector<double> pair(double c, double A, double rho, double phi, double psi, int n) {
  std::vector<double> y;
  for (int k = 0; k < n; ++k) y.push_back(c + A * std::pow(rho, k) * std::cos(k * phi + psi));
  return y;
}

// Exact data: the fit recovers the pair and the limit to rounding (1e-9 leaves room for the
// conditioning of 3 unknowns from a few hundred values).
constexpr double kExact = 1e-9;

TEST(AnalysisSlowMultipliers, DecayingPairAndItsLimit) {
  // The magpie's phugoid, per flapping cycle: |mu| 0.9764 at 5.75 deg (a 5.2 s period at 12 Hz),
  // theta heading for -0.368 deg from 8 deg away.
  const double rho = 0.9764, phi = 5.75 * 3.14159265358979 / 180.0;
  const std::vector<double> y = pair(-0.0064, 0.14, rho, phi, 0.3, 200);
  const SlowMultiplierFit f = fitSlowMultipliers(y);
  ASSERT_TRUE(f.ok);
  EXPECT_NEAR(f.modulus, rho, kExact);
  EXPECT_NEAR(std::arg(f.mu[0]), phi, kExact);
  EXPECT_NEAR(f.mu[1].real(), f.mu[0].real(), kExact);
  EXPECT_NEAR(f.mu[1].imag(), -f.mu[0].imag(), kExact);
  EXPECT_NEAR(f.limit, -0.0064, kExact);
  EXPECT_LT(f.relative_residual, kExact);
  // Another quantity of the same motion (other amplitude, phase and limit): its limit from the
  // same recursion.
  const std::vector<double> z = pair(11.138, 0.9, rho, phi, 2.1, 200);
  EXPECT_NEAR(settledValue(f, z), 11.138, 1e-8);
}

TEST(AnalysisSlowMultipliers, GrowingPairIsOutsideTheUnitCircle) {
  const std::vector<double> y = pair(0.01, 1e-3, 1.0089, 0.07, 0.0, 300);
  const SlowMultiplierFit f = fitSlowMultipliers(y);
  ASSERT_TRUE(f.ok);
  EXPECT_NEAR(f.modulus, 1.0089, kExact);
  EXPECT_NEAR(std::arg(f.mu[0]), 0.07, kExact);
  EXPECT_NEAR(f.limit, 0.01, 1e-8);
}

TEST(AnalysisSlowMultipliers, TwoRealModes) {
  std::vector<double> y;
  for (int k = 0; k < 100; ++k) y.push_back(2.0 + 0.5 * std::pow(0.95, k) - 0.2 * std::pow(0.6, k));
  const SlowMultiplierFit f = fitSlowMultipliers(y);
  ASSERT_TRUE(f.ok);
  EXPECT_NEAR(f.mu[0].real(), 0.95, kExact);
  EXPECT_NEAR(f.mu[1].real(), 0.6, kExact);
  EXPECT_EQ(f.mu[0].imag(), 0.0);
  EXPECT_NEAR(f.limit, 2.0, kExact);
}

TEST(AnalysisSlowMultipliers, RefusesTooFewValuesAndAConstant) {
  EXPECT_FALSE(fitSlowMultipliers(pair(1.0, 0.1, 0.9, 0.2, 0.0, 7)).ok);
  EXPECT_TRUE(fitSlowMultipliers(pair(1.0, 0.1, 0.9, 0.2, 0.0, 8)).ok);
  EXPECT_FALSE(fitSlowMultipliers(std::vector<double>(50, 3.0)).ok);
  EXPECT_TRUE(std::isnan(settledValue(SlowMultiplierFit{}, {1.0, 2.0, 3.0})));
}

// What the residual says: a third mode of comparable size or noise alone fit badly (the free-
// flight settling test uses a fit only below 0.01, free_flight_trim.cpp).
TEST(AnalysisSlowMultipliers, AThirdModeOrNoiseShowsInTheResidual) {
  std::vector<double> y = pair(0.0, 1.0, 0.97, 0.1, 0.0, 200);
  for (int k = 0; k < 200; ++k) y[static_cast<std::size_t>(k)] += 0.5 * std::pow(-0.9, k);
  EXPECT_GT(fitSlowMultipliers(y).relative_residual, 0.01);
  std::mt19937 rng(7);
  std::normal_distribution<double> noise(0.0, 1e-6);
  std::vector<double> n;
  for (int k = 0; k < 200; ++k) n.push_back(-0.0064 + noise(rng));
  const SlowMultiplierFit f = fitSlowMultipliers(n);
  ASSERT_TRUE(f.ok);
  EXPECT_GT(f.relative_residual, 0.5);
}

}  // namespace
}  // namespace orni
