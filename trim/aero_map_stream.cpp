#include "trim/aero_map_stream.hpp"

#include <algorithm>
#include <condition_variable>
#include <exception>
#include <map>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "core/grid/point_pool.hpp"
#include "core/model/cancellation.hpp"

namespace orni {

void streamAeroMap(const FlightCoreModel& model, const AeroMapGrid& grid,
                   const AeroMapOptions& options, std::size_t first,
                   const AeroMapPointCallback& on_point) {
  std::string why;
  if (!grid.IsValid(&why)) throw std::invalid_argument("aero map grid: " + why);
  if (!options.IsValid(&why)) throw std::invalid_argument("aero map options: " + why);
  const std::size_t n = grid.size();
  if (first > n) throw std::invalid_argument("aero map: first point beyond the grid");
  if (first == n) return;
  const std::size_t workers = std::min(n - first, static_cast<std::size_t>(options.threads));
  const std::size_t lookahead = kAeroMapLookaheadPerThread * workers;

  // Guarded by `mutex`: the next point to start, the next to hand over, the finished ones
  // waiting for an earlier point (at most `lookahead`), and the stop flag with its reason.
  std::mutex mutex;
  std::condition_variable progressed;
  std::size_t next_start = first, next_report = first;
  std::map<std::size_t, AeroMapPoint> waiting;
  bool stop = false;
  std::exception_ptr error;

  auto worker = [&]() {
    std::unique_lock<std::mutex> lock(mutex);
    for (;;) {
      progressed.wait(lock, [&] {
        return stop || next_start >= n || next_start < next_report + lookahead;
      });
      if (stop || next_start >= n) return;
      const std::size_t index = next_start++;
      lock.unlock();
      AeroMapPoint result;
      try {
        throwIfCancelled();  // a cancellation point per point (core/model/cancellation.hpp)
        result = computeAeroMapPoint(model, grid.point(index), options);
      } catch (...) {  // computeAeroMapPoint reports std::exception as a status; anything else stops
        lock.lock();
        if (!error) error = std::current_exception();
        stop = true;
        progressed.notify_all();
        return;
      }
      lock.lock();
      waiting.emplace(index, std::move(result));
      // Hand over every finished point that is next in order (the one that completes the order
      // does it for its waiting successors).
      for (auto it = waiting.find(next_report); !stop && it != waiting.end();
           it = waiting.find(next_report)) {
        try {
          if (on_point) on_point(it->first, it->second);
        } catch (...) {
          if (!error) error = std::current_exception();
          stop = true;
        }
        waiting.erase(it);
        ++next_report;
      }
      progressed.notify_all();
    }
  };

  runOnThreads(workers, worker);
  if (error) std::rethrow_exception(error);
}

}  // namespace orni
