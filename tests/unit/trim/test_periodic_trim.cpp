// Periodic-orbit trim and Floquet stability of the free-flying vehicle (trim/periodic_trim.hpp,
// issue 16) against independent truths:
//   - the glide limit (flapping amplitude 0, rigid wing): the periodic orbit is the steady glide,
//     a root of the free-flight right-hand side, and its multipliers are exp(lambda T) of the
//     eigenvalues lambda of the right-hand side's Jacobian (the linearised longitudinal equations,
//     paper Eq. 1, with the strips' MST-TD states), phugoid and short period among them;
//   - the flexible magpie at 12 Hz: a perturbation along the leading Floquet eigenvector, flown
//     by the production free-flight integrator (ARKODE, not the shooting's recorded grid), decays
//     per flapping cycle by the leading multiplier's modulus;
//   - Arnoldi's leading multipliers equal those of the full monodromy matrix;
//   - the two-stage trim (Eq. (4), then level settled free flight) finds the same orbit.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <complex>
#include <string>
#include <vector>

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>

#include "tests/support/magpie_vehicle.hpp"
#include "core/analysis/monodromy.hpp"
#include "core/analysis/periodic_shooting.hpp"
#include "core/dynamics/free_flight.hpp"
#include "core/dynamics/free_flight_system.hpp"
#include "core/dynamics/modal_implicit_split.hpp"
#include "core/integrate/ode_integrator.hpp"
#include "core/model/frames.hpp"
#include "studies/runner/config/vehicle_file.hpp"
#include "trim/free_flight_period_map.hpp"
#include "trim/periodic_trim.hpp"
#include "trim/trim_solver.hpp"

namespace orni {
namespace {

constexpr double kFreqHz = 12.0;

VehicleModel magpie() { return testing::magpieVehicle(); }

TrimOptions periodicOptions(const VehicleModel& /*v*/) {
  TrimOptions o = defaultTrimOptions(testing::magpieDesignPoint());
  o.initial.freq_hz = kFreqHz;
  usePeriodicMethod(&o);
  o.verify_free_flight = false;  // the bounded-norm check is the two-stage trim's; not tested here
  return o;
}

// The states at the ends of `cycles` flapping periods of a free flight from the reduced state x
// (FreeFlightPeriodMap layout, SI) flown by the production integrator (ARKODE: IMEX
// ARK4(3)7L[2]SA for the flexible wing), skin friction frozen at `friction_mps`.
std::vector<std::vector<double>> flyPeriods(const FlightCoreModel& model,
                                            const std::vector<double>& x, double tail_rad,
                                            double friction_mps, int cycles, double rel_tol) {
  FreeFlightSystem sys(model, model.flexible.get(), ControlInput{kFreqHz, tail_rad},
                       orbitScaleSpeed_mps(testing::magpieDesignPoint()));
  sys.setFrictionSpeed(friction_mps);
  const int n = sys.stateCount();
  std::vector<double> y0(static_cast<std::size_t>(n), 0.0);
  std::copy(x.begin(), x.end(), y0.begin() + 2);
  IntegratorOptions io;
  io.rel_tol = rel_tol;
  sys.absoluteTolerances(rel_tol, 0.1 * rel_tol, 0.1 * rel_tol, &io.abs_tol);
  const double T = 1.0 / kFreqHz;
  io.max_step = T / 8.0;
  using Imex = ModalImex<FreeFlightSystem>;
  OdeIntegrator integ(n, Imex::rhs(sys.hasModes()), &sys, Imex::method(sys.hasModes(), sys.nonlinearWing()), io);
  integ.reset(0.0, y0.data());
  std::vector<std::vector<double>> ends;
  for (int k = 1; k <= cycles; ++k) {
    EXPECT_EQ(integ.advanceTo(k * T), IntegratorStatus::kOk) << integ.lastError();
    ends.emplace_back(integ.state() + 2, integ.state() + 2 + x.size());
  }
  return ends;
}

// One periodic trim of the flexible magpie at 12 Hz shared by the tests of this suite.
class PeriodicTrimEfw : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    vehicle_ = new VehicleModel(magpie());
    model_ = new FlightCoreModel(*vehicle_);
    trim_ = new PeriodicTrimSummary(solvePeriodicTrim(*model_, periodicOptions(*vehicle_)));
  }
  static void TearDownTestSuite() {
    delete trim_;
    delete model_;
    delete vehicle_;
  }
  static VehicleModel* vehicle_;
  static FlightCoreModel* model_;
  static PeriodicTrimSummary* trim_;
};
VehicleModel* PeriodicTrimEfw::vehicle_ = nullptr;
FlightCoreModel* PeriodicTrimEfw::model_ = nullptr;
PeriodicTrimSummary* PeriodicTrimEfw::trim_ = nullptr;

