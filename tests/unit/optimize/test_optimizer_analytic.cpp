// The optimiser driver (optimize/optimizer.hpp) on analytic problems with known optima:
//   minimise (x - 1)^2 + (y - 2)^2 subject to x + y <= 2: optimum (0.5, 1.5), f* = 0.5
// with each algorithm; failed evaluations and non-finite values are penalised, never fatal; a
// problem without a feasible point reports the least violation; the merged history is identical
// for any thread count; a journal replay reproduces the history without computing anything.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <mutex>
#include <stdexcept>
#include <string>
#include <vector>

#include "optimize/optimizer.hpp"

namespace orni::opt {
namespace {

constexpr double kOptimumX = 0.5, kOptimumY = 1.5, kOptimumF = 0.5;

/// Per-start state: how many evaluations this start has observed (stands in for a warm start).
struct CountingWorkspace : ProblemWorkspace {
  int observed = 0;
};

/// The constrained quadratic; optionally failing (throwing) or returning NaN in parts of the box.
class Quadratic final : public Problem {
 public:
  bool throw_right = false;   ///< evaluate() throws for x > 3.5
  bool nan_top = false;       ///< NaN objective for y > 3
  double rhs = 2.0;           ///< x + y <= rhs

  int variableCount() const override { return 2; }
  int constraintCount() const override { return 1; }
  int valueCount() const override { return 1; }
  std::unique_ptr<ProblemWorkspace> makeWorkspace() const override {
    return std::make_unique<CountingWorkspace>();
  }
  Evaluation evaluate(const std::vector<double>& x, ProblemWorkspace& w) const override {
    if (throw_right && x[0] > 3.5) throw std::runtime_error("model build failed");
    Evaluation e;
    e.objective = (x[0] - 1.0) * (x[0] - 1.0) + (x[1] - 2.0) * (x[1] - 2.0);
    if (nan_top && x[1] > 3.0) e.objective = std::nan("");
    e.constraints = {x[0] + x[1] - rhs};
    e.values = {static_cast<double>(static_cast<CountingWorkspace&>(w).observed)};
    e.message = "after " + std::to_string(static_cast<CountingWorkspace&>(w).observed);
    return e;
  }
  void observe(const std::vector<double>&, const Evaluation&, ProblemWorkspace& w) const override {
    ++static_cast<CountingWorkspace&>(w).observed;
  }
};

VariableBox box() {
  VariableBox b;
  b.lower = {-5.0, -5.0};
  b.upper = {5.0, 5.0};
  b.initial = {3.0, -4.0};  // feasible (x + y = -1), far from the optimum
  return b;
}

OptimizerOptions optionsFor(Algorithm a) {
  OptimizerOptions o;
  o.algorithm = a;
  o.xtol = 1e-7;
  switch (a) {
    case Algorithm::kCobyla: o.max_evaluations = 300; break;
    case Algorithm::kBobyqa: o.max_evaluations = 2000; break;
    case Algorithm::kIsres:
      o.max_evaluations = 3000;
      o.polish_evaluations = 300;
      break;
  }
  return o;
}

class OptimizeAnalytic : public ::testing::TestWithParam<Algorithm> {};

TEST_P(OptimizeAnalytic, FindsTheConstrainedOptimum) {
  const Quadratic p;
  const OptimizerSummary s = minimize(p, box(), optionsFor(GetParam()));
  SCOPED_TRACE(s.BriefReport());
  const EvaluationRecord* b = s.bestRecord();
  ASSERT_NE(b, nullptr);
  EXPECT_TRUE(s.feasible);
  EXPECT_NEAR(b->x[0], kOptimumX, 2e-3);
  EXPECT_NEAR(b->x[1], kOptimumY, 2e-3);
  EXPECT_NEAR(b->result.objective, kOptimumF, 2e-3);
  EXPECT_LE(b->result.constraints[0], 1e-6);
  EXPECT_LE(static_cast<int>(s.history.size()), optionsFor(GetParam()).max_evaluations + 2);
  // Every record is finite and in order.
  for (std::size_t i = 0; i < s.history.size(); ++i) {
    EXPECT_EQ(s.history[i].index, static_cast<int>(i));
    EXPECT_TRUE(std::isfinite(s.history[i].result.objective));
  }
  std::printf("[ analytic ] %s: x = (%.6f, %.6f), f = %.8f, %zu evaluations, %s\n",
              toString(GetParam()), b->x[0], b->x[1], b->result.objective, s.history.size(),
              s.starts[0].termination.c_str());
}

INSTANTIATE_TEST_SUITE_P(EachAlgorithm, OptimizeAnalytic,
                         ::testing::Values(Algorithm::kCobyla, Algorithm::kBobyqa,
                                           Algorithm::kIsres),
                         [](const auto& p) { return std::string(toString(p.param)); });

TEST(OptimizeDriver, IsresHasGlobalThenPolishStages) {
  const Quadratic p;
  const OptimizerSummary s = minimize(p, box(), optionsFor(Algorithm::kIsres));
  ASSERT_FALSE(s.history.empty());
  EXPECT_EQ(s.history.front().stage, Stage::kGlobal);
  EXPECT_EQ(s.history.back().stage, Stage::kPolish);
  // The polish starts at the best point of the global stage: answered from the cache.
  int first_polish = -1;
  for (std::size_t i = 0; i < s.history.size(); ++i)
    if (s.history[i].stage == Stage::kPolish) {
      first_polish = static_cast<int>(i);
      break;
    }
  ASSERT_GE(first_polish, 0);
  EXPECT_GE(s.history[static_cast<std::size_t>(first_polish)].repeat_of, 0);
  EXPECT_EQ(s.history[static_cast<std::size_t>(first_polish)].source, EvaluationSource::kCached);
}

TEST(OptimizeDriver, FailedAndNonFiniteEvaluationsArePenalisedNotFatal) {
  Quadratic p;
  p.throw_right = true;
  p.nan_top = true;
  OptimizerOptions o = optionsFor(Algorithm::kCobyla);
  // From (3, -4) the first simplex step in x lands at x = 4, where the model fails.
  const OptimizerSummary s = minimize(p, box(), o);
  SCOPED_TRACE(s.BriefReport());
  ASSERT_GE(s.history.size(), 2u);
  const EvaluationRecord& first = s.history[1];
  EXPECT_EQ(first.x[0], 4.0);
  EXPECT_EQ(first.result.status, EvaluationStatus::kFailed);
  EXPECT_EQ(first.result.message, "model build failed");
  EXPECT_EQ(first.result.objective, o.failure_objective);
  EXPECT_EQ(first.result.constraints[0], o.failure_constraint);
  EXPECT_FALSE(first.feasible);
  EXPECT_GT(s.failed, 0);
  for (const EvaluationRecord& r : s.history) {
    EXPECT_TRUE(std::isfinite(r.result.objective));
    EXPECT_TRUE(std::isfinite(r.result.constraints[0]));
  }
  ASSERT_TRUE(s.feasible);
  EXPECT_NEAR(s.bestRecord()->x[0], kOptimumX, 5e-3);
  EXPECT_NEAR(s.bestRecord()->x[1], kOptimumY, 5e-3);
}

TEST(OptimizeDriver, NoFeasiblePointReportsTheLeastViolation) {
  Quadratic p;
  p.rhs = -20.0;  // x + y >= -10 in the box: never feasible; least violation at (-5, -5)
  const OptimizerSummary s = minimize(p, box(), optionsFor(Algorithm::kCobyla));
  ASSERT_NE(s.bestRecord(), nullptr);
  EXPECT_FALSE(s.feasible);
  EXPECT_FALSE(s.converged);
  EXPECT_NEAR(s.bestRecord()->violation, 10.0, 1e-3);
  EXPECT_NE(s.message.find("no feasible point"), std::string::npos);
}

OptimizerOptions multiStart(int threads) {
  OptimizerOptions o = optionsFor(Algorithm::kCobyla);
  o.max_evaluations = 60;
  o.starts = 5;
  o.threads = threads;
  return o;
}

void expectSameHistory(const OptimizerSummary& a, const OptimizerSummary& b) {
  ASSERT_EQ(a.history.size(), b.history.size());
  for (std::size_t i = 0; i < a.history.size(); ++i) {
    const EvaluationRecord &r = a.history[i], &q = b.history[i];
    EXPECT_EQ(r.start, q.start);
    EXPECT_EQ(r.index, q.index);
    EXPECT_EQ(r.x, q.x);
    EXPECT_EQ(r.result.objective, q.result.objective);
    EXPECT_EQ(r.result.constraints, q.result.constraints);
    EXPECT_EQ(r.result.message, q.result.message);
    EXPECT_EQ(r.repeat_of, q.repeat_of);
  }
  EXPECT_EQ(a.best, b.best);
}

TEST(OptimizeDriver, SameHistoryForAnyThreadCount) {
  const Quadratic p;
  const OptimizerSummary one = minimize(p, box(), multiStart(1));
  const OptimizerSummary three = minimize(p, box(), multiStart(3));
  ASSERT_EQ(one.starts.size(), 5u);
  expectSameHistory(one, three);
  // Starts begin at their own points: start 0 at the initial point, the others in the box.
  EXPECT_EQ(one.starts[0].x0, box().initial);
  EXPECT_NE(one.starts[1].x0, one.starts[2].x0);
  // Isres with seeds: also thread-independent.
  OptimizerOptions g = optionsFor(Algorithm::kIsres);
  g.max_evaluations = 400;
  g.starts = 3;
  g.threads = 1;
  const OptimizerSummary g1 = minimize(p, box(), g);
  g.threads = 3;
  const OptimizerSummary g3 = minimize(p, box(), g);
  expectSameHistory(g1, g3);
}

/// A journal in memory: every computed evaluation by (start, index).
struct MemoryJournal {
  std::mutex mutex;
  std::map<std::pair<int, int>, std::pair<std::vector<double>, Evaluation>> records;
  OptimizerHooks writer() {
    OptimizerHooks h;
    h.on_evaluation = [this](const EvaluationRecord& r) {
      if (r.source != EvaluationSource::kComputed) return;
      std::lock_guard<std::mutex> lock(mutex);
      records[{r.start, r.index}] = {r.x, r.result};
    };
    return h;
  }
  OptimizerHooks reader() {
    OptimizerHooks h;
    h.replay = [this](int start, int index,
                      const std::vector<double>& x) -> std::optional<Evaluation> {
      std::lock_guard<std::mutex> lock(mutex);
      const auto it = records.find({start, index});
      if (it == records.end() || it->second.first != x) return std::nullopt;
      return it->second.second;
    };
    return h;
  }
};

TEST(OptimizeDriver, JournalReplayReproducesTheHistory) {
  const Quadratic p;
  MemoryJournal journal;
  const OptimizerSummary fresh = minimize(p, box(), multiStart(2), journal.writer());
  EXPECT_EQ(fresh.replayed, 0);
  EXPECT_EQ(static_cast<std::size_t>(fresh.computed + fresh.cached), fresh.history.size());

  // Complete journal: nothing is computed.
  const OptimizerSummary replay = minimize(p, box(), multiStart(1), journal.reader());
  expectSameHistory(fresh, replay);
  EXPECT_EQ(replay.computed, 0);
  EXPECT_EQ(replay.replayed, fresh.computed);

  // Interrupted run: only the first half of every start is on disk.
  MemoryJournal partial;
  for (const auto& [key, value] : journal.records)
    if (key.second < 15) partial.records[key] = value;
  const OptimizerSummary resumed = minimize(p, box(), multiStart(3), partial.reader());
  expectSameHistory(fresh, resumed);
  EXPECT_GT(resumed.replayed, 0);
  EXPECT_GT(resumed.computed, 0);

  // A journal record at another point is not taken over.
  MemoryJournal wrong;
  for (const auto& [key, value] : journal.records) wrong.records[key] = value;
  wrong.records[{0, 0}].first[0] += 1e-12;
  const OptimizerSummary checked = minimize(p, box(), multiStart(1), wrong.reader());
  expectSameHistory(fresh, checked);
  EXPECT_EQ(checked.computed, 1);
}

// A distributed run's worker computes one start alone (runStart); its records, journaled and
// replayed by minimize(), give the history of a single-process run.
TEST(OptimizeDriver, StartsRunAloneReplayIntoTheSameHistory) {
  const Quadratic p;
  const OptimizerSummary fresh = minimize(p, box(), multiStart(1));
  MemoryJournal journal;
  for (int k = 4; k >= 0; --k) {  // in any order, each start on its own
    const std::vector<EvaluationRecord> records =
        runStart(p, box(), multiStart(1), journal.writer(), k);
    ASSERT_FALSE(records.empty());
    for (const EvaluationRecord& r : records) EXPECT_EQ(r.start, k);
  }
  const OptimizerSummary replay = minimize(p, box(), multiStart(2), journal.reader());
  expectSameHistory(fresh, replay);
  EXPECT_EQ(replay.computed, 0);
  EXPECT_THROW(runStart(p, box(), multiStart(1), {}, 5), std::invalid_argument);
  EXPECT_THROW(runStart(p, box(), multiStart(1), {}, -1), std::invalid_argument);
}

TEST(OptimizeDriver, HookExceptionStopsTheRunAndIsRethrown) {
  const Quadratic p;
  OptimizerHooks h;
  int calls = 0;
  h.on_evaluation = [&](const EvaluationRecord&) {
    if (++calls == 5) throw std::runtime_error("disk full");
  };
  EXPECT_THROW(
      {
        try {
          minimize(p, box(), optionsFor(Algorithm::kCobyla), h);
        } catch (const std::runtime_error& e) {
          EXPECT_STREQ(e.what(), "disk full");
          throw;
        }
      },
      std::runtime_error);
  EXPECT_LE(calls, 7);
}

TEST(OptimizeDriver, RejectsInvalidInput) {
  const Quadratic p;
  VariableBox b = box();
  b.initial = {6.0, 0.0};
  EXPECT_THROW(minimize(p, b, OptimizerOptions()), std::invalid_argument);
  OptimizerOptions o;
  o.max_evaluations = 1;
  EXPECT_THROW(minimize(p, box(), o), std::invalid_argument);
  VariableBox one;
  one.lower = {0.0};
  one.upper = {1.0};
  one.initial = {0.5};
  o = OptimizerOptions();
  o.algorithm = Algorithm::kBobyqa;
  EXPECT_THROW(minimize(p, one, o), std::invalid_argument);  // size mismatch and bobyqa n < 2
}

TEST(OptimizeDriver, HaltonStartPointsInsideTheBox) {
  const VariableBox b = box();
  for (int k = 1; k < 20; ++k) {
    const std::vector<double> x = startPoint(b, k);
    for (int i = 0; i < 2; ++i) {
      EXPECT_GT(x[static_cast<std::size_t>(i)], b.lower[static_cast<std::size_t>(i)]);
      EXPECT_LT(x[static_cast<std::size_t>(i)], b.upper[static_cast<std::size_t>(i)]);
    }
  }
  EXPECT_NEAR(startPoint(b, 1)[0], 0.0, 1e-12);            // 1/2 in base 2
  EXPECT_NEAR(startPoint(b, 1)[1], -5.0 + 10.0 / 3.0, 1e-12);  // 1/3 in base 3
}

}  // namespace
}  // namespace orni::opt
