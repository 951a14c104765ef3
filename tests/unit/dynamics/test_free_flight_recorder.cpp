// What a free flight keeps of its samples (core/dynamics/free_flight_recorder.hpp): the windows
// follow from the options, the history stays bounded whatever the cycle count, the theta extremes
// and the limit-cycle window cover only their cycles; and simulateFree's last-cycle mean loads are
// the period means of its history's last cycle, bit for bit.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "core/analysis/harmonics.hpp"
#include "core/dynamics/free_flight.hpp"
#include "core/dynamics/free_flight_recorder.hpp"
#include "core/dynamics/free_flight_system.hpp"
#include "core/model/frames.hpp"
#include "tests/support/magpie_vehicle.hpp"

namespace orni {
namespace {

VehicleModel rigidMagpie() {
  VehicleModel v = testing::magpieVehicle();
  v.wing.structure = StructureLevel::kRigid;
  return v;
}

TEST(DynamicsFreeFlightRecorder, WindowsFollowFromTheOptions) {
  SimulationOptions o;
  o.cycles = 10;
  o.samples_per_cycle = 8;
  o.free.transient_fraction = 0.25;  // floor(2.5) = 2 cycles
  o.free.limit_cycle_window_samples = 3 * 8;
  FreeFlightWindows w = freeFlightWindows(o);
  EXPECT_EQ(w.transient_cycles, 2);
  EXPECT_EQ(w.first, 16u);
  EXPECT_EQ(w.limit_cycle_cycles, limitCycleWindowCycles(8, 8, 24));
  EXPECT_EQ(w.limit_cycle_first, static_cast<std::size_t>(10 - w.limit_cycle_cycles) * 8);
  EXPECT_EQ(w.analysed_end, 80u);
  // One cycle: no transient (the verdict needs a cycle).
  o.cycles = 1;
  w = freeFlightWindows(o);
  EXPECT_EQ(w.transient_cycles, 0);
  EXPECT_EQ(w.limit_cycle_cycles, 1);
  EXPECT_EQ(w.analysed_end, 8u);
}

TEST(DynamicsFreeFlightRecorder, KeepsABoundedHistoryAndTheExtremesAfterTheTransient) {
  const VehicleModel v = rigidMagpie();
  const FlightCoreModel model(v);
  const double freq_hz = 12.0;
  FreeFlightSystem sys(model, nullptr, ControlInput{freq_hz, 0.3}, 12.0);
  BodyState initial;
  initial.h_m = 10.0;
  initial.theta_rad = 0.2;
  initial.U_mps = 12.0;
  std::vector<double> y(static_cast<std::size_t>(sys.stateCount()), 0.0);
  sys.initialState(0.0, initial, y.data());

  SimulationOptions o;
  o.cycles = 12;
  o.samples_per_cycle = 5;
  o.record_history = false;
  o.free.transient_fraction = 0.5;
  FreeFlightHistory h;
  h.keep_cycles = 2;
  h.t_s.assign(3, 1.0);  // cleared by the recorder
  FreeFlightRecorder rec(sys, freq_hz, o, initial, 1.0, &h, nullptr);
  EXPECT_TRUE(h.t_s.empty());
  EXPECT_EQ(h.keep_cycles, 2);

  const int spc = o.samples_per_cycle;
  const double period_s = 1.0 / freq_hz;
  // theta rises by 0.01 rad per sample, with one excursion in the transient that must not count.
  auto theta = [](std::size_t i) { return i == 7 ? 5.0 : 0.2 + 0.01 * static_cast<double>(i); };
  std::size_t largest = 0;
  for (std::size_t i = 0; i <= static_cast<std::size_t>(o.cycles * spc); ++i) {
    y[2] = theta(i);
    rec.record(static_cast<double>(i) * period_s / spc, y.data());
    if (i > 0 && i % static_cast<std::size_t>(spc) == 0) rec.dropOld(true);
    largest = std::max(largest, h.t_s.size());
  }
  rec.dropOld(false);
  // At most twice the kept cycles (amortised), at the end exactly the kept ones plus the endpoint.
  EXPECT_LE(largest, static_cast<std::size_t>(2 * 2 * spc + 1));
  ASSERT_EQ(h.t_s.size(), static_cast<std::size_t>(2 * spc + 1));
  EXPECT_EQ(h.body.size(), h.t_s.size());
  EXPECT_TRUE(h.samples.empty());  // no loads without record_history
  EXPECT_EQ(rec.historyFirst(), static_cast<std::size_t>((o.cycles - 2) * spc));
  EXPECT_EQ(h.body.front().theta_rad, theta(rec.historyFirst()));
  EXPECT_EQ(rec.lastTime_s(), o.cycles * period_s);

  // Extremes over [first, analysed_end): the transient's excursion and the endpoint left out.
  const LimitCycleMetrics m = rec.limitCycle();
  const std::size_t first = rec.windows().first;
  EXPECT_EQ(first, static_cast<std::size_t>(6 * spc));
  EXPECT_EQ(m.theta_min_rad, theta(first));
  EXPECT_EQ(m.theta_max_rad, theta(static_cast<std::size_t>(o.cycles * spc) - 1));
}

// The mean loads of the last cycle, from the history the run returns (keep_cycles 1: the last
// cycle and its endpoint): the trapezoid on the periodic samples, bit for bit.
TEST(DynamicsFreeFlightRecorder, LastCycleMeanLoadsArePeriodMeansOfTheHistory) {
  const VehicleModel v = rigidMagpie();
  const FlightCoreModel model(v);
  const OperatingPoint point{12.0, 12.0, 16.0 * kDegToRad, 20.0 * kDegToRad};
  SimulationOptions o;
  o.cycles = 3;
  o.samples_per_cycle = 24;
  FreeFlightHistory h;
  const FreeFlightSummary s = simulateFree(model, point, o, &h);
  ASSERT_EQ(s.cycles_run, 3) << s.message;
  const std::size_t n = static_cast<std::size_t>(o.samples_per_cycle);
  ASSERT_EQ(h.samples.size(), n + 1);
  std::vector<double> fv, fh, m;
  for (std::size_t i = 0; i < n; ++i) {
    fv.push_back(h.samples[i].loads.FV_N);
    fh.push_back(h.samples[i].loads.FH_N);
    m.push_back(h.samples[i].loads.M_Nm);
  }
  EXPECT_EQ(s.mean.FV_N, periodMean(fv.data(), n));
  EXPECT_EQ(s.mean.FH_N, periodMean(fh.data(), n));
  EXPECT_EQ(s.mean.M_Nm, periodMean(m.data(), n));
  EXPECT_NE(s.mean.FV_N, 0.0);
}

}  // namespace
}  // namespace orni
