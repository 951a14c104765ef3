// Speed of the continuation of trimmed flight (issue 16 target: the magpie's trim branch over
// 10-16 Hz with 30 points in at most 10 s; now 3 s on two threads, docs/speed.md).
//   BM_ContinuationEfw     : `ornithopter run` of a continuation study without I/O: the periodic
//                            trim at the start, then the branch with the default 8 leading
//                            multipliers at every point (Arnoldi; the tangent by GMRES from the
//                            Jacobian's body columns, docs/theory.md 10.5) and the cycle means.
//                            Arguments: start and end frequency (Hz), points asked for (the first
//                            step is the range over them; the steps adapt, capped at twice as
//                            many), threads (two: Arnoldi on a copy of the map beside the tangent);
//                            counters: points, period maps, events, stable points.
//   BM_ContinuationEfwAll  : the same with all multipliers from the full Jacobian at every point
//                            (trim.periodic.multipliers = 0; its columns on the threads).
#include <benchmark/benchmark.h>

#include <string>

#include "studies/runner/config/vehicle_file.hpp"
#include "trim/trim_continuation.hpp"

namespace {

using namespace orni;

void continuationBenchmark(benchmark::State& state, int multipliers) {
  const VehicleDefinition file =
      studies::loadVehicleFile(std::string(ORNI_SOURCE_DIR) + "/studies/vehicles/efw_magpie.toml");
  const FlightCoreModel model(file.model);
  TrimOptions o = defaultTrimOptions(file.design_point);
  o.initial.freq_hz = static_cast<double>(state.range(0));
  usePeriodicMethod(&o);
  o.periodic.multipliers = multipliers;
  TrimContinuationOptions co;
  co.parameter = PeriodicControl::kFrequency;
  co.to = static_cast<double>(state.range(1));
  // The first step asks for range / points; the steps adapt from there, so the cap on points is
  // twice that (the counters say how many the branch took and whether it reached the end).
  co.step = (co.to - o.initial.freq_hz) / static_cast<double>(state.range(2));
  co.max_points = 2 * static_cast<int>(state.range(2));
  co.threads = static_cast<int>(state.range(3));
  TrimContinuationSummary s;
  for (auto _ : state) {
    s = continueTrim(model, o, co);
    benchmark::DoNotOptimize(s.points.size());
  }
  int stable = 0;
  for (const TrimContinuationPoint& p : s.points) stable += p.orbit.stable ? 1 : 0;
  state.counters["points"] = static_cast<double>(s.points.size());
  state.counters["period_maps"] = static_cast<double>(s.period_maps);
  state.counters["events"] = s.events;
  state.counters["stable"] = stable;
  state.counters["last_hz"] = s.points.empty() ? 0.0 : s.points.back().solution.freq_hz;
  state.counters["completed"] = s.status == ContinuationStatus::kCompleted ? 1.0 : 0.0;
}
void BM_ContinuationEfw(benchmark::State& state) {
  continuationBenchmark(state, PeriodicTrimOptions{}.multipliers);
}
void BM_ContinuationEfwAll(benchmark::State& state) { continuationBenchmark(state, 0); }
BENCHMARK(BM_ContinuationEfwAll)
    ->Args({12, 16, 30, 2})
    ->Args({10, 16, 30, 2})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);
BENCHMARK(BM_ContinuationEfw)
    ->Args({12, 16, 30, 1})
    ->Args({12, 16, 30, 2})
    ->Args({10, 16, 30, 1})
    ->Args({10, 16, 30, 2})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);

}  // namespace
