// Aero map: cycle-mean tethered loads over a grid of (speed, frequency, pitch, tail angle), the
// map of paper Fig. 5 (mean FV and FH against U, theta and f) that trim starts from.
//
// Each grid point is one simulateTethered run (core/dynamics/tethered_simulation.hpp) that stops at
// the periodic steady state. Points run on the thread pool of core/grid/point_pool.hpp and share
// the const FlightCoreModel (docs/design.md 7.1: each run owns its workspace); results are stored
// by point index, so they do not depend on the thread count. No file I/O here: the journal that
// makes a map resumable lives in the runner, fed by the on_point callback and the `known` results.
#pragma once

#include <array>
#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "core/dynamics/flight_core.hpp"
#include "core/dynamics/tethered_simulation.hpp"
#include "core/model/vehicle_model.hpp"
#include "trim/aero_map_options.hpp"

namespace orni {

/// Axes of the map, SI. Points are ordered speed (outermost), frequency, theta, tail (innermost):
/// index = ((i_speed * n_freq + i_freq) * n_theta + i_theta) * n_tail + i_tail.
struct AeroMapGrid {
  std::vector<double> speed_mps;       ///< flight / tunnel speed U, each > 0
  std::vector<double> freq_hz;         ///< flapping frequency f, each > 0
  std::vector<double> theta_rad;       ///< mean pitch attitude, each in (-pi/2, pi/2)
  std::vector<double> tail_angle_rad;  ///< tail elevation delta_T, each in (-pi/2, pi/2)

  /// Number of points (product of the axis sizes).
  std::size_t size() const;
  /// Axis indices {speed, freq, theta, tail} of point `index` < size().
  std::array<std::size_t, 4> axisIndices(std::size_t index) const;
  /// The operating point of point `index` < size().
  OperatingPoint point(std::size_t index) const;
  /// True when every axis is non-empty and every value is in range (and the grid has at most
  /// kMaxAeroMapPoints points); otherwise false with the reason in *why.
  bool IsValid(std::string* why) const;
};

/// Result of one grid point.
struct AeroMapPoint {
  SimulationStatus status = SimulationStatus::kFailed;
  std::string message;          ///< why (one line: no newline characters)
  int cycles_run = 0;
  int steady_state_cycle = -1;  ///< first steady cycle (1-based), -1 when not reached
  double last_cycle_change = 0; ///< scaled cycle-to-cycle change of the last cycle means
  CycleMeans mean;              ///< means over the last cycle (meaningful when status is kOk)
};

/// Called after each computed point with its index and result, from the worker thread that
/// computed it; calls are serialised (never two at once). An exception thrown here stops the
/// build: no new points are started, and buildAeroMap re-throws it after the workers finish.
using AeroMapPointCallback = std::function<void(std::size_t index, const AeroMapPoint& result)>;

struct AeroMapSummary {
  std::vector<AeroMapPoint> points;  ///< one per grid point, in point order
  std::size_t computed = 0;          ///< points simulated by this call (not taken from `known`)
  std::size_t ok = 0, not_converged = 0, diverged = 0, failed = 0;
  double wall_time_s = 0.0;

  /// "180 points (180 computed): 178 ok, 2 not_converged, 0 diverged, 0 failed, 1.23 s".
  std::string BriefReport() const;
};

/// One point: simulateTethered(model, grid.point(index), options.pointOptions(), nullptr), with
/// exceptions turned into status kFailed. Thread-safe for a shared const model.
AeroMapPoint computeAeroMapPoint(const FlightCoreModel& model, const OperatingPoint& point,
                                 const AeroMapOptions& options);

/// Builds the map. `known` (empty, or one entry per point) holds results already available (a
/// resumed journal): those points are not recomputed and on_point is not called for them.
/// Throws std::invalid_argument for an invalid grid or options, and re-throws an exception of
/// on_point.
AeroMapSummary buildAeroMap(const FlightCoreModel& model, const AeroMapGrid& grid,
                            const AeroMapOptions& options,
                            const std::vector<std::optional<AeroMapPoint>>& known = {},
                            const AeroMapPointCallback& on_point = {});

}  // namespace orni
