// Speed of the periodic-orbit trim and its Floquet analysis (issue 16 target: periodic trim plus
// Floquet multipliers of the flexible magpie at 12 Hz in at most 0.5 s on one core).
//   BM_PeriodicTrimEfw12Hz        : `ornithopter trim efw_magpie.toml --freq 12 --method periodic`
//                                   without I/O and without the bounded-norm free flight: the
//                                   Eq. (4) start, the orbit (two passes), the leading 8
//                                   multipliers by Arnoldi, the orbit's histories.
//   BM_PeriodicTrimAllMultipliers : the same with all 106 multipliers (full monodromy, what
//                                   `ornithopter stability` computes).
//   BM_FloquetLeadingAtOrbit      : the Floquet step alone at the converged orbit (Arnoldi).
//   BM_PeriodicTrimEfw12HzTwoThreads : BM_PeriodicTrimEfw12Hz with the Jacobians' runs on 2
//                                   threads (TrimOptions::jacobian_threads; the same bits).
// Counters: period maps, Newton iterations, right-hand sides, max |mu|, converged (0/1).
#include <benchmark/benchmark.h>

#include <string>

#include "core/analysis/monodromy.hpp"
#include "studies/runner/config/vehicle_file.hpp"
#include "trim/periodic_trim.hpp"

namespace {

using namespace orni;

VehicleDefinition magpieFile() {
  return studies::loadVehicleFile(std::string(ORNI_SOURCE_DIR) +
                                  "/studies/vehicles/efw_magpie.toml");
}

VehicleModel magpie() { return magpieFile().model; }

TrimOptions periodicOptions(const VehicleModel& /*v*/, int multipliers) {
  TrimOptions o = defaultTrimOptions(magpieFile().design_point);
  o.initial.freq_hz = 12.0;
  usePeriodicMethod(&o);
  o.verify_free_flight = false;
  o.periodic.multipliers = multipliers;
  return o;
}

void periodicTrim(benchmark::State& state, int multipliers, int threads = 1) {
  const VehicleModel v = magpie();
  const FlightCoreModel model(v);
  TrimOptions o = periodicOptions(v, multipliers);
  o.jacobian_threads = threads;
  PeriodicTrimSummary s;
  for (auto _ : state) {
    s = solvePeriodicTrim(model, o);
    benchmark::DoNotOptimize(s.solution.speed_mps);
  }
  state.counters["period_maps"] = static_cast<double>(s.shooting.period_maps + s.floquet_maps);
  state.counters["newton_iterations"] = s.shooting.iterations;
  state.counters["rhs"] = static_cast<double>(s.rhs_evaluations);
  state.counters["max_modulus"] = s.floquet_valid ? s.floquet.max_modulus : 0.0;
  state.counters["converged"] = s.converged ? 1 : 0;
}

void BM_PeriodicTrimEfw12Hz(benchmark::State& s) { periodicTrim(s, 8); }
void BM_PeriodicTrimAllMultipliers(benchmark::State& s) { periodicTrim(s, 0); }
void BM_PeriodicTrimEfw12HzTwoThreads(benchmark::State& s) { periodicTrim(s, 8, 2); }
BENCHMARK(BM_PeriodicTrimEfw12Hz)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_PeriodicTrimEfw12HzTwoThreads)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_PeriodicTrimAllMultipliers)->Unit(benchmark::kMillisecond);

void BM_FloquetLeadingAtOrbit(benchmark::State& state) {
  const VehicleModel v = magpie();
  const FlightCoreModel model(v);
  TrimOptions o = periodicOptions(v, 8);
  o.periodic.floquet = false;
  const PeriodicTrimSummary t = solvePeriodicTrim(model, o);
  if (!t.converged) {
    state.SkipWithError(("no orbit: " + t.message).c_str());
    return;
  }
  FreeFlightPeriodMapOptions mo;
  mo.rel_tol = o.periodic.rel_tol;
  mo.friction_speed_mps = t.friction_speed_mps;
  mo.design_point = o.design_point;  // as the trim's map
  FreeFlightPeriodMap map(model, mo);
  const std::vector<double> p = FreeFlightPeriodMap::parameters(t.solution);
  std::string why;
  map.refreshDiscretisation(t.orbit_start.data(), p.data(), &why);
  ArnoldiOptions ao;
  ao.count = 8;
  MonodromyEigen e;
  for (auto _ : state) {
    e = leadingMultipliers(map, t.orbit_start, p, ao);
    benchmark::DoNotOptimize(e.multipliers.data());
  }
  state.counters["period_maps"] = static_cast<double>(e.period_maps);
  state.counters["krylov_dimension"] = e.krylov_dimension;
}
BENCHMARK(BM_FloquetLeadingAtOrbit)->Unit(benchmark::kMillisecond);

}  // namespace
