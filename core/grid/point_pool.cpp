#include "core/grid/point_pool.hpp"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <stdexcept>
#include <thread>

#include "core/model/cancellation.hpp"

namespace orni {

void runPoints(const std::vector<std::size_t>& todo, int threads, const PointWork& work,
               const PointDone& on_done) {
  if (threads < 1 || threads > 1024)
    throw std::invalid_argument("runPoints: threads must be in [1, 1024]");
  if (!work) throw std::invalid_argument("runPoints: no work function");

  // Each index is taken by exactly one worker; the caller's result slots need no lock. The
  // completion callback is serialised by `done_mutex`.
  std::atomic<std::size_t> cursor{0};
  std::atomic<bool> stop{false};
  std::mutex done_mutex;
  std::mutex error_mutex;
  std::exception_ptr error;
  auto fail = [&](std::exception_ptr e) {
    std::lock_guard<std::mutex> lock(error_mutex);
    if (!error) error = std::move(e);
    stop.store(true, std::memory_order_relaxed);
  };
  auto worker = [&]() {
    for (;;) {
      if (stop.load(std::memory_order_relaxed)) return;
      const std::size_t k = cursor.fetch_add(1, std::memory_order_relaxed);
      if (k >= todo.size()) return;
      const std::size_t index = todo[k];
      try {
        throwIfCancelled();  // a cancellation point per point (core/model/cancellation.hpp)
        work(index);
      } catch (...) {
        fail(std::current_exception());
        return;
      }
      if (on_done) {
        std::lock_guard<std::mutex> lock(done_mutex);
        if (stop.load(std::memory_order_relaxed)) return;
        try {
          on_done(index);
        } catch (...) {
          fail(std::current_exception());
          return;
        }
      }
    }
  };

  const std::size_t workers = std::min(todo.size(), static_cast<std::size_t>(threads));
  runOnThreads(workers, worker);
  if (error) std::rethrow_exception(error);
}

void runOnThreads(std::size_t workers, const std::function<void()>& worker) {
  if (workers <= 1) {
    worker();
    return;
  }
  std::vector<std::thread> pool;
  pool.reserve(workers);
  for (std::size_t w = 0; w < workers; ++w) pool.emplace_back(worker);
  for (std::thread& t : pool) t.join();
}

}  // namespace orni
