// Vehicles built in code for core tests (independent of the TOML loader): the RFW rig as in
// studies/vehicles/rfw_tunnel.toml.
#pragma once

#include "core/model/frames.hpp"
#include "core/model/vehicle_model.hpp"

namespace orni::testing {

inline VehicleModel rfwRig() {
  VehicleModel v;
  v.name = "rfw_test";
  v.wing.planform = Planform::kRectangular;
  v.wing.semispan_m = 0.27;
  v.wing.root_chord_m = 0.54 / 5.58;
  v.wing.strip_count = 27;
  v.wing.skin = WingSkin{"RIPSTOP", 4e-5};
  v.materials.push_back(Material{"RIPSTOP", 2e9, 0.35, 1000.0});
  v.materials.push_back(Material{"CFRP", 135e9, 0.3, 1600.0});
  v.wing.members.push_back(WingMember{"LE", "CFRP", 0.003, 0.0, 0.0, 0.0, 0.27});
  v.flapping.amplitude_rad = 33.06 * kDegToRad;
  return v;
}

/// The rig's point of studies/vehicles/rfw_tunnel.toml: 6 m/s, 4 Hz, theta 0.
inline OperatingPoint rfwRigPoint() { return OperatingPoint{6.0, 4.0, 0.0, 0.0}; }

}  // namespace orni::testing
