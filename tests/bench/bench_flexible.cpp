// Flexible wing (issue targets: model build <= 200 ms; 10 cycles tethered EFW <= 10 ms). The
// tethered run integrates the modal stiffness implicitly (SimulationOptions::modal_integration,
// the default; explicit:0); explicit:1 is the explicit ARK4(3)6L run, for comparison.
//   BM_EfwModalWingBuild: mesh (5 mm) + assembly + eigen-solution + reduction (incl. the
//     geometric-stiffness projections and, nonlinear:1, the condensed membrane of the
//     geometrically nonlinear wing, docs/theory.md 4.7); modes:0 = the vehicle's 24, modes:12 = the
//     count of earlier versions (the like-for-like comparison with their figures), modes:48 the
//     count the slack membrane needs. Target: <= 0.5 s with the nonlinear identification.
//   BM_TetheredEfwFlexible10Cycles: 10 flapping cycles at the vehicle's operating point, MST-TD;
//     modes as above; nonlinear:0 the linear wing (the default), 1 the nonlinear. Target:
//     nonlinear within 2x the linear.
//   BM_TetheredEfwFlexible10CyclesHistories: the linear run recorded at 100 samples a cycle;
//     target: at most 20 % over the run without histories.
//   BM_EfwCoRotational: one evaluation of the large-rotation static wing (corotational.hpp) of the
//     literal EFW at a deflected state (3504 facets, 435 members), what each Newton iteration of
//     orni_film_static --kinematics co-rotational costs: part 0 the internal force, 1 the tangent;
//     film 0 the elastic skin, 1 the wrinkling film (20 N/m cap). No target (a reference tool).
//   BM_FlexibleTetheredRhs: one right-hand side of that run; BM_FlexibleTetheredSample: one
//     history sample evaluated at the state; BM_FlexibleTetheredSampleFromDerivative: one from
//     the dense output (the histories' default).
#include <benchmark/benchmark.h>

#include <string>
#include <vector>

#include "core/dynamics/flexible_tethered.hpp"
#include "core/dynamics/flexible_wing.hpp"
#include "core/dynamics/tethered_simulation.hpp"
#include "core/structure/corotational.hpp"
#include "core/structure/fe_assembly.hpp"
#include "core/structure/modal_wing.hpp"
#include "core/structure/static_shapes.hpp"
#include "core/structure/wing_mesh.hpp"
#include "studies/runner/config/vehicle_file.hpp"

