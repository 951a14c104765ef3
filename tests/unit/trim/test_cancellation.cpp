// Cooperative cancellation (core/model/cancellation.hpp) at each kind of cancellation point:
//   - a point pool starts no point once cancellation is requested and throws Cancelled (one and
//     two threads), after the points already running have finished;
//   - a tethered simulation stops at the next flapping cycle;
//   - a trim (Ceres) requested to stop in its cost function leaves the solver and throws;
//   - an optimisation stops at the next evaluation and hands no cancelled evaluation to its
//     journal hook (a resumed run must compute it);
//   - a Cancelled is not a std::exception, so the handlers that turn one into a failed point let
//     it pass; after clearCancellation() everything runs normally.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <exception>
#include <memory>
#include <type_traits>
#include <vector>

#include "core/dynamics/tethered_simulation.hpp"
#include "core/grid/point_pool.hpp"
#include "core/model/cancellation.hpp"
#include "core/model/frames.hpp"
#include "optimize/optimizer.hpp"
#include "tests/support/magpie_vehicle.hpp"
#include "trim/trim_solver.hpp"

namespace orni {
namespace {

/// Withdraws any request when a test ends, passed or failed.
struct ClearOnExit {
  ~ClearOnExit() { clearCancellation(); }
};

static_assert(!std::is_base_of_v<std::exception, Cancelled>,
              "handlers of std::exception must let a cancellation pass");

TEST(Cancellation, PointPoolStartsNoPointAfterTheRequest) {
  for (int threads : {1, 2}) {
    ClearOnExit clear;
    std::vector<std::size_t> todo(50);
    for (std::size_t i = 0; i < todo.size(); ++i) todo[i] = i;
    std::atomic<int> started{0};
    EXPECT_THROW(runPoints(todo, threads,
                           [&](std::size_t i) {
                             ++started;
                             if (i == 5) requestCancellation();
                           }),
                 Cancelled);
    // Point 5 asked; at most the points already taken by the other worker ran after it.
    EXPECT_LE(started.load(), 6 + threads) << threads;
    clearCancellation();
    std::atomic<int> all{0};
    runPoints(todo, threads, [&](std::size_t) { ++all; });
    EXPECT_EQ(all.load(), 50);
  }
}

TEST(Cancellation, TetheredSimulationStopsAtTheNextCycle) {
  ClearOnExit clear;
  const FlightCoreModel model(testing::magpieVehicle());
  SimulationOptions o;
  o.cycles = 3;
  o.stop_when_steady = false;
  const OperatingPoint point{10.8, 12.0, 9.2 * kDegToRad, 11.85 * kDegToRad};
  requestCancellation();
  EXPECT_TRUE(cancellationRequested());
  EXPECT_THROW(simulateTethered(model, point, o, nullptr, nullptr), Cancelled);
  clearCancellation();
  const SimulationSummary s = simulateTethered(model, point, o, nullptr, nullptr);
  EXPECT_EQ(s.cycles_run, 3);
}

TEST(Cancellation, TrimLeavesCeresAndThrows) {
  ClearOnExit clear;
  int calls = 0;
  const MeanLoadsFunction loads = [&](const OperatingPoint& p, TrimEvaluationPurpose) {
    if (++calls == 3) requestCancellation();
    throwIfCancelled();  // as a tethered run does at its next cycle
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
  EXPECT_THROW(solveTrim(TrimReference{1.2, 0.08}, loads, o), Cancelled);
  EXPECT_EQ(calls, 3);  // the solver did not go on calling a cancelled run
}

/// f = (x - 1)^2 + (y - 2)^2; the cancellation is requested during evaluation `cancel_at`.
class Bowl final : public opt::Problem {
 public:
  explicit Bowl(int cancel_at) : cancel_at_(cancel_at) {}
  int variableCount() const override { return 2; }
  int constraintCount() const override { return 0; }
  int valueCount() const override { return 0; }
  opt::Evaluation evaluate(const std::vector<double>& x, opt::ProblemWorkspace&) const override {
    if (++evaluations_ == cancel_at_) requestCancellation();
    throwIfCancelled();
    opt::Evaluation e;
    e.objective = (x[0] - 1.0) * (x[0] - 1.0) + (x[1] - 2.0) * (x[1] - 2.0);
    return e;
  }

 private:
  int cancel_at_;
  mutable int evaluations_ = 0;
};

TEST(Cancellation, OptimisationStopsAndJournalsNoCancelledEvaluation) {
  ClearOnExit clear;
  const Bowl bowl(4);
  opt::VariableBox b;
  b.lower = {-5.0, -5.0};
  b.upper = {5.0, 5.0};
  b.initial = {3.0, -4.0};
  opt::OptimizerOptions o;
  o.algorithm = opt::Algorithm::kCobyla;
  o.max_evaluations = 100;
  opt::OptimizerHooks hooks;
  int journaled = 0;
  hooks.on_evaluation = [&](const opt::EvaluationRecord&) { ++journaled; };
  EXPECT_THROW(opt::minimize(bowl, b, o, hooks), Cancelled);
  EXPECT_EQ(journaled, 3);  // the three finished evaluations, not the cancelled fourth
  clearCancellation();
  const Bowl again(-1);
  const opt::OptimizerSummary s = opt::minimize(again, b, o);
  ASSERT_NE(s.bestRecord(), nullptr);
  EXPECT_NEAR(s.bestRecord()->result.objective, 0.0, 1e-3);
}

}  // namespace
}  // namespace orni
