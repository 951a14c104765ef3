// Pseudo-arclength continuation of periodic orbits (core/analysis/periodic_continuation.hpp)
// through a fold of a small forced problem with analytic orbits and multipliers:
//
//   x' = a(t) (p - x^2),   y' = -y + cos(2 pi t / T),   a(t) = 1 + 0.5 sin(2 pi t / T),  T = 1.
//
// a > 0, so x' has the sign of p - x^2 and the periodic orbits in x are exactly the equilibria
// x = +-sqrt(p) (p > 0): one branch folding at p = 0, x = 0. Multipliers: exp(-2 x T) (the
// integral of a over a period is T) and exp(-T) (the y equation); the upper branch is stable, the
// lower one has a multiplier above 1, and one passes +1 at the fold. A fixed-step RK4 (400 steps)
// keeps the equilibria exactly (every stage vanishes there), so the discrete map folds at p = 0.
#include <gtest/gtest.h>

#include <Eigen/Core>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "core/analysis/periodic_continuation.hpp"

namespace orni {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kFoldTol = 1e-6;        // the tolerance on the fold's parameter
// Forward differences (step 1e-7) of a smooth RK4 map: relative to max(1, |mu|) (on the lower
// branch the multiplier reaches exp(2 sqrt(1.5)) = 11.6; its difference error is 5e-7 of that).
constexpr double kMultiplierTol = 1e-6;

class FoldMap final : public PeriodMap {
 public:
  /// y' gains + coupling p: the y orbit then moves along the branch (y0 + coupling p), which the
  /// leading-multiplier route's partial Jacobian (y's column taken as decayed) gets wrong.
  double coupling = 0.0;
  int stateCount() const override { return 2; }
  int parameterCount() const override { return 1; }
  int conditionCount() const override { return 0; }
  double stateScale(int) const override { return 1.0; }
  double parameterScale(int) const override { return 1.0; }
  double conditionScale(int) const override { return 1.0; }
  double period_s(const double*) const override { return 1.0; }
  bool flow(const double* x, const double* p, double* x_T, double*, std::string*) override {
    constexpr int kSteps = 400;
    const double h = 1.0 / kSteps;
    double u = x[0], v = x[1];
    auto f = [&](double t, double uu, double vv, double* du, double* dv) {
      *du = (1.0 + 0.5 * std::sin(2.0 * kPi * t)) * (p[0] - uu * uu);
      *dv = -vv + std::cos(2.0 * kPi * t) + coupling * p[0];
    };
    for (int k = 0; k < kSteps; ++k) {
      const double t = k * h;
      double k1u, k1v, k2u, k2v, k3u, k3v, k4u, k4v;
      f(t, u, v, &k1u, &k1v);
      f(t + 0.5 * h, u + 0.5 * h * k1u, v + 0.5 * h * k1v, &k2u, &k2v);
      f(t + 0.5 * h, u + 0.5 * h * k2u, v + 0.5 * h * k2v, &k3u, &k3v);
      f(t + h, u + h * k3u, v + h * k3v, &k4u, &k4v);
      u += h / 6.0 * (k1u + 2.0 * k2u + 2.0 * k3u + k4u);
      v += h / 6.0 * (k1v + 2.0 * k2v + 2.0 * k3v + k4v);
    }
    x_T[0] = u;
    x_T[1] = v;
    return true;
  }
};

/// y(0) of the periodic solution of y' = -y + cos(w t): (cos + w sin) / (1 + w^2) at t = 0.
double periodicY0() { return 1.0 / (1.0 + 4.0 * kPi * kPi); }

ContinuationOptions foldOptions() {
  ContinuationOptions o;
  o.parameter = 0;
  o.lambda_min = -1.0;
  o.lambda_max = 1.5;
  o.direction = -1;
  o.initial_step = 0.1;
  o.max_step = 0.3;
  o.max_points = 80;
  o.residual_tol = 1e-11;
  return o;
}

ContinuationSummary foldBranch(FoldMap& map, const ContinuationCallback& cb = {},
                               const ContinuationPoint* resume = nullptr,
                               const ContinuationOptions& options = foldOptions()) {
  ShootingOptions so;  // no free parameters, no conditions
  return continuePeriodicOrbits(map, {1.0, periodicY0() + map.coupling * 1.0}, {1.0}, so, options,
                                cb, {}, resume);
}

// The leading-multiplier route (only x's column differenced, y's taken as decayed): its partial
// Jacobian's null vector is wrong in y by the factor 1 - exp(-1), GMRES makes it exact.
ContinuationOptions leadingOptions() {
  ContinuationOptions o = foldOptions();
  o.leading_multipliers = 1;
  o.slow_states = {0};
  o.max_krylov = 4;
  // The chord matrix of the corrector is the partial Jacobian (Broyden-updated), which converges
  // more slowly than the full one: let the steps grow up to 6 iterations, as trim_continuation does.
  o.target_iterations = 6;
  return o;
}
constexpr double kCoupling = 0.5;

/// The index of the fifth regular point (the start counts), where the resume tests pick up.
std::size_t fifthRegularPoint(const ContinuationSummary& s) {
  std::size_t at = 0;
  for (int regular = 0; at < s.points.size(); ++at)
    if (s.points[at].event.empty() && ++regular == 5) break;
  return at;
}

TEST(PeriodicContinuation, FollowsTheBranchThroughTheFoldAndLocatesIt) {
  FoldMap map;
  const ContinuationSummary s = foldBranch(map);
  ASSERT_EQ(s.status, ContinuationStatus::kCompleted) << s.message;
  ASSERT_GE(s.points.size(), 10u);
  // It went down the upper branch, turned at the fold and left the range at p = 1.5 on the lower.
  EXPECT_EQ(s.points.front().lambda, 1.0);
  EXPECT_NEAR(s.points.back().lambda, 1.5, 1e-12);
  EXPECT_NEAR(s.points.back().x[0], -std::sqrt(1.5), 1e-9);

  int folds = 0;
  for (const ContinuationPoint& pt : s.points) {
    // Every point lies on x^2 = p, y = y0, with the analytic multipliers.
    ASSERT_NEAR(pt.x[0] * pt.x[0], pt.lambda, 1e-9) << pt.index;
    ASSERT_NEAR(pt.x[1], periodicY0(), 1e-9);
    const double mu_x = std::exp(-2.0 * pt.x[0]), mu_y = std::exp(-1.0);
    ASSERT_EQ(pt.multipliers.size(), 2);
    const double m0 = std::abs(pt.multipliers[0]), m1 = std::abs(pt.multipliers[1]);
    const double big = std::max(mu_x, mu_y), small = std::min(mu_x, mu_y);
    EXPECT_NEAR(std::max(m0, m1), big, kMultiplierTol * std::max(1.0, big)) << pt.lambda;
    EXPECT_NEAR(std::min(m0, m1), small, kMultiplierTol * std::max(1.0, small)) << pt.lambda;
    if (pt.event.empty()) {
      EXPECT_EQ(pt.stable, pt.x[0] > 0.0) << pt.lambda;
    }
    if (pt.event == "fold") {
      ++folds;
      EXPECT_NEAR(pt.lambda, 0.0, kFoldTol);
      EXPECT_NEAR(pt.max_modulus, 1.0, 2e-3);  // |mu| = exp(-2x), x ~ sqrt(1e-6)
    } else {
      EXPECT_TRUE(pt.event.empty()) << pt.event << " at " << pt.lambda;
    }
  }
  EXPECT_EQ(folds, 1);
  EXPECT_EQ(s.events, 1);
}

TEST(PeriodicContinuation, ResumedFromARecordedPointGivesTheSamePoints) {
  FoldMap map;
  const ContinuationSummary full = foldBranch(map);
  ASSERT_EQ(full.status, ContinuationStatus::kCompleted) << full.message;
  // Resume after the fourth regular point, in a fresh map.
  const std::size_t at = fifthRegularPoint(full);
  ASSERT_LT(at + 3, full.points.size());
  FoldMap fresh;
  const ContinuationSummary resumed = foldBranch(fresh, {}, &full.points[at]);
  ASSERT_EQ(resumed.status, ContinuationStatus::kCompleted) << resumed.message;
  ASSERT_EQ(resumed.points.size(), full.points.size() - at - 1);
  for (std::size_t k = 0; k < resumed.points.size(); ++k) {
    const ContinuationPoint& a = full.points[at + 1 + k];
    const ContinuationPoint& b = resumed.points[k];
    EXPECT_EQ(a.event, b.event);
    EXPECT_EQ(a.index, b.index);
    EXPECT_EQ(a.lambda, b.lambda) << k;  // bit for bit
    EXPECT_EQ(a.x, b.x) << k;
    EXPECT_EQ(a.arclength, b.arclength) << k;
  }
}

TEST(PeriodicContinuation, LeadingMultiplierRouteFindsTheExactTangentAndTheFold) {
  FoldMap map;
  map.coupling = kCoupling;
  const ContinuationSummary s = foldBranch(map, {}, nullptr, leadingOptions());
  ASSERT_EQ(s.status, ContinuationStatus::kCompleted) << s.message;
  ASSERT_GE(s.points.size(), 10u);
  EXPECT_NEAR(s.points.back().x[0], -std::sqrt(1.5), 1e-9);
  int folds = 0;
  double worst_tangent = 0.0;
  for (const ContinuationPoint& pt : s.points) {
    ASSERT_NEAR(pt.x[0] * pt.x[0], pt.lambda, 1e-9) << pt.index;
    ASSERT_NEAR(pt.x[1], periodicY0() + kCoupling * pt.lambda, 1e-9);
    // The branch (x, y, p) = (x, y0 + c x^2, x^2): tangent along (1, 2 c x, 2 x).
    Eigen::Vector3d exact(1.0, 2.0 * kCoupling * pt.x[0], 2.0 * pt.x[0]);
    exact.normalize();
    ASSERT_EQ(pt.tangent.size(), 3);
    const double error = std::min((pt.tangent - exact).norm(), (pt.tangent + exact).norm());
    worst_tangent = std::max(worst_tangent, error);
    // 1e-6: the tangent's GMRES tolerance (1e-7 on |DH t|) over the smallest singular value of
    // DH away from the fold, plus the forward differences' 1e-7.
    EXPECT_LT(error, 1e-6) << pt.lambda;
    const double mu_x = std::exp(-2.0 * pt.x[0]), mu_y = std::exp(-1.0);
    EXPECT_NEAR(pt.max_modulus, std::max(mu_x, mu_y), kMultiplierTol * std::max(1.0, mu_x));
    if (pt.event == "fold") {
      ++folds;
      EXPECT_NEAR(pt.lambda, 0.0, kFoldTol);
    } else {
      EXPECT_TRUE(pt.event.empty()) << pt.event << " at " << pt.lambda;
    }
  }
  EXPECT_EQ(folds, 1);
  std::printf("leading-multiplier route: %zu points, %ld period maps, worst tangent error %.2e\n",
              s.points.size(), s.period_maps, worst_tangent);

  // The test can fail: the partial Jacobian's own null vector (y's column -1 instead of
  // exp(-1) - 1, so t_y = (1 - exp(-1)) c t_p instead of c t_p) is off by 0.15 at the start.
  const double x0 = 1.0;
  Eigen::Vector3d partial(1.0, (1.0 - std::exp(-1.0)) * kCoupling * 2.0 * x0, 2.0 * x0);
  Eigen::Vector3d exact0(1.0, 2.0 * kCoupling * x0, 2.0 * x0);
  EXPECT_GT((partial.normalized() - exact0.normalized()).norm(), 0.1);
}

TEST(PeriodicContinuation, LeadingMultiplierRouteResumesBitForBit) {
  FoldMap map;
  map.coupling = kCoupling;
  const ContinuationSummary full = foldBranch(map, {}, nullptr, leadingOptions());
  ASSERT_EQ(full.status, ContinuationStatus::kCompleted) << full.message;
  const std::size_t at = fifthRegularPoint(full);
  ASSERT_LT(at + 3, full.points.size());
  FoldMap fresh;
  fresh.coupling = kCoupling;
  const ContinuationSummary resumed = foldBranch(fresh, {}, &full.points[at], leadingOptions());
  ASSERT_EQ(resumed.status, ContinuationStatus::kCompleted) << resumed.message;
  ASSERT_EQ(resumed.points.size(), full.points.size() - at - 1);
  for (std::size_t k = 0; k < resumed.points.size(); ++k) {
    const ContinuationPoint& a = full.points[at + 1 + k];
    const ContinuationPoint& b = resumed.points[k];
    EXPECT_EQ(a.event, b.event);
    EXPECT_EQ(a.lambda, b.lambda) << k;  // bit for bit
    EXPECT_EQ(a.x, b.x) << k;
    EXPECT_EQ(a.tangent, b.tangent) << k;
  }
}

TEST(PeriodicContinuation, CallbackStopsTheRunAndBadOptionsThrow) {
  FoldMap map;
  int seen = 0;
  const ContinuationSummary s = foldBranch(map, [&](const ContinuationPoint&) {
    return ++seen < 3;
  });
  EXPECT_EQ(s.status, ContinuationStatus::kInterrupted);
  EXPECT_EQ(seen, 3);
  ContinuationOptions bad = foldOptions();
  bad.lambda_max = bad.lambda_min;
  std::string why;
  EXPECT_FALSE(bad.IsValid(&why));
  ShootingOptions so;
  EXPECT_THROW(continuePeriodicOrbits(map, {1.0, 0.0}, {1.0}, so, bad), std::invalid_argument);
  ContinuationOptions krylov = foldOptions();
  krylov.leading_multipliers = 4;
  krylov.max_krylov = 4;  // must exceed the multipliers wanted
  EXPECT_FALSE(krylov.IsValid(&why));
  krylov.max_krylov = 5;
  EXPECT_TRUE(krylov.IsValid(&why)) << why;
  krylov.tangent_tol = 0.0;
  EXPECT_FALSE(krylov.IsValid(&why));
  ContinuationOptions outside = foldOptions();
  outside.lambda_max = 0.5;  // the start p = 1 outside
  EXPECT_THROW(continuePeriodicOrbits(map, {1.0, 0.0}, {1.0}, so, outside),
               std::invalid_argument);
}

}  // namespace
}  // namespace orni
