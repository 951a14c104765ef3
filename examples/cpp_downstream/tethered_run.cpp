// A downstream program: load a vehicle file, fly it tethered in the wind tunnel for a few cycles
// at its operating point, print the last cycle's mean loads. Built against the installed package
// (find_package(ornithopter)); tests/package/install_downstream.sh builds and runs it in CI.
#include <cstdio>
#include <cstring>
#include <exception>

#include <ornithopter/ornithopter.hpp>  // the public API in one include (docs/cpp.md)

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: tethered_run VEHICLE.toml\n");
    return 2;
  }
  // The header's version and the package's (ornithopterConfigVersion.cmake) are the same number.
  if (std::strcmp(orni::kVersion, PACKAGE_VERSION_FROM_CMAKE) != 0) {
    std::fprintf(stderr, "version mismatch: header %s, package %s\n", orni::kVersion,
                 PACKAGE_VERSION_FROM_CMAKE);
    return 1;
  }
  try {
    // The same reader and checks as `ornithopter simulate VEHICLE.toml`: the vehicle and its
    // design point ([operating_point]).
    const orni::VehicleDefinition vehicle = orni::studies::loadVehicleFile(argv[1]);
    const orni::FlightCoreModel model(vehicle.model);
    const orni::OperatingPoint& point = vehicle.design_point;
    orni::SimulationOptions options;
    options.cycles = 3;
    options.record_history = false;
    const orni::SimulationSummary s =
        orni::simulateTethered(model, point, options, /*history=*/nullptr);
    std::printf("ornithopter %s: %s, U = %g m/s, f = %g Hz, theta = %g deg\n", orni::kVersion,
                orni::toString(s.status), point.speed_mps, point.freq_hz,
                point.theta_rad * orni::kRadToDeg);
    std::printf("cycles %d: mean FV = %.6g N, FH = %.6g N, M = %.6g N m, power = %.6g W\n",
                s.cycles_run, s.mean.FV_N, s.mean.FH_N, s.mean.M_Nm, s.mean.power_aero_W);
    return s.status == orni::SimulationStatus::kFailed ? 1 : 0;
  } catch (const orni::studies::InputError& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "failed: %s\n", e.what());
    return 1;
  }
}
