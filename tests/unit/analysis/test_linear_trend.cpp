// The streamed least-squares trend (core/analysis/linear_trend.hpp): bit-identical to the two-pass
// formula while it keeps the values, the same slope to rounding once it folds them into running
// sums (long runs), in bounded memory.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "core/analysis/linear_trend.hpp"

namespace orni {
namespace {

TEST(AnalysisLinearTrend, ExactWhileKeptAndTheSameSlopeOnceFolded) {
  std::mt19937 rng(14);
  std::normal_distribution<double> noise(0.0, 0.3);
  std::vector<double> y;
  LinearTrend trend;
  EXPECT_EQ(trend.slope(), 0.0);
  const std::size_t n = 3 * LinearTrend::kExactValues + 17;
  for (std::size_t i = 0; i < n; ++i) {
    y.push_back(2.5 - 1.25e-3 * static_cast<double>(i) + noise(rng));
    trend.add(y.back());
    if (i + 1 == LinearTrend::kExactValues) {
      EXPECT_EQ(trend.slope(), leastSquaresSlope(y));  // bit for bit
    }
  }
  EXPECT_EQ(trend.count(), n);
  const double exact = leastSquaresSlope(y);
  EXPECT_NEAR(trend.slope(), exact, 1e-12 * std::abs(exact));
  EXPECT_NEAR(exact, -1.25e-3, 1e-4);
}

TEST(AnalysisLinearTrend, FewValues) {
  LinearTrend t;
  t.add(1.0);
  EXPECT_EQ(t.slope(), 0.0);
  t.add(3.0);
  EXPECT_EQ(t.slope(), 2.0);
}

}  // namespace
}  // namespace orni
