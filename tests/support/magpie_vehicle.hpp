// The paper's ornithopter as committed (studies/vehicles/efw_magpie.toml: calibrated, flexible
// wing, 12 modes), loaded through the vehicle-file reader, for tests of the flexible wing.
#pragma once

#include <string>

#include "studies/runner/config/vehicle_file.hpp"

namespace orni::testing {

/// The file's vehicle and its design point ([operating_point]).
inline VehicleDefinition magpieDefinition() {
  return studies::loadVehicleFile(std::string(ORNI_SOURCE_DIR) +
                                  "/studies/vehicles/efw_magpie.toml");
}

inline VehicleModel magpieVehicle() { return magpieDefinition().model; }

/// The file's [operating_point]: Table 3's published trim point (12 Hz, 10.8 m/s, 9.2 deg,
/// tail 11.85 deg).
inline OperatingPoint magpieDesignPoint() { return magpieDefinition().design_point; }

}  // namespace orni::testing
