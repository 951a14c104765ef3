// Free flight (issue target: 10 flapping cycles with the flexible wing in at most 15 ms median).
//   BM_FreeEfwFlexible10Cycles: magpie at the paper's trim point, 12 modes, MST-TD, tail, no
//   load sampling (the verdict and limit cycle need only the body states).
//   BM_FreeEfwRigid10Cycles: the same with the rigid wing.
#include <benchmark/benchmark.h>

#include <string>

#include "core/dynamics/free_flight.hpp"
#include "studies/runner/config/vehicle_file.hpp"

namespace {

using namespace orni;

void runFree(benchmark::State& state, StructureLevel level, bool periodic_start) {
  VehicleDefinition file =
      studies::loadVehicleFile(std::string(ORNI_SOURCE_DIR) + "/studies/vehicles/efw_magpie.toml");
  VehicleModel& v = file.model;
  v.wing.structure = level;
  const FlightCoreModel model(v);
  SimulationOptions opts;
  opts.cycles = 10;
  opts.record_history = false;
  opts.free.divergence_ratio = 1e6;  // time the whole horizon even off trim
  // The metric is 10 cycles of free flight; the release in the periodic state (a tethered
  // run to its steady state first) is timed separately.
  opts.free.periodic_start_cycles = periodic_start ? 40 : 0;
  long evals = 0;
  for (auto _ : state) {
    const FreeFlightSummary s = simulateFree(model, file.design_point, opts, nullptr);
    benchmark::DoNotOptimize(s.verdict.norm_ratio_max);
    evals = s.rhs_evaluations;
    if (s.cycles_run != 10) state.SkipWithError(s.message.c_str());
  }
  state.counters["rhs_evals"] = static_cast<double>(evals);
}

void BM_FreeEfwFlexible10Cycles(benchmark::State& state) {
  runFree(state, StructureLevel::kFlexible, false);
}
BENCHMARK(BM_FreeEfwFlexible10Cycles)->Unit(benchmark::kMillisecond);

void BM_FreeEfwFlexible10CyclesPeriodicStart(benchmark::State& state) {
  runFree(state, StructureLevel::kFlexible, true);
}
BENCHMARK(BM_FreeEfwFlexible10CyclesPeriodicStart)->Unit(benchmark::kMillisecond);

void BM_FreeEfwRigid10Cycles(benchmark::State& state) {
  runFree(state, StructureLevel::kRigid, false);
}
BENCHMARK(BM_FreeEfwRigid10Cycles)->Unit(benchmark::kMillisecond);

}  // namespace
