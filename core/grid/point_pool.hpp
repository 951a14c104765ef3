// Many independent runs on a pool of threads (docs/design.md 6): aero-map points, sweep points.
//
// runPoints() hands the indices of `todo` to `threads` workers through an atomic cursor (work
// stealing: a slow point does not hold up the others). Each index is computed exactly once, by one
// worker, and the caller stores the result in a slot of its own indexed by that index, so the
// results do not depend on the thread count or on the order in which points finish (docs/design.md
// 7.1: the workers share the const model, each run owns its workspace). No file I/O here.
#pragma once

#include <cstddef>
#include <functional>
#include <vector>

namespace orni {

/// Computes point `index` (called from a worker thread; calls for different indices run
/// concurrently, so it must only write state owned by that index). Exceptions should be turned
/// into a status by the callee: one that escapes stops the pool like an exception of on_done.
using PointWork = std::function<void(std::size_t index)>;

/// Called after `work(index)` returned, from the same worker thread; calls are serialised (never
/// two at once), e.g. to journal the result and draw progress.
using PointDone = std::function<void(std::size_t index)>;

/// Runs work(i) and then on_done(i) for every i in `todo`, on min(threads, todo.size()) threads
/// (the calling thread alone when that is 1). The first exception thrown by `work` or `on_done`
/// stops the pool: no new points are started, the running ones finish, and runPoints re-throws
/// it after every worker has joined. Throws std::invalid_argument when threads is outside
/// [1, 1024].
void runPoints(const std::vector<std::size_t>& todo, int threads, const PointWork& work,
               const PointDone& on_done = {});

/// Runs `worker` on `workers` threads (on the calling thread alone when workers <= 1) and joins
/// them all: the fan-out of runPoints and of the aero-map stream. `worker` catches its own
/// exceptions (an escaping one terminates, as for any std::thread).
void runOnThreads(std::size_t workers, const std::function<void()>& worker);

}  // namespace orni