// The tolerance on the periodic residual (scaled states).
constexpr double kPeriodicResidualTol = 1e-8;

TEST_F(PeriodicTrimEfw, ConvergesToALevelPeriodicOrbitThatIsStable) {
  const PeriodicTrimSummary& s = *trim_;
  ASSERT_EQ(s.status, TrimStatus::kOk) << s.message;
  EXPECT_TRUE(s.converged);
  EXPECT_LE(s.shooting.residual_max, kPeriodicResidualTol);
  // The Eq. (4) start is solved as a start only (TrimOptions::start_only): forward differences
  // (3 runs a Jacobian) and no Jacobian at the point that met its tolerance (15 runs here, 36 with
  // central differences and that last Jacobian; the orbit moved by < 1e-6 deg and m/s).
  ASSERT_TRUE(s.stage1.converged) << s.stage1.message;
  ASSERT_FALSE(s.stage1.evaluation_log.empty());
  EXPECT_EQ(s.stage1.evaluation_log.back().purpose, TrimEvaluationPurpose::kResidual);
  EXPECT_EQ(s.stage1.derivative_evaluations % 3, 0);
  EXPECT_LE(s.stage1.evaluations, 24);
  ASSERT_EQ(s.shooting.g.size(), 1u);
  EXPECT_LE(std::abs(s.shooting.g[0]), 0.1 * kPeriodicResidualTol);  // altitude gain, m
  EXPECT_DOUBLE_EQ(s.solution.freq_hz, kFreqHz);
  // The orbit flown one period by ARKODE (adaptive, independent of the recorded grid) returns
  // within the integration tolerance: 2.8e-4 scaled at rel_tol 1e-5 (1e-3 leaves margin).
  EXPECT_LT(s.orbit_check, 1e-3);
  ASSERT_TRUE(s.floquet_valid) << s.floquet_message;
  EXPECT_TRUE(s.floquet.stable);
  EXPECT_FALSE(s.floquet.complete);
  EXPECT_EQ(s.floquet.state_count, static_cast<int>(s.orbit_start.size()));
  EXPECT_EQ(s.floquet.multipliers.size(), 8u);
  // The weak motion is the phugoid: a slowly decaying pair (|mu| 0.985 per cycle, 12.3 s period),
  // then the short period.
  const FloquetMultiplier& lead = s.floquet.multipliers[0];
  EXPECT_EQ(lead.label.rfind("phugoid-like", 0), 0u) << lead.label;
  EXPECT_NEAR(lead.modulus, 0.98491, 1e-3);
  EXPECT_TRUE(lead.oscillatory);
  EXPECT_EQ(s.floquet.multipliers[2].label.rfind("short-period-like", 0), 0u)
      << s.floquet.multipliers[2].label;
  EXPECT_LT(s.floquet.multipliers[2].modulus, 0.5);
  EXPECT_NEAR(s.floquet.margin, 1.0 - lead.modulus, 0.0);
  // The histories hold one period; their altitude returns to its start (to the integration error:
  // the sample phases join the step grid there, 5e-7 m measured).
  ASSERT_EQ(s.history.t_s.size(), 201u);
  EXPECT_NEAR(s.history.body.back().h_m, s.history.body.front().h_m, 1e-5);
  // The sampled aerodynamic power (periodic_orbit.csv) averages to the orbit's mean power, the
  // integral of the same integrand (it was never filled in, 0 in every sample): the periodic
  // rectangle rule over 200 samples, within 1 %.
  double power_sum = 0.0;
  for (std::size_t k = 0; k + 1 < s.history.samples.size(); ++k)
    power_sum += s.history.samples[k].loads.power_aero_W;
  const double sampled_mean = power_sum / static_cast<double>(s.history.samples.size() - 1);
  ASSERT_GT(s.mean.power_aero_W, 0.0);
  EXPECT_NEAR(sampled_mean / s.mean.power_aero_W, 1.0, 0.01);
}

