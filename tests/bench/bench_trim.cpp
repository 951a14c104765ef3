// Speed of the trim solver (issue target: one trim solve of efw_magpie at 12 Hz in at most 2 s).
//   BM_TrimEfw12Hz : `ornithopter trim efw_magpie.toml --freq 12` without I/O: default options,
//                    initial guess = the vehicle's operating point (paper Table 3). With the
//                    committed vehicle this solve ends not_converged on the tail bound (no
//                    equilibrium inside the bounds), the costliest kind of solve.
//   BM_TrimEfw6Hz  : the same at 6 Hz, where the vehicle trims (a converging solve).
//   BM_TrimEfw12HzTwoThreads : BM_TrimEfw12Hz with each Jacobian's runs on 2 threads
//                    (TrimOptions::jacobian_threads, `trim -j 2`; the same result).
// Counters: periodic runs (residual + derivative), solver iterations, converged (0/1).
#include <benchmark/benchmark.h>

#include <string>

#include "studies/runner/config/vehicle_file.hpp"
#include "trim/trim_solver.hpp"

namespace {

using namespace orni;

void trimEfw(benchmark::State& state, double freq_hz, int threads = 1) {
  const VehicleDefinition file =
      studies::loadVehicleFile(std::string(ORNI_SOURCE_DIR) + "/studies/vehicles/efw_magpie.toml");
  const FlightCoreModel model(file.model);
  TrimOptions o = defaultTrimOptions(file.design_point);
  o.initial.freq_hz = freq_hz;
  o.jacobian_threads = threads;
  TrimSummary s;
  for (auto _ : state) {
    s = solveTrim(model, o);
    benchmark::DoNotOptimize(s.solution.speed_mps);
  }
  state.counters["periodic_runs"] = s.evaluations;
  state.counters["residual_runs"] = s.residual_evaluations;
  state.counters["iterations"] = s.iterations;
  state.counters["converged"] = s.converged ? 1 : 0;
}

void BM_TrimEfw12Hz(benchmark::State& s) { trimEfw(s, 12.0); }
void BM_TrimEfw6Hz(benchmark::State& s) { trimEfw(s, 6.0); }
void BM_TrimEfw12HzTwoThreads(benchmark::State& s) { trimEfw(s, 12.0, 2); }
BENCHMARK(BM_TrimEfw12Hz)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_TrimEfw12HzTwoThreads)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_TrimEfw6Hz)->Unit(benchmark::kMillisecond);

}  // namespace
