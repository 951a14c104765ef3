// The streamed aero map (trim/aero_map_stream.hpp): every point handed over once, in point order,
// with buildAeroMap's result, for any thread count and from any first point; a callback failure
// stops the map and comes back to the caller.
#include <gtest/gtest.h>

#include <cstddef>
#include <stdexcept>
#include <vector>

#include "core/model/frames.hpp"
#include "tests/support/test_vehicles.hpp"
#include "trim/aero_map.hpp"
#include "trim/aero_map_stream.hpp"

namespace orni {
namespace {

/// 3 speeds x 2 frequencies x 3 pitches = 18 points of the RFW rig.
AeroMapGrid rigGrid() {
  AeroMapGrid g;
  g.speed_mps = {4.0, 6.0, 8.0};
  g.freq_hz = {3.0, 4.0};
  g.theta_rad = {0.0, 10.0 * kDegToRad, 20.0 * kDegToRad};
  g.tail_angle_rad = {0.0};
  return g;
}

TEST(TrimAeroMapStream, HandsOverEveryPointInOrderWithTheMapsResult) {
  const FlightCoreModel model(testing::rfwRig());
  const AeroMapGrid grid = rigGrid();
  AeroMapOptions options;
  options.simulation.cycles = 12;
  const AeroMapSummary map = buildAeroMap(model, grid, options);
  for (const int threads : {1, 3}) {
    for (const std::size_t first : {std::size_t{0}, std::size_t{7}, grid.size()}) {
      options.threads = threads;
      std::vector<std::size_t> order;
      streamAeroMap(model, grid, options, first, [&](std::size_t i, const AeroMapPoint& p) {
        order.push_back(i);
        EXPECT_EQ(p.status, map.points[i].status);
        EXPECT_EQ(p.message, map.points[i].message);
        EXPECT_EQ(p.mean.FV_N, map.points[i].mean.FV_N);
        EXPECT_EQ(p.mean.FH_N, map.points[i].mean.FH_N);
        EXPECT_EQ(p.mean.power_hinge_W, map.points[i].mean.power_hinge_W);
      });
      ASSERT_EQ(order.size(), grid.size() - first) << threads << " threads from " << first;
      for (std::size_t k = 0; k < order.size(); ++k) EXPECT_EQ(order[k], first + k);
    }
  }
}

TEST(TrimAeroMapStream, ACallbackFailureStopsTheMap) {
  const FlightCoreModel model(testing::rfwRig());
  AeroMapOptions options;
  options.simulation.cycles = 12;
  options.threads = 2;
  std::size_t calls = 0;
  EXPECT_THROW(streamAeroMap(model, rigGrid(), options, 0,
                             [&](std::size_t, const AeroMapPoint&) {
                               if (++calls == 3) throw std::runtime_error("disk full");
                             }),
               std::runtime_error);
  EXPECT_EQ(calls, 3u);
  EXPECT_THROW(streamAeroMap(model, rigGrid(), options, 19, {}), std::invalid_argument);
}

}  // namespace
}  // namespace orni
