// Continuation of the magpie's trimmed flight over the flapping frequency
// (trim/trim_continuation.hpp):
//   - the start point is the periodic trim at 12 Hz, and its multipliers are that trim's full
//     Floquet analysis;
//   - the branch's last point, landed exactly on 12.6 Hz, agrees with a periodic trim solved
//     there directly (both freeze the skin friction at an orbit's airspeed in two passes; measured
//     below);
//   - every point is an orbit (residual within the tolerance), in order along the parameter;
//   - the Jacobian columns on two threads (each on a copy of the period map) give the same
//     branch to the last bit as on one.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "core/model/frames.hpp"
#include "tests/support/magpie_vehicle.hpp"
#include "trim/periodic_trim.hpp"
#include "trim/trim_continuation.hpp"

namespace orni {
namespace {

constexpr double kStartHz = 12.0;
constexpr double kEndHz = 12.6;

VehicleModel magpie() { return testing::magpieVehicle(); }

TrimOptions periodicAt(const VehicleModel& /*v*/, double f_hz) {
  TrimOptions o = defaultTrimOptions(testing::magpieDesignPoint());
  o.initial.freq_hz = f_hz;
  usePeriodicMethod(&o);
  o.verify_free_flight = false;
  return o;
}

class TrimContinuationEfw : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    model_ = new FlightCoreModel(magpie());
    TrimContinuationOptions co;
    co.parameter = PeriodicControl::kFrequency;
    co.to = kEndHz;
    co.step = 0.2;
    co.max_points = 10;
    branch_ = new TrimContinuationSummary(
        continueTrim(*model_, periodicAt(model_->vehicle, kStartHz), co));
  }
  static void TearDownTestSuite() {
    delete branch_;
    delete model_;
  }
  static FlightCoreModel* model_;
  static TrimContinuationSummary* branch_;
};
FlightCoreModel* TrimContinuationEfw::model_ = nullptr;
TrimContinuationSummary* TrimContinuationEfw::branch_ = nullptr;

TEST_F(TrimContinuationEfw, FollowsTheBranchToTheEndOfTheRange) {
  const TrimContinuationSummary& b = *branch_;
  ASSERT_EQ(b.status, ContinuationStatus::kCompleted) << b.message;
  ASSERT_GE(b.points.size(), 3u);
  EXPECT_DOUBLE_EQ(b.points.front().solution.freq_hz, kStartHz);
  EXPECT_NEAR(b.points.back().solution.freq_hz, kEndHz, 1e-12);
  double previous = 0.0;
  for (const TrimContinuationPoint& p : b.points) {
    EXPECT_LE(p.orbit.residual_max, 1e-8) << p.solution.freq_hz;
    EXPECT_GT(p.solution.freq_hz, previous);  // no fold between 12 and 12.6 Hz
    previous = p.solution.freq_hz;
    // trim.periodic.multipliers' default 8 (a conjugate pair kept whole: 8 or 9) by Arnoldi.
    EXPECT_GE(p.orbit.multipliers.size(), 8);
    EXPECT_LE(p.orbit.multipliers.size(), 9);
    EXPECT_FALSE(p.leading_label.empty());
  }
}

TEST_F(TrimContinuationEfw, TwoJacobianThreadsGiveTheSameBits) {
  const TrimContinuationSummary& one = *branch_;
  TrimContinuationOptions co;
  co.parameter = PeriodicControl::kFrequency;
  co.to = kEndHz;
  co.step = 0.2;
  co.max_points = 10;
  co.threads = 2;
  const TrimContinuationSummary two =
      continueTrim(*model_, periodicAt(model_->vehicle, kStartHz), co);
  ASSERT_EQ(two.status, one.status) << two.message;
  EXPECT_EQ(two.period_maps, one.period_maps);
  ASSERT_EQ(two.points.size(), one.points.size());
  for (std::size_t i = 0; i < one.points.size(); ++i) {
    const ContinuationPoint& a = one.points[i].orbit;
    const ContinuationPoint& b = two.points[i].orbit;
    EXPECT_EQ(a.x, b.x) << i;  // exact: the same columns, whichever thread took them
    EXPECT_EQ(a.p, b.p) << i;
    EXPECT_EQ(a.tangent, b.tangent) << i;
    ASSERT_EQ(a.multipliers.size(), b.multipliers.size());
    for (Eigen::Index k = 0; k < a.multipliers.size(); ++k)
      EXPECT_EQ(a.multipliers[k], b.multipliers[k]) << i << " " << k;
    EXPECT_EQ(one.points[i].mean.power_aero_W, two.points[i].mean.power_aero_W) << i;
  }
}