// Convergence check of the chosen tolerances: the periodic trim at its defaults (period
// map grid rel_tol 1e-5, periodic residual 1e-8) against a reference with the grid 100 times
// tighter (1e-7) and the residual at 1e-10. Measured 2026-12-06 (printed below): the trim moves by
// 2e-4 deg, 7e-4 m/s and 5e-4 deg (bounds: 0.05 deg, 0.02 m/s, a tenth of the tolerances we
// hold Table 3 to), the flight-dynamics multipliers (phugoid, short period) by 3e-6 and 7e-5
// (bound 1e-4). The strongly damped wing
// modes (|mu| ~0.08: 92 % of the motion gone in a cycle) are not resolved by the default grid: their
// moduli move by 0.002-0.006, their arguments by up to 60 deg, and they converge only slowly with
// the grid (wing mode 13: 0.0066+0.0716i / -0.0032+0.0708i / -0.0045+0.0705i at 1e-6 / 1e-7 / 1e-8).
// So the 1e-4 holds for the multipliers that decide the stability margin, and a wing mode's
// multiplier is good to 0.01 in modulus only (docs/theory.md 10.4).
// The periodic trim on two threads (TrimOptions::jacobian_threads: the Eq. (4) start's
// forward-difference runs and the orbit's Newton Jacobian columns, each on a copy of the map):
// the same bits as on one thread.
TEST_F(PeriodicTrimEfw, TwoThreadsGiveTheSameBits) {
  const PeriodicTrimSummary& one = *trim_;
  ASSERT_EQ(one.status, TrimStatus::kOk) << one.message;
  TrimOptions o = periodicOptions(*vehicle_);
  o.jacobian_threads = 2;
  const PeriodicTrimSummary two = solvePeriodicTrim(*model_, o);
  ASSERT_EQ(two.status, TrimStatus::kOk) << two.message;
  EXPECT_EQ(two.stage1.evaluations, one.stage1.evaluations);
  EXPECT_EQ(two.stage1.solution.theta_rad, one.stage1.solution.theta_rad);
  EXPECT_EQ(two.stage1.solution.speed_mps, one.stage1.solution.speed_mps);
  EXPECT_EQ(two.shooting.period_maps, one.shooting.period_maps);
  EXPECT_EQ(two.shooting.iterations, one.shooting.iterations);
  EXPECT_EQ(two.orbit_start, one.orbit_start);
  EXPECT_EQ(two.solution.theta_rad, one.solution.theta_rad);
  EXPECT_EQ(two.solution.speed_mps, one.solution.speed_mps);
  EXPECT_EQ(two.solution.tail_angle_rad, one.solution.tail_angle_rad);
  ASSERT_TRUE(two.floquet_valid && one.floquet_valid);
  ASSERT_EQ(two.floquet.multipliers.size(), one.floquet.multipliers.size());
  for (std::size_t i = 0; i < one.floquet.multipliers.size(); ++i)
    EXPECT_EQ(two.floquet.multipliers[i].mu, one.floquet.multipliers[i].mu) << i;
}

