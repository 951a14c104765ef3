// The aero-map builder (trim/aero_map.hpp): point order, each map value is exactly the direct
// tethered simulation at that point with the same options (issue acceptance 4), results do not
// depend on the thread count (rigid and flexible wing), known points are not recomputed, and bad
// grids, options and callback failures are reported.
#include <gtest/gtest.h>

#include <atomic>
#include <mutex>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/dynamics/tethered_simulation.hpp"
#include "core/model/frames.hpp"
#include "studies/runner/config/vehicle_file.hpp"
#include "trim/aero_map.hpp"

namespace orni {
namespace {

VehicleModel efw() {
  return studies::loadVehicleFile(std::string(ORNI_SOURCE_DIR) +
                                  "/studies/vehicles/efw_magpie.toml").model;
}

/// 2 speeds x 2 frequencies x 3 pitches x 2 tail angles = 24 points.
AeroMapGrid smallGrid() {
  AeroMapGrid g;
  g.speed_mps = {10.0, 14.0};
  g.freq_hz = {10.0, 16.0};
  g.theta_rad = {0.0, 7.5 * kDegToRad, 15.0 * kDegToRad};
  g.tail_angle_rad = {5.0 * kDegToRad, 11.85 * kDegToRad};
  return g;
}

void expectSamePoint(const AeroMapPoint& a, const AeroMapPoint& b) {
  EXPECT_EQ(a.status, b.status);
  EXPECT_EQ(a.message, b.message);
  EXPECT_EQ(a.cycles_run, b.cycles_run);
  EXPECT_EQ(a.steady_state_cycle, b.steady_state_cycle);
  EXPECT_EQ(a.last_cycle_change, b.last_cycle_change);
  EXPECT_EQ(a.mean.FV_N, b.mean.FV_N);
  EXPECT_EQ(a.mean.FH_N, b.mean.FH_N);
  EXPECT_EQ(a.mean.M_Nm, b.mean.M_Nm);
  EXPECT_EQ(a.mean.power_aero_W, b.mean.power_aero_W);
  EXPECT_EQ(a.mean.power_hinge_W, b.mean.power_hinge_W);
}

TEST(TrimAeroMap, PointOrderIsSpeedFreqThetaTail) {
  const AeroMapGrid g = smallGrid();
  ASSERT_EQ(g.size(), 24u);
  std::size_t index = 0;
  for (std::size_t is = 0; is < 2; ++is)
    for (std::size_t jf = 0; jf < 2; ++jf)
      for (std::size_t kt = 0; kt < 3; ++kt)
        for (std::size_t la = 0; la < 2; ++la, ++index) {
          EXPECT_EQ(g.axisIndices(index), (std::array<std::size_t, 4>{is, jf, kt, la}));
          const OperatingPoint p = g.point(index);
          EXPECT_EQ(p.speed_mps, g.speed_mps[is]);
          EXPECT_EQ(p.freq_hz, g.freq_hz[jf]);
          EXPECT_EQ(p.theta_rad, g.theta_rad[kt]);
          EXPECT_EQ(p.tail_angle_rad, g.tail_angle_rad[la]);
        }
}

// Issue acceptance 4: the map value at a grid point is the direct simulation at that point.
TEST(TrimAeroMap, EveryPointEqualsTheDirectSimulationExactly) {
  const FlightCoreModel model(efw());
  const AeroMapGrid grid = smallGrid();
  AeroMapOptions options;
  options.threads = 2;
  const AeroMapSummary map = buildAeroMap(model, grid, options);
  ASSERT_EQ(map.points.size(), grid.size());
  EXPECT_EQ(map.computed, grid.size());
  EXPECT_EQ(map.ok, grid.size()) << map.BriefReport();

  // The options a user would pass for "stop at the steady state, at most 40 cycles".
  SimulationOptions direct;
  direct.cycles = 40;
  direct.record_history = false;
  direct.stop_when_steady = true;
  for (std::size_t i = 0; i < grid.size(); ++i) {
    SCOPED_TRACE(i);
    const SimulationSummary s = simulateTethered(model, grid.point(i), direct, nullptr);
    const AeroMapPoint& p = map.points[i];
    EXPECT_EQ(p.status, s.status);
    EXPECT_EQ(p.message, s.message);
    EXPECT_EQ(p.cycles_run, s.cycles_run);
    EXPECT_EQ(p.steady_state_cycle, s.steady_state_cycle);
    EXPECT_EQ(p.mean.FV_N, s.mean.FV_N);
    EXPECT_EQ(p.mean.FH_N, s.mean.FH_N);
    EXPECT_EQ(p.mean.M_Nm, s.mean.M_Nm);
    EXPECT_EQ(p.mean.power_hinge_W, s.mean.power_hinge_W);
    EXPECT_EQ(p.mean.power_aero_W, s.mean.power_aero_W);
  }
  // One point written out by hand: U = 14 m/s, f = 10 Hz, theta = 7.5 deg, tail = 11.85 deg.
  const SimulationSummary s =
      simulateTethered(model, OperatingPoint{14.0, 10.0, 7.5 * kDegToRad, 11.85 * kDegToRad},
                       direct, nullptr);
  const std::size_t index = ((1 * 2 + 0) * 3 + 1) * 2 + 1;
  EXPECT_EQ(map.points[index].mean.FV_N, s.mean.FV_N);
  EXPECT_EQ(map.points[index].mean.FH_N, s.mean.FH_N);
}

TEST(TrimAeroMap, ResultsDoNotDependOnTheThreadCount) {
  const FlightCoreModel model(efw());
  const AeroMapGrid grid = smallGrid();
  AeroMapOptions one, three;
  one.threads = 1;
  three.threads = 3;
  const AeroMapSummary a = buildAeroMap(model, grid, one);
  const AeroMapSummary b = buildAeroMap(model, grid, three);
  ASSERT_EQ(a.points.size(), b.points.size());
  for (std::size_t i = 0; i < a.points.size(); ++i) {
    SCOPED_TRACE(i);
    expectSamePoint(a.points[i], b.points[i]);
  }
}

TEST(TrimAeroMap, FlexibleWingSharedBetweenThreads) {
  VehicleModel v = efw();
  v.wing.structure = StructureLevel::kFlexible;
  v.wing.fe.element_size_m = 0.01;  // coarse mesh: fast test
  v.wing.fe.max_modes = 6;
  const FlightCoreModel model(v);  // the modal wing is built here, once, before any thread
  ASSERT_TRUE(model.flexible);
  AeroMapGrid grid;
  grid.speed_mps = {10.0, 12.0};
  grid.freq_hz = {12.0};
  grid.theta_rad = {0.0, 10.0 * kDegToRad};
  grid.tail_angle_rad = {0.0};
  AeroMapOptions one, two;
  one.simulation.cycles = two.simulation.cycles = 8;
  two.threads = 2;
  const AeroMapSummary a = buildAeroMap(model, grid, one);
  const AeroMapSummary b = buildAeroMap(model, grid, two);
  for (std::size_t i = 0; i < a.points.size(); ++i) {
    SCOPED_TRACE(i);
    expectSamePoint(a.points[i], b.points[i]);
    EXPECT_NE(a.points[i].status, SimulationStatus::kFailed) << a.points[i].message;
  }
}

TEST(TrimAeroMap, KnownPointsAreNotRecomputed) {
  const FlightCoreModel model(efw());
  const AeroMapGrid grid = smallGrid();
  AeroMapOptions options;
  options.threads = 2;
  const AeroMapSummary full = buildAeroMap(model, grid, options);

  std::vector<std::optional<AeroMapPoint>> known(grid.size());
  for (std::size_t i = 0; i < grid.size(); i += 3) known[i] = full.points[i];
  std::mutex m;
  std::set<std::size_t> computed;
  const AeroMapSummary resumed =
      buildAeroMap(model, grid, options, known, [&](std::size_t index, const AeroMapPoint&) {
        std::lock_guard<std::mutex> lock(m);
        EXPECT_TRUE(computed.insert(index).second) << "point " << index << " computed twice";
      });
  EXPECT_EQ(resumed.computed, grid.size() - 8);
  EXPECT_EQ(computed.size(), grid.size() - 8);
  for (std::size_t i = 0; i < grid.size(); ++i) {
    SCOPED_TRACE(i);
    EXPECT_EQ(computed.count(i) == 1, !known[i].has_value());
    expectSamePoint(resumed.points[i], full.points[i]);
  }
}

TEST(TrimAeroMap, CallbackErrorStopsTheBuild) {
  const FlightCoreModel model(efw());
  const AeroMapGrid grid = smallGrid();
  AeroMapOptions options;
  options.threads = 2;
  std::atomic<int> calls{0};
  EXPECT_THROW(buildAeroMap(model, grid, options, {},
                            [&](std::size_t, const AeroMapPoint&) {
                              if (++calls == 3) throw std::runtime_error("disk full");
                            }),
               std::runtime_error);
  EXPECT_EQ(calls.load(), 3);  // no callback after the failing one
}

TEST(TrimAeroMap, RejectsBadGridsAndOptions) {
  const FlightCoreModel model(efw());
  AeroMapOptions options;
  AeroMapGrid g = smallGrid();
  g.theta_rad.clear();
  EXPECT_THROW(buildAeroMap(model, g, options), std::invalid_argument);
  g = smallGrid();
  g.speed_mps.push_back(0.0);
  EXPECT_THROW(buildAeroMap(model, g, options), std::invalid_argument);
  g = smallGrid();
  g.theta_rad.push_back(2.0);  // > pi/2
  EXPECT_THROW(buildAeroMap(model, g, options), std::invalid_argument);
  g = smallGrid();
  options.threads = 0;
  EXPECT_THROW(buildAeroMap(model, g, options), std::invalid_argument);
  options.threads = 1;
  options.simulation.steady_tol = 0.0;
  EXPECT_THROW(buildAeroMap(model, g, options), std::invalid_argument);
  options.simulation.steady_tol = 1e-3;
  std::vector<std::optional<AeroMapPoint>> wrong_size(3);
  EXPECT_THROW(buildAeroMap(model, g, options, wrong_size), std::invalid_argument);
}

TEST(TrimAeroMap, PointOptionsForceTheMapSettings) {
  AeroMapOptions options;
  EXPECT_EQ(options.simulation.cycles, 40);
  options.simulation.record_history = true;
  options.simulation.stop_when_steady = false;
  const SimulationOptions p = options.pointOptions();
  EXPECT_FALSE(p.record_history);
  EXPECT_TRUE(p.stop_when_steady);
  EXPECT_EQ(p.cycles, 40);
}

TEST(TrimAeroMap, NotConvergedPointsKeepTheirReason) {
  const FlightCoreModel model(efw());
  AeroMapGrid grid;
  grid.speed_mps = {10.0};
  grid.freq_hz = {12.0};
  grid.theta_rad = {5.0 * kDegToRad};
  grid.tail_angle_rad = {0.0};
  AeroMapOptions options;
  options.simulation.cycles = 1;  // one cycle cannot show a steady state
  const AeroMapSummary map = buildAeroMap(model, grid, options);
  ASSERT_EQ(map.points.size(), 1u);
  EXPECT_EQ(map.points[0].status, SimulationStatus::kNotConverged);
  EXPECT_NE(map.points[0].message.find("not reached"), std::string::npos);
  EXPECT_EQ(map.not_converged, 1u);
  EXPECT_EQ(map.ok, 0u);
}

}  // namespace
}  // namespace orni