TEST_F(TrimContinuationEfw, StartIsThePeriodicTrimWithItsFullFloquetAnalysis) {
  const TrimContinuationSummary& b = *branch_;
  ASSERT_FALSE(b.points.empty());
  TrimOptions o = periodicAt(model_->vehicle, kStartHz);
  o.periodic.multipliers = 0;  // all of them
  const PeriodicTrimSummary direct = solvePeriodicTrim(*model_, o);
  ASSERT_TRUE(direct.converged && direct.floquet_valid) << direct.message;
  const TrimContinuationPoint& start = b.points.front();
  // The same orbit, up to one more friction pass (the branch moves the friction to the trim
  // orbit's own airspeed and corrects again; the trim stopped after its second pass) and a grid
  // chosen again at the orbit: measured 9e-6 rad (0.0005 deg); bound 2e-5 rad.
  EXPECT_NEAR(start.solution.tail_angle_rad, direct.solution.tail_angle_rad, 2e-5);
  // Leading multipliers: the continuation's monodromy (forward differences at the point) against
  // the trim's (its Jacobian at the solution): both difference the same map, 1e-5.
  for (int k = 0; k < 4; ++k)
    EXPECT_NEAR(std::abs(start.orbit.multipliers[k]), direct.floquet.multipliers[k].modulus, 1e-5)
        << k;
  EXPECT_EQ(start.leading_label, direct.floquet.multipliers.front().label);
}

TEST_F(TrimContinuationEfw, EndAgreesWithAPeriodicTrimSolvedThereUpToTheFrozenFriction) {
  const TrimContinuationSummary& b = *branch_;
  ASSERT_EQ(b.status, ContinuationStatus::kCompleted) << b.message;
  const PeriodicTrimSummary direct = solvePeriodicTrim(*model_, periodicAt(model_->vehicle, kEndHz));
  ASSERT_TRUE(direct.converged) << direct.message;
  const TrimContinuationPoint& end = b.points.back();
  // Both freeze the friction at an orbit's mean airspeed in two passes (the branch: the previous
  // point's, then the point's own; the trim: the Eq. (4) speed, then its first orbit's): they
  // differ by what a third pass would change. Measured at 12.6 Hz: 0.00025 deg, 0.0005 m/s,
  // 0.0005 deg; bounds 0.002 deg, 0.001 m/s, 0.002 deg (1/50 of the trim regression's).
  EXPECT_NEAR(end.solution.theta_rad * kRadToDeg, direct.solution.theta_rad * kRadToDeg, 0.002);
  EXPECT_NEAR(end.solution.speed_mps, direct.solution.speed_mps, 0.001);
  EXPECT_NEAR(end.solution.tail_angle_rad * kRadToDeg, direct.solution.tail_angle_rad * kRadToDeg,
              0.002);
  std::printf("12.6 Hz: branch theta %.5f U %.5f tail %.5f; direct %.5f %.5f %.5f (friction %.3f "
              "vs %.3f m/s)\n",
              end.solution.theta_rad * kRadToDeg, end.solution.speed_mps,
              end.solution.tail_angle_rad * kRadToDeg, direct.solution.theta_rad * kRadToDeg,
              direct.solution.speed_mps, direct.solution.tail_angle_rad * kRadToDeg,
              end.friction_speed_mps, direct.friction_speed_mps);
}