TEST_F(PeriodicTrimEfw, DefaultTolerancesAgreeWithATightReference) {
  const PeriodicTrimSummary& s = *trim_;
  ASSERT_EQ(s.status, TrimStatus::kOk) << s.message;
  TrimOptions tight = periodicOptions(*vehicle_);
  tight.periodic.rel_tol = 1e-7;
  tight.periodic.residual_tol = 1e-10;
  const PeriodicTrimSummary ref = solvePeriodicTrim(*model_, tight);
  ASSERT_EQ(ref.status, TrimStatus::kOk) << ref.message;
  const double d_theta_deg = (s.solution.theta_rad - ref.solution.theta_rad) * kRadToDeg;
  const double d_speed_mps = s.solution.speed_mps - ref.solution.speed_mps;
  const double d_tail_deg = (s.solution.tail_angle_rad - ref.solution.tail_angle_rad) * kRadToDeg;
  EXPECT_LT(std::abs(d_theta_deg), 0.05);
  EXPECT_LT(std::abs(d_speed_mps), 0.02);
  EXPECT_LT(std::abs(d_tail_deg), 0.05);

  ASSERT_TRUE(s.floquet_valid && ref.floquet_valid);
  ASSERT_EQ(s.floquet.multipliers.size(), ref.floquet.multipliers.size());
  constexpr double kFlightDynamicsModulus = 0.2;  // phugoid 0.98, short period 0.34; wings < 0.1
  double d_flight = 0.0, d_wing_modulus = 0.0;
  int flight_count = 0;
  for (std::size_t i = 0; i < s.floquet.multipliers.size(); ++i) {
    const FloquetMultiplier& m = s.floquet.multipliers[i];
    const FloquetMultiplier& r = ref.floquet.multipliers[i];  // by modulus, pairs adjacent
    if (r.modulus > kFlightDynamicsModulus) {
      EXPECT_EQ(m.label, r.label);
      d_flight = std::max(d_flight, std::abs(m.mu - r.mu));
      ++flight_count;
    } else {
      d_wing_modulus = std::max(d_wing_modulus, std::abs(m.modulus - r.modulus));
    }
  }
  EXPECT_EQ(flight_count, 4);  // the phugoid and short-period pairs
  EXPECT_LT(d_flight, 1e-4);
  EXPECT_LT(d_wing_modulus, 0.01);
  EXPECT_LT(std::abs(s.floquet.margin - ref.floquet.margin), 1e-4);
  std::printf("default - tight: theta %.2e deg, U %.2e m/s, tail %.2e deg; flight-dynamics "
              "multipliers %.2e, wing-mode moduli %.2e\n",
              d_theta_deg, d_speed_mps, d_tail_deg, d_flight, d_wing_modulus);
}

// The multiplier check (trim.periodic.multiplier_check, on in `stability`) against a tight
// reference: every multiplier of the full monodromy at the default grid that the check calls
// resolved (|mu| >= 0.005 and a 10 times finer grid moves it by at most 5 % of |mu|; the floor
// comes from this test: without it the aero-lag multipliers below 1e-3 failed it, off by up to
// 60 % with changes of 1e-8) lies within 10 % of |mu| of its
// partner on a grid 100 times finer (twice the check's bound: the reference has errors of its own,
// about 2 % of |mu| on the wing modes at 1e-7, see above); the phugoid and short-period pairs are
// resolved; and the check does flag multipliers that the default grid gets wrong by more than
// 5 % (the strongly damped wing modes).
TEST_F(PeriodicTrimEfw, MultipliersTheCheckCallsResolvedAgreeWithATightReference) {
  TrimOptions o = periodicOptions(*vehicle_);
  o.periodic.multipliers = 0;  // all of them, as `stability`
  o.periodic.multiplier_check = true;
  const PeriodicTrimSummary s = solvePeriodicTrim(*model_, o);
  ASSERT_EQ(s.status, TrimStatus::kOk) << s.message;
  ASSERT_TRUE(s.floquet_valid && s.floquet.checked) << s.floquet.check_method;
  TrimOptions tight = o;
  tight.periodic.rel_tol = 1e-7;
  tight.periodic.residual_tol = 1e-10;
  tight.periodic.multiplier_check = false;
  const PeriodicTrimSummary ref = solvePeriodicTrim(*model_, tight);
  ASSERT_EQ(ref.status, TrimStatus::kOk) << ref.message;
  ASSERT_TRUE(ref.floquet_valid);
  MonodromyEigen reference;
  reference.ok = true;
  reference.multipliers.resize(static_cast<Eigen::Index>(ref.floquet.multipliers.size()));
  for (std::size_t k = 0; k < ref.floquet.multipliers.size(); ++k)
    reference.multipliers[static_cast<Eigen::Index>(k)] = ref.floquet.multipliers[k].mu;
  FloquetAnalysis against_reference = s.floquet;
  compareWithRefined(&against_reference, reference, "the tight reference");
  int resolved = 0, flagged_and_off = 0, flagged = 0;
  for (std::size_t i = 0; i < s.floquet.multipliers.size(); ++i) {
    const FloquetMultiplier& m = s.floquet.multipliers[i];
    const double error = against_reference.multipliers[i].refinement_change;
    if (m.resolved()) {
      ++resolved;
      EXPECT_LE(error, 2.0 * kResolvedChangeFraction * m.modulus)
          << i << " " << m.label << " mu " << m.mu << " check " << m.refinement_change;
    } else {
      ++flagged;
      if (error > kResolvedChangeFraction * m.modulus) ++flagged_and_off;
    }
  }
  for (int k = 0; k < 4; ++k)
    EXPECT_TRUE(s.floquet.multipliers[static_cast<std::size_t>(k)].resolved())
        << s.floquet.multipliers[static_cast<std::size_t>(k)].label;
  EXPECT_GT(flagged_and_off, 0);
  std::printf("%zu multipliers: %d resolved (all within 10 %% of the reference), %d flagged, %d "
              "of them off by more than 5 %%\n",
              s.floquet.multipliers.size(), resolved, flagged, flagged_and_off);
}

