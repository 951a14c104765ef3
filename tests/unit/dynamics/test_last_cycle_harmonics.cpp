// lastCycleHarmonics (core/dynamics/last_cycle_harmonics.hpp) on loads built from known
// trigonometric series: the amplitudes of the harmonics (exact for a band-limited signal sampled
// over one period: the discrete projection has no aliasing below N/2), the peak phase, the half
// ranges; only the last cycle counts (the cycles before carry other amplitudes); too short a
// history gives nothing.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/dynamics/last_cycle_harmonics.hpp"

namespace orni {
namespace {

constexpr double kTwoPi = 6.283185307179586;
constexpr double kProjectionTol = 1e-12;  // round-off of a 64-point projection of O(1) values

/// Three cycles of `spc` samples plus the end point; the last cycle has the amplitudes given, the
/// earlier ones five times them.
std::vector<LoadSample> loads(std::size_t spc) {
  std::vector<LoadSample> out;
  for (std::size_t k = 0; k <= 3 * spc; ++k) {
    const double w = kTwoPi * static_cast<double>(k) / static_cast<double>(spc);
    const double gain = k < 2 * spc ? 5.0 : 1.0;
    LoadSample s;
    s.FV_N = 1.0 + gain * (2.0 * std::cos(w + 0.3) + 0.5 * std::cos(2.0 * w - 1.0));
    s.FH_N = -0.2 + gain * (0.7 * std::sin(w) + 0.1 * std::cos(2.0 * w));
    s.M_Nm = gain * 0.04 * std::cos(w - 2.0);
    s.tip_deflection_m = gain * 0.01 * std::sin(w);
    s.tip_twist_rad = gain * 0.05 * std::cos(w);
    out.push_back(s);
  }
  return out;
}

TEST(LastCycleHarmonics, AmplitudesOfAKnownSeries) {
  const std::size_t spc = 64;
  const auto h = lastCycleHarmonics(loads(spc), spc);
  ASSERT_TRUE(h.has_value());
  EXPECT_NEAR(h->FV_1f.amplitude, 2.0, kProjectionTol);
  EXPECT_NEAR(h->FV_2f.amplitude, 0.5, kProjectionTol);
  EXPECT_NEAR(h->FH_1f.amplitude, 0.7, kProjectionTol);
  EXPECT_NEAR(h->FH_2f.amplitude, 0.1, kProjectionTol);
  EXPECT_NEAR(h->M_1f.amplitude, 0.04, kProjectionTol);
  // FH = 0.7 sin(w) + 0.1 cos(2w) peaks at w = pi/2 (FH' = cos(w) (0.7 - 0.4 sin(w))): sample
  // 16 of 64. FV's peak phase: its largest sample of the last cycle.
  EXPECT_DOUBLE_EQ(h->FH_peak_phase, 16.0 / 64.0);
  std::size_t best = 0;
  const std::vector<LoadSample> l = loads(spc);
  for (std::size_t i = 1; i < spc; ++i)
    if (l[2 * spc + i].FV_N > l[2 * spc + best].FV_N) best = i;
  EXPECT_DOUBLE_EQ(h->FV_peak_phase, static_cast<double>(best) / spc);
  EXPECT_NEAR(h->tip_deflection_amplitude_m, 0.01, kProjectionTol);
  EXPECT_NEAR(h->tip_twist_amplitude_rad, 0.05, kProjectionTol);
}

TEST(LastCycleHarmonics, NeedsAWholeCycle) {
  const std::size_t spc = 16;
  std::vector<LoadSample> l = loads(spc);
  l.resize(spc);  // one sample short of a cycle
  EXPECT_FALSE(lastCycleHarmonics(l, spc).has_value());
  l.resize(spc + 1);
  EXPECT_TRUE(lastCycleHarmonics(l, spc).has_value());
  EXPECT_FALSE(lastCycleHarmonics(l, 0).has_value());
}

}  // namespace
}  // namespace orni
