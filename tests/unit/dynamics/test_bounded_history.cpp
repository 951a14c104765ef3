// Long runs stream (issue 14, defect 1): a tethered or free run keeps only its last cycles in
// memory (history_window.hpp) and hands every sample to its observer, and the analyses made on
// the way (cycle means, the bounded-norm verdict, the theta extremes, the limit-cycle window) give
// the numbers the stored whole histories give.
#include <gtest/gtest.h>

#include <cstddef>
#include <vector>

#include "core/analysis/limit_cycle.hpp"
#include "core/dynamics/free_flight.hpp"
#include "core/dynamics/history_window.hpp"
#include "core/dynamics/tethered_simulation.hpp"
#include "studies/runner/config/vehicle_file.hpp"
#include "tests/support/test_vehicles.hpp"

namespace orni {
namespace {

struct TetheredRecord : TetheredRunObserver {
  std::vector<double> t_s;
  std::vector<LoadSample> loads;
  std::vector<CycleMeans> cycles;
  void onSample(double t, double, const LoadSample& l) override {
    t_s.push_back(t);
    loads.push_back(l);
  }
  void onCycle(int cycle, const CycleMeans& m) override {
    EXPECT_EQ(cycle, static_cast<int>(cycles.size()) + 1);
    cycles.push_back(m);
  }
};

TEST(DynamicsBoundedHistory, OldSamplesToDropKeepsTheLastWholeCycles) {
  // 4 samples per cycle, keep 2 cycles: whole cycles are counted with the sample that ends them.
  EXPECT_EQ(oldSamplesToDrop(9, 4, 2, false), 0u);   // 2 cycles + end sample
  EXPECT_EQ(oldSamplesToDrop(13, 4, 2, false), 4u);  // 3 cycles: drop 1
  EXPECT_EQ(oldSamplesToDrop(15, 4, 2, false), 4u);  // 3 cycles + 2 of the next
  EXPECT_EQ(oldSamplesToDrop(13, 4, 2, true), 0u);   // amortised: waits for 4 cycles
  EXPECT_EQ(oldSamplesToDrop(17, 4, 2, true), 8u);
  EXPECT_EQ(oldSamplesToDrop(0, 4, 2, false), 0u);
}

TEST(DynamicsBoundedHistory, TetheredRunKeepsItsLastCyclesAndStreamsEverySample) {
  const FlightCoreModel model(testing::rfwRig());
  const OperatingPoint p{6.0, 4.0, 20.0 * kDegToRad, 0.0};
  SimulationOptions o;
  o.cycles = 30;
  o.samples_per_cycle = 16;
  for (const int keep : {1, 3}) {
    TimeHistory h;
    h.keep_cycles = keep;
    TetheredRecord all;
    const SimulationSummary s = simulateTethered(model, p, o, &h, &all);
    ASSERT_EQ(s.status, SimulationStatus::kOk) << s.message;
    const std::size_t spc = 16, kept = static_cast<std::size_t>(keep) * spc + 1;
    ASSERT_EQ(all.t_s.size(), 30 * spc + 1);
    ASSERT_EQ(all.cycles.size(), 30u);
    ASSERT_EQ(h.loads.size(), kept);
    EXPECT_LE(h.loads.capacity(), 2 * static_cast<std::size_t>(keep) * spc + 1);
    // The kept samples are the last ones streamed, bit for bit.
    const std::size_t base = all.t_s.size() - kept;
    for (std::size_t i = 0; i < kept; ++i) {
      EXPECT_EQ(h.t_s[i], all.t_s[base + i]);
      EXPECT_EQ(h.loads[i].FV_N, all.loads[base + i].FV_N);
    }
    EXPECT_EQ(all.cycles.back().FV_N, s.mean.FV_N);
    EXPECT_EQ(all.cycles.back().power_hinge_W, s.mean.power_hinge_W);
  }
  // The history does not change the run: the same means without it.
  TetheredRecord only;
  const SimulationSummary a = simulateTethered(model, p, o, nullptr, &only);
  TimeHistory h;
  const SimulationSummary b = simulateTethered(model, p, o, &h, nullptr);
  EXPECT_EQ(a.mean.FV_N, b.mean.FV_N);
  EXPECT_EQ(a.mean.M_Nm, b.mean.M_Nm);
  TimeHistory bad;
  bad.keep_cycles = 0;
  EXPECT_THROW(simulateTethered(model, p, o, &bad), std::invalid_argument);
}

struct FreeRecord : FreeFlightObserver {
  std::vector<double> t_s, delta, U, W, theta, Q, h;
  void onSample(double t, double d, const BodyState& b, const FreeFlightSample*) override {
    t_s.push_back(t);
    delta.push_back(d);
    U.push_back(b.U_mps);
    W.push_back(b.W_mps);
    theta.push_back(b.theta_rad);
    Q.push_back(b.Q_radps);
    h.push_back(b.h_m);
  }
};

TEST(DynamicsBoundedHistory, FreeFlightAnalysesOnTheWayWhatTheWholeHistoryGives) {
  // The frozen rigid-wing magpie (it flies bounded at the paper's trim point).
  const VehicleDefinition file = studies::loadVehicleFile(
      std::string(ORNI_SOURCE_DIR) + "/tests/data/sensitivity/magpie_rigid_fixture.toml");
  const FlightCoreModel model(file.model);
  const OperatingPoint& point = file.design_point;
  SimulationOptions o;
  o.mode = FlightMode::kFree;
  o.cycles = 30;
  o.samples_per_cycle = 20;
  o.free.transient_fraction = 0.2;  // cycles 7-30 judged
  o.free.limit_cycle_window_samples = 10 * 20 + 7;  // the limit cycle of the last 10 cycles
  FreeFlightHistory kept;
  kept.keep_cycles = 2;
  FreeRecord all;
  const FreeFlightSummary s = simulateFree(model, point, o, &kept, &all);
  ASSERT_EQ(s.status, SimulationStatus::kOk) << s.message;
  ASSERT_TRUE(s.analysed);
  const std::size_t spc = 20, n = 30 * spc + 1;
  ASSERT_EQ(all.t_s.size(), n);
  ASSERT_EQ(kept.body.size(), 2 * spc + 1);
  EXPECT_EQ(kept.body.back().h_m, all.h.back());
  EXPECT_EQ(s.first_analysed_cycle, 7);
  EXPECT_EQ(s.limit_cycle_first_cycle, 21);

  // The verdict of the whole stored history after the transient, bit for bit.
  const BodyState& r = s.initial;
  const FreeFlightBounds& b = o.free.bounds;
  const double R_Q = 2.0 * kPi * point.freq_hz * b.theta_rad;
  const BoundedNormResult whole =
      boundedNorm(all.t_s,
                  {{&all.U, r.U_mps, b.U_mps, "U"},
                   {&all.W, r.W_mps, b.W_mps, "W"},
                   {&all.theta, r.theta_rad, b.theta_rad, "theta"},
                   {&all.Q, r.Q_radps, R_Q, "Q"},
                   {&all.h, r.h_m, b.h_m, "h"}},
                  6 * spc, 20);
  EXPECT_EQ(s.verdict.norm_ratio_max, whole.norm_ratio_max);
  EXPECT_EQ(s.verdict.time_of_max_s, whole.time_of_max_s);
  EXPECT_EQ(s.verdict.drift_per_window, whole.drift_per_window);
  EXPECT_EQ(s.verdict.reason, whole.reason);
  // Theta extremes over every judged cycle; the rest over the last 10 cycles.
  const LimitCycleMetrics judged =
      analyseLimitCycle(all.t_s, all.delta, all.theta, all.h, 6 * spc, 20,
                        point.freq_hz);
  EXPECT_EQ(s.limit_cycle.theta_min_rad, judged.theta_min_rad);
  EXPECT_EQ(s.limit_cycle.theta_max_rad, judged.theta_max_rad);
  const LimitCycleMetrics last10 = analyseLimitCycle(
      all.t_s, all.delta, all.theta, all.h, 20 * spc, 20, point.freq_hz);
  EXPECT_EQ(s.limit_cycle.altitude_p2p_fast_m, last10.altitude_p2p_fast_m);
  EXPECT_EQ(s.limit_cycle.altitude_p2p_slow_m, last10.altitude_p2p_slow_m);
  EXPECT_EQ(s.limit_cycle.climb_rate_mps, last10.climb_rate_mps);
  ASSERT_EQ(s.limit_cycle.spectrum_theta.amplitude.size(), last10.spectrum_theta.amplitude.size());
  for (std::size_t k = 0; k < last10.spectrum_theta.amplitude.size(); ++k)
    EXPECT_EQ(s.limit_cycle.spectrum_theta.amplitude[k], last10.spectrum_theta.amplitude[k]);
}

// The observer may end a run after a whole cycle (FreeFlightObserver::endRunAfterCycle, the
// settled free flight's use): the run is then those cycles, not judged, and its samples and kept
// cycles are the first cycles of the full run's, bit for bit.
struct EndAfter : FreeRecord {
  int end_after = 0;
  std::vector<int> asked;
  bool endRunAfterCycle(int cycle) override {
    asked.push_back(cycle);
    return cycle == end_after;
  }
};

TEST(DynamicsBoundedHistory, TheObserverMayEndAFreeFlightAfterACycle) {
  const VehicleDefinition file = studies::loadVehicleFile(
      std::string(ORNI_SOURCE_DIR) + "/tests/data/sensitivity/magpie_rigid_fixture.toml");
  const FlightCoreModel model(file.model);
  SimulationOptions o;
  o.mode = FlightMode::kFree;
  o.cycles = 12;
  o.samples_per_cycle = 20;
  FreeRecord full;
  ASSERT_EQ(simulateFree(model, file.design_point, o, nullptr, &full).status,
            SimulationStatus::kOk);
  EndAfter part;
  part.end_after = 5;
  FreeFlightHistory kept;
  kept.keep_cycles = 2;
  const FreeFlightSummary s = simulateFree(model, file.design_point, o, &kept, &part);
  EXPECT_EQ(s.status, SimulationStatus::kOk) << s.message;
  EXPECT_EQ(s.cycles_run, 5);
  EXPECT_FALSE(s.analysed);
  EXPECT_NE(s.message.find("5 of 12 cycles"), std::string::npos) << s.message;
  EXPECT_EQ(part.asked, (std::vector<int>{1, 2, 3, 4, 5}));
  const std::size_t n = 5 * 20 + 1;
  ASSERT_EQ(part.h.size(), n);
  for (std::size_t i = 0; i < n; ++i) EXPECT_EQ(part.h[i], full.h[i]);
  ASSERT_EQ(kept.body.size(), 2u * 20u + 1u);
  EXPECT_EQ(kept.body.back().h_m, full.h[n - 1]);
  // Never asked after the last cycle: a run that is not ended is judged as always.
  EndAfter never;
  never.end_after = 0;
  const FreeFlightSummary w = simulateFree(model, file.design_point, o, nullptr, &never);
  EXPECT_TRUE(w.analysed);
  EXPECT_EQ(never.asked.size(), 11u);
}

}  // namespace
}  // namespace orni
