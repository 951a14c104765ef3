// The readers and writers of a study file's sections, private to the study loader
// (study_file.cpp's readStudyRoot calls them in file order). Each lives in a file of its own:
//   study_vehicle.cpp     `vehicle` (path or inline table), vehicle_source, [override]
//   simulate_section.cpp  [simulate] and [simulate.free]; the integrator tolerances it shares
//                         with [aeromap]
//   aeromap_section.cpp   [aeromap]
//   grid_axis.cpp         the grid axes of [aeromap] and of a sweep
//   kind_sections.cpp     which section a kind may have, and the dispatch to each kind's reader
// Includes toml++ through toml_access.hpp.
#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "studies/runner/config/study_file.hpp"
#include "studies/runner/config/toml_access.hpp"

namespace orni::studies {

/// The top-level table, the parsed document and its read context: what a section's reader reads.
struct StudyDocument {
  TableReader& top;
  toml::table& root;
  const std::shared_ptr<ReadContext>& context;
};

/// The study's vehicle: `vehicle` (a path relative to the study's folder, or an inline table),
/// vehicle_source and [override]; sets study.vehicle, vehicle_path and point.
void readStudyVehicle(StudyDocument doc, const std::filesystem::path& study_file, Study& study);

/// Rejects the top-level sections `sections` when the study's kind may not have them (an error at
/// the section naming the kinds that may); the rule of each section is kind_sections.cpp's.
void rejectSectionsOfOtherKinds(const TableReader& top, const std::vector<std::string>& sections,
                                StudyKind kind);

/// Everything after the vehicle: for every section in file-format order, rejects it when the
/// study's kind may not have it, and reads it (with its kind's checks) when the kind uses it.
void readKindSections(StudyDocument doc, Study& study);

/// [simulate] (optional; kind simulate): the operating point, the options and [simulate.free];
/// sets study.settings to SimulateSettings (the defaults without a [simulate]).
void readSimulateSection(StudyDocument doc, Study& study);
/// A free flight of the geometrically nonlinear wing whose study gave no rel_tol flies at
/// kNonlinearWingFreeFlightRelTol (1e-5) instead of the default 1e-4, where its verdicts are not
/// converged (simulation_options.hpp). Called by readSimulateSection and wherever the mode is set
/// after reading (`simulate --mode free`).
void applyWingTolerance(Study& study);
/// Writes [simulate] with every option ([simulate.free] in free flight) at `point`.
void writeSimulateSection(const SimulateSettings& simulate, const orni::OperatingPoint& point,
                          TomlWriter& out);

/// [aeromap] (required; kind aeromap).
void readAeromapSection(StudyDocument doc, Study& study);
/// Writes [aeromap]: its axes (specs as "A:B:N") and options.
void writeAeromapSection(const AeromapSettings& aeromap, TomlWriter& out);
/// The tail-angle axis of an aero map that gives none: the operating point's tail angle (deg).
GridAxis defaultTailAngleAxis(const orni::OperatingPoint& point);

/// The integrator tolerances shared by [simulate] and [aeromap] (`section`, the field-table
/// prefix): rel_tol, abs_tol, separation_abs_tol, steady_tol, read and written in this order.
void readTolerances(TableReader& r, orni::SimulationOptions& o, const std::string& section);
void writeTolerances(const orni::SimulationOptions& o, TomlWriter& out);

/// SimulationOptions::IsValid's "<field> must be <condition>" as an InputError at the key of that
/// field in `section` (or at the section when the default is at fault).
[[noreturn]] void throwInvalidOptions(const TableReader& section, const std::string& why);

}  // namespace orni::studies
