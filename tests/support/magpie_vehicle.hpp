// The paper's ornithopter as committed (studies/vehicles/efw_magpie.toml: calibrated, flexible
// wing, 12 modes), loaded through the vehicle-file reader, for tests of the flexible wing.
#pragma once

#include <string>

#include "studies/runner/config/vehicle_file.hpp"

namespace orni::testing {

inline VehicleModel magpieVehicle() {
  return studies::loadVehicleFile(std::string(ORNI_SOURCE_DIR) +
                                  "/studies/vehicles/efw_magpie.toml");
}

}  // namespace orni::testing
