// The horizon of the Eq. (5) check after a settled free flight (trim/free_flight_check.hpp,
// coveringSlowMotion): raised to cover three periods of the slowest motion the flight measured,
// only for a clean fit of a decaying oscillation, and capped.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "core/analysis/slow_multipliers.hpp"
#include "trim/free_flight_check.hpp"

namespace orni {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Cycle means of a motion y_k = 1 + a r^k cos(2 pi k / period) (period in cycles; period <= 0: a
// real decay a r^k), 120 cycles, plus a deterministic "noise" of the given size.
std::vector<double> motion(double r, double period, double noise = 0.0) {
  std::vector<double> y;
  for (int k = 0; k < 120; ++k) {
    const double shape = period > 0.0 ? std::cos(2.0 * kPi * k / period) : 1.0;
    y.push_back(1.0 + 0.3 * std::pow(r, k) * shape + noise * std::sin(12.9898 * k * k));
  }
  return y;
}

FreeFlightCheckOptions sixtyCycles() {
  FreeFlightCheckOptions o;
  o.cycles = 60;
  o.free.transient_fraction = 0.2;
  return o;
}

TEST(FreeFlightCheckHorizon, CoversThreeSlowPeriodsOfACleanDecayingOscillation) {
  // The calibrated magpie's phugoid at Table 3's point: 0.9896 a cycle, 4.23 s at 12 Hz.
  const SlowMultiplierFit fit = fitSlowMultipliers(motion(0.9896, 50.8));
  ASSERT_TRUE(fit.ok);
  std::string why;
  const FreeFlightCheckOptions o = coveringSlowMotion(sixtyCycles(), fit, &why);
  // 3 periods of 50.8 cycles in the 80 % of the horizon after the transient: 190.5 -> 191.
  EXPECT_EQ(o.cycles, 191);
  EXPECT_NE(why.find("from 60 to 191 cycles"), std::string::npos) << why;
  EXPECT_EQ(o.free.transient_fraction, 0.2);  // the rest of the options kept
}

TEST(FreeFlightCheckHorizon, UnchangedWithoutACleanDecayingOscillation) {
  std::string why;
  // A short oscillation: 3 periods fit in the default window already.
  EXPECT_EQ(coveringSlowMotion(sixtyCycles(), fitSlowMultipliers(motion(0.98, 12.0)), &why).cycles, 60);
  // A real (non-oscillating) decay, a growing oscillation, a fit of noise, no fit at all.
  EXPECT_EQ(coveringSlowMotion(sixtyCycles(), fitSlowMultipliers(motion(0.97, 0.0)), &why).cycles, 60);
  EXPECT_EQ(coveringSlowMotion(sixtyCycles(), fitSlowMultipliers(motion(1.01, 50.8)), &why).cycles, 60);
  const SlowMultiplierFit noisy = fitSlowMultipliers(motion(0.9896, 50.8, 0.05));
  EXPECT_GT(noisy.relative_residual, kCleanSlowFitResidual);
  EXPECT_EQ(coveringSlowMotion(sixtyCycles(), noisy, &why).cycles, 60);
  EXPECT_EQ(coveringSlowMotion(sixtyCycles(), SlowMultiplierFit{}, &why).cycles, 60);
  EXPECT_TRUE(why.empty()) << why;
}

TEST(FreeFlightCheckHorizon, CappedAtTenTimesTheHorizon) {
  std::string why;
  const FreeFlightCheckOptions o =
      coveringSlowMotion(sixtyCycles(), fitSlowMultipliers(motion(0.999, 400.0)), &why);
  EXPECT_EQ(o.cycles, 600);
  EXPECT_NE(why.find("capped"), std::string::npos) << why;
}

}  // namespace
}  // namespace orni
