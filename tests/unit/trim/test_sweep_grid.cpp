// The points of a sweep (trim/sweep_grid.hpp): full factorial, first axis outermost, and the
// thread pool that runs them (trim/point_pool.hpp): every index exactly once, results by index
// whatever the thread count, exceptions stop the pool and reach the caller.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <thread>
#include <cstddef>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "trim/point_pool.hpp"
#include "trim/sweep_grid.hpp"

namespace orni::trim {
namespace {

TEST(TrimSweepGrid, FirstAxisOutermostLastFastest) {
  const SweepGrid g{{3, 2, 4}};
  EXPECT_EQ(g.size(), 24u);
  EXPECT_EQ(g.axisIndices(0), (std::vector<std::size_t>{0, 0, 0}));
  EXPECT_EQ(g.axisIndices(1), (std::vector<std::size_t>{0, 0, 1}));
  EXPECT_EQ(g.axisIndices(3), (std::vector<std::size_t>{0, 0, 3}));
  EXPECT_EQ(g.axisIndices(4), (std::vector<std::size_t>{0, 1, 0}));
  EXPECT_EQ(g.axisIndices(8), (std::vector<std::size_t>{1, 0, 0}));
  EXPECT_EQ(g.axisIndices(23), (std::vector<std::size_t>{2, 1, 3}));
  for (std::size_t i = 0; i < g.size(); ++i) EXPECT_EQ(g.pointIndex(g.axisIndices(i)), i);
  // Rows of one combination of the inner axes are every (n_1 * n_2)-th row (the sweep figure).
  for (std::size_t i0 = 0; i0 < 3; ++i0)
    EXPECT_EQ(g.axisIndices(i0 * 8 + 5), (std::vector<std::size_t>{i0, 1, 1}));
  EXPECT_THROW(g.pointIndex({0, 2, 0}), std::invalid_argument);
  EXPECT_THROW(g.pointIndex({0, 0}), std::invalid_argument);

  const SweepGrid one{{7}};
  EXPECT_EQ(one.size(), 7u);
  EXPECT_EQ(one.axisIndices(5), (std::vector<std::size_t>{5}));
}

TEST(TrimSweepGrid, Validity) {
  std::string why;
  EXPECT_TRUE((SweepGrid{{3, 3}}).IsValid(&why)) << why;
  EXPECT_FALSE((SweepGrid{{}}).IsValid(&why));
  EXPECT_NE(why.find("at least one axis"), std::string::npos);
  EXPECT_FALSE((SweepGrid{{3, 0}}).IsValid(&why));
  EXPECT_NE(why.find("at least one value"), std::string::npos);
  EXPECT_FALSE((SweepGrid{{kMaxSweepPoints, 2}}).IsValid(&why));
  EXPECT_NE(why.find("more than"), std::string::npos);
  EXPECT_TRUE((SweepGrid{{kMaxSweepPoints}}).IsValid(&why));
  EXPECT_FALSE((SweepGrid{std::vector<std::size_t>(kMaxSweepAxes + 1, 1)}).IsValid(&why));
}

TEST(TrimPointPool, EveryIndexOnceResultsByIndexForAnyThreadCount) {
  std::vector<std::size_t> todo;
  for (std::size_t i = 0; i < 50; i += 2) todo.push_back(i);  // a resumed run: every other point
  for (int threads : {1, 2, 3, 8, 64}) {
    SCOPED_TRACE(threads);
    std::vector<double> result(50, -1.0);
    std::vector<std::size_t> done;
    std::atomic<int> calls{0};
    runPoints(
        todo, threads,
        [&](std::size_t i) {
          ++calls;
          result[i] = 0.5 * static_cast<double>(i * i);
        },
        [&](std::size_t i) { done.push_back(i); });  // serialised: no lock needed
    EXPECT_EQ(calls.load(), 25);
    EXPECT_EQ(std::set<std::size_t>(done.begin(), done.end()),
              std::set<std::size_t>(todo.begin(), todo.end()));
    EXPECT_EQ(done.size(), todo.size());
    for (std::size_t i = 0; i < 50; ++i)
      EXPECT_EQ(result[i], i % 2 == 0 ? 0.5 * static_cast<double>(i * i) : -1.0);
  }
  runPoints({}, 4, [](std::size_t) { FAIL() << "no points to run"; });
  EXPECT_THROW(runPoints(todo, 0, [](std::size_t) {}), std::invalid_argument);
}

TEST(TrimPointPool, AnExceptionStopsThePoolAndReachesTheCaller) {
  std::vector<std::size_t> todo(200);
  for (std::size_t i = 0; i < todo.size(); ++i) todo[i] = i;
  for (int threads : {1, 2}) {
    std::atomic<int> started{0};
    // Points after the failing one take a millisecond (a real point takes far longer): without
    // it a second thread could finish all 200 trivial points before the failure is seen.
    EXPECT_THROW(runPoints(todo, threads,
                           [&](std::size_t i) {
                             ++started;
                             if (i == 3) throw std::runtime_error("point 3 failed");
                             if (i > 3) std::this_thread::sleep_for(std::chrono::milliseconds(1));
                           }),
                 std::runtime_error);
    EXPECT_LT(started.load(), 200);  // no new points after the failure
    started = 0;
    std::size_t reported = 0;
    EXPECT_THROW(runPoints(
                     todo, threads,
                     [&](std::size_t) {
                       ++started;
                       std::this_thread::sleep_for(std::chrono::milliseconds(1));
                     },
                     [&](std::size_t) {
                       if (++reported == 5) throw std::runtime_error("journal full");
                     }),
                 std::runtime_error);
    EXPECT_EQ(reported, 5u);
    EXPECT_LT(started.load(), 200);
  }
}

}  // namespace
}  // namespace orni::trim
