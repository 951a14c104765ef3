// The public C++ API of ornithopter in one include, as an installed package's user writes it:
//   find_package(ornithopter) ... target_link_libraries(app PRIVATE ornithopter::studies)
//   #include <ornithopter/ornithopter.hpp>
// (installed as <prefix>/include/ornithopter/ornithopter.hpp; docs/cpp.md). It gathers what a
// program needs to read a vehicle, build its model, fly it tethered or free, trim it, map it and
// judge its stability, or run any study file into a folder as the command line does.
#pragma once

#include "core/version.hpp"                        // kVersion, kGitRevision

#include "core/model/frames.hpp"                   // unit conversions (kRadToDeg, ...)
#include "core/model/invalid_model_error.hpp"      // a model the core rejects
#include "core/model/vehicle_model.hpp"            // VehicleModel, OperatingPoint

#include "core/dynamics/flight_core.hpp"           // FlightCoreModel: the vehicle, built once
#include "core/dynamics/free_flight.hpp"           // simulateFree (paper Eqs. 1-2, 5)
#include "core/dynamics/simulation_options.hpp"    // SimulationOptions, SimulationSummary
#include "core/dynamics/tethered_simulation.hpp"   // simulateTethered (the wind tunnel)

#include "trim/aero_map.hpp"                       // aero maps (paper Fig. 5)
#include "trim/periodic_trim.hpp"                  // periodic-orbit trim, Floquet multipliers
#include "trim/trim_solver.hpp"                    // trim in level flight (paper Eq. 4)

#include "studies/runner/commands/run_study.hpp"   // run a study into a folder, as the CLI
#include "studies/runner/config/input_error.hpp"   // bad input: file, line, key, expected
#include "studies/runner/config/study_file.hpp"    // study files
#include "studies/runner/config/vehicle_file.hpp"  // loadVehicleFile, vehicleToToml
