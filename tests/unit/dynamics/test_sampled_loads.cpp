// The tethered flexible wing's history samples from the integrator's dense output
// (FlexibleTetheredSystem::sampleFromDerivative, docs/theory.md 9.4) against samples evaluated at
// the sampled state and against a tight-tolerance reference.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <string>
#include <vector>

#include "core/dynamics/flexible_wing.hpp"
#include "core/dynamics/free_flight.hpp"
#include "core/dynamics/tethered_simulation.hpp"
#include "studies/runner/config/vehicle_file.hpp"

namespace orni {
namespace {

struct Channel {
  const char* name;
  double LoadSample::*field;
};
const Channel kChannels[] = {
    {"FV", &LoadSample::FV_N},
    {"FH", &LoadSample::FH_N},
    {"M", &LoadSample::M_Nm},
    {"power_aero", &LoadSample::power_aero_W},
    {"power_hinge", &LoadSample::power_hinge_W},
    {"FV_wing_aero", &LoadSample::FV_wing_aero_N},
    {"FV_wing_inertial", &LoadSample::FV_wing_inertial_N},
    {"FH_wing_inertial", &LoadSample::FH_wing_inertial_N},
    {"M_wing_inertial", &LoadSample::M_wing_inertial_Nm},
    {"separated_fraction", &LoadSample::separated_fraction},
    {"tip_twist", &LoadSample::tip_twist_rad},
};

// The magpie's own flexible wing (24 modes, linear) at its design point, 4 cycles recorded at
// 100 samples a cycle.
class SampledLoads : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    const auto file = studies::loadVehicleFile(std::string(ORNI_SOURCE_DIR) +
                                               "/studies/vehicles/efw_magpie.toml");
    model_ = new FlightCoreModel(file.model);
    point_ = file.design_point;
  }
  static void TearDownTestSuite() {
    delete model_;
    delete table3_model_;
    table3_model_ = nullptr;
  }

  static SimulationSummary run(double rel_tol, bool interpolate, TimeHistory* h) {
    SimulationOptions o;
    o.cycles = 4;
    o.samples_per_cycle = 100;
    o.rel_tol = rel_tol;
    o.interpolate_sampled_loads = interpolate;
    return simulateTethered(*model_, point_, o, h);
  }
  // The calibrated vehicle (efw_magpie_table3.toml: the nonlinear membrane wing), built once for
  // the tests that need it.
  static const FlightCoreModel& table3Model() {
    if (!table3_model_) {
      const auto file = studies::loadVehicleFile(std::string(ORNI_SOURCE_DIR) +
                                                 "/studies/vehicles/efw_magpie_table3.toml");
      table3_model_ = new FlightCoreModel(file.model);
    }
    return *table3_model_;
  }
  static FlightCoreModel* model_;
  static FlightCoreModel* table3_model_;
  static OperatingPoint point_;
};
FlightCoreModel* SampledLoads::model_ = nullptr;
FlightCoreModel* SampledLoads::table3_model_ = nullptr;
OperatingPoint SampledLoads::point_;

// Table 3's trim point (U 10.8 m/s, f 12 Hz, theta 9.2 deg, tail 11.85 deg).
const OperatingPoint kTable3{10.8, 12.0, 9.2 * M_PI / 180.0, 11.85 * M_PI / 180.0};

const LoadSample& loadsAt(const TimeHistory& h, std::size_t i) { return h.loads[i]; }
const LoadSample& loadsAt(const FreeFlightHistory& h, std::size_t i) { return h.samples[i].loads; }
std::size_t sampleCount(const TimeHistory& h) { return h.loads.size(); }
std::size_t sampleCount(const FreeFlightHistory& h) { return h.samples.size(); }

// Largest deviation of a's last cycle (101 samples) from b's, relative to b's peak-to-peak there.
template <class History>
double deviation(const History& a, const History& b, const Channel& c) {
  const std::size_t n = sampleCount(b), first = n - 101;
  double lo = 1e300, hi = -1e300, dev = 0.0;
  for (std::size_t i = first; i < n; ++i) {
    const double r = loadsAt(b, i).*c.field;
    lo = std::min(lo, r);
    hi = std::max(hi, r);
    dev = std::max(dev, std::abs(loadsAt(a, i).*c.field - r));
  }
  return dev / (hi - lo);
}

