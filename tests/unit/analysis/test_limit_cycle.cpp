// Limit-cycle metrics and the bounded-norm criterion on synthetic histories with known answers.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/analysis/limit_cycle.hpp"

namespace orni {
namespace {

constexpr double kPi = 3.14159265358979323846;

TEST(AnalysisLimitCycle, SpectrumFindsAmplitudeAndFrequencyOfASinusoid) {
  const double f = 12.0, dt = 1.0 / (f * 50);
  std::vector<double> x;
  for (int i = 0; i < 50 * 24; ++i)
    x.push_back(0.3 + 0.2 * std::sin(2 * kPi * f * i * dt) + 0.05 * std::cos(2 * kPi * 2 * f * i * dt));
  const Spectrum s = amplitudeSpectrum(x.data(), x.size(), dt, 40.0);
  EXPECT_DOUBLE_EQ(dominantFrequency(s), 12.0);
  for (std::size_t k = 0; k < s.freq_hz.size(); ++k) {
    if (std::abs(s.freq_hz[k] - 12.0) < 1e-9) {
      EXPECT_NEAR(s.amplitude[k], 0.2, 1e-12);
    }
    if (std::abs(s.freq_hz[k] - 24.0) < 1e-9) {
      EXPECT_NEAR(s.amplitude[k], 0.05, 1e-12);
    }
  }
}

TEST(AnalysisLimitCycle, AltitudeSplitsIntoFlappingAndSlowOscillations) {
  // h = 1 cm peak-to-peak at 12 Hz + 3 cm peak-to-peak at 0.5 Hz + a climb of 0.1 m/s.
  const double f = 12.0;
  const int spc = 60, cycles = 96;  // 8 s
  std::vector<double> t, d, th, h;
  for (int i = 0; i <= spc * cycles; ++i) {
    const double ti = i / (f * spc);
    t.push_back(ti);
    d.push_back(0.577 * std::sin(2 * kPi * f * ti));
    th.push_back(0.17 + 0.17 * std::sin(2 * kPi * f * ti - 1.0));
    h.push_back(2.0 + 0.005 * std::sin(2 * kPi * f * ti) + 0.015 * std::sin(2 * kPi * 0.5 * ti) +
                0.1 * ti);
  }
  const LimitCycleMetrics m = analyseLimitCycle(t, d, th, h, 0, spc, f);
  EXPECT_NEAR(m.altitude_p2p_fast_m, 0.01, 0.0005);
  // The linear trend fitted over 4 slow periods absorbs part of the sinusoid (least-squares
  // bias of a whole-period sine against t): the estimate is within 0.006 m.
  EXPECT_NEAR(m.altitude_p2p_slow_m, 0.03, 0.006);
  EXPECT_NEAR(m.climb_rate_mps, 0.1, 0.005);
  EXPECT_NEAR(m.theta_min_rad, 0.0, 1e-3);
  EXPECT_NEAR(m.theta_max_rad, 0.34, 1e-3);
  EXPECT_DOUBLE_EQ(m.dominant_freq_theta_hz, 12.0);
  EXPECT_DOUBLE_EQ(m.dominant_freq_delta_hz, 12.0);
}

TEST(AnalysisLimitCycle, BoundedNormJudgesSizeAndDrift) {
  const int spc = 20, cycles = 30;
  std::vector<double> t, small, big, drifting;
  for (int i = 0; i <= spc * cycles; ++i) {
    t.push_back(i * 0.01);
    small.push_back(1.0 + 0.5 * std::sin(0.7 * i));  // +-0.5 of bound 1: bounded
    big.push_back(1.0 + 1.5 * std::sin(0.7 * i));    // exceeds the bound
    drifting.push_back(1.0 + 0.9 * i / double(spc * cycles));  // inside, but a secular trend
  }
  const BoundedNormResult ok = boundedNorm(t, {{&small, 1.0, 1.0, "theta"}}, 0, spc);
  EXPECT_TRUE(ok.bounded) << ok.reason;
  EXPECT_NEAR(ok.norm_ratio_max, 0.5, 1e-3);
  const BoundedNormResult out = boundedNorm(t, {{&big, 1.0, 1.0, "theta"}}, 0, spc);
  EXPECT_FALSE(out.bounded);
  EXPECT_EQ(out.worst_state, "theta");
  const BoundedNormResult dr = boundedNorm(t, {{&drifting, 1.0, 1.0, "h"}}, 0, spc);
  EXPECT_FALSE(dr.bounded);
  EXPECT_TRUE(dr.drift);
  EXPECT_EQ(dr.drift_state, "h");
}

}  // namespace
}  // namespace orni
