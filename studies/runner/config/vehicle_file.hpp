// Vehicle files (TOML) <-> orni::VehicleDefinition (the VehicleModel and its design point).
//
// Units live in the key suffixes (_m, _deg, _gpa, _kgpm3, ...); the model is SI and radians. The
// conversion happens here and nowhere else (docs/design.md 7.3). The schema is documented in
// studies/vehicles/efw_magpie.toml. Every error is an InputError naming file, line and key.
//
// Private to orni_studies (includes toml++ through toml_access.hpp); the rest of the program uses
// study_file.hpp or loadVehicleFile through it.
#pragma once

#include <toml++/toml.h>

#include <filesystem>
#include <string>
#include <vector>

#include "core/model/vehicle_model.hpp"
#include "studies/runner/config/toml_access.hpp"

namespace orni::studies {

/// Reads and validates a vehicle file: the vehicle and its design point ([operating_point]).
/// Throws InputError.
orni::VehicleDefinition loadVehicleFile(const std::filesystem::path& file);

/// Validates an already parsed vehicle document (e.g. one with a study's overrides merged in).
/// Nodes carry their own file and line; `file_for_messages` is named for nodes without a source.
orni::VehicleDefinition parseVehicleTable(const toml::table& root,
                                          const std::filesystem::path& file_for_messages);

/// Same, with full control of the messages: `context` (file, foreign file and its key prefix) and
/// the dotted path of `root` inside its document ("" for a vehicle file, "vehicle" for the inline
/// vehicle of a resolved study).
orni::VehicleDefinition parseVehicleTable(const toml::table& root, const ReadContext& context,
                                          const std::string& root_path);

/// Writes the complete vehicle in file units and key names, every default filled in, under the
/// table path `prefix` ({} = document root, {"vehicle"} = a [vehicle] table). Numbers are written
/// so that parseVehicleTable reproduces the model exactly.
void writeVehicleToml(const orni::VehicleDefinition& vehicle, TomlWriter& out,
                      const std::vector<std::string>& prefix);

/// The complete vehicle as a stand-alone vehicle-file document.
std::string vehicleToToml(const orni::VehicleDefinition& vehicle);

}  // namespace orni::studies