// The leading 8 multipliers by Arnoldi against the full monodromy matrix (107 period maps) on the
// same grid: the same numbers to the finite-difference noise (1e-6 is the Ritz tolerance).
TEST_F(PeriodicTrimEfw, ArnoldiLeadingMultipliersEqualThoseOfTheFullMonodromy) {
  const PeriodicTrimSummary& s = *trim_;
  ASSERT_TRUE(s.floquet_valid);
  FreeFlightPeriodMapOptions mo;
  mo.rel_tol = periodicOptions(*vehicle_).periodic.rel_tol;
  mo.friction_speed_mps = s.friction_speed_mps;
  mo.design_point = testing::magpieDesignPoint();  // as the trim's map
  FreeFlightPeriodMap map(*model_, mo);
  std::vector<double> p = FreeFlightPeriodMap::parameters(s.solution);
  std::string why;
  ASSERT_TRUE(map.refreshDiscretisation(s.orbit_start.data(), p.data(), &why)) << why;
  Eigen::MatrixXd M;
  long maps = 0;
  ASSERT_TRUE(monodromyByDifferences(map, s.orbit_start, p, 1e-7, &M, &maps, &why)) << why;
  EXPECT_EQ(maps, static_cast<long>(s.orbit_start.size()) + 1);
  const MonodromyEigen full = eigenOfMonodromy(M);
  ASSERT_TRUE(full.ok);
  ArnoldiOptions ao;
  ao.count = 8;
  const MonodromyEigen lead = leadingMultipliers(map, s.orbit_start, p, ao);
  ASSERT_TRUE(lead.ok) << lead.message;
  ASSERT_EQ(lead.multipliers.size(), 8);
  EXPECT_LT(lead.period_maps, 40);  // the point of Arnoldi: far fewer maps than 107
  for (Eigen::Index k = 0; k < 8; ++k)
    EXPECT_LT(std::abs(lead.multipliers[k] - full.multipliers[k]), 1e-6)
        << k << ": " << lead.multipliers[k] << " vs " << full.multipliers[k];
}

