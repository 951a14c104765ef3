// The points of a sweep (core/grid/sweep_grid.hpp): full factorial, first axis outermost, one
// index per combination of the axes, and the limits on axes and points.
#include <gtest/gtest.h>

#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/grid/sweep_grid.hpp"

namespace orni {
namespace {

TEST(GridSweepPoints, FirstAxisOutermostLastFastest) {
  const SweepGrid g{{3, 2, 4}};
  EXPECT_EQ(g.size(), 24u);
  EXPECT_EQ(g.axisIndices(0), (std::vector<std::size_t>{0, 0, 0}));
  EXPECT_EQ(g.axisIndices(1), (std::vector<std::size_t>{0, 0, 1}));
  EXPECT_EQ(g.axisIndices(3), (std::vector<std::size_t>{0, 0, 3}));
  EXPECT_EQ(g.axisIndices(4), (std::vector<std::size_t>{0, 1, 0}));
  EXPECT_EQ(g.axisIndices(8), (std::vector<std::size_t>{1, 0, 0}));
  EXPECT_EQ(g.axisIndices(23), (std::vector<std::size_t>{2, 1, 3}));
  for (std::size_t i = 0; i < g.size(); ++i) EXPECT_EQ(g.pointIndex(g.axisIndices(i)), i);
  // Rows of one combination of the inner axes are every (n_1 * n_2)-th row (the sweep figure).
  for (std::size_t i0 = 0; i0 < 3; ++i0)
    EXPECT_EQ(g.axisIndices(i0 * 8 + 5), (std::vector<std::size_t>{i0, 1, 1}));
  EXPECT_THROW(g.pointIndex({0, 2, 0}), std::invalid_argument);
  EXPECT_THROW(g.pointIndex({0, 0}), std::invalid_argument);

  const SweepGrid one{{7}};
  EXPECT_EQ(one.size(), 7u);
  EXPECT_EQ(one.axisIndices(5), (std::vector<std::size_t>{5}));
}

TEST(GridSweepPoints, Validity) {
  std::string why;
  EXPECT_TRUE((SweepGrid{{3, 3}}).IsValid(&why)) << why;
  EXPECT_FALSE((SweepGrid{{}}).IsValid(&why));
  EXPECT_NE(why.find("at least one axis"), std::string::npos);
  EXPECT_FALSE((SweepGrid{{3, 0}}).IsValid(&why));
  EXPECT_NE(why.find("at least one value"), std::string::npos);
  EXPECT_FALSE((SweepGrid{{kMaxSweepPoints, 2}}).IsValid(&why));
  EXPECT_NE(why.find("more than"), std::string::npos);
  EXPECT_TRUE((SweepGrid{{kMaxSweepPoints}}).IsValid(&why));
  EXPECT_FALSE((SweepGrid{std::vector<std::size_t>(kMaxSweepAxes + 1, 1)}).IsValid(&why));
}

}  // namespace
}  // namespace orni
