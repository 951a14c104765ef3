#include "trim/aero_map.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <utility>

#include "core/grid/point_pool.hpp"
#include "core/model/field_table.hpp"
#include "core/model/invariant.hpp"

namespace orni {

namespace {

/// One line: newlines and other control characters become spaces (the runner's files keep one
/// point per line).
std::string oneLine(std::string s) {
  for (char& c : s)
    if (static_cast<unsigned char>(c) < 0x20) c = ' ';
  return s;
}

}  // namespace

std::size_t AeroMapGrid::size() const {
  return speed_mps.size() * freq_hz.size() * theta_rad.size() * tail_angle_rad.size();
}

std::array<std::size_t, 4> AeroMapGrid::axisIndices(std::size_t index) const {
  std::array<std::size_t, 4> i{};
  i[3] = index % tail_angle_rad.size();
  index /= tail_angle_rad.size();
  i[2] = index % theta_rad.size();
  index /= theta_rad.size();
  i[1] = index % freq_hz.size();
  i[0] = index / freq_hz.size();
  return i;
}

OperatingPoint AeroMapGrid::point(std::size_t index) const {
  const auto i = axisIndices(index);
  return OperatingPoint{speed_mps[i[0]], freq_hz[i[1]], theta_rad[i[2]], tail_angle_rad[i[3]]};
}

bool AeroMapGrid::IsValid(std::string* why) const {
  auto fail = [why](const char* m) {
    if (why) *why = m;
    return false;
  };
  if (speed_mps.empty() || freq_hz.empty() || theta_rad.empty() || tail_angle_rad.empty())
    return fail("every axis needs at least one value");
  // The ranges of the [aeromap] axes in the field table (SI).
  const std::pair<const char*, const std::vector<double>*> axes[] = {
      {"aeromap.speed_mps", &speed_mps},
      {"aeromap.freq_hz", &freq_hz},
      {"aeromap.theta_deg", &theta_rad},
      {"aeromap.tail_angle_deg", &tail_angle_rad}};
  for (const auto& [key, values] : axes) {
    const FieldSpec& f = field(key);
    for (const double v : *values)
      if (!f.siRange().contains(v)) {
        if (why) *why = std::string(key) + " values must be in " + f.range.interval() + " " +
                        std::string(f.unit);
        return false;
      }
  }
  // Product without overflow: each factor is checked against the remaining budget.
  std::size_t n = 1;
  for (const std::size_t k : {speed_mps.size(), freq_hz.size(), theta_rad.size(),
                              tail_angle_rad.size()}) {
    if (k > kMaxAeroMapPoints / n) return fail("the grid has more than 10000000 points");
    n *= k;
  }
  return true;
}

SimulationOptions AeroMapOptions::pointOptions() const {
  SimulationOptions o = simulation;
  o.mode = FlightMode::kTethered;
  o.record_history = false;
  o.stop_when_steady = true;
  return o;
}

bool AeroMapOptions::IsValid(std::string* why) const {
  if (threads < 1 || threads > 1024) {
    if (why) *why = "threads must be in [1, 1024]";
    return false;
  }
  return pointOptions().IsValid(why);
}

std::string AeroMapSummary::BriefReport() const {
  char buf[200];
  std::snprintf(buf, sizeof buf,
                "%zu points (%zu computed): %zu ok, %zu not_converged, %zu diverged, %zu failed, "
                "%.3g s",
                points.size(), computed, ok, not_converged, diverged, failed, wall_time_s);
  return buf;
}

AeroMapPoint computeAeroMapPoint(const FlightCoreModel& model, const OperatingPoint& point,
                                 const AeroMapOptions& options) {
  AeroMapPoint r;
  try {
    const SimulationSummary s = simulateTethered(model, point, options.pointOptions(), nullptr);
    r.status = s.status;
    r.message = oneLine(s.message);
    r.cycles_run = s.cycles_run;
    r.steady_state_cycle = s.steady_state_cycle;
    r.last_cycle_change = s.last_cycle_change;
    r.mean = s.mean;
  } catch (const std::exception& e) {
    rethrowIfProgrammingError(e);  // core/model/invariant.hpp: stops the map
    r.status = SimulationStatus::kFailed;
    r.message = oneLine(std::string("simulation threw: ") + e.what());
  }
  return r;
}

AeroMapSummary buildAeroMap(const FlightCoreModel& model, const AeroMapGrid& grid,
                            const AeroMapOptions& options,
                            const std::vector<std::optional<AeroMapPoint>>& known,
                            const AeroMapPointCallback& on_point) {
  const auto t0 = std::chrono::steady_clock::now();
  std::string why;
  if (!grid.IsValid(&why)) throw std::invalid_argument("aero map grid: " + why);
  if (!options.IsValid(&why)) throw std::invalid_argument("aero map options: " + why);
  const std::size_t n = grid.size();
  if (!known.empty() && known.size() != n)
    throw std::invalid_argument("aero map: `known` must be empty or have one entry per point");

  AeroMapSummary summary;
  summary.points.resize(n);
  std::vector<std::size_t> todo;
  for (std::size_t i = 0; i < n; ++i) {
    if (!known.empty() && known[i])
      summary.points[i] = *known[i];
    else
      todo.push_back(i);
  }

  // Each result slot is written by exactly one worker and read only after the pool has joined.
  runPoints(
      todo, options.threads,
      [&](std::size_t index) {
        summary.points[index] = computeAeroMapPoint(model, grid.point(index), options);
      },
      [&](std::size_t index) {
        if (on_point) on_point(index, summary.points[index]);
      });

  summary.computed = todo.size();
  for (const AeroMapPoint& p : summary.points) {
    switch (p.status) {
      case SimulationStatus::kOk: ++summary.ok; break;
      case SimulationStatus::kNotConverged: ++summary.not_converged; break;
      case SimulationStatus::kDiverged: ++summary.diverged; break;
      case SimulationStatus::kFailed: ++summary.failed; break;
    }
  }
  summary.wall_time_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return summary;
}

}  // namespace orni
