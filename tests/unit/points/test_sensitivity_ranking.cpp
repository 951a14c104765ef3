// The effects of a sensitivity study (commands/sensitivity_ranking.hpp) on hand-made rows: deltas
// from the base, swing |high - low|, the ranking by swing (ties in file order, parameters without
// a swing last), shares of the largest swing, and empty cells that stay "no value".
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "studies/runner/points/sensitivity_point.hpp"
#include "studies/runner/points/sensitivity_ranking.hpp"

namespace orni::studies {
namespace {

std::size_t columnOf(const std::string& name) {
  const std::vector<SensitivityColumn>& c = sensitivityResultColumns();
  for (std::size_t i = 0; i < c.size(); ++i)
    if (c[i].name == name) return i;
  ADD_FAILURE() << "no column " << name;
  return 0;
}

/// A row whose theta_mean_deg cell is `theta` ("" = no value) and hinge power `power`.
SweepPointResult row(const std::string& theta, const std::string& power = "1") {
  SweepPointResult r;
  r.status = theta.empty() ? "not_converged" : "ok";
  r.cells.assign(sensitivityResultColumns().size(), std::string());
  r.cells[columnOf("theta_mean_deg")] = theta;
  r.cells[columnOf("hinge_power_W")] = power;
  return r;
}

TEST(CommandsSensitivityRanking, ColumnsHaveThePredictionsOfIssue13) {
  std::vector<std::string> predictions;
  for (const SensitivityColumn& c : sensitivityResultColumns())
    if (c.prediction) predictions.push_back(c.name);
  const std::vector<std::string> expected = {"theta_mean_deg",
                                             "speed_mps",
                                             "tail_angle_deg",
                                             "hinge_power_W",
                                             "pitch_swing_deg",
                                             "altitude_p2p_m",
                                             "altitude_p2p_slow_m",
                                             "norm_ratio_max",
                                             "CF_V_min",
                                             "CF_V_max",
                                             "CF_H_min",
                                             "CF_H_max",
                                             "CM_CG_min",
                                             "CM_CG_max"};
  EXPECT_EQ(predictions, expected);
  // The predictions come first, so a prediction's column index is its rank in the list.
  for (std::size_t i = 0; i < expected.size(); ++i)
    EXPECT_TRUE(sensitivityResultColumns()[i].prediction);
}

TEST(CommandsSensitivityRanking, DeltasSwingsAndRanking) {
  // Base 9; parameter 0: 8 .. 10 (swing 2); parameter 1: 9.5 .. 8.5 (swing 1, falls);
  // parameter 2: 11 .. 7 (swing 4); parameter 3: 10 .. 12 (swing 2, ties with 0: file order);
  // parameter 4: no trim at high (no swing, |delta_low| = 5: after every swing).
  const std::vector<SweepPointResult> rows = {row("9"),   row("8"),  row("10"), row("9.5"),
                                              row("8.5"), row("11"), row("7"),  row("10"),
                                              row("12"),  row("4"),  row("")};
  const std::vector<PredictionRanking> r = rankSensitivity(5, rows);
  ASSERT_EQ(r.size(), 14u);
  const PredictionRanking& theta = r[0];
  EXPECT_EQ(theta.column, columnOf("theta_mean_deg"));
  ASSERT_TRUE(theta.base.has_value());
  EXPECT_EQ(*theta.base, 9.0);
  ASSERT_EQ(theta.ranked.size(), 5u);
  const std::size_t order[] = {2, 0, 3, 1, 4};
  for (std::size_t k = 0; k < 5; ++k) EXPECT_EQ(theta.ranked[k].parameter, order[k]) << k;

  const SensitivityEffect& top = theta.ranked[0];
  EXPECT_EQ(*top.low_value, 11.0);
  EXPECT_EQ(*top.high_value, 7.0);
  EXPECT_EQ(*top.delta_low, 2.0);
  EXPECT_EQ(*top.delta_high, -2.0);
  EXPECT_EQ(*top.swing, 4.0);
  EXPECT_EQ(*top.swing_share, 1.0);
  EXPECT_EQ(*theta.ranked[1].swing_share, 0.5);
  EXPECT_EQ(*theta.ranked[3].delta_low, 0.5);
  EXPECT_EQ(*theta.ranked[3].delta_high, -0.5);

  const SensitivityEffect& missing = theta.ranked[4];
  EXPECT_EQ(*missing.delta_low, -5.0);
  EXPECT_FALSE(missing.high_value.has_value());
  EXPECT_FALSE(missing.delta_high.has_value());
  EXPECT_FALSE(missing.swing.has_value());
  EXPECT_FALSE(missing.swing_share.has_value());

  // Every hinge power is 1 except where the trim failed: no swing is 0, shares are 0.
  const PredictionRanking& power = r[3];
  EXPECT_EQ(power.column, columnOf("hinge_power_W"));
  for (const SensitivityEffect& e : power.ranked) {
    if (!e.swing) continue;
    EXPECT_EQ(*e.swing, 0.0);
    EXPECT_EQ(*e.swing_share, 0.0);
  }
  // A prediction without any value: no base, no delta, no swing.
  const PredictionRanking& cfv = r[8];
  EXPECT_FALSE(cfv.base.has_value());
  for (const SensitivityEffect& e : cfv.ranked) EXPECT_FALSE(e.low_value || e.delta_low || e.swing);
}

TEST(CommandsSensitivityRanking, WithoutABaseThereAreSwingsButNoDeltas) {
  const std::vector<SweepPointResult> rows = {row(""), row("8"), row("10")};
  const std::vector<PredictionRanking> r = rankSensitivity(1, rows);
  const SensitivityEffect& e = r[0].ranked[0];
  EXPECT_FALSE(r[0].base.has_value());
  EXPECT_FALSE(e.delta_low.has_value());
  EXPECT_FALSE(e.delta_high.has_value());
  ASSERT_TRUE(e.swing.has_value());
  EXPECT_EQ(*e.swing, 2.0);
}

TEST(CommandsSensitivityRanking, RejectsMalformedRows) {
  EXPECT_THROW(rankSensitivity(2, {row("9"), row("8"), row("10")}), std::invalid_argument);
  EXPECT_THROW(rankSensitivity(1, {row("9"), row("nan"), row("10")}), std::invalid_argument);
  EXPECT_THROW(rankSensitivity(1, {row("9"), row("8x"), row("10")}), std::invalid_argument);
  EXPECT_EQ(cellNumber(""), std::nullopt);
  EXPECT_EQ(*cellNumber("-1.5e-05"), -1.5e-05);
}

}  // namespace
}  // namespace orni::studies
