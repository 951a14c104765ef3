// The trim solver machinery against analytic cycle-mean loads with a known equilibrium
// (docs/design.md 7.9: known optimum, finite-difference check of the Jacobian): residual scaling,
// the central/one-sided Jacobian, convergence to the root, bounds, least squares, failures, options.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/model/frames.hpp"
#include "trim/trim_solver.hpp"

namespace orni {
namespace {

// The known equilibrium of the analytic loads.
constexpr double kThetaStarDeg = 8.0;
constexpr double kSpeedStar = 9.0;
constexpr double kTailStarDeg = 15.0;
constexpr double kWeight = 1.2;      // N
constexpr double kLength = 0.08;     // m
// Tolerances (named, docs/design.md 7.9).
constexpr double kRootTolDeg = 1e-6;       // solved root vs the known one, deg
constexpr double kRootTolSpeed = 1e-6;     // m/s
constexpr double kCentralJacobianRel = 1e-5;  // central difference, O(h^2) with h = 0.05 deg
constexpr double kOneSidedJacobianRel = 2e-2; // one-sided at a bound, O(h)

const TrimReference kRef{kWeight, kLength};

// Lift ~ U^2 sin(theta), thrust minus drag ~ 1 - (U/U*)^2, a pitching moment linear in all three:
// nonlinear, coupled, with the single root (theta*, U*, delta*) in the default bounds.
CycleMeans analyticMeans(const OperatingPoint& p) {
  const double th_s = kThetaStarDeg * kDegToRad, d_s = kTailStarDeg * kDegToRad;
  const double u = p.speed_mps / kSpeedStar;
  CycleMeans m;
  m.FV_N = kWeight * u * u * std::sin(p.theta_rad) / std::sin(th_s);
  m.FH_N = 0.4 * (1.0 - u * u) - 0.5 * (p.theta_rad - th_s);
  m.M_Nm = -0.02 * (p.tail_angle_rad - d_s) - 0.01 * (p.theta_rad - th_s) +
           0.001 * (p.speed_mps - kSpeedStar);
  return m;
}

MeanLoadsFunction analyticLoads(int* calls = nullptr) {
  return [calls](const OperatingPoint& p, TrimEvaluationPurpose) {
    if (calls) ++*calls;
    PeriodicEvaluation e;
    e.ok = true;
    e.steady = true;
    e.cycles = 1;
    e.mean = analyticMeans(p);
    return e;
  };
}

TrimOptions analyticOptions() {
  TrimOptions o;
  o.initial = OperatingPoint{5.0, 12.0, 3.0 * kDegToRad, 0.0};
  o.residual_tol = 1e-10;
  o.verify_free_flight = false;
  return o;
}

TEST(TrimAnalytic, ScaledResidualIsEquationFourOverWeight) {
  const TrimResidual r{0.12, -0.06, 0.0024};
  const auto s = scaledResidual(kRef, r);
  EXPECT_DOUBLE_EQ(s[0], 0.1);
  EXPECT_DOUBLE_EQ(s[1], -0.05);
  EXPECT_DOUBLE_EQ(s[2], 0.025);
  EXPECT_DOUBLE_EQ(scaledResidualMax(kRef, r), 0.1);
}

TEST(TrimAnalytic, UnknownNamesRoundTrip) {
  for (TrimUnknown u : kAllTrimUnknowns) {
    EXPECT_EQ(parseTrimUnknown(trimUnknownName(u)), u);
    EXPECT_EQ(parseTrimUnknown(trimUnknownShortName(u)), u);
    OperatingPoint p;
    setUnknownValue(&p, u, 0.25);
    EXPECT_DOUBLE_EQ(unknownValue(p, u), 0.25);
  }
  EXPECT_FALSE(parseTrimUnknown("theta_deg").has_value());
}

TEST(TrimAnalytic, ResidualIsCachedPerPoint) {
  int calls = 0;
  const TrimOptions o = analyticOptions();
  TrimProblem problem(kRef, analyticLoads(&calls), o.initial, o.unknowns, o.fd_steps, o.bounds);
  const std::vector<double> x = problem.solverValues(o.initial);
  double r1[3], r2[3];
  ASSERT_TRUE(problem.residual(x.data(), r1));
  ASSERT_TRUE(problem.residual(x.data(), r2));
  EXPECT_EQ(calls, 1);
  for (int i = 0; i < 3; ++i) EXPECT_EQ(r1[i], r2[i]);
  const CycleMeans m = analyticMeans(o.initial);
  EXPECT_DOUBLE_EQ(r1[0], (m.FV_N - kWeight) / kWeight);
  EXPECT_DOUBLE_EQ(r1[1], m.FH_N / kWeight);
  EXPECT_DOUBLE_EQ(r1[2], m.M_Nm / (kWeight * kLength));
}

// Analytic Jacobian of the scaled residual in solver units (deg, m/s, deg).
void analyticJacobian(const OperatingPoint& p, double J[3][3]) {
  const double th_s = kThetaStarDeg * kDegToRad;
  const double u = p.speed_mps / kSpeedStar;
  const double d = kDegToRad;
  J[0][0] = u * u * std::cos(p.theta_rad) / std::sin(th_s) * d;
  J[0][1] = 2.0 * u / kSpeedStar * std::sin(p.theta_rad) / std::sin(th_s);
  J[0][2] = 0.0;
  J[1][0] = -0.5 / kWeight * d;
  J[1][1] = -0.8 * u / kSpeedStar / kWeight;
  J[1][2] = 0.0;
  J[2][0] = -0.01 / (kWeight * kLength) * d;
  J[2][1] = 0.001 / (kWeight * kLength);
  J[2][2] = -0.02 / (kWeight * kLength) * d;
}

TEST(TrimAnalytic, CentralDifferenceJacobianMatchesTheAnalyticOne) {
  const TrimOptions o = analyticOptions();
  TrimProblem problem(kRef, analyticLoads(), o.initial, o.unknowns, o.fd_steps, o.bounds);
  const std::vector<double> x = problem.solverValues(o.initial);
  double Jfd[9];
  ASSERT_TRUE(problem.jacobian(x.data(), Jfd));
  double J[3][3];
  analyticJacobian(o.initial, J);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      EXPECT_NEAR(Jfd[i * 3 + j], J[i][j], kCentralJacobianRel * (std::abs(J[i][j]) + 1e-3))
          << "row " << i << " column " << j;
  // Six derivative runs: two per unknown.
  int derivative_runs = 0;
  for (const TrimEvaluationRecord& r : problem.log())
    derivative_runs += r.purpose == TrimEvaluationPurpose::kDerivative;
  EXPECT_EQ(derivative_runs, 6);
}

TEST(TrimAnalytic, OneSidedDifferenceAtABound) {
  TrimOptions o = analyticOptions();
  o.initial.speed_mps = o.bounds[trimIndex(TrimUnknown::kSpeed)].upper;  // on the upper bound
  TrimProblem problem(kRef, analyticLoads(), o.initial, o.unknowns, o.fd_steps, o.bounds);
  const std::vector<double> x = problem.solverValues(o.initial);
  double Jfd[9];
  ASSERT_TRUE(problem.jacobian(x.data(), Jfd));
  for (const TrimEvaluationRecord& r : problem.log())
    EXPECT_LE(r.point.speed_mps, o.bounds[trimIndex(TrimUnknown::kSpeed)].upper);
  double J[3][3];
  analyticJacobian(o.initial, J);
  for (int i = 0; i < 3; ++i)
    EXPECT_NEAR(Jfd[i * 3 + 1], J[i][1], kOneSidedJacobianRel * (std::abs(J[i][1]) + 1e-3));
}

// The start-only solve's Jacobian (TrimOptions::start_only): forward differences, first order in
// the step (h = 0.05 deg / 0.02 m/s on curvatures of order 1: the relative error is O(h), as at a
// bound), one run per unknown and the residual run at x, backward on the upper bound.
TEST(TrimAnalytic, ForwardDifferenceJacobianUsesOneRunPerUnknown) {
  const TrimOptions o = analyticOptions();
  for (const bool on_upper_bound : {false, true}) {
    OperatingPoint at = o.initial;
    if (on_upper_bound) at.speed_mps = o.bounds[trimIndex(TrimUnknown::kSpeed)].upper;
    TrimProblem problem(kRef, analyticLoads(), at, o.unknowns, o.fd_steps, o.bounds,
                        /*forward_differences=*/true);
    const std::vector<double> x = problem.solverValues(at);
    double Jfd[9];
    ASSERT_TRUE(problem.jacobian(x.data(), Jfd));
    double J[3][3];
    analyticJacobian(at, J);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        EXPECT_NEAR(Jfd[i * 3 + j], J[i][j], kOneSidedJacobianRel * (std::abs(J[i][j]) + 1e-3))
            << "row " << i << " column " << j << (on_upper_bound ? " (on the bound)" : "");
    int derivative_runs = 0, residual_runs = 0;
    for (const TrimEvaluationRecord& r : problem.log()) {
      derivative_runs += r.purpose == TrimEvaluationPurpose::kDerivative;
      residual_runs += r.purpose == TrimEvaluationPurpose::kResidual;
      EXPECT_LE(r.point.speed_mps, o.bounds[trimIndex(TrimUnknown::kSpeed)].upper);
    }
    EXPECT_EQ(derivative_runs, 3);
    EXPECT_EQ(residual_runs, 1);  // r(x), reused by a residual call at x
    double r[3];
    ASSERT_TRUE(problem.residual(x.data(), r));
    EXPECT_EQ(problem.log().size(), 4u);
  }
}

// A start-only solve reaches the tolerance with fewer runs, and ends on the residual run that met
// it: no Jacobian is made at the converged point (the central solve makes one there, 6 runs).
TEST(TrimAnalytic, StartOnlySolveMakesNoJacobianAtTheConvergedPoint) {
  TrimOptions o = analyticOptions();
  o.residual_tol = 1e-3;  // the periodic method's start
  const TrimSummary central = solveTrim(kRef, analyticLoads(), o);
  o.start_only = true;
  const TrimSummary start = solveTrim(kRef, analyticLoads(), o);
  ASSERT_TRUE(central.converged) << central.message;
  ASSERT_TRUE(start.converged) << start.message;
  EXPECT_LE(start.scaled_residual_max, 1e-3);
  ASSERT_FALSE(start.evaluation_log.empty());
  const TrimEvaluationRecord& last = start.evaluation_log.back();
  EXPECT_EQ(last.purpose, TrimEvaluationPurpose::kResidual);
  EXPECT_LE(last.scaled_max, 1e-3);
  EXPECT_EQ(central.evaluation_log.back().purpose, TrimEvaluationPurpose::kDerivative);
  EXPECT_LT(start.evaluations, central.evaluations);
  EXPECT_EQ(start.evaluations, start.residual_evaluations + start.derivative_evaluations);
}

// Two solves record the same evaluations: every point, purpose, outcome and residual, in order.
void expectSameSolve(const TrimSummary& a, const TrimSummary& b, const std::string& what) {
  SCOPED_TRACE(what);
  EXPECT_EQ(a.status, b.status);
  EXPECT_EQ(a.message, b.message);
  EXPECT_EQ(a.iterations, b.iterations);
  EXPECT_EQ(a.solution.theta_rad, b.solution.theta_rad);
  EXPECT_EQ(a.solution.speed_mps, b.solution.speed_mps);
  EXPECT_EQ(a.solution.tail_angle_rad, b.solution.tail_angle_rad);
  EXPECT_EQ(a.failed_evaluations, b.failed_evaluations);
  ASSERT_EQ(a.evaluation_log.size(), b.evaluation_log.size());
  for (std::size_t i = 0; i < a.evaluation_log.size(); ++i) {
    const TrimEvaluationRecord &x = a.evaluation_log[i], &y = b.evaluation_log[i];
    EXPECT_EQ(x.index, y.index);
    EXPECT_EQ(x.iteration, y.iteration);
    EXPECT_EQ(x.purpose, y.purpose);
    EXPECT_EQ(x.point.theta_rad, y.point.theta_rad);
    EXPECT_EQ(x.point.speed_mps, y.point.speed_mps);
    EXPECT_EQ(x.point.tail_angle_rad, y.point.tail_angle_rad);
    EXPECT_EQ(x.result.ok, y.result.ok);
    EXPECT_EQ(x.residual.FV_N, y.residual.FV_N);
    EXPECT_EQ(x.residual.FH_N, y.residual.FH_N);
    EXPECT_EQ(x.residual.M_Nm, y.residual.M_Nm);
  }
}

// The runs of one Jacobian on several threads (TrimOptions::jacobian_threads): the same solve and
// the same log as on one thread, with central and with forward differences, and when a derivative
// run fails (the log stops at the first failure, as the sequential loop does; the runs after it
// are made and dropped).
TEST(TrimAnalytic, JacobianThreadsGiveTheSameSolveAndLog) {
  for (bool forward : {false, true}) {
    TrimOptions o = analyticOptions();
    o.start_only = forward;
    const TrimSummary one = solveTrim(kRef, analyticLoads(), o);
    ASSERT_TRUE(one.converged) << one.message;
    for (int threads : {2, 3, 7}) {
      o.jacobian_threads = threads;
      expectSameSolve(one, solveTrim(kRef, analyticLoads(), o),
                      (forward ? "forward, " : "central, ") + std::to_string(threads) + " threads");
    }
  }
  // Loads that fail below theta 2.99 deg: the first Jacobian's second run (theta - step) fails.
  const MeanLoadsFunction failing = [](const OperatingPoint& p, TrimEvaluationPurpose) {
    PeriodicEvaluation e;
    e.ok = p.theta_rad > 2.99 * kDegToRad;
    e.message = e.ok ? "" : "diverged (test)";
    e.mean = analyticMeans(p);
    return e;
  };
  TrimOptions o = analyticOptions();
  const TrimSummary one = solveTrim(kRef, failing, o);
  ASSERT_GT(one.failed_evaluations, 0);
  EXPECT_EQ(one.evaluation_log[2].purpose, TrimEvaluationPurpose::kDerivative);
  EXPECT_FALSE(one.evaluation_log[2].result.ok);  // residual, theta + step, theta - step
  o.jacobian_threads = 2;
  expectSameSolve(one, solveTrim(kRef, failing, o), "a failed derivative run, 2 threads");
}

TEST(TrimAnalytic, SolvesToTheKnownEquilibrium) {
  int calls = 0;
  const TrimSummary s = solveTrim(kRef, analyticLoads(&calls), analyticOptions());
  ASSERT_EQ(s.status, TrimStatus::kOk) << s.message << "\n" << s.ceres_report;
  EXPECT_TRUE(s.converged);
  EXPECT_FALSE(s.least_squares);
  EXPECT_EQ(s.termination, TrimTermination::kResidualTolerance);
  EXPECT_NEAR(s.solution.theta_rad * kRadToDeg, kThetaStarDeg, kRootTolDeg);
  EXPECT_NEAR(s.solution.speed_mps, kSpeedStar, kRootTolSpeed);
  EXPECT_NEAR(s.solution.tail_angle_rad * kRadToDeg, kTailStarDeg, kRootTolDeg);
  EXPECT_DOUBLE_EQ(s.solution.freq_hz, 12.0);  // not an unknown: held
  EXPECT_LE(s.scaled_residual_max, 1e-10);
  // The reported residual is the loads at the solution minus the weight.
  const CycleMeans m = analyticMeans(s.solution);
  EXPECT_DOUBLE_EQ(s.residual.FV_N, m.FV_N - kWeight);
  EXPECT_DOUBLE_EQ(s.residual.FH_N, m.FH_N);
  EXPECT_DOUBLE_EQ(s.residual.M_Nm, m.M_Nm);
  EXPECT_EQ(s.evaluations, calls);
  EXPECT_EQ(s.evaluations, s.residual_evaluations + s.derivative_evaluations);
  EXPECT_EQ(static_cast<int>(s.evaluation_log.size()), s.evaluations);
  ASSERT_FALSE(s.iteration_log.empty());
  EXPECT_EQ(s.iteration_log.front().iteration, 0);
  EXPECT_EQ(s.iterations, s.iteration_log.back().iteration);
  EXPECT_LE(s.iteration_log.back().scaled_max, 1e-10);
  EXPECT_FALSE(s.BriefReport().empty());
  EXPECT_EQ(s.free_flight.status, FreeFlightStatus::kSkipped);
}

TEST(TrimAnalytic, DefaultToleranceStopsAtOneTenThousandthOfTheWeight) {
  TrimOptions o = analyticOptions();
  o.residual_tol = 1e-4;
  const TrimSummary s = solveTrim(kRef, analyticLoads(), o);
  ASSERT_TRUE(s.converged) << s.message;
  EXPECT_LE(std::abs(s.residual.FV_N), 1e-4 * kWeight);
  EXPECT_LE(std::abs(s.residual.FH_N), 1e-4 * kWeight);
  EXPECT_LE(std::abs(s.residual.M_Nm) / kLength, 1e-4 * kWeight);
}

TEST(TrimAnalytic, RootOutsideTheBoundsIsNotConvergedWithTheBoundNamed) {
  TrimOptions o = analyticOptions();
  o.bounds[trimIndex(TrimUnknown::kTailAngle)].upper = 10.0 * kDegToRad;  // delta* = 15 deg
  const TrimSummary s = solveTrim(kRef, analyticLoads(), o);
  EXPECT_EQ(s.status, TrimStatus::kNotConverged);
  EXPECT_FALSE(s.converged);
  ASSERT_EQ(s.at_bound.size(), 1u);
  EXPECT_NE(s.at_bound[0].find("tail_angle_deg at its upper bound 10 deg"), std::string::npos);
  EXPECT_NE(s.message.find("no equilibrium inside the bounds"), std::string::npos) << s.message;
  EXPECT_NEAR(s.solution.tail_angle_rad * kRadToDeg, 10.0, 1e-9);
}

TEST(TrimAnalytic, FewerUnknownsIsALeastSquaresSolve) {
  TrimOptions o = analyticOptions();
  o.unknowns = {TrimUnknown::kThetaMean, TrimUnknown::kSpeed};
  o.initial.tail_angle_rad = 5.0 * kDegToRad;  // held away from delta*: M cannot vanish
  const TrimSummary s = solveTrim(kRef, analyticLoads(), o);
  EXPECT_TRUE(s.least_squares);
  EXPECT_EQ(s.status, TrimStatus::kNotConverged);
  EXPECT_NE(s.message.find("least-squares"), std::string::npos) << s.message;
  EXPECT_DOUBLE_EQ(s.solution.tail_angle_rad, 5.0 * kDegToRad);

  // With the held value at its equilibrium value the least-squares solve finds the equilibrium.
  o.initial.tail_angle_rad = kTailStarDeg * kDegToRad;
  const TrimSummary exact = solveTrim(kRef, analyticLoads(), o);
  EXPECT_TRUE(exact.least_squares);
  EXPECT_EQ(exact.status, TrimStatus::kOk) << exact.message;
  EXPECT_NEAR(exact.solution.speed_mps, kSpeedStar, kRootTolSpeed);
}

TEST(TrimAnalytic, FailureAtTheInitialGuessIsReported) {
  const MeanLoadsFunction failing = [](const OperatingPoint&, TrimEvaluationPurpose) {
    PeriodicEvaluation e;
    e.ok = false;
    e.message = "integrator failure (test)";
    return e;
  };
  ::testing::internal::CaptureStderr();
  const TrimSummary s = solveTrim(kRef, failing, analyticOptions());
  // Ceres's own log line ("Terminating: Residual and Jacobian evaluation failed") stays off the
  // console: the summary says it.
  EXPECT_EQ(::testing::internal::GetCapturedStderr(), "");
  EXPECT_EQ(s.status, TrimStatus::kNotConverged);
  EXPECT_EQ(s.termination, TrimTermination::kSimulationFailure);
  EXPECT_NE(s.message.find("integrator failure (test)"), std::string::npos) << s.message;
  EXPECT_EQ(s.failed_evaluations, 1);
}

TEST(TrimAnalytic, InfeasibleTrialPointsAreStepsRejected) {
  // The loads fail for U > 11 m/s; the root (U* = 9) is still found from U = 5.
  const MeanLoadsFunction loads = [](const OperatingPoint& p, TrimEvaluationPurpose) {
    PeriodicEvaluation e;
    e.ok = p.speed_mps <= 11.0;
    e.mean = analyticMeans(p);
    if (!e.ok) e.message = "diverged (test)";
    return e;
  };
  const TrimSummary s = solveTrim(kRef, loads, analyticOptions());
  EXPECT_EQ(s.status, TrimStatus::kOk) << s.message;
  EXPECT_NEAR(s.solution.speed_mps, kSpeedStar, kRootTolSpeed);
}

TEST(TrimAnalytic, OptionsValidation) {
  std::string why;
  TrimOptions o = analyticOptions();
  EXPECT_TRUE(o.IsValid(&why)) << why;

  TrimOptions reversed = o;
  reversed.bounds[trimIndex(TrimUnknown::kSpeed)] = TrimBounds{30.0, 2.0};
  EXPECT_FALSE(reversed.IsValid(&why));
  EXPECT_NE(why.find("speed_mps"), std::string::npos) << why;

  TrimOptions four = o;
  four.unknowns.push_back(TrimUnknown::kFreq);
  EXPECT_FALSE(four.IsValid(&why));

  TrimOptions twice = o;
  twice.unknowns = {TrimUnknown::kSpeed, TrimUnknown::kSpeed};
  EXPECT_FALSE(twice.IsValid(&why));
  EXPECT_NE(why.find("distinct"), std::string::npos) << why;

  TrimOptions outside = o;
  outside.initial.theta_rad = 60.0 * kDegToRad;
  EXPECT_FALSE(outside.IsValid(&why));
  EXPECT_NE(why.find("theta_mean_deg"), std::string::npos) << why;

  TrimOptions narrow = o;
  narrow.bounds[trimIndex(TrimUnknown::kThetaMean)] = TrimBounds{2.9 * kDegToRad, 3.0 * kDegToRad};
  EXPECT_FALSE(narrow.IsValid(&why));  // narrower than four finite-difference steps

  EXPECT_THROW(solveTrim(kRef, analyticLoads(), outside), std::invalid_argument);
}

}  // namespace
}  // namespace orni