// The default route (the leading multipliers by Arnoldi, the tangent by GMRES from a Jacobian
// that differences the body's columns only) against the full Jacobian at every point
// (trim.periodic.multipliers = 0): the same start orbit, so the same tangent and leading
// multipliers up to the differences' error, and the same end point up to the corrector's
// tolerance, for well under half the period maps.
TEST_F(TrimContinuationEfw, LeadingRouteAgreesWithTheFullJacobian) {
  const TrimContinuationSummary& leading = *branch_;
  ASSERT_EQ(leading.status, ContinuationStatus::kCompleted) << leading.message;
  TrimOptions o = periodicAt(model_->vehicle, kStartHz);
  o.periodic.multipliers = 0;
  TrimContinuationOptions co;
  co.parameter = PeriodicControl::kFrequency;
  co.to = kEndHz;
  co.step = 0.2;
  co.max_points = 10;
  const TrimContinuationSummary full = continueTrim(*model_, o, co);
  ASSERT_EQ(full.status, ContinuationStatus::kCompleted) << full.message;
  const ContinuationPoint& a = leading.points.front().orbit;
  const ContinuationPoint& b = full.points.front().orbit;
  ASSERT_EQ(a.x, b.x);  // the same start solve
  EXPECT_FALSE(a.multipliers_complete);
  EXPECT_TRUE(b.multipliers_complete);
  EXPECT_EQ(b.multipliers.size(), static_cast<Eigen::Index>(b.x.size()));
  // Tangents: both from forward differences (step 1e-7) of the same map; GMRES stops at
  // |DH t| <= 1e-7, which the phugoid's multiplier 0.985 (DH's smallest singular value ~0.015)
  // amplifies to ~7e-6. Measured 4.4e-6; bound 2e-5.
  const double tangent_gap = (a.tangent - b.tangent).norm();
  EXPECT_LT(tangent_gap, 2e-5);
  double mu_gap = 0.0;
  for (Eigen::Index k = 0; k < 6; ++k)
    mu_gap = std::max(mu_gap, std::abs(a.multipliers[k] - b.multipliers[k]));
  // Arnoldi's Ritz residual tolerance is 1e-6 (scaled states); bound 1e-5 as the start's test.
  EXPECT_LT(mu_gap, 1e-5);
  EXPECT_EQ(leading.points.front().leading_label, full.points.front().leading_label);
  const TrimContinuationPoint& ea = leading.points.back();
  const TrimContinuationPoint& eb = full.points.back();
  EXPECT_NEAR(ea.solution.theta_rad * kRadToDeg, eb.solution.theta_rad * kRadToDeg, 1e-4);
  EXPECT_NEAR(ea.solution.speed_mps, eb.solution.speed_mps, 1e-4);
  EXPECT_NEAR(ea.solution.tail_angle_rad * kRadToDeg, eb.solution.tail_angle_rad * kRadToDeg,
              1e-4);
  EXPECT_NEAR(ea.orbit.max_modulus, eb.orbit.max_modulus, 1e-5);
  EXPECT_LT(2 * leading.period_maps, full.period_maps);
  std::printf("leading route: %zu points, %ld maps; full Jacobian: %zu points, %ld maps; start "
              "tangent gap %.2e, leading multipliers gap %.2e; end theta %.6f / %.6f deg, U %.6f "
              "/ %.6f m/s\n",
              leading.points.size(), leading.period_maps, full.points.size(), full.period_maps,
              tangent_gap, mu_gap, ea.solution.theta_rad * kRadToDeg,
              eb.solution.theta_rad * kRadToDeg, ea.solution.speed_mps, eb.solution.speed_mps);
}

TEST(TrimContinuationOptionsCheck, ParameterMustDifferFromTheControl) {
  const FlightCoreModel model(magpie());
  TrimContinuationOptions co;
  co.parameter = PeriodicControl::kTailAngle;  // the default control
  EXPECT_THROW(continueTrim(model, periodicAt(model.vehicle, kStartHz), co),
               std::invalid_argument);
  co.parameter = PeriodicControl::kFrequency;
  co.step = 0.0;
  std::string why;
  EXPECT_FALSE(co.IsValid(&why));
}

}  // namespace
}  // namespace orni