TEST_F(SampledLoads, InterpolatedSamplesAreAsAccurateAsTheIntegration) {
  TimeHistory interpolated, evaluated, reference, interpolated_tight, evaluated_tight;
  const SimulationSummary a = run(1e-4, true, &interpolated);
  const SimulationSummary b = run(1e-4, false, &evaluated);
  const SimulationSummary r = run(1e-8, false, &reference);
  const SimulationSummary at = run(1e-6, true, &interpolated_tight);
  const SimulationSummary bt = run(1e-6, false, &evaluated_tight);
  for (const SimulationSummary* s : {&a, &b, &r, &at, &bt}) {
    ASSERT_TRUE(s->status == SimulationStatus::kOk || s->status == SimulationStatus::kNotConverged)
        << s->message;
    ASSERT_EQ(s->cycles_run, 4);
  }
  for (const TimeHistory* h :
       {&interpolated, &evaluated, &reference, &interpolated_tight, &evaluated_tight})
    ASSERT_EQ(h->loads.size(), 101u);  // the last cycle (keep_cycles 1), both ends

  // Sampling does not touch the integration: the same steps, the same cycle means (quadratures).
  EXPECT_EQ(a.steps, b.steps);
  EXPECT_EQ(a.rhs_evaluations, b.rhs_evaluations);
  EXPECT_EQ(a.mean.FV_N, b.mean.FV_N);
  EXPECT_EQ(a.mean.power_hinge_W, b.mean.power_hinge_W);
  // What comes from the sampled state alone is the same.
  EXPECT_EQ(interpolated.loads.back().tip_deflection_m, evaluated.loads.back().tip_deflection_m);

  // Against the reference (rel_tol 1e-8), over the last cycle, relative to each channel's
  // peak-to-peak. Measured 2026-12-06 (printed below): at rel_tol 1e-4 the interpolated samples
  // deviate by 1.9e-3 .. 6.9e-3 (1.9e-2 for the small M_wing_inertial), the evaluated ones by
  // 2.1e-3 .. 1.3e-2 (3.2e-2); at 1e-6 by 4e-5 .. 5.7e-4 and 3e-5 .. 3.4e-4. So the interpolated
  // loads have the integration's accuracy and converge with its tolerance like the evaluated
  // ones. Bounds: at 1e-4, 1.5e-2 or the evaluated samples' own deviation if larger; at 1e-6,
  // 1e-3 (a sample error that did not converge with the tolerance would stay near the first).
  constexpr double kAtDefault = 1.5e-2, kAtTight = 1e-3;
  for (const Channel& c : kChannels) {
    const double da = deviation(interpolated, reference, c);
    const double db = deviation(evaluated, reference, c);
    const double dat = deviation(interpolated_tight, reference, c);
    const double dbt = deviation(evaluated_tight, reference, c);
    std::printf("%-20s rel_tol 1e-4: interpolated %.2e evaluated %.2e | 1e-6: %.2e %.2e\n", c.name,
                da, db, dat, dbt);
    EXPECT_LT(da, std::max(kAtDefault, db)) << c.name;
    EXPECT_LT(dat, kAtTight) << c.name;
  }
}

// The calibrated vehicle's nonlinear (membrane) wing at Table 3's point, as the paper's Fig. 9
// holds it: the membrane's stiff force (tangent frequencies of kHz) turns the interpolated state's
// small error into a large error of q'' and of the loads evaluated from it, so the evaluated samples
// are far off at the default tolerance while the interpolated ones are as accurate as on the
// linear wing (the reason "interpolated" is the default, docs/theory.md 9.4). Until 2026-12-07 the
// committed Fig. 9 of this vehicle showed +-100 N "bursts" that were this sampling error.
TEST_F(SampledLoads, NonlinearWingInterpolatedSamplesConvergeWhereEvaluatedOnesDoNot) {
  const FlightCoreModel& nonlinear = table3Model();
  ASSERT_TRUE(nonlinear.vehicle.wing.fe.nonlinear);
  auto run = [&](double rel_tol, bool interpolate, TimeHistory* h) {
    SimulationOptions o;
    o.cycles = 3;
    o.samples_per_cycle = 100;
    o.rel_tol = rel_tol;
    o.interpolate_sampled_loads = interpolate;
    return simulateTethered(nonlinear, kTable3, o, h);
  };
  TimeHistory interpolated, evaluated, interpolated_tight, reference;
  const SimulationSummary a = run(1e-4, true, &interpolated);
  const SimulationSummary b = run(1e-4, false, &evaluated);
  const SimulationSummary at = run(1e-6, true, &interpolated_tight);
  const SimulationSummary r = run(1e-8, true, &reference);
  for (const SimulationSummary* s : {&a, &b, &at, &r}) {
    ASSERT_TRUE(s->status == SimulationStatus::kOk || s->status == SimulationStatus::kNotConverged)
        << s->message;
    ASSERT_EQ(s->cycles_run, 3);
  }
  // Measured 2026-12-07 (printed; the third cycle, still in the transient, where the state itself
  // is off by 2.7e-2 of tip_twist's peak-to-peak at 1e-4): at rel_tol 1e-4 the evaluated samples'
  // loads are off by 4 to 79 peak-to-peaks, the interpolated ones' by 2e-2 .. 3.1e-1 (the wing's
  // inertial loads, from q'', the worst), a factor 200 to 420 better; at 1e-6 the interpolated
  // ones by at most 2.2e-3. (The 10-cycle Fig. 9 study at its steady state, against 1e-8: evaluated
  // at 1e-6 still 5.4e-2 on the inertial loads, interpolated at 1e-6 2.5e-3, at 1e-4 8e-2; the
  // 1e-8 reference's two kinds of sample agree to 2.3e-4.) Bounds: the interpolated at least 20
  // times better than the evaluated on every load channel at 1e-4 (the reason for the default),
  // and within 1e-2 at 1e-6 (the samples converge with the tolerance).
  constexpr double kBetterThanEvaluated = 20.0, kAtTight = 1e-2;
  const double LoadSample::*state_only[] = {&LoadSample::separated_fraction,
                                            &LoadSample::tip_twist_rad};
  for (const Channel& c : kChannels) {
    const double da = deviation(interpolated, reference, c);
    const double db = deviation(evaluated, reference, c);
    const double dat = deviation(interpolated_tight, reference, c);
    std::printf("%-20s rel_tol 1e-4: interpolated %.2e evaluated %.2e | 1e-6 interpolated %.2e\n",
                c.name, da, db, dat);
    const bool load = std::find(std::begin(state_only), std::end(state_only), c.field) ==
                      std::end(state_only);
    if (load) {
      EXPECT_GT(db, kBetterThanEvaluated * da) << c.name;
    }
    EXPECT_LT(dat, kAtTight) << c.name;
  }
}

