// Tethered rigid-wing simulation of the RFW rig (paper section 2, Fig. 2): symmetry, harmonic
// content, phase, convergence, inertial loads against a closed form, power balance.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/analysis/harmonics.hpp"
#include "core/dynamics/tethered_simulation.hpp"
#include "tests/support/test_vehicles.hpp"

namespace orni {
namespace {

/// Analytic-limit vehicles (outside the physical ranges on purpose) skip core's model checks.
constexpr FlightCoreModel::Checks kLimitTest = FlightCoreModel::Checks::kSkippedForLimitTests;

// Acceptance: mean FV at theta 0 within 1 % of its amplitude (symmetry of the flat plate).
constexpr double kSymmetryFraction = 0.01;
// Acceptance: cycle means move < 0.2 % (of max(|mean|, oscillation amplitude)) when the
// integrator tolerances are tightened tenfold. The largest is FH at theta 20 (measured 0.12 %
// with the bounded attached flow of issue 13, 20 cycles as 10): its suction is blended with
// sqrt(f), whose slope is unbounded as a stalling strip's f nears 0; every other channel moves
// less than 0.05 %.
constexpr double kConvergenceFraction = 2e-3;

struct RfwRun {
  SimulationSummary summary;
  TimeHistory history;
  std::vector<CycleMeans> cycles;  ///< every cycle's means (TetheredRunObserver::onCycle)
  std::size_t spc = 0;
  std::size_t lastCycleStart() const { return history.loads.size() - 1 - spc; }
  const double* channel(double LoadSample::*field) const {
    return &(history.loads[lastCycleStart()].*field);
  }
  static constexpr std::size_t kStride = sizeof(LoadSample) / sizeof(double);
  Harmonic harmonic(double LoadSample::*field, int order) const {
    return periodHarmonic(channel(field), spc, order, kStride);
  }
};

RfwRun runRfw(double theta_deg, SimulationOptions opts = {}, VehicleModel v = testing::rfwRig()) {
  static_assert(sizeof(LoadSample) % sizeof(double) == 0, "LoadSample must hold only doubles");
  const FlightCoreModel model(v);
  OperatingPoint p{6.0, 4.0, theta_deg * kDegToRad, 0.0};
  RfwRun r;
  opts.record_history = true;
  r.spc = static_cast<std::size_t>(opts.samples_per_cycle);
  struct Cycles : TetheredRunObserver {
    std::vector<CycleMeans>* out;
    void onSample(double, double, const LoadSample&) override {}
    void onCycle(int, const CycleMeans& m) override { out->push_back(m); }
  } cycles;
  cycles.out = &r.cycles;
  r.summary = simulateTethered(model, p, opts, &r.history, &cycles);
  return r;
}

TEST(DynamicsTetheredRfw, ThetaZeroIsSymmetricAndFvPeaksInTheDownstroke) {
  const RfwRun r = runRfw(0.0);
  ASSERT_EQ(r.summary.status, SimulationStatus::kOk) << r.summary.message;
  const Harmonic fv1 = r.harmonic(&LoadSample::FV_N, 1);
  EXPECT_LT(std::abs(r.summary.mean.FV_N), kSymmetryFraction * fv1.amplitude);
  // FV oscillates at f: the fundamental dominates every other harmonic.
  for (int n = 2; n <= 5; ++n) EXPECT_GT(fv1.amplitude, 5.0 * r.harmonic(&LoadSample::FV_N, n).amplitude);
  // Peak in the downstroke: delta_M = A sin(w t) falls for t/T in (1/4, 3/4).
  const double peak = peakPhase(r.channel(&LoadSample::FV_N), r.spc, RfwRun::kStride);
  EXPECT_GT(peak, 0.25);
  EXPECT_LT(peak, 0.75);
  // FH is dominated by 2f (paper Fig. 2: twice the flapping frequency).
  const Harmonic fh2 = r.harmonic(&LoadSample::FH_N, 2);
  for (int n : {1, 3, 4, 5}) EXPECT_GT(fh2.amplitude, 3.0 * r.harmonic(&LoadSample::FH_N, n).amplitude);
  // A flapping flat plate at zero pitch produces net thrust.
  EXPECT_GT(r.summary.mean.FH_N, 0.0);
}

TEST(DynamicsTetheredRfw, ThetaTwentyGivesPositiveMeanLift) {
  const RfwRun r = runRfw(20.0);
  ASSERT_EQ(r.summary.status, SimulationStatus::kOk) << r.summary.message;
  EXPECT_GT(r.summary.mean.FV_N, 0.1 * r.harmonic(&LoadSample::FV_N, 1).amplitude);
}

TEST(DynamicsTetheredRfw, PeriodicSteadyStateIsDetectedNotAssumed) {
  const RfwRun r = runRfw(20.0);
  EXPECT_GE(r.summary.steady_state_cycle, 2);
  EXPECT_LE(r.summary.steady_state_cycle, 10);
  SimulationOptions one;
  one.cycles = 1;  // one cycle cannot show a periodic state
  EXPECT_EQ(runRfw(20.0, one).summary.status, SimulationStatus::kNotConverged);
}

TEST(DynamicsTetheredRfw, CycleMeansConvergeWhenTolerancesTightenTenfold) {
  for (double theta : {0.0, 20.0}) {
    SimulationOptions base;
    SimulationOptions tight = base;
    tight.rel_tol = base.rel_tol / 10.0;
    tight.abs_tol = base.abs_tol / 10.0;
    tight.separation_abs_tol = base.separation_abs_tol / 10.0;
    const RfwRun a = runRfw(theta, base), b = runRfw(theta, tight);
    struct Channel {
      double CycleMeans::*mean;
      double LoadSample::*sample;
      const char* name;
    };
    for (const Channel& c : {Channel{&CycleMeans::FV_N, &LoadSample::FV_N, "FV"},
                             Channel{&CycleMeans::FH_N, &LoadSample::FH_N, "FH"},
                             Channel{&CycleMeans::M_Nm, &LoadSample::M_Nm, "M"},
                             Channel{&CycleMeans::power_aero_W, &LoadSample::power_aero_W, "P"}}) {
      const double ma = a.summary.mean.*c.mean, mb = b.summary.mean.*c.mean;
      const double amp = std::max(b.harmonic(c.sample, 1).amplitude, b.harmonic(c.sample, 2).amplitude);
      const double scale = std::max(std::abs(mb), amp);
      EXPECT_LT(std::abs(ma - mb), kConvergenceFraction * scale)
          << c.name << " at theta " << theta << ": " << ma << " vs " << mb;
    }
  }
}

// With (almost) no air the loads are the wing inertia alone: a rod of mass m along the span gives
// FV = -2 m (L/2) (ddot(delta) cos(delta) - dot(delta)^2 sin(delta)) at theta 0 (closed form).
TEST(DynamicsTetheredRfw, InertialLoadsMatchTheRigidRodClosedForm) {
  VehicleModel v = testing::rfwRig();
  v.air.density_kgpm3 = 1e-12;
  v.wing.skin = WingSkin{};  // rod only
  const FlightCoreModel model(v, kLimitTest);  // no air, no skin
  const double m = model.wing_mass.total.mass_kg, L = 0.27;
  FlightCoreData data(model);
  std::vector<double> states(static_cast<std::size_t>(model.aeroStateCount()), 0.0);
  const BodyMotion body = tetheredBodyMotion(6.0, 0.0);
  const ControlInput ctl{4.0, 0.0};
  initialAeroStates(model, body, ctl, 0.0, states.data());
  for (double t : {0.0, 0.03, 0.07, 0.11, 0.19}) {
    LoadSample s;
    evaluateLoads(model, data, body, ctl, t, states.data(), nullptr, &s);
    const FlapState f = flapStateAt(v.flapping.amplitude_rad, 4.0, t);
    const double expected = -2.0 * m * 0.5 * L *
                            (f.delta_ddot_radps2 * std::cos(f.delta_rad) -
                             f.delta_dot_radps * f.delta_dot_radps * std::sin(f.delta_rad));
    EXPECT_NEAR(s.FV_wing_inertial_N, expected, 1e-12 * std::max(1.0, std::abs(expected)));
    EXPECT_NEAR(s.FH_wing_inertial_N, 0.0, 1e-15);
  }
}

// Over a periodic cycle the inertial loads average to zero (momentum is periodic), so the mean
// hinge power equals the mean aerodynamic power, and the propulsive efficiency is below one.
TEST(DynamicsTetheredRfw, PowerBalanceOverACycle) {
  const RfwRun r = runRfw(0.0);
  const double inertial_mean = periodMean(r.channel(&LoadSample::FV_wing_inertial_N), r.spc, RfwRun::kStride);
  const double fv_amp = r.harmonic(&LoadSample::FV_N, 1).amplitude;
  EXPECT_LT(std::abs(inertial_mean), 1e-6 * fv_amp);  // spectral accuracy of the periodic mean
  EXPECT_NEAR(r.summary.mean.power_hinge_W, r.summary.mean.power_aero_W,
              1e-3 * r.summary.mean.power_aero_W);
  const double thrust_power = r.summary.mean.FH_N * 6.0;
  EXPECT_GT(r.summary.mean.power_aero_W, thrust_power);
  EXPECT_GT(thrust_power, 0.0);
}

// The 3-D MST-TD pipeline and DeLaurier's planar model agree for small, attached, nearly
// harmonic motion (docs/theory.md 5.7: MST-TD reduces to DeLaurier there). Residual differences:
// q_ref = rho V_r^2/2 vs rho U V/2 and the resultant vs linear angle, both O((hdot/U)^2).
TEST(DynamicsTetheredRfw, MstTdMatchesDeLaurierForSmallAttachedMotion) {
  VehicleModel v = testing::rfwRig();
  v.flapping.amplitude_rad = 2.0 * kDegToRad;
  v.aero.stall_width_rad = 0.0;
  v.aero.separation_lag_tf0 = 0.0;
  const RfwRun td = runRfw(4.0, {}, v);
  v.aero.model = AeroModelKind::kDeLaurier1993;
  const RfwRun dl = runRfw(4.0, {}, v);
  ASSERT_EQ(td.summary.status, SimulationStatus::kOk);
  EXPECT_NEAR(td.summary.mean.FV_N, dl.summary.mean.FV_N, 0.01 * std::abs(dl.summary.mean.FV_N));
  EXPECT_NEAR(td.summary.mean.power_aero_W, dl.summary.mean.power_aero_W,
              0.02 * std::abs(dl.summary.mean.power_aero_W));
  const Harmonic a = td.harmonic(&LoadSample::FV_wing_aero_N, 1);
  const Harmonic b = dl.harmonic(&LoadSample::FV_wing_aero_N, 1);
  EXPECT_NEAR(a.amplitude, b.amplitude, 0.02 * b.amplitude);
  EXPECT_NEAR(a.phase_rad, b.phase_rad, 0.02);
}

// The algebraic delaurier1993 model has no state: its loads are a periodic function of time
// from the first instant, with DeLaurier's hard stall switch (issue 13 item 6). The cycle means
// are exact for that periodic solution (no false "not reached" from integrating across the
// switch), and at theta 0 the symmetric stroke makes mean FV vanish up to rounding.
constexpr double kStatelessSymmetryFraction = 1e-9;  // issue 13: 0 to 1e-9 of the amplitude

VehicleModel algebraicRfw() {
  VehicleModel v = testing::rfwRig();
  v.aero.model = AeroModelKind::kDeLaurier1993;
  v.aero.stall_width_rad = 0.0;  // DeLaurier's instantaneous attached/separated switch
  return v;
}

TEST(DynamicsTetheredRfw, AlgebraicModelIsPeriodicFromTheFirstCycleWithExactMeans) {
  for (double theta_deg : {0.0, 20.0}) {
    SimulationOptions opts;
    opts.cycles = 6;
    const RfwRun r = runRfw(theta_deg, opts, algebraicRfw());
    ASSERT_EQ(r.summary.status, SimulationStatus::kOk) << r.summary.message;
    EXPECT_EQ(r.summary.steady_state_cycle, 1);
    EXPECT_EQ(r.summary.last_cycle_change, 0.0);
    ASSERT_EQ(r.cycles.size(), 6u);
    for (const CycleMeans& c : r.cycles) EXPECT_EQ(c.FV_N, r.summary.mean.FV_N);
    // The stall switch really acts at theta 20 (the test must exercise it).
    if (theta_deg == 20.0) {
      double sep_max = 0.0;
      for (const LoadSample& s : r.history.loads) sep_max = std::max(sep_max, s.separated_fraction);
      EXPECT_GT(sep_max, 0.1);
    }
  }
  const RfwRun r0 = runRfw(0.0, {}, algebraicRfw());
  const Harmonic fv1 = r0.harmonic(&LoadSample::FV_N, 1);
  EXPECT_LT(std::abs(r0.summary.mean.FV_N), kStatelessSymmetryFraction * fv1.amplitude);
  EXPECT_LT(std::abs(r0.summary.mean.M_Nm),
            kStatelessSymmetryFraction * r0.harmonic(&LoadSample::M_Nm, 1).amplitude);
}

// The sampled mean is the integral: a 4096-point rule against the same loads integrated by the
// adaptive quadrature state of a near-stateless run (stall switch smoothed so the integrand is
// smooth), within the integrator's tolerance.
TEST(DynamicsTetheredRfw, AlgebraicModelMeansMatchAnIndependentQuadrature) {
  VehicleModel v = algebraicRfw();
  v.aero.stall_angle_max_rad = 1.5;  // attached everywhere: a smooth periodic integrand
  v.aero.stall_angle_min_rad = -1.5;
  const RfwRun sampled = runRfw(20.0, {}, v);
  // Independent: the rectangle rule over the recorded history at 100 samples per cycle is
  // spectrally accurate for this smooth load (harmonics beyond 50 f are negligible).
  double fv = 0.0, fh = 0.0;
  const std::size_t start = sampled.lastCycleStart();
  for (std::size_t i = start; i < start + sampled.spc; ++i) {
    fv += sampled.history.loads[i].FV_N;
    fh += sampled.history.loads[i].FH_N;
  }
  fv /= static_cast<double>(sampled.spc);
  fh /= static_cast<double>(sampled.spc);
  EXPECT_NEAR(sampled.summary.mean.FV_N, fv, 1e-9 * std::abs(fv) + 1e-12);
  EXPECT_NEAR(sampled.summary.mean.FH_N, fh, 1e-9 * std::abs(fh) + 1e-12);
}

}  // namespace
}  // namespace orni
