// Study files (TOML, architecture.md section 5) -> Study.
//
// This is the header the rest of the program includes: no toml++ here. Errors are InputError
// (input_error.hpp) naming file, line and key; main maps them to exit status 2.
//
// Top-level keys of a study file:
//   kind     (required) "simulate" | "modes" | "aeromap" | "trim" | "optimize" | "sweep"
//   name     (optional) run name, [A-Za-z0-9_.-]+; default: the file stem
//   vehicle  (required) path of the vehicle file relative to the study's folder, or an inline
//            [vehicle] table (as written into study.resolved.toml)
//   vehicle_source (optional, only with an inline [vehicle]) where that vehicle came from
//   [override] (optional) any vehicle key with the vehicle file's names and units, e.g.
//            `tail.arm_m = 0.12` or `[override.wing] semispan_m = 0.3`; tables are merged key by
//            key, scalars and arrays are replaced. Errors in overridden values name the study file,
//            its line and the key as 'override.tail.arm_m'.
//   [simulate] (optional, kind = "simulate" only) mode "tethered"|"free", speed_mps, freq_hz,
//            theta_deg, tail_angle_deg (default: the vehicle's operating point), cycles, rel_tol,
//            abs_tol, steady_tol, samples_per_cycle (default: SimulationOptions).
//   [trim]   (optional, kind = "trim" only) freq_hz, unknowns = ["theta_mean_deg", "speed_mps",
//            "tail_angle_deg"] (any 1-3 of these and "freq_hz"), initial = { theta_mean_deg,
//            speed_mps, tail_angle_deg } (default: the vehicle's operating point), bounds =
//            { <unknown> = [lower, upper] }, max_iterations, residual_tol, function_tol, rel_tol,
//            steady_tol, max_cycles, derivative_cycles; see config/trim_section.hpp for ranges and
//            defaults. A trim study needs a vehicle with a [body] (its mass sets the weight).
// Sections of the other kinds ([aeromap], ...) are not defined yet and are rejected.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "core/dynamics/simulation_options.hpp"
#include "core/model/vehicle_model.hpp"
#include "studies/runner/config/input_error.hpp"
#include "trim/trim_options.hpp"

namespace orni::studies {

enum class StudyKind { kSimulate, kModes, kAeromap, kTrim, kOptimize, kSweep };

/// "simulate", "modes", "aeromap", "trim", "optimize", "sweep".
std::string_view toString(StudyKind kind);
/// The kind of that spelling, or nullopt.
std::optional<StudyKind> parseStudyKind(std::string_view text);

struct Study {
  StudyKind kind = StudyKind::kSimulate;
  std::string name;                    ///< run name (output folder results/<name>/)
  std::filesystem::path study_path;    ///< the study file; empty for studyFromVehicle
  std::filesystem::path vehicle_path;  ///< the vehicle path as written in the study (relative
                                       ///< to study_path's folder), or as given to
                                       ///< studyFromVehicle; empty for an inline vehicle
                                       ///< without vehicle_source
  orni::VehicleModel vehicle;          ///< resolved, overrides applied, SI
  orni::OperatingPoint point;          ///< the vehicle's operating point with [simulate] applied
  orni::SimulationOptions simulate;    ///< [simulate] options (defaults for other kinds)
  orni::TrimOptions trim;              ///< [trim] options (kind trim; SI)
};

/// Reads and validates a study file and the vehicle it names. Throws InputError.
Study loadStudyFile(const std::filesystem::path& study_file);

/// The study behind `ornithopter simulate VEHICLE.toml` (and `trim VEHICLE.toml` with kind trim):
/// name = the vehicle file stem, point = the vehicle's operating point, default options (for trim:
/// defaultTrimOptions, not yet validated against the bounds; the caller applies its flags and
/// checks TrimOptions::IsValid). Throws InputError (also for a trim of a vehicle without [body]).
Study studyFromVehicle(const std::filesystem::path& vehicle_file,
                       StudyKind kind = StudyKind::kSimulate);

/// study.resolved.toml: a complete TOML document with every default filled in: kind, name,
/// vehicle_source (the vehicle path as given), [simulate] with all options (kind simulate), [trim]
/// with all options (kind trim), and the
/// resolved vehicle as a [vehicle] table in file units and key names. loadStudyFile reads it back
/// into the same Study (apart from study_path).
std::string resolvedStudyToml(const Study& study);

}  // namespace orni::studies
