#include "optimize/design_space.hpp"

#include <stdexcept>
#include <string_view>
#include <utility>

namespace orni::opt {

namespace {

constexpr std::string_view kMemberPrefix = "wing.members.";

/// The accessor of a vehicle key (a programming error when there is none).
const VehicleNumber& numberOf(std::string_view key, int component = -1) {
  if (const VehicleNumber* n = findVehicleNumber(key, component)) return *n;
  throw std::logic_error("design space: no accessor for " + std::string(key));
}

/// The design fields that are vehicle keys, in the order of messages.
const std::vector<std::string_view>& vehicleFields() {
  static const std::vector<std::string_view> k = {
      "tail.area_m2",         "tail.aspect_ratio",    "tail.arm_m",           "tail.height_m",
      "kinematics.hinge_x_m", "kinematics.hinge_z_m", "wing.skin.thickness_m"};
  return k;
}

/// A member's design fields: the name after "wing.members.NAME.", the field-table key and the
/// component of a pair (start_x_m is the x of start_xy_m).
struct MemberField {
  std::string_view name;
  std::string_view key;
  int component;
};
const std::vector<MemberField>& memberFields() {
  static const std::vector<MemberField> k = {
      {"diameter_m", "wing.members[].diameter_m", -1},
      {"start_x_m", "wing.members[].start_xy_m", 0},
      {"start_y_m", "wing.members[].start_xy_m", 1},
      {"end_x_m", "wing.members[].end_xy_m", 0},
      {"end_y_m", "wing.members[].end_xy_m", 1},
  };
  return k;
}

std::string memberList(const VehicleModel& v) {
  std::string s;
  for (std::size_t i = 0; i < v.wing.members.size(); ++i)
    s += (i ? ", " : "") + v.wing.members[i].name;
  return s.empty() ? "none" : s;
}

}  // namespace

std::vector<std::string> designFieldNames(const VehicleModel& vehicle) {
  std::vector<std::string> names;
  for (const std::string_view f : vehicleFields()) names.emplace_back(f);
  for (const WingMember& m : vehicle.wing.members)
    for (const MemberField& f : memberFields())
      names.push_back(std::string(kMemberPrefix) + m.name + "." + std::string(f.name));
  return names;
}

bool resolveDesignField(const std::string& text, const VehicleModel& vehicle,
                        std::vector<DesignField>* fields, std::string* why) {
  for (const std::string_view f : vehicleFields()) {
    if (text != f) continue;
    const VehicleNumber& number = numberOf(f);
    if (!number.presentIn(vehicle)) {  // the tail's keys
      *why = "the vehicle has no [tail]";
      return false;
    }
    fields->push_back(DesignField{VehicleNumberRef{&number, 0}, text});
    return true;
  }
  const std::string_view t(text);
  if (t.substr(0, kMemberPrefix.size()) == kMemberPrefix) {
    const std::string_view rest = t.substr(kMemberPrefix.size());
    const std::size_t dot = rest.rfind('.');
    if (dot == std::string_view::npos || dot == 0) {
      *why = "expected wing.members.<NAME>.<field>";
      return false;
    }
    const std::string_view member = rest.substr(0, dot), key = rest.substr(dot + 1);
    const MemberField* kind = nullptr;
    for (const MemberField& f : memberFields())
      if (key == f.name) kind = &f;
    if (!kind) {
      std::string known;
      for (const MemberField& f : memberFields())
        known += (known.empty() ? "" : ", ") + std::string(f.name);
      *why = "unknown member field '" + std::string(key) + "' (known: " + known + ")";
      return false;
    }
    const bool wildcard = member.back() == '*';
    const std::string_view prefix = wildcard ? member.substr(0, member.size() - 1) : member;
    const VehicleNumber& number = numberOf(kind->key, kind->component);
    const std::size_t before = fields->size();
    for (std::size_t i = 0; i < vehicle.wing.members.size(); ++i) {
      const std::string& name = vehicle.wing.members[i].name;
      const bool match = wildcard ? std::string_view(name).substr(0, prefix.size()) == prefix
                                  : std::string_view(name) == member;
      if (match)
        fields->push_back(DesignField{VehicleNumberRef{&number, i},
                                      std::string(kMemberPrefix) + name + "." + std::string(key)});
    }
    if (fields->size() == before) {
      *why = "no member " + std::string(wildcard ? "name starting with '" : "named '") +
             std::string(prefix) + "' (members: " + memberList(vehicle) + ")";
      return false;
    }
    return true;
  }
  std::string known;
  for (const std::string_view f : vehicleFields()) known += std::string(f) + ", ";
  *why = "unknown design field (known: " + known + "wing.members.<NAME>.diameter_m | start_x_m | " +
         "start_y_m | end_x_m | end_y_m, <NAME> may end in '*')";
  return false;
}

double fieldValue(const VehicleModel& v, const DesignField& f) { return f.ref.get(v); }

void setFieldValue(VehicleModel* v, const DesignField& f, double value) { f.ref.set(*v, value); }

VehicleModel applyDesign(const VehicleModel& base, const DesignSpace& space,
                         const std::vector<double>& x) {
  if (x.size() != space.variables.size())
    throw std::invalid_argument("applyDesign: " + std::to_string(x.size()) + " values for " +
                                std::to_string(space.variables.size()) + " variables");
  VehicleModel v = base;
  for (std::size_t i = 0; i < x.size(); ++i)
    for (const DesignField& f : space.variables[i].fields) setFieldValue(&v, f, x[i]);
  return v;
}

}  // namespace orni::opt