// A deviation along the leading (phugoid) eigenvector, flown by ARKODE: its component in the
// pair's eigenplane shrinks by |mu| per flapping cycle. Two flights (on the orbit and perturbed)
// at rel_tol 1e-8, the difference projected on (Re v, Im v) by least squares: c_k = a_k + i b_k
// with |c_k| = |c_0| |mu|^k for the linearised flow.
TEST_F(PeriodicTrimEfw, PerturbationAlongTheLeadingEigenvectorDecaysByItsModulusPerCycle) {
  const PeriodicTrimSummary& s = *trim_;
  ASSERT_TRUE(s.floquet_valid);
  const FloquetMultiplier& lead = s.floquet.multipliers[0];
  const std::size_t n = s.orbit_start.size();
  const double eps = 1e-3;  // scaled: 1e-3 m/s in U, 1e-4 rad in theta; linear to 1e-6
  std::vector<double> perturbed = s.orbit_start;
  for (std::size_t i = 0; i < n; ++i)
    perturbed[i] += eps * s.state_scales[i] * lead.eigenvector[static_cast<Eigen::Index>(i)].real();
  constexpr int kCycles = 24;
  constexpr double kFlightRelTol = 1e-8;
  const auto ref = flyPeriods(*model_, s.orbit_start, s.solution.tail_angle_rad,
                              s.friction_speed_mps, kCycles, kFlightRelTol);
  const auto pert = flyPeriods(*model_, perturbed, s.solution.tail_angle_rad,
                               s.friction_speed_mps, kCycles, kFlightRelTol);
  Eigen::MatrixXd B(static_cast<Eigen::Index>(n), 2);
  B.col(0) = lead.eigenvector.real();
  B.col(1) = -lead.eigenvector.imag();
  std::vector<double> amplitude;
  for (int k = 0; k < kCycles; ++k) {
    Eigen::VectorXd d(static_cast<Eigen::Index>(n));
    for (std::size_t i = 0; i < n; ++i)
      d[static_cast<Eigen::Index>(i)] =
          (pert[static_cast<std::size_t>(k)][i] - ref[static_cast<std::size_t>(k)][i]) /
          s.state_scales[i];
    const Eigen::Vector2d ab = B.colPivHouseholderQr().solve(d);
    amplitude.push_back(ab.norm());
  }
  // From cycle 4 (the other components, |mu| <= 0.38, are below 1 % of the start by then) to the
  // last.
  const double rate = std::pow(amplitude.back() / amplitude[3], 1.0 / (kCycles - 4));
  RecordProperty("measured_rate", std::to_string(rate));
  RecordProperty("leading_modulus", std::to_string(lead.modulus));
  EXPECT_NEAR(rate, lead.modulus, 0.02 * lead.modulus);  // the 2 %
  // Stricter: the decay per cycle, 1 - |mu| = 0.015, to 1 % (measured 0.01 %: rate 0.984907
  // against |mu| 0.984909; the grid map at rel_tol 1e-5 against ARKODE at 1e-8).
  EXPECT_NEAR(1.0 - rate, 1.0 - lead.modulus, 0.01 * (1.0 - lead.modulus));
}

