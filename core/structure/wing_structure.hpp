// What the wing's finite-element model is built from: the wing itself
// (planform, members, skin, wing.fe settings) and the materials it names. Nothing else of the
// vehicle (air, aerodynamics, flapping, body, tail, operating point) reaches core/structure, so
// nothing else can change a modal wing or the key it is cached under
// (core/dynamics/modal_wing_cache.hpp).
#pragma once

#include <string>
#include <vector>

#include "core/model/vehicle_model.hpp"

namespace orni::structure {

/// A view of a vehicle's structural inputs (references: use it within the vehicle's life, do not
/// keep it). Any VehicleModel converts to one, so callers pass their vehicle and the FE code sees
/// only its wing and materials.
struct WingStructure {
  const WingModel& wing;
  const std::vector<Material>& materials;
  const std::string& vehicle_name;  ///< only for the heading of a CalculiX deck

  WingStructure(const WingModel& wing_in, const std::vector<Material>& materials_in,
                const std::string& vehicle_name_in)
      : wing(wing_in), materials(materials_in), vehicle_name(vehicle_name_in) {}
  // Implicit on purpose: "the wing of this vehicle" (see the file comment).
  WingStructure(const VehicleModel& vehicle)  // NOLINT(google-explicit-constructor)
      : WingStructure(vehicle.wing, vehicle.materials, vehicle.name) {}

  /// The material of that name, or nullptr.
  const Material* findMaterial(const std::string& material_name) const {
    for (const Material& m : materials)
      if (m.name == material_name) return &m;
    return nullptr;
  }
};

}  // namespace orni::structure
