// Speed of the periodic-flight core (issue targets: docs/speed.md and the closing notes).
//   BM_TetheredRfw10Cycles/mst-td : 10 flapping cycles of the rigid-wing tethered RFW case,
//                                   27 strips, MST-TD, default tolerances (target <= 2 ms).
#include <benchmark/benchmark.h>

#include <string>

#include "core/dynamics/tethered_simulation.hpp"
#include "core/model/frames.hpp"
#include "studies/runner/config/vehicle_file.hpp"

namespace {

using namespace orni;

VehicleModel rfw(AeroModelKind kind) {
  VehicleModel v =
      studies::loadVehicleFile(std::string(ORNI_SOURCE_DIR) + "/studies/vehicles/rfw_tunnel.toml")
          .model;
  v.aero.model = kind;
  return v;
}

void tetheredRfw10Cycles(benchmark::State& state, AeroModelKind kind, double theta_deg) {
  const FlightCoreModel model(rfw(kind));
  SimulationOptions opts;
  opts.cycles = 10;
  opts.record_history = false;
  const OperatingPoint point{6.0, 4.0, theta_deg * kDegToRad, 0.0};
  long evals = 0;
  for (auto _ : state) {
    const SimulationSummary s = simulateTethered(model, point, opts, nullptr);
    benchmark::DoNotOptimize(s.mean.FV_N);
    evals = s.rhs_evaluations;
  }
  state.counters["rhs_evals"] = static_cast<double>(evals);
  state.counters["strips"] = static_cast<double>(model.strips.size());
}

void BM_TetheredRfw10Cycles_MstTd_theta0(benchmark::State& s) {
  tetheredRfw10Cycles(s, AeroModelKind::kMstTd, 0.0);
}
void BM_TetheredRfw10Cycles_MstTd_theta20(benchmark::State& s) {
  tetheredRfw10Cycles(s, AeroModelKind::kMstTd, 20.0);
}
void BM_TetheredRfw10Cycles_DeLaurier_theta20(benchmark::State& s) {
  tetheredRfw10Cycles(s, AeroModelKind::kDeLaurier1993, 20.0);
}
BENCHMARK(BM_TetheredRfw10Cycles_MstTd_theta0)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_TetheredRfw10Cycles_MstTd_theta20)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_TetheredRfw10Cycles_DeLaurier_theta20)->Unit(benchmark::kMillisecond);

// One right-hand side: 27 strips of MST-TD plus inertia (the unit cost behind the above).
void BM_RightHandSide_MstTd27(benchmark::State& state) {
  const FlightCoreModel model(rfw(AeroModelKind::kMstTd));
  FlightCoreData data(model);
  const BodyMotion body = tetheredBodyMotion(6.0, 20.0 * kDegToRad);
  const ControlInput ctl{4.0, 0.0};
  std::vector<double> y(static_cast<std::size_t>(model.aeroStateCount())), yd(y.size());
  initialAeroStates(model, body, ctl, 0.0, y.data());
  LoadSample out;
  double t = 0.0;
  for (auto _ : state) {
    evaluateLoads(model, data, body, ctl, t, y.data(), yd.data(), &out);
    benchmark::DoNotOptimize(out.FV_N);
    t += 1e-4;
  }
}
BENCHMARK(BM_RightHandSide_MstTd27);

}  // namespace
