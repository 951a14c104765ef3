// Accessors of the vehicle's numbers (vehicle_fields.hpp). Each entry names its member once: the
// macros below make the getter and the setter of an entry from the same expression, so they
// cannot drift apart; the tests check that the expression is the member the key names.
#include "core/model/vehicle_fields.hpp"

#include <cmath>
#include <string>

namespace orni {

namespace {

using E = VehicleElement;

// A double member `expr` of `v` (element index `i`).
#define ORNI_NUMBER(KEY, COMPONENT, ELEMENT, EXPR)                                       \
  VehicleNumber {                                                                        \
    KEY, COMPONENT, ELEMENT,                                                             \
        [](const VehicleModel& v, std::size_t i) -> double {                             \
          (void)i;                                                                       \
          return EXPR;                                                                   \
        },                                                                               \
        [](VehicleModel& v, std::size_t i, double si) {                                  \
          (void)i;                                                                       \
          EXPR = si;                                                                     \
        }                                                                                \
  }
// An int member (rounded to the nearest when set).
#define ORNI_INTEGER(KEY, EXPR)                                                          \
  VehicleNumber {                                                                        \
    KEY, -1, E::kNone,                                                                   \
        [](const VehicleModel& v, std::size_t) -> double { return EXPR; },               \
        [](VehicleModel& v, std::size_t, double si) {                                    \
          EXPR = static_cast<int>(std::lround(si));                                      \
        }                                                                                \
  }
#define ORNI_PLAIN(KEY, EXPR) ORNI_NUMBER(KEY, -1, E::kNone, EXPR)
#define ORNI_MEMBER(KEY, COMPONENT, FIELD) \
  ORNI_NUMBER(KEY, COMPONENT, E::kMember, v.wing.members.at(i).FIELD)
#define ORNI_MATERIAL(KEY, FIELD) ORNI_NUMBER(KEY, -1, E::kMaterial, v.materials.at(i).FIELD)

std::vector<VehicleNumber> makeNumbers() {
  return {
      ORNI_PLAIN("air.density_kgpm3", v.air.density_kgpm3),
      ORNI_PLAIN("air.kinematic_viscosity_m2ps", v.air.kinematic_viscosity_m2ps),
      ORNI_PLAIN("air.gravity_mps2", v.air.gravity_mps2),

      ORNI_PLAIN("wing.semispan_m", v.wing.semispan_m),
      ORNI_PLAIN("wing.root_chord_m", v.wing.root_chord_m),
      ORNI_PLAIN("wing.incidence_deg", v.wing.incidence_rad),
      ORNI_INTEGER("wing.strips", v.wing.strip_count),
      ORNI_PLAIN("wing.p3_aft_of_le_m", v.wing.p3_aft_of_le_m),
      ORNI_PLAIN("wing.member_diameter_scale", v.wing.member_diameter_scale),
      ORNI_PLAIN("wing.skin.thickness_m", v.wing.skin.thickness_m),
      ORNI_PLAIN("wing.skin.pretension_N_per_m", v.wing.skin.pretension_N_per_m),
      ORNI_MEMBER("wing.members[].diameter_m", -1, diameter_m),
      ORNI_MEMBER("wing.members[].start_xy_m", 0, start_x_W_m),
      ORNI_MEMBER("wing.members[].start_xy_m", 1, start_y_W_m),
      ORNI_MEMBER("wing.members[].end_xy_m", 0, end_x_W_m),
      ORNI_MEMBER("wing.members[].end_xy_m", 1, end_y_W_m),

      ORNI_PLAIN("wing.fe.element_size_m", v.wing.fe.element_size_m),
      ORNI_INTEGER("wing.fe.modes", v.wing.fe.max_modes),
      ORNI_PLAIN("wing.fe.cutoff_hz", v.wing.fe.cutoff_hz),
      ORNI_PLAIN("wing.fe.damping_ratio", v.wing.fe.damping_ratio),

      ORNI_MATERIAL("materials.*.youngs_modulus_gpa", youngs_modulus_pa),
      ORNI_MATERIAL("materials.*.poisson_ratio", poisson_ratio),
      ORNI_MATERIAL("materials.*.density_kgpm3", density_kgpm3),

      ORNI_PLAIN("aero.aspect_ratio", v.aero.aspect_ratio),
      ORNI_PLAIN("aero.zero_lift_angle_deg", v.aero.zero_lift_angle_rad),
      ORNI_PLAIN("aero.moment_coefficient_ac", v.aero.moment_coefficient_ac),
      ORNI_PLAIN("aero.suction_efficiency", v.aero.suction_efficiency),
      ORNI_PLAIN("aero.crossflow_drag_coefficient", v.aero.crossflow_drag_coefficient),
      ORNI_PLAIN("aero.stall_angle_max_deg", v.aero.stall_angle_max_rad),
      ORNI_PLAIN("aero.stall_angle_min_deg", v.aero.stall_angle_min_rad),
      ORNI_PLAIN("aero.stall_width_deg", v.aero.stall_width_rad),
      ORNI_PLAIN("aero.separation_lag_tf0", v.aero.separation_lag_tf0),
      ORNI_PLAIN("aero.min_speed_mps", v.aero.min_speed_mps),

      ORNI_PLAIN("kinematics.amplitude_deg", v.flapping.amplitude_rad),
      ORNI_PLAIN("kinematics.hinge_x_m", v.flapping.hinge_x_B_m),
      ORNI_PLAIN("kinematics.hinge_z_m", v.flapping.hinge_z_B_m),

      ORNI_PLAIN("body.mass_kg", v.body.mass_kg),
      ORNI_PLAIN("body.pitch_inertia_kgm2", v.body.pitch_inertia_kgm2),
      ORNI_PLAIN("body.drag_area_m2", v.body.drag_area_m2),

      ORNI_PLAIN("tail.area_m2", v.tail.area_m2),
      ORNI_PLAIN("tail.aspect_ratio", v.tail.aspect_ratio),
      ORNI_PLAIN("tail.zero_lift_drag_coefficient", v.tail.zero_lift_drag_coefficient),
      ORNI_PLAIN("tail.oswald_efficiency", v.tail.oswald_efficiency),
      ORNI_PLAIN("tail.arm_m", v.tail.arm_m),
      ORNI_PLAIN("tail.height_m", v.tail.height_m),
      ORNI_PLAIN("tail.mass_kg", v.tail.mass_kg),
      ORNI_PLAIN("tail.downwash_factor", v.tail.downwash_factor),

  };
}

#undef ORNI_MATERIAL
#undef ORNI_MEMBER
#undef ORNI_PLAIN
#undef ORNI_INTEGER
#undef ORNI_NUMBER

bool startsWith(std::string_view s, std::string_view prefix) {
  return s.substr(0, prefix.size()) == prefix;
}

}  // namespace

bool VehicleNumber::presentIn(const VehicleModel& vehicle) const {
  if (startsWith(key, "body.")) return vehicle.body.present;
  if (startsWith(key, "tail.")) return vehicle.tail.present;
  return true;
}

std::size_t VehicleNumber::count(const VehicleModel& vehicle) const {
  switch (element) {
    case VehicleElement::kNone: return 1;
    case VehicleElement::kMember: return vehicle.wing.members.size();
    case VehicleElement::kMaterial: return vehicle.materials.size();
  }
  return 1;
}

const std::vector<VehicleNumber>& vehicleNumbers() {
  static const std::vector<VehicleNumber> numbers = makeNumbers();
  return numbers;
}

const std::vector<DesignPointNumber>& designPointNumbers() {
  static const std::vector<DesignPointNumber> numbers = {
      {"operating_point.speed_mps", &OperatingPoint::speed_mps},
      {"operating_point.freq_hz", &OperatingPoint::freq_hz},
      {"operating_point.theta_deg", &OperatingPoint::theta_rad},
      {"operating_point.tail_angle_deg", &OperatingPoint::tail_angle_rad},
  };
  return numbers;
}

const VehicleNumber* findVehicleNumber(std::string_view key, int component) {
  const FieldSpec* spec = findField(key);  // normalises indices and material names
  if (!spec) return nullptr;
  for (const VehicleNumber& n : vehicleNumbers())
    if (n.key == spec->key && n.component == component) return &n;
  return nullptr;
}

std::optional<VehicleNumberRef> resolveVehicleNumber(const VehicleModel& vehicle,
                                                     std::string_view key, int component) {
  const VehicleNumber* number = findVehicleNumber(key, component);
  if (!number) return std::nullopt;
  std::size_t index = 0;
  if (number->element == VehicleElement::kMember) {
    const std::size_t open = key.find('['), close = key.find(']');
    if (open == std::string_view::npos || close == std::string_view::npos || close <= open + 1)
      return std::nullopt;
    index = 0;
    for (std::size_t k = open + 1; k < close; ++k) {
      const char c = key[k];
      if (c < '0' || c > '9') return std::nullopt;
      index = index * 10 + static_cast<std::size_t>(c - '0');
    }
  } else if (number->element == VehicleElement::kMaterial) {
    const std::string_view prefix = "materials.";
    if (!startsWith(key, prefix)) return std::nullopt;
    const std::string_view rest = key.substr(prefix.size());
    const std::size_t dot = rest.rfind('.');
    if (dot == std::string_view::npos) return std::nullopt;
    const std::string name(rest.substr(0, dot));
    index = vehicle.materials.size();
    for (std::size_t k = 0; k < vehicle.materials.size(); ++k)
      if (vehicle.materials[k].name == name) index = k;
  }
  if (index >= number->count(vehicle)) return std::nullopt;
  return VehicleNumberRef{number, index};
}

}  // namespace orni