// The same in free flight (FreeFlightSystem::sample with the dense output's derivative: the
// accelerations u' from the interpolant, the circulatory loads evaluated): the calibrated vehicle
// released at Table 3's point, two cycles at the nonlinear wing's free-flight tolerance 1e-5,
// against a 1e-8 reference. The free flight's mean loads are the samples' means, so they carry
// the sampling error too.
TEST_F(SampledLoads, NonlinearWingFreeFlightSamplesTakeTheAccelerationsFromTheInterpolant) {
  const FlightCoreModel& nonlinear = table3Model();
  ASSERT_TRUE(nonlinear.vehicle.wing.fe.nonlinear);
  auto fly = [&](double rel_tol, bool interpolate, FreeFlightHistory* h) {
    SimulationOptions o;
    o.mode = FlightMode::kFree;
    o.cycles = 2;
    o.samples_per_cycle = 100;
    o.rel_tol = rel_tol;
    o.interpolate_sampled_loads = interpolate;
    o.free.periodic_start_cycles = 0;  // released from rest: the run alone
    h->keep_cycles = 1;
    return simulateFree(nonlinear, kTable3, o, h);
  };
  FreeFlightHistory interpolated, evaluated, reference;
  const FreeFlightSummary a = fly(1e-5, true, &interpolated);
  const FreeFlightSummary b = fly(1e-5, false, &evaluated);
  const FreeFlightSummary r = fly(1e-8, true, &reference);
  for (const FreeFlightSummary* s : {&a, &b, &r}) {
    ASSERT_EQ(s->status, SimulationStatus::kOk) << s->message;
    ASSERT_EQ(s->cycles_run, 2);
  }
  ASSERT_EQ(interpolated.samples.size(), reference.samples.size());
  // The same integration: the body states are the same bits, only the samples' loads differ.
  EXPECT_EQ(a.steps, b.steps);
  EXPECT_EQ(interpolated.body.back().theta_rad, evaluated.body.back().theta_rad);
  // Measured 2026-12-07 (printed): the interpolated samples' loads within 2.2e-3 .. 5.4e-3 of a
  // peak-to-peak, the evaluated ones' 0.21 .. 0.47 (the state-only channels the same); the mean
  // lift 1.134295 interpolated, 1.173827 evaluated (+3.4 %), 1.135061 N the reference. Bounds: the
  // interpolated within 2e-2 of a peak-to-peak (four times the largest measured; the tethered
  // wing's default-tolerance error scale, above), at least 20 times better than the evaluated on
  // every load channel, and the mean lift within 2e-3 relative (three times the measured).
  constexpr double kInterpolated = 2e-2, kBetterThanEvaluated = 20.0, kMeanFv = 2e-3;
  const double LoadSample::*load_channels[] = {&LoadSample::FV_N, &LoadSample::FH_N,
                                               &LoadSample::M_Nm, &LoadSample::power_aero_W,
                                               &LoadSample::FV_wing_aero_N};
  for (const Channel& c : kChannels) {
    if (std::find(std::begin(load_channels), std::end(load_channels), c.field) ==
        std::end(load_channels))
      continue;  // the wing's inertial loads and the hinge power are not sampled in free flight
    const double da = deviation(interpolated, reference, c), db = deviation(evaluated, reference, c);
    std::printf("free %-18s rel_tol 1e-5: interpolated %.2e evaluated %.2e\n", c.name, da, db);
    EXPECT_LT(da, kInterpolated) << c.name;
    EXPECT_GT(db, kBetterThanEvaluated * da) << c.name;
  }
  std::printf("free mean FV: interpolated %.6f evaluated %.6f reference %.6f N\n", a.mean.FV_N,
              b.mean.FV_N, r.mean.FV_N);
  EXPECT_NEAR(a.mean.FV_N, r.mean.FV_N, kMeanFv * std::abs(r.mean.FV_N));
}

}  // namespace
}  // namespace orni