namespace {

using namespace orni;

VehicleDefinition efwFile() {
  return studies::loadVehicleFile(std::string(ORNI_SOURCE_DIR) +
                                  "/studies/vehicles/efw_magpie.toml");
}

VehicleModel efwFlexible() {
  VehicleModel v = efwFile().model;
  v.wing.structure = StructureLevel::kFlexible;
  return v;
}

void BM_EfwModalWingBuild(benchmark::State& state) {
  VehicleModel v = efwFlexible();
  if (state.range(0) > 0) v.wing.fe.max_modes = static_cast<int>(state.range(0));
  v.wing.fe.nonlinear = state.range(1) != 0;
  int elements = 0;
  for (auto _ : state) {
    const structure::WingMesh mesh = structure::buildWingMesh(v, v.wing.fe.element_size_m);
    const structure::ModalWingOptions opts = structure::modalWingOptionsOf(v.wing.fe);
    const structure::ModalWing mw = structure::buildModalWing(v, mesh, opts);
    benchmark::DoNotOptimize(mw.frequencies_hz.data());
    elements = static_cast<int>(mesh.triangles.size() + mesh.beams.size());
  }
  state.counters["elements"] = elements;
}
BENCHMARK(BM_EfwModalWingBuild)
    ->ArgNames({"modes", "nonlinear"})
    ->Args({0, 0})
    ->Args({0, 1})
    ->Args({12, 0})
    ->Args({12, 1})
    ->Args({48, 1})
    ->Unit(benchmark::kMillisecond);

// explicit 0: the default, modal stiffness implicit; 1: the explicit ARK4(3)6L table.
void BM_TetheredEfwFlexible10Cycles(benchmark::State& state) {
  VehicleModel v = efwFlexible();
  if (state.range(1) > 0) v.wing.fe.max_modes = static_cast<int>(state.range(1));
  v.wing.fe.nonlinear = state.range(2) != 0;
  const FlightCoreModel model(v);
  const OperatingPoint point = efwFile().design_point;
  SimulationOptions opts;
  opts.cycles = 10;
  opts.record_history = false;
  opts.modal_integration =
      state.range(0) == 0 ? ModalIntegration::kImplicit : ModalIntegration::kExplicit;
  long evals = 0;
  for (auto _ : state) {
    const SimulationSummary s = simulateTethered(model, point, opts, nullptr);
    benchmark::DoNotOptimize(s.mean.FV_N);
    evals = s.rhs_evaluations;
  }
  state.counters["rhs_evals"] = static_cast<double>(evals);
  state.counters["modes"] = model.flexible->mode_count;
}
BENCHMARK(BM_TetheredEfwFlexible10Cycles)
    ->ArgNames({"explicit", "modes", "nonlinear"})
    ->Args({0, 0, 0})
    ->Args({0, 0, 1})
    ->Args({1, 0, 0})
    ->Args({1, 0, 1})
    ->Args({0, 12, 0})
    ->Args({0, 12, 1})
    ->Args({1, 12, 0})
    ->Unit(benchmark::kMillisecond);

// The calibrated vehicle (efw_magpie_table3.toml, the nonlinear wing) tethered at its design point
// for 10 cycles with 48 modes, the count its slack membrane needs statically (docs/theory.md 4.7):
// the condensed membrane as the truncated factor G (R = 353 of P = 1176 pairs).
void BM_TetheredTable3Membrane48Modes(benchmark::State& state) {
  const VehicleDefinition file = studies::loadVehicleFile(std::string(ORNI_SOURCE_DIR) +
                                                          "/studies/vehicles/efw_magpie_table3.toml");
  VehicleModel v = file.model;
  v.wing.fe.max_modes = 48;
  const FlightCoreModel model(v);
  SimulationOptions opts;
  opts.cycles = 10;
  opts.record_history = false;
  long evals = 0;
  double fv = 0.0;
  for (auto _ : state) {
    const SimulationSummary s = simulateTethered(model, file.design_point, opts, nullptr);
    benchmark::DoNotOptimize(s.mean.FV_N);
    evals = s.rhs_evaluations;
    fv = s.mean.FV_N;
  }
  state.counters["rhs_evals"] = static_cast<double>(evals);
  state.counters["rank"] = model.flexible->membrane().rank();
  state.counters["FV_N"] = fv;
}
BENCHMARK(BM_TetheredTable3Membrane48Modes)->Unit(benchmark::kMillisecond)->Iterations(1);

// The same 10 cycles (linear wing, the vehicle's modes) recorded at 100 samples a cycle into a
// TimeHistory, as the CLI and the Python module run them: the cost of the histories is the
// difference to BM_TetheredEfwFlexible10Cycles/explicit:0/modes:0/nonlinear:0 (target <= 20 %).
// interpolated:1 (the default) takes the samples' loads from the dense output, interpolated:0
// evaluates them at the sampled state (SimulationOptions::interpolate_sampled_loads).
void BM_TetheredEfwFlexible10CyclesHistories(benchmark::State& state) {
  const FlightCoreModel model(efwFlexible());
  const OperatingPoint point = efwFile().design_point;
  SimulationOptions opts;
  opts.cycles = 10;
  opts.record_history = true;
  opts.samples_per_cycle = 100;
  opts.interpolate_sampled_loads = state.range(0) != 0;
  std::size_t samples = 0;
  for (auto _ : state) {
    TimeHistory history;
    const SimulationSummary s = simulateTethered(model, point, opts, &history);
    benchmark::DoNotOptimize(s.mean.FV_N);
    samples = history.t_s.size();
  }
  state.counters["samples"] = static_cast<double>(samples);
}
BENCHMARK(BM_TetheredEfwFlexible10CyclesHistories)
    ->ArgName("interpolated")
    ->Arg(1)
    ->Arg(0)
    ->Unit(benchmark::kMillisecond);

// The flexible tethered wing at the vehicle's operating point (nonlinear: the membrane wing) on a
// state of the orbit: what the right-hand side and sample benchmarks evaluate.
struct TetheredWingAtState {
  FlightCoreModel model;
  OperatingPoint op = efwFile().design_point;
  FlexibleTetheredSystem sys;
  std::vector<double> y;
  explicit TetheredWingAtState(bool nonlinear)
      : model(withNonlinearWing(nonlinear)),
        sys(model, *model.flexible, tetheredBodyMotion(op.speed_mps, op.theta_rad),
            ControlInput{op.freq_hz, op.tail_angle_rad}),
        y(static_cast<std::size_t>(sys.stateCount())) {
    sys.initialState(0.0, y.data());
    for (int i = 0; i < 2 * model.flexible->mode_count; ++i) y[static_cast<std::size_t>(i)] = 1e-4;
  }
  static VehicleModel withNonlinearWing(bool nonlinear) {
    VehicleModel v = efwFlexible();
    v.wing.fe.nonlinear = nonlinear;
    return v;
  }
};

// One right-hand side of the flexible tethered wing (strip kinematics, MST-TD kernel, modal
// loads, apparent mass and its LDL^T solve, resultant, quadratures).
void BM_FlexibleTetheredRhs(benchmark::State& state) {
  TetheredWingAtState w(state.range(0) != 0);
  std::vector<double> ydot(w.y.size());
  double t = 0.0;
  for (auto _ : state) {
    w.sys.rhs(t, w.y.data(), ydot.data());
    benchmark::DoNotOptimize(ydot.data());
    t += 1e-5;
  }
}
BENCHMARK(BM_FlexibleTetheredRhs)->ArgName("nonlinear")->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);

