// Accessors of the vehicle's numbers: every number, integer and pair of the
// field table's vehicle group (the design point's [operating_point] through designPointNumbers)
// is read and written here, in SI, by its key. The design variables
// (optimize/design_space.hpp), the calibration parameters (trim/calibration.hpp) and the sweep's
// comparison of points (studies/runner/config/sweep_study.cpp) go through these accessors instead
// of their own lists of members; tests/unit/model/test_vehicle_fields.cpp fails when a vehicle
// number of the field table has no accessor, or an accessor reads or writes another field than
// its key names.
//
// Keys are the field table's: "tail.arm_m", "wing.members[].diameter_m" (an element of
// WingModel::members), "materials.*.density_kgpm3" (an element of VehicleModel::materials). A pair
// ("wing.members[].start_xy_m") has one accessor per component (0 = x, 1 = y).
#pragma once

#include <cstddef>
#include <optional>
#include <string_view>
#include <vector>

#include "core/model/field_table.hpp"
#include "core/model/vehicle_model.hpp"

namespace orni {

/// The array whose element a number belongs to.
enum class VehicleElement {
  kNone,      ///< a number of the vehicle itself (the index is ignored)
  kMember,    ///< an element of WingModel::members ("wing.members[]...")
  kMaterial,  ///< an element of VehicleModel::materials ("materials.*...")
};

/// One number of a VehicleModel named by a field-table key, in SI (file value * si_per_unit).
struct VehicleNumber {
  std::string_view key;  ///< the field-table key
  int component = -1;    ///< a pair's component, 0 (x) or 1 (y); -1 for a number or integer
  VehicleElement element = VehicleElement::kNone;
  /// The value of element `index` (SI). Integers are returned as doubles.
  double (*get)(const VehicleModel& vehicle, std::size_t index) = nullptr;
  /// Writes the value of element `index` (SI); integers are rounded to the nearest.
  void (*set)(VehicleModel& vehicle, std::size_t index, double si) = nullptr;

  /// The field-table entry of the key (unit, SI scale, range).
  const FieldSpec& spec() const { return field(key); }
  /// False when the key's optional section is absent ([body], [tail]): the value is not used.
  bool presentIn(const VehicleModel& vehicle) const;
  /// How many elements the vehicle has: 1, its members or its materials.
  std::size_t count(const VehicleModel& vehicle) const;
};

/// Every accessor, in the order of the field table (a pair's x before its y).
const std::vector<VehicleNumber>& vehicleNumbers();

/// One number of a vehicle file's design point ([operating_point], VehicleDefinition), in SI.
/// Not a VehicleNumber: the point is not part of the VehicleModel (docs/design.md 7.1).
struct DesignPointNumber {
  std::string_view key;                  ///< the field-table key, "operating_point.freq_hz"
  double OperatingPoint::*member = nullptr;

  const FieldSpec& spec() const { return field(key); }
  double get(const OperatingPoint& p) const { return p.*member; }
  void set(OperatingPoint& p, double si) const { p.*member = si; }
};

/// The design point's accessors, in the order of the field table.
const std::vector<DesignPointNumber>& designPointNumbers();

/// The accessor of a field-table key ("wing.members[].diameter_m"; concrete keys
/// "wing.members[2].diameter_m" are normalised as findField does), and of a pair's component;
/// nullptr when there is none.
const VehicleNumber* findVehicleNumber(std::string_view key, int component = -1);

/// One concrete number of a vehicle: an accessor and the element it is applied to.
struct VehicleNumberRef {
  const VehicleNumber* number = nullptr;
  std::size_t index = 0;  ///< the member or material; 0 for VehicleElement::kNone

  double get(const VehicleModel& vehicle) const { return number->get(vehicle, index); }
  void set(VehicleModel& vehicle, double si) const { number->set(vehicle, index, si); }
};

/// The number a concrete key names in `vehicle`: "tail.arm_m", "wing.members[3].diameter_m"
/// (an index), "materials.LE1.density_kgpm3" (a material name); for a pair, `component`. Nothing
/// when the key has no accessor or the element does not exist.
std::optional<VehicleNumberRef> resolveVehicleNumber(const VehicleModel& vehicle,
                                                     std::string_view key, int component = -1);

}  // namespace orni
