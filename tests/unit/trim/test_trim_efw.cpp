// Trim of the paper's ornithopter (studies/vehicles/efw_magpie.toml: the honest vehicle of issue
// 13, Table 1's wing read literally, one fitted discrete choice) at the paper's 12 Hz: the residual
// is the core's cycle means minus the weight; the Eq. (4) stage re-evaluated with an independent,
// tighter simulation is in equilibrium to 1e-4 W; the free-flight refined trim is the vehicle's
// committed prediction (results/paper/trim_magpie) and flies bounded; three initial guesses find
// the same trim; impossible requests end not_converged with a reason. The honest vehicle does not
// trim at the paper's Table 3 point (theta 9.2 deg, U 10.8 m/s, tail 11.85 deg): its wing makes
// more thrust than its small drag needs there (results/README.md, the literal-wing
// investigation), so it trims faster and with more tail.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "tests/support/magpie_vehicle.hpp"
#include "core/dynamics/tethered_simulation.hpp"
#include "core/model/frames.hpp"
#include "studies/runner/config/vehicle_file.hpp"
#include "trim/free_flight_trim.hpp"
#include "trim/trim_solver.hpp"

namespace orni {
namespace {

// Equilibrium tolerance of the issue: |FV - W|, |FH|, |M| / c_mean below 1e-4 W.
constexpr double kEquilibriumFraction = 1e-4;
// Multi-start agreement. The Eq. (4) stage stops anywhere inside the 1e-4 W box (~0.001-0.006 deg,
// ~0.003 m/s wide); the free-flight stage stops at a settled climb angle below 0.01 deg, which
// leaves the tail angle within ~0.01 deg and the settled means within ~0.02 deg and ~0.01 m/s.
constexpr double kSameTrimDeg = 0.05;
constexpr double kSameTrimSpeed = 0.02;
constexpr double kTrimFreqHz = 12.0;
// The honest vehicle's committed 12 Hz trim (results/paper/trim_magpie/summary.json) and how far a
// change may move it before this regression fails: a few times the multi-start spread above, far
// below any physical change (0.5 deg, 0.3 m/s, 0.5 deg: the tolerances we hold Table 3 to). It is
// the periodic orbit of test_periodic_trim.cpp (13.558 deg, 18.022 m/s, 16.584 deg; measured here
// 13.562 deg, 18.017 m/s, 16.588 deg). With the strip loads at the quarter chord spread as a flat
// plate's consistent nodal loads it moved from 16.21 deg, 16.50 m/s, 19.74 deg (the old coupling:
// 2/3 of the lift on the leading edge, 1/3 on the trailing-edge skin node); before the free flights
// were flown until settled it was 16.35 deg, 16.32 m/s, 19.98 deg, an unsettled phugoid.
constexpr double kCommittedThetaDeg = 13.56, kCommittedSpeed = 18.02, kCommittedTailDeg = 16.59;
constexpr double kThetaTolDeg = 0.1, kSpeedTol = 0.05, kTailTolDeg = 0.1;
// Paper Table 3, which the honest vehicle does not reach (within 0.5 deg and 0.3 m/s).
constexpr double kPaperThetaDeg = 9.2, kPaperSpeed = 10.8;

VehicleModel efw() { return testing::magpieVehicle(); }

TrimOptions optionsAt(const VehicleModel& /*v*/, double freq_hz) {
  TrimOptions o = defaultTrimOptions(testing::magpieDesignPoint());
  o.initial.freq_hz = freq_hz;
  return o;
}

TEST(TrimEfw, ResidualIsTheCycleMeansMinusTheWeight) {
  const VehicleModel v = efw();
  const FlightCoreModel model(v);
  const TrimOptions o = optionsAt(v, 12.0);
  const TrimReference ref = trimReference(model);
  EXPECT_DOUBLE_EQ(ref.weight_N, v.body.mass_kg * v.air.gravity_mps2);
  EXPECT_DOUBLE_EQ(ref.length_m, model.mean_chord_m);

  TrimProblem problem(ref, tetheredMeanLoads(model, o.simulation, o.derivative_cycles), o.initial,
                      o.unknowns, o.fd_steps, o.bounds);
  const std::vector<double> x = problem.solverValues(o.initial);
  EXPECT_DOUBLE_EQ(x[0], 9.2);
  EXPECT_DOUBLE_EQ(x[1], 10.8);
  EXPECT_NEAR(x[2], 11.85, 1e-12);
  double r[3];
  ASSERT_TRUE(problem.residual(x.data(), r));

  const SimulationSummary direct = simulateTethered(model, o.initial, o.simulation, nullptr);
  ASSERT_EQ(direct.status, SimulationStatus::kOk) << direct.message;
  EXPECT_DOUBLE_EQ(r[0], (direct.mean.FV_N - ref.weight_N) / ref.weight_N);
  EXPECT_DOUBLE_EQ(r[1], direct.mean.FH_N / ref.weight_N);
  EXPECT_DOUBLE_EQ(r[2], direct.mean.M_Nm / (ref.weight_N * ref.length_m));
  const TrimEvaluationRecord& rec = problem.log().front();
  EXPECT_EQ(rec.result.cycles, direct.cycles_run);
  EXPECT_TRUE(rec.result.steady);
}

TEST(TrimEfw, TrimsAtItsCommittedPointAndFliesBounded) {
  const VehicleModel v = efw();
  const FlightCoreModel model(v);
  const TrimSummary s = solveTrim(model, optionsAt(v, kTrimFreqHz));
  ASSERT_EQ(s.status, TrimStatus::kOk) << s.message;
  EXPECT_LE(s.scaled_residual_max, kEquilibriumFraction);
  EXPECT_TRUE(s.refined_in_free_flight);
  EXPECT_NEAR(s.solution.theta_rad * kRadToDeg, kCommittedThetaDeg, kThetaTolDeg);
  EXPECT_NEAR(s.solution.speed_mps, kCommittedSpeed, kSpeedTol);
  EXPECT_NEAR(s.solution.tail_angle_rad * kRadToDeg, kCommittedTailDeg, kTailTolDeg);
  // The finding, pinned: not the paper's point (more than 0.5 deg and 0.3 m/s away).
  EXPECT_GT(std::abs(s.solution.theta_rad * kRadToDeg - kPaperThetaDeg), 0.5);
  EXPECT_GT(std::abs(s.solution.speed_mps - kPaperSpeed), 0.3);
  EXPECT_EQ(s.free_flight.status, FreeFlightStatus::kBounded) << s.free_flight.message;
  EXPECT_TRUE(s.free_flight.bounded);

  // Independent re-evaluation of the Eq. (4) stage: tighter integrator and steady-state
  // tolerances, more cycles.
  SimulationOptions strict;
  strict.record_history = false;
  strict.stop_when_steady = true;
  strict.cycles = 60;
  strict.rel_tol = 1e-7;
  strict.steady_tol = 1e-6;
  const SimulationSummary check = simulateTethered(model, s.tethered_solution, strict, nullptr);
  ASSERT_EQ(check.status, SimulationStatus::kOk) << check.message;
  const double W = s.reference.weight_N;
  EXPECT_LT(std::abs(check.mean.FV_N - W), kEquilibriumFraction * W);
  EXPECT_LT(std::abs(check.mean.FH_N), kEquilibriumFraction * W);
  EXPECT_LT(std::abs(check.mean.M_Nm) / model.mean_chord_m, kEquilibriumFraction * W);
}

// Convergence check of the two-stage trim's tolerances: solveTrim at its defaults
// (Eq. (4): integrator rel_tol 1e-6, steady_tol 1e-5, equilibrium 1e-4 W; the free-flight
// refinement: settled flights at rel_tol 1e-4, settled within 0.005 deg, level within 0.01 deg)
// against a reference built from the same two stages with every one of those 100 times tighter
// (the refinement's integrator tolerance is not an option of solveTrim: the reference calls the
// stage itself, as solveTrim does). The bound: 0.05 deg and 0.02 m/s (the tail as theta), a tenth
// of the tolerances we hold Table 3 to. Measured 2026-12-06: 0.002 deg, 0.0006 m/s, 0.0003 deg
// (the reference flew 9 settled flights; 24 s in all).
TEST(TrimEfw, DefaultTolerancesAgreeWithATightReference) {
  const VehicleModel v = efw();
  const FlightCoreModel model(v);
  TrimOptions o = optionsAt(v, kTrimFreqHz);
  o.verify_free_flight = false;  // the check judges the trim, it does not move it
  const TrimSummary s = solveTrim(model, o);
  ASSERT_EQ(s.status, TrimStatus::kOk) << s.message;
  ASSERT_TRUE(s.refined_in_free_flight);

  TrimOptions tight = o;
  tight.simulation.rel_tol *= 0.01;
  tight.simulation.steady_tol *= 0.01;
  tight.residual_tol *= 0.01;
  tight.refine_in_free_flight = false;
  const TrimSummary eq4 = solveTrim(model, tight);
  ASSERT_EQ(eq4.status, TrimStatus::kOk) << eq4.message;
  SimulationOptions sim;
  sim.rel_tol = 0.01 * settledFlightRelTol(model);
  FreeFlightTrimOptions fo;
  fo.settled.cycles = o.refine_cycles;
  fo.settled.window_cycles = o.refine_cycles / 3;
  fo.settled.max_cycles = 10 * o.refine_cycles;
  fo.settled.settled_tol_rad *= 0.01;
  fo.climb_angle_tol_rad *= 0.01;
  const FreeFlightTrim ref = solveFreeFlightTrim(model, eq4.solution, sim, fo);
  ASSERT_TRUE(ref.converged) << ref.message;

  const double d_theta_deg = (s.solution.theta_rad - ref.solution.theta_rad) * kRadToDeg;
  const double d_speed_mps = s.solution.speed_mps - ref.solution.speed_mps;
  const double d_tail_deg = (s.solution.tail_angle_rad - ref.solution.tail_angle_rad) * kRadToDeg;
  EXPECT_LT(std::abs(d_theta_deg), kSameTrimDeg);
  EXPECT_LT(std::abs(d_speed_mps), kSameTrimSpeed);
  EXPECT_LT(std::abs(d_tail_deg), kSameTrimDeg);
  std::printf("default - tight: theta %.2e deg, U %.2e m/s, tail %.2e deg (%d settled flights)\n",
              d_theta_deg, d_speed_mps, d_tail_deg, ref.evaluations);
}

TEST(TrimEfw, ThreeInitialGuessesFindTheSameTrim) {
  const VehicleModel v = efw();
  const FlightCoreModel model(v);
  struct Guess {
    double theta_deg, speed_mps, tail_deg;
  };
  const Guess guesses[] = {{9.2, 10.8, 11.85}, {4.0, 8.0, 5.0}, {16.0, 13.0, 20.0}};
  std::vector<TrimSummary> runs;
  for (const Guess& g : guesses) {
    TrimOptions o = optionsAt(v, kTrimFreqHz);
    o.initial.theta_rad = g.theta_deg * kDegToRad;
    o.initial.speed_mps = g.speed_mps;
    o.initial.tail_angle_rad = g.tail_deg * kDegToRad;
    runs.push_back(solveTrim(model, o));
    ASSERT_EQ(runs.back().status, TrimStatus::kOk)
        << "from (" << g.theta_deg << ", " << g.speed_mps << ", " << g.tail_deg
        << "): " << runs.back().message;
  }
  for (std::size_t i = 1; i < runs.size(); ++i) {
    EXPECT_NEAR(runs[i].solution.theta_rad * kRadToDeg, runs[0].solution.theta_rad * kRadToDeg,
                kSameTrimDeg);
    EXPECT_NEAR(runs[i].solution.speed_mps, runs[0].solution.speed_mps, kSameTrimSpeed);
    EXPECT_NEAR(runs[i].solution.tail_angle_rad * kRadToDeg,
                runs[0].solution.tail_angle_rad * kRadToDeg, kSameTrimDeg);
  }
}

// A 10 kg vehicle at 12 Hz: not enough lift at any speed and pitch inside the bounds.
// Eq. (4) only gives the free-flight refinement its release point: a solve stopped early as
// stalled (here forced: an iteration that does not cut the cost a million-fold is a stall) but
// within 1 % of the weight is refined to the same level settled flight as the converged one
// (TrimOptions::refine_stalled_max_residual); with that allowance at zero it is not refined.
TEST(TrimEfw, StalledEquation4NearTheEquilibriumIsRefinedToTheSameTrim) {
  const VehicleModel v = efw();
  const FlightCoreModel model(v);
  TrimOptions o = optionsAt(v, kTrimFreqHz);
  o.initial.theta_rad = 13.0 * kDegToRad;  // near the trim: Eq. (4) within 1 % after a step
  o.initial.speed_mps = 17.5;
  o.initial.tail_angle_rad = 16.0 * kDegToRad;
  o.stall_iterations = 1;
  o.stall_decrease = 0.999999;
  const TrimSummary s = solveTrim(model, o);
  ASSERT_TRUE(s.refined_in_free_flight) << s.message;
  ASSERT_EQ(s.status, TrimStatus::kOk) << s.message;
  EXPECT_GT(s.scaled_residual_max, kEquilibriumFraction) << "Eq. (4) did not stall early";
  EXPECT_LE(s.scaled_residual_max, o.refine_stalled_max_residual);
  EXPECT_EQ(s.message.rfind("Eq. (4) stalled within", 0), 0u) << s.message;
  EXPECT_NEAR(s.solution.theta_rad * kRadToDeg, kCommittedThetaDeg, kThetaTolDeg);
  EXPECT_NEAR(s.solution.speed_mps, kCommittedSpeed, kSpeedTol);
  EXPECT_NEAR(s.solution.tail_angle_rad * kRadToDeg, kCommittedTailDeg, kTailTolDeg);

  o.refine_stalled_max_residual = 0.0;
  o.verify_free_flight = false;
  const TrimSummary strict = solveTrim(model, o);
  EXPECT_EQ(strict.status, TrimStatus::kNotConverged);
  EXPECT_FALSE(strict.refined_in_free_flight);
}

TEST(TrimEfw, ImpossibleRequestIsNotConvergedWithAReason) {
  VehicleModel v = efw();
  v.body.mass_kg = 10.0;
  v.body.pitch_inertia_kgm2 = 0.03;
  const FlightCoreModel model(v);
  const TrimSummary s = solveTrim(model, optionsAt(v, 12.0));
  SCOPED_TRACE(s.message);
  EXPECT_EQ(s.status, TrimStatus::kNotConverged);
  EXPECT_FALSE(s.converged);
  EXPECT_GT(s.scaled_residual_max, kEquilibriumFraction);
  EXPECT_NE(s.message.find("tolerance"), std::string::npos);
  EXPECT_EQ(s.free_flight.status, FreeFlightStatus::kSkipped);
}

TEST(TrimEfw, VehicleWithoutBodyCannotBeTrimmed) {
  VehicleModel v = efw();
  v.body.present = false;
  const FlightCoreModel model(v);
  EXPECT_THROW(solveTrim(model, optionsAt(v, 12.0)), std::invalid_argument);
}

}  // namespace
}  // namespace orni