// The two-stage trim (Eq. (4), then level settled free flight: trim/free_flight_trim.hpp) settles
// on the periodic orbit: the same theta_mean, airspeed and tail angle from two methods that share
// only the vehicle's right-hand side. Tolerances: the secant stops at |climb angle| <= 0.01 deg,
// and the settled climb angle moves by 1.87 deg per deg of tail angle here (theta by 2.45 deg, the
// airspeed by -0.97 m/s; settled flights at the two-stage trim's tail angle +-0.25 deg): up to
// 0.005 deg of tail angle, 0.013 deg of theta, 0.005 m/s; the settled means are good to 0.005 deg
// (SettledFlightOptions::settled_tol_rad), up to 0.003 deg of tail angle, 0.007 deg of theta,
// 0.003 m/s more. Measured: 0.0036 deg, 0.0046 m/s, 0.0036 deg (two-stage 13.5616 deg,
// 18.0169 m/s, 16.5875 deg). With the old strip-load coupling (before the quarter-chord flat-plate
// loads) the slopes were 1.09, 1.7 deg and -0.68 m/s per deg and the agreement 0.0002 deg,
// 0.0016 m/s, 0.0004 deg at 16.21 deg, 16.50 m/s, 19.74 deg. The two-stage trim's free flights
// used to be judged after 120 cycles with the last 40 averaged, a third of that phugoid's 132-cycle
// period (|mu| 0.986 a cycle): the window's mean climb angle was off by 0.15 deg and the trim by
// 0.14 deg, 0.18 m/s and 0.24 deg (16.35 deg, 16.32 m/s, 19.98 deg).
TEST_F(PeriodicTrimEfw, TwoStageTrimSettlesOnThePeriodicOrbit) {
  const PeriodicTrimSummary& s = *trim_;
  ASSERT_EQ(s.status, TrimStatus::kOk);
  const double theta_deg = s.solution.theta_rad * kRadToDeg;
  const double tail_deg = s.solution.tail_angle_rad * kRadToDeg;
  // The periodic trim itself (to 0.01 deg, 0.01 m/s, 0.01 deg: its rel_tol and Newton tolerance
  // move it by < 0.001).
  EXPECT_NEAR(theta_deg, 13.558, 0.01);
  EXPECT_NEAR(s.solution.speed_mps, 18.022, 0.01);
  EXPECT_NEAR(tail_deg, 16.584, 0.01);

  TrimOptions o = defaultTrimOptions(testing::magpieDesignPoint());
  o.initial.freq_hz = kFreqHz;
  o.verify_free_flight = false;
  const TrimSummary two_stage = solveTrim(*model_, o);
  ASSERT_EQ(two_stage.status, TrimStatus::kOk) << two_stage.message;
  ASSERT_TRUE(two_stage.refined_in_free_flight);
  EXPECT_NEAR(two_stage.solution.theta_rad * kRadToDeg, theta_deg, 0.03);
  EXPECT_NEAR(two_stage.solution.speed_mps, s.solution.speed_mps, 0.01);
  EXPECT_NEAR(two_stage.solution.tail_angle_rad * kRadToDeg, tail_deg, 0.02);
}

