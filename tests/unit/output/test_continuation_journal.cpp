// The continuation journal's records (studies/runner/output/continuation_journal.hpp): a point
// comes back with every number to the bit and its label with its spaces (a resumed run writes the
// same bytes only then), and a torn or inconsistent payload is refused, not half read.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <string>

#include "studies/runner/output/continuation_journal.hpp"

namespace orni::studies {
namespace {

TrimContinuationPoint samplePoint() {
  TrimContinuationPoint p;
  ContinuationPoint& o = p.orbit;
  o.index = 7;
  o.event = "fold";
  o.lambda = 12.345678901234567;
  o.arclength = 0.1 / 3.0;
  o.residual_max = 1e-11;
  o.corrector_iterations = 3;
  o.max_modulus = 0.987654321;
  o.stable = true;
  o.tangent_lambda = -0.25;
  o.step = 0.05;
  o.step_scale = 0.5;
  o.x = {0.1, -0.2};
  o.p = {12.0, 0.3, 1.0 / 7.0};
  o.y = Eigen::VectorXd::LinSpaced(3, -1.0, std::nextafter(1.0, 2.0));
  o.tangent = Eigen::VectorXd::Constant(3, 1.0 / 3.0);
  o.grid_origin = Eigen::VectorXd::Constant(3, 2.0);
  o.multipliers.resize(2);
  o.multipliers << std::complex<double>(0.9, 0.1), std::complex<double>(0.9, -0.1);
  p.solution.theta_rad = 0.16;
  p.solution.speed_mps = 10.8;
  p.solution.tail_angle_rad = 0.2068;
  p.solution.freq_hz = 12.0;
  p.cg_shift_m = -1e-3;
  p.mean.FV_N = 2.5;
  p.mean.altitude_p2p_m = 0.004;
  p.friction_speed_mps = 10.79;
  p.leading_label = "phugoid-like | slow";
  return p;
}

TEST(ContinuationJournal, PointComesBackToTheBit) {
  const TrimContinuationPoint p = samplePoint();
  TrimContinuationPoint q;
  ASSERT_TRUE(decodeContinuationPoint(encodeContinuationPoint(p), &q));
  EXPECT_EQ(q.orbit.event, "fold");
  EXPECT_EQ(q.orbit.index, 7);
  EXPECT_EQ(q.orbit.corrector_iterations, 3);
  EXPECT_TRUE(q.orbit.stable);
  EXPECT_EQ(q.orbit.lambda, p.orbit.lambda);
  EXPECT_EQ(q.orbit.arclength, p.orbit.arclength);
  EXPECT_EQ(q.orbit.p, p.orbit.p);
  EXPECT_EQ(q.orbit.y, p.orbit.y);
  EXPECT_EQ(q.orbit.multipliers, p.orbit.multipliers);
  EXPECT_EQ(q.solution.tail_angle_rad, p.solution.tail_angle_rad);
  EXPECT_EQ(q.cg_shift_m, p.cg_shift_m);
  EXPECT_EQ(q.mean.altitude_p2p_m, p.mean.altitude_p2p_m);
  EXPECT_EQ(q.leading_label, "phugoid-like | slow");
  // Encoding the decoded point gives the same text: a resumed run's point is the journal's.
  EXPECT_EQ(encodeContinuationPoint(q), encodeContinuationPoint(p));

  TrimContinuationPoint regular = p;
  regular.orbit.event.clear();
  ASSERT_TRUE(decodeContinuationPoint(encodeContinuationPoint(regular), &q));
  EXPECT_TRUE(q.orbit.event.empty());
}

TEST(ContinuationJournal, TornOrInconsistentPayloadIsRefused) {
  const std::string text = encodeContinuationPoint(samplePoint());
  TrimContinuationPoint q;
  EXPECT_FALSE(decodeContinuationPoint(text.substr(0, text.size() / 2), &q));
  EXPECT_FALSE(decodeContinuationPoint(text.substr(0, text.find(" |")), &q));  // no label
  EXPECT_FALSE(decodeContinuationPoint("", &q));
  TrimContinuationPoint p = samplePoint();
  p.orbit.tangent = Eigen::VectorXd::Zero(2);  // not one per unknown
  EXPECT_FALSE(decodeContinuationPoint(encodeContinuationPoint(p), &q));
  p = samplePoint();
  p.orbit.multipliers.resize(p.orbit.multipliers.size() + 1);  // more than one per state
  p.orbit.multipliers.setConstant(0.5);
  EXPECT_FALSE(decodeContinuationPoint(encodeContinuationPoint(p), &q));
  p.orbit.multipliers.resize(0);  // none
  EXPECT_FALSE(decodeContinuationPoint(encodeContinuationPoint(p), &q));
}

// The leading multipliers (Arnoldi, trim.periodic.multipliers > 0) are fewer than the states.
TEST(ContinuationJournal, PointWithTheLeadingMultipliersComesBack) {
  TrimContinuationPoint p = samplePoint();
  ASSERT_GE(p.orbit.x.size(), 2u);
  p.orbit.multipliers.resize(1);
  p.orbit.multipliers << std::complex<double>(0.98, 0.04);
  TrimContinuationPoint q;
  ASSERT_TRUE(decodeContinuationPoint(encodeContinuationPoint(p), &q));
  EXPECT_EQ(q.orbit.multipliers, p.orbit.multipliers);
  EXPECT_FALSE(q.orbit.multipliers_complete);
  EXPECT_EQ(encodeContinuationPoint(q), encodeContinuationPoint(p));
  ASSERT_TRUE(decodeContinuationPoint(encodeContinuationPoint(samplePoint()), &q));
  EXPECT_TRUE(q.orbit.multipliers_complete);
}

}  // namespace
}  // namespace orni::studies
