// Speed of the aero-map builder (issue target: the 180-point map of paper Fig. 5's ranges,
// `--speed 10:20:6 --freq 10:20:6 --theta 0:20:5` of studies/vehicles/efw_magpie.toml, in at most
// 5 s with -j 2). Wall-clock time (UseRealTime), the FlightCoreModel built once outside the loop as
// the command does; no file output.
//   BM_AeroMapEfw180/threads:1 and /threads:2
#include <benchmark/benchmark.h>

#include <string>

#include "core/grid/grid_spec.hpp"
#include "core/model/frames.hpp"
#include "studies/runner/config/vehicle_file.hpp"
#include "trim/aero_map.hpp"

namespace {

using namespace orni;

AeroMapGrid fig5Grid() {
  AeroMapGrid g;
  g.speed_mps = gridValues(parseGridSpec("10:20:6"));
  g.freq_hz = gridValues(parseGridSpec("10:20:6"));
  for (const double d : gridValues(parseGridSpec("0:20:5"))) g.theta_rad.push_back(d * kDegToRad);
  return g;
}

void BM_AeroMapEfw180(benchmark::State& state) {
  const VehicleDefinition file =
      studies::loadVehicleFile(std::string(ORNI_SOURCE_DIR) + "/studies/vehicles/efw_magpie.toml");
  const VehicleModel& v = file.model;
  const FlightCoreModel model(v);
  AeroMapGrid grid = fig5Grid();
  grid.tail_angle_rad = {file.design_point.tail_angle_rad};
  AeroMapOptions options;
  options.threads = static_cast<int>(state.range(0));
  AeroMapSummary map;
  for (auto _ : state) {
    map = buildAeroMap(model, grid, options);
    benchmark::DoNotOptimize(map.points.data());
  }
  int cycles = 0;
  for (const AeroMapPoint& p : map.points) cycles += p.cycles_run;
  state.counters["points"] = static_cast<double>(map.points.size());
  state.counters["ok"] = static_cast<double>(map.ok);
  state.counters["cycles_per_point"] = static_cast<double>(cycles) /
                                       static_cast<double>(map.points.size());
}
BENCHMARK(BM_AeroMapEfw180)
    ->ArgName("threads")
    ->Arg(1)
    ->Arg(2)
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);

}  // namespace