// ------------------------------------------------------------------------------------------------
// Glide limit: flapping amplitude 0, rigid wing. The orbit is an equilibrium (the steady glide at
// the given tail angle, descending: no level condition, no free control) and the monodromy is
// exp(A T) with A the Jacobian of the right-hand side there.
TEST(PeriodicTrimGlide, MultipliersAreExpLambdaTOfTheLinearisedLongitudinalEquations) {
  VehicleModel v = magpie();
  v.wing.structure = StructureLevel::kRigid;
  v.flapping.amplitude_rad = 0.0;
  const OperatingPoint guess{12.0, kFreqHz, 5.0 * kDegToRad, 10.0 * kDegToRad};
  // Amplitude 0 is the limit itself, outside the input range (0, 90) deg.
  const FlightCoreModel model(v, FlightCoreModel::Checks::kSkippedForLimitTests);
  constexpr double kFriction = 12.0;
  FreeFlightPeriodMapOptions mo;
  mo.rel_tol = 1e-8;             // the map's own integration error well below the 1e-4 asked
  mo.max_step_fraction = 0.0625;
  mo.friction_speed_mps = kFriction;
  mo.design_point = guess;
  FreeFlightPeriodMap map(model, mo);
  FreeFlightSystem sys(model, nullptr, ControlInput{kFreqHz, guess.tail_angle_rad}, kFriction);
  std::vector<double> y(static_cast<std::size_t>(sys.stateCount()), 0.0);
  sys.initialState(0.0, trimmedBodyState(guess, 0.0), y.data());
  sys.setFrictionSpeed(kFriction);
  const int n = map.stateCount();
  ASSERT_EQ(sys.powerOffset() - 2, n);
  const std::vector<double> x0(y.begin() + 2, y.begin() + 2 + n);
  ShootingOptions so;
  so.first_jacobian_states = {0, 1, 2, 3};
  const ShootingSummary s = solveShooting(map, x0, FreeFlightPeriodMap::parameters(guess), so);
  ASSERT_EQ(s.status, ShootingStatus::kConverged) << s.message;
  ASSERT_TRUE(s.jacobian_valid);

  // The steady glide: the right-hand side vanishes (to rounding, in state scales per second).
  std::copy(s.x.begin(), s.x.end(), y.begin() + 2);
  std::vector<double> f(y.size()), fp(y.size()), fm(y.size());
  sys.rhs(0.0, y.data(), f.data());
  for (int i = 0; i < n; ++i)
    EXPECT_LT(std::abs(f[static_cast<std::size_t>(i + 2)]) / map.stateScale(i), 1e-9) << i;
  EXPECT_GT(s.x[1], 5.0);  // a real glide, not a stall
  EXPECT_NEAR(s.x[3], 0.0, 1e-12);

  // A = df/dx by central differences (scaled states), its eigenvalues lambda.
  Eigen::MatrixXd A(n, n);
  for (int j = 0; j < n; ++j) {
    const double h = 1e-6 * map.stateScale(j);
    std::vector<double> yp = y, ym = y;
    yp[static_cast<std::size_t>(j + 2)] += h;
    ym[static_cast<std::size_t>(j + 2)] -= h;
    sys.rhs(0.0, yp.data(), fp.data());
    sys.rhs(0.0, ym.data(), fm.data());
    for (int i = 0; i < n; ++i)
      A(i, j) = (fp[static_cast<std::size_t>(i + 2)] - fm[static_cast<std::size_t>(i + 2)]) /
                (2.0 * h) * map.stateScale(j) / map.stateScale(i);
  }
  Eigen::EigenSolver<Eigen::MatrixXd> es(A, false);
  ASSERT_EQ(es.info(), Eigen::Success);
  const double T = 1.0 / kFreqHz;
  std::vector<std::complex<double>> expected;
  for (int k = 0; k < n; ++k) expected.push_back(std::exp(es.eigenvalues()[k] * T));

  std::vector<FloquetStateInfo> names = map.stateInfo();
  const FloquetAnalysis fa = analyseFloquet(s.monodromy, T, names);
  ASSERT_EQ(static_cast<int>(fa.multipliers.size()), n);
  constexpr double kGlideTol = 1e-4;  // the tolerance (measured 1.2e-7)
  for (const FloquetMultiplier& m : fa.multipliers) {
    double best = 1e300;
    for (const std::complex<double>& e : expected) best = std::min(best, std::abs(m.mu - e));
    EXPECT_LT(best, kGlideTol) << "multiplier " << m.mu;
  }
  // The rigid-body longitudinal modes lead: phugoid (lambda -0.13 +- 1.39i 1/s here), then the
  // short period (-15.5 +- 36i 1/s); then the strips' lag states.
  ASSERT_GE(fa.multipliers.size(), 4u);
  EXPECT_EQ(fa.multipliers[0].label.rfind("phugoid-like", 0), 0u) << fa.multipliers[0].label;
  EXPECT_EQ(fa.multipliers[2].label.rfind("short-period-like", 0), 0u) << fa.multipliers[2].label;
  EXPECT_NEAR(fa.multipliers[0].exponent_per_s.real(), std::log(fa.multipliers[0].modulus) / T,
              1e-12);
  EXPECT_TRUE(fa.multipliers[0].oscillatory);
  EXPECT_GT(fa.multipliers[0].period_s, 1.0);  // the phugoid is slow
  EXPECT_LT(fa.multipliers[2].period_s, 0.5);  // the short period is fast
}

// A vehicle far too heavy for its wings: no Eq. (4) start, reported (no exception, no NaN in the
// reported trim point: it is the start's last iterate).
TEST(PeriodicTrimFailure, ImpossibleRequestIsNotConvergedWithAReason) {
  VehicleModel v = magpie();
  v.body.mass_kg = 10.0;
  v.body.pitch_inertia_kgm2 = 0.03;
  const FlightCoreModel model(v);
  const PeriodicTrimSummary s = solvePeriodicTrim(model, periodicOptions(v));
  EXPECT_EQ(s.status, TrimStatus::kNotConverged);
  EXPECT_FALSE(s.converged);
  EXPECT_FALSE(s.floquet_valid);
  EXPECT_NE(s.message.find("Eq. (4)"), std::string::npos) << s.message;
  EXPECT_TRUE(std::isfinite(s.solution.theta_rad) && std::isfinite(s.solution.speed_mps) &&
              std::isfinite(s.solution.tail_angle_rad));
  EXPECT_EQ(s.free_flight.status, FreeFlightStatus::kSkipped);
}

}  // namespace
}  // namespace orni
