// Design space: named design variables with bounds, each mapped to one or more fields of a
// VehicleModel (a group moves several fields together, e.g. the four stiffener diameters).
//
// Field names are the vehicle file's keys (units in the suffix; every field here is in metres,
// square metres or dimensionless, so file units are SI):
//   tail.area_m2, tail.aspect_ratio, tail.arm_m, tail.height_m
//   kinematics.hinge_x_m, kinematics.hinge_z_m          (the hinge P2 relative to the CG P1)
//   wing.skin.thickness_m
//   wing.members.<NAME>.diameter_m                      (member sections)
//   wing.members.<NAME>.start_x_m / start_y_m / end_x_m / end_y_m
//                                                       (member layout: one coordinate of a
//                                                        start_xy_m / end_xy_m point)
// <NAME> is a member name, or a prefix followed by '*' for every member whose name starts with it
// ("wing.members.STIF*.diameter_m" = STIF1..STIF4).
//
// The vehicle's mass properties are held: body.mass_kg is the total flight mass and
// body.pitch_inertia_kgm2 the whole vehicle's, whatever the members or the tail become (the
// design changes the wing's own mass and inertia, which the wing model computes from its members).
#pragma once

#include <string>
#include <vector>

#include "core/model/field_table.hpp"
#include "core/model/vehicle_fields.hpp"
#include "core/model/vehicle_model.hpp"

namespace orni::opt {

/// One resolved field: the vehicle number it sets (core/model/vehicle_fields.hpp: the accessor of
/// its key and, for member fields, the index of the member in WingModel::members).
struct DesignField {
  VehicleNumberRef ref;
  std::string name;  ///< the resolved key ("wing.members.STIF1.diameter_m")

  /// The field-table entry of the vehicle key this field sets ("tail.area_m2",
  /// "wing.members[].diameter_m", "wing.members[].end_xy_m" for end_x_m and end_y_m): its range
  /// (SI = file units for every design field) bounds the variable.
  const FieldSpec& spec() const { return ref.number->spec(); }
};

/// Resolves a field name (wildcards expanded) against `vehicle`. On failure returns false and says
/// why in *why ("no member named 'STIF9'", "unknown field ..."), with the list of known names.
bool resolveDesignField(const std::string& text, const VehicleModel& vehicle,
                        std::vector<DesignField>* fields, std::string* why);

/// Every field name a design variable may use for this vehicle (members expanded), for messages.
std::vector<std::string> designFieldNames(const VehicleModel& vehicle);

/// The value of a field in `vehicle` (SI).
double fieldValue(const VehicleModel& vehicle, const DesignField& field);
/// Set a field of `vehicle` (SI).
void setFieldValue(VehicleModel* vehicle, const DesignField& field, double value);

/// A design variable: one value applied to every field of the group.
struct DesignVariable {
  std::string name;                 ///< label (history columns, summary `design` keys)
  std::vector<std::string> field_names;  ///< as given (before expansion); default {name}
  std::vector<DesignField> fields;  ///< resolved, at least one
  double lower = 0.0, upper = 0.0;  ///< SI, lower < upper
  double initial = 0.0;             ///< SI, in [lower, upper]
};

struct DesignSpace {
  std::vector<DesignVariable> variables;
  int size() const { return static_cast<int>(variables.size()); }
};

/// A copy of `base` with variable i's value x[i] written to each of its fields.
VehicleModel applyDesign(const VehicleModel& base, const DesignSpace& space,
                         const std::vector<double>& x);

}  // namespace orni::opt
