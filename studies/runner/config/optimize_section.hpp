// The [optimize] section of a study file (kind = "optimize") <-> OptimizeSettings.
//
// Private to orni_studies (includes toml++ through toml_access.hpp). Keys (file units in the
// suffixes; every design field is in m, m^2 or dimensionless, so its bounds are SI); the valid
// range of each is its entry in the field table (core/model/field_table.cpp, `ornithopter keys
// optimize`), the ranges below are its copy for reading:
//
//   algorithm          "cobyla" (default) | "bobyqa" (AUGLAG + BOBYQA, >= 2 variables) | "isres"
//                      (global ISRES, then a COBYLA polish)
//   objective          "power" (default: cycle-mean hinge power at trim, W) | "pitch_amplitude"
//                      (half the peak-to-peak pitch of the free flight, deg) | "weighted"
//   max_evaluations    evaluations per start, every stage included, [2, 1000000]; default 100
//   starts             multi-start count [1, 1000]; default 1 (start 0 = the initial design,
//                      others Halton points in the box); spread over `-j` threads
//   seed               [0, 1000000000]; default 1 (start k uses seed + k)
//   freq_hz            flapping frequency of the trim [0.01, 200]; default the vehicle's operating
//                      point (the initial guess when freq_hz is a trim unknown)
//   initial_step       first step as a fraction of each variable's range (0, 1]; default 0.1
//   xtol               stop when a step is below this fraction of every range [0, 1); 1e-4
//   ftol_rel           stop when the objective changes by less than this fraction [0, 1); 0 = off
//   constraint_tol     feasible when every constraint g <= constraint_tol [0, 1); 1e-6
//   warm_start         start each trim from the last converged trim of the start; default true
//   polish_evaluations (isres only) evaluations of the COBYLA polish; 0 = max_evaluations / 4
//   population         (isres only) 0 = NLopt's 20 (n + 1), else [2, 100000]
//   variables          (required) an array of tables, inline or as [[optimize.variables]]:
//                        name    (required) label, [A-Za-z0-9_.*-]+, unique; also the field when
//                                `fields` is absent
//                        fields  (optional) array of design field names set together (a group);
//                                see optimize/design_space.hpp ("tail.area_m2",
//                                "wing.members.STIF*.diameter_m", ...)
//                        lower, upper (required) bounds, lower < upper, inside the range of
//                                every field the variable sets (tail.arm_m's for "tail.arm_m")
//                        initial (optional) start value; default the vehicle's value (required
//                                when the fields of a group differ)
//   [optimize.constraints] bounded (bool, default true: free flight bounded, paper Eq. 5),
//                      pitch_amplitude_max_deg, tip_deflection_max_m (flexible wing),
//                      structural_mass_max_kg (both wings): limits, 0 = off (default).
//                      The trim constraint is always on.
//   [optimize.weights] (only with objective = "weighted") power_per_W (default 1),
//                      pitch_amplitude_per_deg (default 0), not both 0
//   [optimize.trim]    every [trim] key except freq_hz (trim_section.hpp): unknowns, initial,
//                      bounds, tolerances of the trim of each evaluation
//
// Every error is an InputError naming file, line and key ('optimize.variables[1].upper', ...).
#pragma once

#include <string>
#include <vector>

#include "core/model/vehicle_model.hpp"
#include "studies/runner/config/study_file.hpp"
#include "studies/runner/config/toml_access.hpp"

namespace orni::studies {

/// The keys an [optimize] table may have.
std::vector<std::string> optimizeSectionKeys();

/// Reads an [optimize] table against `vehicle` (overrides applied) and its file's design point
/// (the default of optimize.freq_hz and of the trim's initial guess). Calls finish(). Throws
/// InputError.
OptimizeSettings readOptimizeSection(TableReader& optimize, const orni::VehicleModel& vehicle,
                                     const orni::OperatingPoint& design_point);

/// Writes [optimize] with every key and its sub-tables, so that readOptimizeSection reproduces
/// `settings`.
void writeOptimizeSection(const OptimizeSettings& settings, TomlWriter& out);

}  // namespace orni::studies
