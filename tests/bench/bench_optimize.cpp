// Speed of one design evaluation of the optimiser (issue 6 target: model build + trim + free-flight
// check in at most 1.5 s): DesignProblem::evaluate on efw_magpie, exactly what `ornithopter
// optimize` runs per point (the vehicle check by re-reading it, FlightCoreModel, solveTrim with its
// free-flight check of 60 cycles, the constraints).
//   BM_DesignEvaluationRigid6Hz   : rigid wing at 6 Hz, where the vehicle trims (a converging
//                                   trim followed by the free flight).
//   BM_DesignEvaluationRigid12Hz  : rigid wing at 12 Hz (paper Table 3), where the committed
//                                   vehicle does not trim: the costliest kind of trim (stalls on
//                                   the tail bound), no free flight.
//   BM_DesignEvaluationFlexible6Hz: flexible wing at 6 Hz with a new stiffener diameter at every
//                                   iteration, so that the FE model and modes are rebuilt each
//                                   time (no cache hit), plus trim and free flight.
// Counters: periodic runs of the trim, trim converged (0/1), free flight flown (s).
#include <benchmark/benchmark.h>

#include <string>

#include "optimize/design_problem.hpp"
#include "studies/runner/config/vehicle_file.hpp"

namespace {

using namespace orni;
using namespace orni::opt;

VehicleModel magpie() {
  return studies::loadVehicleFile(std::string(ORNI_SOURCE_DIR) +
                                  "/studies/vehicles/efw_magpie.toml");
}

DesignSpace space(const VehicleModel& v, bool stiffeners) {
  DesignSpace s;
  auto add = [&](const std::string& name, double lo, double hi) {
    DesignVariable var;
    var.name = name;
    std::string why;
    resolveDesignField(name, v, &var.fields, &why);
    var.lower = lo;
    var.upper = hi;
    var.initial = fieldValue(v, var.fields.front());
    s.variables.push_back(var);
  };
  add("tail.area_m2", 0.004, 0.012);
  add("tail.arm_m", 0.08, 0.16);
  if (stiffeners) add("wing.members.STIF*.diameter_m", 2e-4, 8e-4);
  return s;
}

void evaluate(benchmark::State& state, double freq_hz, bool flexible) {
  VehicleModel v = magpie();
  if (flexible) v.wing.structure = StructureLevel::kFlexible;
  DesignProblemOptions o;
  o.trim = defaultTrimOptions(v);
  o.trim.initial.freq_hz = freq_hz;
  if (freq_hz < 10.0) {  // the 6 Hz trim of README.md
    o.trim.initial.theta_rad = 14.0 * 0.017453292519943295;
    o.trim.initial.speed_mps = 8.0;
    o.trim.initial.tail_angle_rad = 30.0 * 0.017453292519943295;
  }
  o.validate = [](const VehicleModel& d) { studies::validateVehicle(d); };
  const DesignProblem p(v, space(v, flexible), o);
  std::vector<double> x = p.box().initial;
  Evaluation e;
  int i = 0;
  for (auto _ : state) {
    if (flexible) x[2] = 4e-4 * (1.0 + 1e-6 * ++i);  // a new structure: no modal-cache hit
    auto ws = p.makeWorkspace();
    e = p.evaluate(x, *ws);
    benchmark::DoNotOptimize(e.objective);
  }
  state.counters["periodic_runs"] = e.values[kPeriodicRuns];
  state.counters["trim_converged"] = e.values[kTrimConverged];
  state.counters["free_flight_s"] = e.values[kFlownTime];
}

void BM_DesignEvaluationRigid6Hz(benchmark::State& s) { evaluate(s, 6.0, false); }
void BM_DesignEvaluationRigid12Hz(benchmark::State& s) { evaluate(s, 12.0, false); }
void BM_DesignEvaluationFlexible6Hz(benchmark::State& s) { evaluate(s, 6.0, true); }
BENCHMARK(BM_DesignEvaluationRigid6Hz)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_DesignEvaluationRigid12Hz)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_DesignEvaluationFlexible6Hz)->Unit(benchmark::kMillisecond);

}  // namespace
