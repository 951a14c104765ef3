// Options of an aero-map build (docs/design.md 7.5: plain struct, defaults, IsValid). Kept apart
// from aero_map.hpp so that the study-file reader can hold them without the flight core's headers.
#pragma once

#include <cstddef>
#include <string>

#include "core/dynamics/simulation_options.hpp"

namespace orni {

/// Largest map the builder accepts (points).
constexpr std::size_t kMaxAeroMapPoints = 10000000;

struct AeroMapOptions {
  /// Options of every point's run. The builder forces record_history = false and
  /// stop_when_steady = true; `cycles` is the maximum per point.
  SimulationOptions simulation = defaultSimulation();
  int threads = 1;  ///< worker threads, [1, 1024]

  static SimulationOptions defaultSimulation() {
    SimulationOptions o;
    o.cycles = 40;
    o.record_history = false;
    o.stop_when_steady = true;
    return o;
  }
  /// The options each point's simulateTethered receives (simulation with the forced fields).
  SimulationOptions pointOptions() const;
  /// True when every field is inside its range; otherwise false with the reason in *why.
  bool IsValid(std::string* why) const;
};

}  // namespace orni
