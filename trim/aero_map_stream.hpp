// An aero map of any size in bounded memory: the points [first, grid.size()) are computed on
// options.threads threads and handed to the caller in point order as they finish, while no worker
// starts a point more than kAeroMapLookaheadPerThread x threads points after the oldest one not
// yet handed over (a slow point holds back that many finished successors, never more). The
// caller writes each result out (the runner's journal and aeromap.csv), so nothing grows with the
// grid. The results are those of buildAeroMap (aero_map.hpp), whatever the thread count.
#pragma once

#include <cstddef>

#include "core/dynamics/flight_core.hpp"
#include "trim/aero_map.hpp"

namespace orni {

/// Points a worker may run ahead of the oldest point not yet handed over, per thread.
constexpr std::size_t kAeroMapLookaheadPerThread = 8;

/// Computes points first .. grid.size() - 1 and calls on_point(index, result) for each, in index
/// order, from a worker thread (serialised). An exception thrown by on_point stops the map: no
/// new point is started, the running ones finish unreported, and it is re-thrown after the
/// workers have joined. Throws std::invalid_argument for an invalid grid or options or first >
/// grid.size().
void streamAeroMap(const FlightCoreModel& model, const AeroMapGrid& grid,
                   const AeroMapOptions& options, std::size_t first,
                   const AeroMapPointCallback& on_point);

}  // namespace orni
