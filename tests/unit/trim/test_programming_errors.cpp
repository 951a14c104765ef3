// Programming errors fail the run; numerical failures are outcomes (core/model/invariant.hpp).
// A misspelt field name inside a design evaluation or a trim point must not be recorded as a
// "failed evaluation" and optimised around: it propagates out of the optimiser (NLopt) and out
// of Ceres (which is left without an exception and aborted, then the error is rethrown).
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/model/field_table.hpp"
#include "core/model/invalid_model_error.hpp"
#include "core/model/invariant.hpp"
#include "optimize/optimizer.hpp"
#include "trim/trim_solver.hpp"

namespace orni {
namespace {

TEST(Invariant, DemandThrowsALogicErrorNamingThePlace) {
  EXPECT_NO_THROW(ORNI_DEMAND(1 + 1 == 2, "arithmetic"));
  try {
    ORNI_DEMAND(1 + 1 == 3, "arithmetic holds");
    ADD_FAILURE() << "no throw";
  } catch (const std::logic_error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("invariant violated: arithmetic holds (1 + 1 == 3 at "), std::string::npos)
        << what;
    EXPECT_NE(what.find("test_programming_errors.cpp:"), std::string::npos) << what;
  }
}

TEST(Invariant, WhichErrorsAreProgrammingErrors) {
  EXPECT_TRUE(isProgrammingError(std::logic_error("misspelt")));
  EXPECT_TRUE(isProgrammingError(std::out_of_range("index")));
  EXPECT_FALSE(isProgrammingError(std::invalid_argument("a value outside its rules")));
  EXPECT_FALSE(isProgrammingError(InvalidModelError("members cross")));
  EXPECT_FALSE(isProgrammingError(std::runtime_error("did not converge")));
}

/// A design problem whose evaluation reads a field by a misspelt name (a programming error) at
/// x > 3.5, and fails numerically (an outcome) at y > 3.
class MisspeltDesign final : public opt::Problem {
 public:
  int variableCount() const override { return 2; }
  int constraintCount() const override { return 0; }
  opt::Evaluation evaluate(const std::vector<double>& x, opt::ProblemWorkspace&) const override {
    if (x[1] > 3.0) throw std::runtime_error("the periodic run diverged");
    if (x[0] > 3.5) (void)field("tail.arm_mm");  // misspelt: "tail.arm_m"
    opt::Evaluation e;
    e.objective = (x[0] - 1.0) * (x[0] - 1.0) + (x[1] - 2.0) * (x[1] - 2.0);
    return e;
  }
};

TEST(ProgrammingErrors, AMisspeltFieldInADesignEvaluationFailsTheRun) {
  MisspeltDesign p;
  opt::VariableBox box;
  box.lower = {-5.0, -5.0};
  box.upper = {5.0, 5.0};
  box.initial = {3.0, -4.0};  // the first simplex step in x lands at x = 4
  opt::OptimizerOptions o;
  o.algorithm = opt::Algorithm::kCobyla;
  o.max_evaluations = 50;
  try {
    (void)opt::minimize(p, box, o);
    ADD_FAILURE() << "the run finished: the misspelt field was taken for a failed evaluation";
  } catch (const std::logic_error& e) {
    EXPECT_NE(std::string(e.what()).find("tail.arm_mm"), std::string::npos) << e.what();
  }
  // A numerical failure stays an outcome: the run goes on and reports it.
  box.initial = {0.0, 2.5};  // steps into y > 3
  const opt::OptimizerSummary s = opt::minimize(p, box, o);
  EXPECT_GE(s.history.size(), 2u);
}

TEST(ProgrammingErrors, AMisspeltFieldInATrimPointLeavesCeresAndFailsTheTrim) {
  int calls = 0;
  const MeanLoadsFunction loads = [&](const OperatingPoint& p, TrimEvaluationPurpose) {
    if (++calls == 3) (void)field("trim.freq_hzz");  // misspelt
    PeriodicEvaluation e;
    e.ok = true;
    e.steady = true;
    e.cycles = 1;
    e.mean.FV_N = 1.2 * std::sin(p.theta_rad) / std::sin(0.14) * p.speed_mps / 9.0;
    e.mean.FH_N = 0.4 * (1.0 - p.speed_mps / 9.0);
    e.mean.M_Nm = -0.02 * (p.tail_angle_rad - 0.26);
    return e;
  };
  TrimOptions o;
  o.initial = OperatingPoint{5.0, 12.0, 3.0 * kDegToRad, 0.0};
  o.verify_free_flight = false;
  EXPECT_THROW(solveTrim(TrimReference{1.2, 0.08}, loads, o), std::logic_error);
  EXPECT_EQ(calls, 3);  // Ceres did not go on calling after the error
}

}  // namespace
}  // namespace orni