// One history sample of that run (FlexibleTetheredSystem::sample: the right-hand side's loads plus
// the inertial loads by the lumped sums, the separated area and the hinge power).
void BM_FlexibleTetheredSample(benchmark::State& state) {
  TetheredWingAtState w(state.range(0) != 0);
  double t = 0.0;
  LoadSample s;
  for (auto _ : state) {
    w.sys.sample(t, w.y.data(), &s);
    benchmark::DoNotOptimize(s.FV_N);
    t += 1e-5;
  }
}
BENCHMARK(BM_FlexibleTetheredSample)->ArgName("nonlinear")->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);

// The same sample from the dense output's derivative (FlexibleTetheredSystem::
// sampleFromDerivative, what the histories use since 2026-12-06): the inertial loads, the hinge
// power's rates and the separated area, no strip evaluation. ydot is the right-hand side at the
// state, as the interpolant gives it at a step's end.
void BM_FlexibleTetheredSampleFromDerivative(benchmark::State& state) {
  TetheredWingAtState w(state.range(0) != 0);
  std::vector<double> ydot(w.y.size());
  w.sys.rhs(0.0, w.y.data(), ydot.data());
  double t = 0.0;
  LoadSample s;
  for (auto _ : state) {
    w.sys.sampleFromDerivative(t, w.y.data(), ydot.data(), &s);
    benchmark::DoNotOptimize(s.FV_N);
    t += 1e-5;
  }
}
BENCHMARK(BM_FlexibleTetheredSampleFromDerivative)
    ->ArgName("nonlinear")
    ->Arg(0)
    ->Arg(1)
    ->Unit(benchmark::kMicrosecond);

// The co-rotational EFW at a deflected state: the linear answer to 1 Pa of lift, times 10.
void BM_EfwCoRotational(benchmark::State& state) {
  const VehicleModel v = efwFile().model;
  const structure::WingMesh mesh = structure::buildWingMesh(v, v.wing.fe.element_size_m);
  const structure::WingFeModel fe = structure::assembleWingFe(v, mesh);
  structure::FilmLaw film;
  film.compression_cap_n_per_m = 20.0;
  const structure::CoRotationalTerms terms(
      v, mesh, fe.stiffness,
      state.range(1) != 0 ? structure::SkinMembrane::kTensionField : structure::SkinMembrane::kElastic,
      film);
  structure::NonlinearStaticOptions linear;
  linear.nonlinear = false;
  const Eigen::VectorXd u =
      10.0 * structure::solveWingStatic(v, mesh, structure::WingSupport::of(v.wing.fe),
                                        structure::uniformLiftLoad(mesh, 1.0), linear)
                 .displacement;
  for (auto _ : state) {
    if (state.range(0) == 0) {
      const Eigen::VectorXd f = terms.strainForce(u);
      benchmark::DoNotOptimize(f.data());
    } else {
      const structure::SparseMatrix k = terms.strainTangent(u);
      benchmark::DoNotOptimize(k.valuePtr());
    }
  }
  state.counters["elements"] = static_cast<double>(mesh.triangles.size() + mesh.beams.size());
}
BENCHMARK(BM_EfwCoRotational)
    ->ArgNames({"part", "film"})
    ->Args({0, 0})
    ->Args({1, 0})
    ->Args({0, 1})
    ->Args({1, 1})
    ->Unit(benchmark::kMillisecond);

}  // namespace
