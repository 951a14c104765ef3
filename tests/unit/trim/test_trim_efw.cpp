// Trim of the paper's ornithopter (studies/vehicles/efw_magpie.toml) with the periodic tethered
// core: the residual is the core's cycle means minus the weight; a solved trim re-evaluated with an
// independent, tighter simulation is in equilibrium to 1e-4 W; three initial guesses find the same
// trim; impossible requests end not_converged with a reason.
//
// The committed vehicle has no equilibrium at 12 Hz with the tail inside its default bounds (excess
// thrust; see README.md, "ornithopter trim"), so the converging cases fly at 6 Hz, where one exists
// (about theta 14.35 deg, U 8.15 m/s, delta_T 30.3 deg). These tests check the solver, not the
// calibration of the vehicle: they do not pin the trim values.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/dynamics/tethered_simulation.hpp"
#include "core/model/frames.hpp"
#include "studies/runner/config/vehicle_file.hpp"
#include "trim/trim_solver.hpp"

namespace orni {
namespace {

// Equilibrium tolerance of the issue: |FV - W|, |FH|, |M| / c_mean below 1e-4 W.
constexpr double kEquilibriumFraction = 1e-4;
// Multi-start agreement. The solve stops anywhere inside the 1e-4 W box; with the sensitivities at
// the 6 Hz trim (dFV/dtheta ~ 0.09 N/deg, dM/ddelta_T ~ 1.7e-3 N m/deg, dFH/dU ~ -0.04 N/(m/s),
// from its Jacobian runs) that box is ~0.001 deg, ~0.006 deg and ~0.003 m/s wide; allow a few times
// that (observed: 1e-4).
constexpr double kSameTrimDeg = 0.02;
constexpr double kSameTrimSpeed = 0.01;
constexpr double kTrimFreqHz = 6.0;

VehicleModel efw() {
  return studies::loadVehicleFile(std::string(ORNI_SOURCE_DIR) +
                                  "/studies/vehicles/efw_magpie.toml");
}

TrimOptions optionsAt(const VehicleModel& v, double freq_hz) {
  TrimOptions o = defaultTrimOptions(v);
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

TEST(TrimEfw, SolvedTrimIsInEquilibriumWhenReevaluatedIndependently) {
  const VehicleModel v = efw();
  const FlightCoreModel model(v);
  const TrimSummary s = solveTrim(model, optionsAt(v, kTrimFreqHz));
  ASSERT_EQ(s.status, TrimStatus::kOk) << s.message;
  EXPECT_LE(s.scaled_residual_max, kEquilibriumFraction);
  // The converged trim is flown freely (paper Eq. 5): a verdict with a reason, never "not run".
  EXPECT_TRUE(s.free_flight.status == FreeFlightStatus::kBounded ||
              s.free_flight.status == FreeFlightStatus::kUnbounded)
      << toString(s.free_flight.status) << ": " << s.free_flight.message;
  EXPECT_FALSE(s.free_flight.message.empty());

  // Independent re-evaluation: tighter integrator and steady-state tolerances, more cycles.
  SimulationOptions strict;
  strict.record_history = false;
  strict.stop_when_steady = true;
  strict.cycles = 60;
  strict.rel_tol = 1e-7;
  strict.steady_tol = 1e-6;
  const SimulationSummary check = simulateTethered(model, s.solution, strict, nullptr);
  ASSERT_EQ(check.status, SimulationStatus::kOk) << check.message;
  const double W = s.reference.weight_N;
  EXPECT_LT(std::abs(check.mean.FV_N - W), kEquilibriumFraction * W);
  EXPECT_LT(std::abs(check.mean.FH_N), kEquilibriumFraction * W);
  EXPECT_LT(std::abs(check.mean.M_Nm) / model.mean_chord_m, kEquilibriumFraction * W);
}

TEST(TrimEfw, ThreeInitialGuessesFindTheSameTrim) {
  const VehicleModel v = efw();
  const FlightCoreModel model(v);
  struct Guess {
    double theta_deg, speed_mps, tail_deg;
  };
  const Guess guesses[] = {{9.2, 10.8, 11.85}, {5.0, 6.0, 0.0}, {25.0, 12.0, 40.0}};
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

// A heavy vehicle: 1 kg at 6 Hz (lift needs a speed where drag exceeds the flapping thrust) and
// 10 kg at 12 Hz (not enough lift at any speed inside the bounds). At 12 Hz a 1 kg vehicle does
// trim in this model, near 28 m/s, because the wing's mean thrust grows with speed.
TEST(TrimEfw, ImpossibleRequestsAreNotConvergedWithAReason) {
  struct Case {
    double mass_kg, freq_hz;
  };
  for (const Case c : {Case{1.0, 6.0}, Case{10.0, 12.0}}) {
    VehicleModel v = efw();
    v.body.mass_kg = c.mass_kg;
    const FlightCoreModel model(v);
    const TrimSummary s = solveTrim(model, optionsAt(v, c.freq_hz));
    SCOPED_TRACE(std::to_string(c.mass_kg) + " kg at " + std::to_string(c.freq_hz) + " Hz: " +
                 s.message);
    EXPECT_EQ(s.status, TrimStatus::kNotConverged);
    EXPECT_FALSE(s.converged);
    EXPECT_GT(s.scaled_residual_max, kEquilibriumFraction);
    EXPECT_NE(s.message.find("tolerance"), std::string::npos);
    EXPECT_FALSE(s.at_bound.empty());
    EXPECT_EQ(s.free_flight.status, FreeFlightStatus::kSkipped);
  }
}

TEST(TrimEfw, VehicleWithoutBodyCannotBeTrimmed) {
  VehicleModel v = efw();
  v.body.present = false;
  const FlightCoreModel model(v);
  EXPECT_THROW(solveTrim(model, optionsAt(v, 12.0)), std::invalid_argument);
}

}  // namespace
}  // namespace orni
