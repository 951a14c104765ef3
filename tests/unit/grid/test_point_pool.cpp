// The thread pool that runs independent points (core/grid/point_pool.hpp): every index exactly
// once, results by index whatever the thread count, exceptions stop the pool and reach the caller.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cstddef>
#include <set>
#include <stdexcept>
#include <thread>
#include <vector>

#include "core/grid/point_pool.hpp"

namespace orni {
namespace {

TEST(GridPointPool, EveryIndexOnceResultsByIndexForAnyThreadCount) {
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

TEST(GridPointPool, AnExceptionStopsThePoolAndReachesTheCaller) {
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
}  // namespace orni
