#include "optimize/design_space.hpp"

#include <stdexcept>
#include <string_view>
#include <utility>

namespace orni::opt {

namespace {

constexpr std::string_view kMemberPrefix = "wing.members.";

const std::vector<std::pair<std::string_view, DesignFieldKind>>& vehicleFields() {
  static const std::vector<std::pair<std::string_view, DesignFieldKind>> k = {
      {"tail.area_m2", DesignFieldKind::kTailArea},
      {"tail.aspect_ratio", DesignFieldKind::kTailAspectRatio},
      {"tail.arm_m", DesignFieldKind::kTailArm},
      {"tail.height_m", DesignFieldKind::kTailHeight},
      {"kinematics.hinge_x_m", DesignFieldKind::kHingeX},
      {"kinematics.hinge_z_m", DesignFieldKind::kHingeZ},
      {"wing.skin.thickness_m", DesignFieldKind::kSkinThickness},
  };
  return k;
}

const std::vector<std::pair<std::string_view, DesignFieldKind>>& memberFields() {
  static const std::vector<std::pair<std::string_view, DesignFieldKind>> k = {
      {"diameter_m", DesignFieldKind::kMemberDiameter},
      {"start_x_m", DesignFieldKind::kMemberStartX},
      {"start_y_m", DesignFieldKind::kMemberStartY},
      {"end_x_m", DesignFieldKind::kMemberEndX},
      {"end_y_m", DesignFieldKind::kMemberEndY},
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

const FieldSpec& DesignField::spec() const {
  switch (kind) {
    case DesignFieldKind::kTailArea: return field("tail.area_m2");
    case DesignFieldKind::kTailAspectRatio: return field("tail.aspect_ratio");
    case DesignFieldKind::kTailArm: return field("tail.arm_m");
    case DesignFieldKind::kTailHeight: return field("tail.height_m");
    case DesignFieldKind::kHingeX: return field("kinematics.hinge_x_m");
    case DesignFieldKind::kHingeZ: return field("kinematics.hinge_z_m");
    case DesignFieldKind::kSkinThickness: return field("wing.skin.thickness_m");
    case DesignFieldKind::kMemberDiameter: return field("wing.members[].diameter_m");
    case DesignFieldKind::kMemberStartX:
    case DesignFieldKind::kMemberStartY: return field("wing.members[].start_xy_m");
    case DesignFieldKind::kMemberEndX:
    case DesignFieldKind::kMemberEndY: return field("wing.members[].end_xy_m");
  }
  throw std::logic_error("DesignField::spec: unknown field kind");
}

std::vector<std::string> designFieldNames(const VehicleModel& vehicle) {
  std::vector<std::string> names;
  for (const auto& f : vehicleFields()) names.emplace_back(f.first);
  for (const WingMember& m : vehicle.wing.members)
    for (const auto& f : memberFields())
      names.push_back(std::string(kMemberPrefix) + m.name + "." + std::string(f.first));
  return names;
}

bool resolveDesignField(const std::string& text, const VehicleModel& vehicle,
                        std::vector<DesignField>* fields, std::string* why) {
  for (const auto& f : vehicleFields()) {
    if (text != f.first) continue;
    if (f.second <= DesignFieldKind::kTailHeight && !vehicle.tail.present) {
      *why = "the vehicle has no [tail]";
      return false;
    }
    fields->push_back(DesignField{f.second, -1, text});
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
    const DesignFieldKind* kind = nullptr;
    for (const auto& f : memberFields())
      if (key == f.first) kind = &f.second;
    if (!kind) {
      std::string known;
      for (const auto& f : memberFields()) known += (known.empty() ? "" : ", ") + std::string(f.first);
      *why = "unknown member field '" + std::string(key) + "' (known: " + known + ")";
      return false;
    }
    const bool wildcard = member.back() == '*';
    const std::string_view prefix = wildcard ? member.substr(0, member.size() - 1) : member;
    const std::size_t before = fields->size();
    for (std::size_t i = 0; i < vehicle.wing.members.size(); ++i) {
      const std::string& name = vehicle.wing.members[i].name;
      const bool match = wildcard ? std::string_view(name).substr(0, prefix.size()) == prefix
                                  : std::string_view(name) == member;
      if (match)
        fields->push_back(DesignField{*kind, static_cast<int>(i),
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
  for (const auto& f : vehicleFields()) known += std::string(f.first) + ", ";
  *why = "unknown design field (known: " + known + "wing.members.<NAME>.diameter_m | start_x_m | " +
         "start_y_m | end_x_m | end_y_m, <NAME> may end in '*')";
  return false;
}

double fieldValue(const VehicleModel& v, const DesignField& f) {
  auto member = [&]() -> const WingMember& {
    return v.wing.members.at(static_cast<std::size_t>(f.member));
  };
  switch (f.kind) {
    case DesignFieldKind::kTailArea: return v.tail.area_m2;
    case DesignFieldKind::kTailAspectRatio: return v.tail.aspect_ratio;
    case DesignFieldKind::kTailArm: return v.tail.arm_m;
    case DesignFieldKind::kTailHeight: return v.tail.height_m;
    case DesignFieldKind::kHingeX: return v.flapping.hinge_x_B_m;
    case DesignFieldKind::kHingeZ: return v.flapping.hinge_z_B_m;
    case DesignFieldKind::kSkinThickness: return v.wing.skin.thickness_m;
    case DesignFieldKind::kMemberDiameter: return member().diameter_m;
    case DesignFieldKind::kMemberStartX: return member().start_x_W_m;
    case DesignFieldKind::kMemberStartY: return member().start_y_W_m;
    case DesignFieldKind::kMemberEndX: return member().end_x_W_m;
    case DesignFieldKind::kMemberEndY: return member().end_y_W_m;
  }
  throw std::logic_error("fieldValue: unknown field kind");
}

void setFieldValue(VehicleModel* v, const DesignField& f, double value) {
  auto member = [&]() -> WingMember& {
    return v->wing.members.at(static_cast<std::size_t>(f.member));
  };
  switch (f.kind) {
    case DesignFieldKind::kTailArea: v->tail.area_m2 = value; return;
    case DesignFieldKind::kTailAspectRatio: v->tail.aspect_ratio = value; return;
    case DesignFieldKind::kTailArm: v->tail.arm_m = value; return;
    case DesignFieldKind::kTailHeight: v->tail.height_m = value; return;
    case DesignFieldKind::kHingeX: v->flapping.hinge_x_B_m = value; return;
    case DesignFieldKind::kHingeZ: v->flapping.hinge_z_B_m = value; return;
    case DesignFieldKind::kSkinThickness: v->wing.skin.thickness_m = value; return;
    case DesignFieldKind::kMemberDiameter: member().diameter_m = value; return;
    case DesignFieldKind::kMemberStartX: member().start_x_W_m = value; return;
    case DesignFieldKind::kMemberStartY: member().start_y_W_m = value; return;
    case DesignFieldKind::kMemberEndX: member().end_x_W_m = value; return;
    case DesignFieldKind::kMemberEndY: member().end_y_W_m = value; return;
  }
  throw std::logic_error("setFieldValue: unknown field kind");
}

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
