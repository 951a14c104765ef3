#include "studies/runner/config/vehicle_file.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <utility>

#include "core/model/frames.hpp"

namespace orni::studies {

namespace {

// File units -> SI: si = file_value * factor (and the writer inverts exactly this product).
constexpr double kDeg = orni::kDegToRad;
constexpr double kGpa = 1e9;
/// Tolerance of the "member inside the planform" check at the trailing edge (m).
constexpr double kPlanformTolerance_m = 1e-9;

const std::vector<std::pair<std::string, Planform>> kPlanforms = {
    {"rectangular", Planform::kRectangular}, {"quarter_ellipse", Planform::kQuarterEllipse}};
const std::vector<std::pair<std::string, StructureLevel>> kStructures = {
    {"rigid", StructureLevel::kRigid}, {"flexible", StructureLevel::kFlexible}};
const std::vector<std::pair<std::string, AeroModelKind>> kAeroModels = {
    {"mst-td", AeroModelKind::kMstTd}, {"delaurier1993", AeroModelKind::kDeLaurier1993}};
const std::vector<std::pair<std::string, CirculationLag>> kLags = {
    {"scherer", CirculationLag::kScherer1}, {"jones", CirculationLag::kJones2}};
/// Cross axis n_u of the universal joint at P3 (structure.md 2.1): the wing normal z_W or y_W.
const std::vector<std::pair<std::string, bool>> kCrossAxes = {{"normal", true}, {"span", false}};
/// The joint at P3 (structure.md 2.1, WingFeSettings::p3_joint).
const std::vector<std::pair<std::string, P3Joint>> kP3Joints = {
    {"universal", P3Joint::kUniversal},
    {"spherical", P3Joint::kSpherical},
    {"revolute_x", P3Joint::kRevoluteX},
    {"clamped", P3Joint::kClamped}};
/// The root chord's support: free (attached at P2 and P3 only) or pinned along y_W = 0.
const std::vector<std::pair<std::string, bool>> kRootEdges = {{"free", false}, {"pinned", true}};
/// Stiffness of the inertial loads on the modes (structure.md 3.7).
const std::vector<std::pair<std::string, InertialStiffness>> kInertialStiffness = {
    {"both", InertialStiffness::kBoth},
    {"softening_only", InertialStiffness::kSofteningOnly},
    {"none", InertialStiffness::kNone}};
/// Largest number of fixed-interface modes a vehicle may ask for.
constexpr int kMaxModes = 200;

template <typename E>
std::string nameOf(const std::vector<std::pair<std::string, E>>& choices, E value) {
  for (const auto& c : choices)
    if (c.second == value) return c.first;
  return choices.front().first;
}

// Ranges in FILE units. Angles: the model's radian ranges written in degrees (rounded inwards).
const Range kAlpha0Deg = Range::closed(-11.45, 11.45);   // |alpha0| <= 0.2 rad
const Range kStallWidthDeg = Range::closed(0.0, 11.45);  // delta_s <= 0.2 rad
const Range kHalfTurnDeg = Range::open(-90.0, 90.0);

double chordAt(const WingModel& wing, double y_m) {
  if (wing.planform == Planform::kRectangular) return wing.root_chord_m;
  const double r = y_m / wing.semispan_m;
  return wing.root_chord_m * std::sqrt(std::max(0.0, 1.0 - r * r));
}

std::string pointText(const std::vector<double>& p) {
  return "[" + formatNumber(p[0]) + ", " + formatNumber(p[1]) + "]";
}

std::vector<Material> readMaterials(TableReader& top) {
  const toml::node* node = top.take("materials");
  const std::string expected = "at least one [materials.NAME] table";
  if (!node) throw top.missingError("materials", expected);
  const toml::table* table = node->as_table();
  if (!table) throw top.valueError("materials", expected, describeNode(*node));
  if (table->empty()) throw top.valueError("materials", expected, "an empty table");
  const std::string path = top.path().empty() ? "materials" : top.path() + ".materials";
  std::vector<std::string> names;  // any name is allowed: each names a material
  for (const auto& kv : *table) names.emplace_back(kv.first.str());
  TableReader mats(*table, path, top.context(), names);
  std::vector<Material> out;
  for (const std::string& name : mats.presentKeys()) {
    TableReader m =
        mats.requiredTable(name, {"youngs_modulus_gpa", "poisson_ratio", "density_kgpm3"});
    Material mat;
    mat.name = name;
    mat.youngs_modulus_pa = m.requiredDouble("youngs_modulus_gpa", Range::positive()) * kGpa;
    mat.poisson_ratio = m.requiredDouble("poisson_ratio", Range::open(-1.0, 0.5));
    mat.density_kgpm3 = m.requiredDouble("density_kgpm3", Range::positive());
    m.finish();
    out.push_back(std::move(mat));
  }
  mats.finish();
  return out;
}

std::string requireMaterial(TableReader& r, const std::vector<Material>& materials) {
  const std::string name = r.requiredString("material");
  for (const Material& m : materials)
    if (m.name == name) return name;
  std::vector<std::string> names;
  for (const Material& m : materials) names.push_back(m.name);
  std::string expected = "the name of a [materials.NAME] table (";
  for (std::size_t i = 0; i < names.size(); ++i)
    expected += (i ? ", " : "") + TomlWriter::stringText(names[i]);
  expected += ")";
  std::string got = "an unknown material " + TomlWriter::stringText(name);
  const std::string near = closestMatch(name, names);
  if (!near.empty()) got += " (did you mean " + TomlWriter::stringText(near) + "?)";
  throw r.valueError("material", expected, got);
}

void readWing(TableReader& top, VehicleModel& v) {
  TableReader w =
      top.requiredTable("wing", {"planform", "semispan_m", "root_chord_m", "incidence_deg",
                                 "strips", "structure", "p3_aft_of_le_m", "skin", "members",
                                 "member_diameter_scale", "fe"});
  WingModel& wing = v.wing;
  wing.planform = w.requiredEnum("planform", kPlanforms);
  wing.semispan_m = w.requiredDouble("semispan_m", Range::positive());
  wing.root_chord_m = w.requiredDouble("root_chord_m", Range::positive());
  wing.incidence_rad = w.optionalDouble("incidence_deg", 0.0, Range::open(-45.0, 45.0)) * kDeg;
  wing.strip_count = w.requiredInt("strips", 1, 500);
  wing.structure = w.optionalEnum("structure", StructureLevel::kRigid, kStructures);
  wing.p3_aft_of_le_m = w.optionalDouble("p3_aft_of_le_m", 0.5 * wing.root_chord_m,
                                         Range::closed(0.0, wing.root_chord_m));
  wing.member_diameter_scale =
      w.optionalDouble("member_diameter_scale", 1.0, Range::open(0.0, 100.0));

  TableReader skin = w.requiredTable("skin", {"material", "thickness_m"});
  wing.skin.material = requireMaterial(skin, v.materials);
  wing.skin.thickness_m = skin.requiredDouble("thickness_m", Range::positive());
  skin.finish();

  std::vector<TableReader> members =
      w.optionalTableArray("members", {"name", "material", "diameter_m", "start_xy_m", "end_xy_m"});
  std::vector<int> name_lines;
  wing.members.clear();
  for (TableReader& m : members) {
    WingMember member;
    member.name = m.requiredString("name");
    for (std::size_t i = 0; i < wing.members.size(); ++i)
      if (wing.members[i].name == member.name)
        throw m.valueError("name",
                           "a unique member name (" + TomlWriter::stringText(member.name) +
                               " is already used at line " + std::to_string(name_lines[i]) + ")",
                           describeNode(*m.table().get("name")));
    name_lines.push_back(m.lineOf("name"));
    member.material = requireMaterial(m, v.materials);
    member.diameter_m = m.requiredDouble("diameter_m", Range::positive());
    const std::vector<double> start = m.requiredNumberArray("start_xy_m", 2, Range::any());
    const std::vector<double> end = m.requiredNumberArray("end_xy_m", 2, Range::any());
    for (const char* key : {"start_xy_m", "end_xy_m"}) {
      const std::vector<double>& p = (key[0] == 's') ? start : end;
      const double x = p[0], y = p[1];
      const bool y_ok = y >= 0.0 && y <= wing.semispan_m;
      const double c = y_ok ? chordAt(wing, y) : 0.0;
      if (!y_ok || x > 0.0 || x < -c - kPlanformTolerance_m) {
        std::string expected =
            "a point [x_W, y_W] inside the planform (0 <= y_W <= " + formatNumber(wing.semispan_m) +
            ", -c(y_W) <= x_W <= 0";
        if (y_ok) expected += " with -c(y_W) = " + formatNumber(-c);
        expected += ")";
        throw m.valueError(key, expected, pointText(p));
      }
    }
    if (start[0] == end[0] && start[1] == end[1])
      throw m.valueError("end_xy_m", "a point different from start_xy_m (nonzero member length)",
                         pointText(end));
    member.start_x_W_m = start[0];
    member.start_y_W_m = start[1];
    member.end_x_W_m = end[0];
    member.end_y_W_m = end[1];
    m.finish();
    wing.members.push_back(std::move(member));
  }

  // [wing.fe]: finite-element and modal settings, every key optional (structure.md 1.6, 2.5, 2.6).
  if (std::optional<TableReader> fe = w.optionalTable(
          "fe", {"element_size_m", "modes", "cutoff_hz", "damping_ratio", "p3_cross_axis",
                 "p3_joint", "root_edge", "inertial_stiffness"})) {
    WingFeSettings& f = wing.fe;
    f.element_size_m = fe->optionalDouble("element_size_m", f.element_size_m,
                                          Range::openClosed(0.0, wing.semispan_m));
    f.mode_count = fe->optionalInt("modes", f.mode_count, 1, kMaxModes);
    f.cutoff_hz = fe->optionalDouble("cutoff_hz", f.cutoff_hz, Range::nonNegative());
    f.damping_ratio =
        fe->optionalDouble("damping_ratio", f.damping_ratio, Range::closedOpen(0.0, 1.0));
    f.p3_cross_axis_normal =
        fe->optionalEnum("p3_cross_axis", f.p3_cross_axis_normal, kCrossAxes);
    f.p3_joint = fe->optionalEnum("p3_joint", f.p3_joint, kP3Joints);
    f.root_edge_pinned = fe->optionalEnum("root_edge", f.root_edge_pinned, kRootEdges);
    f.inertial_stiffness =
        fe->optionalEnum("inertial_stiffness", f.inertial_stiffness, kInertialStiffness);
    fe->finish();
  } else if (!(wing.fe.element_size_m <= wing.semispan_m)) {
    // Default h = min(5 mm, s), so that a (tiny) wing without [wing.fe] still writes a resolved
    // file that loads again.
    wing.fe.element_size_m = wing.semispan_m;
  }
  w.finish();
}

void readAero(TableReader& top, AeroParameters& a) {
  std::optional<TableReader> r = top.optionalTable(
      "aero",
      {"model", "circulation_lag", "aspect_ratio", "zero_lift_angle_deg", "moment_coefficient_ac",
       "suction_efficiency", "crossflow_drag_coefficient", "skin_friction", "stall_angle_max_deg",
       "stall_angle_min_deg", "stall_width_deg", "separation_lag_tf0", "min_speed_mps"});
  if (!r) return;
  a.model = r->optionalEnum("model", a.model, kAeroModels);
  a.lag = r->optionalEnum("circulation_lag", a.lag, kLags);
  a.aspect_ratio = r->optionalDouble("aspect_ratio", 0.0, Range::positive());
  if (auto d = r->maybeDouble("zero_lift_angle_deg", kAlpha0Deg)) a.zero_lift_angle_rad = *d * kDeg;
  a.moment_coefficient_ac =
      r->optionalDouble("moment_coefficient_ac", a.moment_coefficient_ac, Range::closed(-0.5, 0.5));
  a.suction_efficiency =
      r->optionalDouble("suction_efficiency", a.suction_efficiency, Range::closed(0.0, 1.0));
  a.crossflow_drag_coefficient = r->optionalDouble(
      "crossflow_drag_coefficient", a.crossflow_drag_coefficient, Range::closed(0.0, 3.0));
  a.skin_friction = r->optionalBool("skin_friction", a.skin_friction);
  if (auto d = r->maybeDouble("stall_angle_max_deg", Range::open(0.0, 90.0)))
    a.stall_angle_max_rad = *d * kDeg;
  if (auto d = r->maybeDouble("stall_angle_min_deg", Range::open(-90.0, 0.0)))
    a.stall_angle_min_rad = *d * kDeg;
  if (auto d = r->maybeDouble("stall_width_deg", kStallWidthDeg)) a.stall_width_rad = *d * kDeg;
  a.separation_lag_tf0 =
      r->optionalDouble("separation_lag_tf0", a.separation_lag_tf0, Range::closed(0.0, 50.0));
  a.min_speed_mps = r->optionalDouble("min_speed_mps", a.min_speed_mps, Range::positive());
  r->finish();
}

}  // namespace

VehicleModel parseVehicleTable(const toml::table& root, const ReadContext& context,
                               const std::string& root_path) {
  auto ctx = std::make_shared<const ReadContext>(context);
  TableReader top(root, root_path, ctx,
                  {"name", "description", "air", "wing", "materials", "aero", "kinematics", "body",
                   "tail", "operating_point"});
  VehicleModel v;
  v.name = top.requiredString("name");
  v.description = top.optionalString("description", "", true);

  if (std::optional<TableReader> air =
          top.optionalTable("air", {"density_kgpm3", "kinematic_viscosity_m2ps", "gravity_mps2"})) {
    v.air.density_kgpm3 =
        air->optionalDouble("density_kgpm3", v.air.density_kgpm3, Range::openClosed(0.0, 10.0));
    v.air.kinematic_viscosity_m2ps = air->optionalDouble(
        "kinematic_viscosity_m2ps", v.air.kinematic_viscosity_m2ps, Range::openClosed(0.0, 1e-3));
    v.air.gravity_mps2 =
        air->optionalDouble("gravity_mps2", v.air.gravity_mps2, Range::closed(0.0, 100.0));
    air->finish();
  }

  v.materials = readMaterials(top);
  readWing(top, v);
  readAero(top, v.aero);

  {
    TableReader k = top.requiredTable("kinematics", {"amplitude_deg", "hinge_x_m", "hinge_z_m"});
    v.flapping.amplitude_rad = k.requiredDouble("amplitude_deg", Range::open(0.0, 90.0)) * kDeg;
    v.flapping.hinge_x_B_m = k.optionalDouble("hinge_x_m", 0.0, Range::any());
    v.flapping.hinge_z_B_m = k.optionalDouble("hinge_z_m", 0.0, Range::any());
    k.finish();
  }

  std::optional<TableReader> body =
      top.optionalTable("body", {"mass_kg", "pitch_inertia_kgm2", "drag_area_m2"});
  if (body) {
    v.body.present = true;
    v.body.mass_kg = body->requiredDouble("mass_kg", Range::positive());
    v.body.pitch_inertia_kgm2 = body->requiredDouble("pitch_inertia_kgm2", Range::positive());
    v.body.drag_area_m2 = body->optionalDouble("drag_area_m2", 0.0, Range::nonNegative());
    body->finish();
  }

  std::optional<TableReader> tail = top.optionalTable(
      "tail", {"area_m2", "aspect_ratio", "zero_lift_drag_coefficient", "oswald_efficiency",
               "arm_m", "height_m", "mass_kg", "downwash_factor"});
  if (tail) {
    TailModel& t = v.tail;
    t.present = true;
    t.area_m2 = tail->requiredDouble("area_m2", Range::positive());
    t.aspect_ratio = tail->requiredDouble("aspect_ratio", Range::positive());
    t.zero_lift_drag_coefficient =
        tail->requiredDouble("zero_lift_drag_coefficient", Range::closed(0.0, 1.0));
    t.oswald_efficiency =
        tail->optionalDouble("oswald_efficiency", 0.9, Range::openClosed(0.0, 1.0));
    t.arm_m = tail->requiredDouble("arm_m", Range::positive());
    t.height_m = tail->optionalDouble("height_m", 0.0, Range::any());
    t.mass_kg = tail->optionalDouble("mass_kg", 0.0, Range::nonNegative());
    t.downwash_factor = tail->optionalDouble("downwash_factor", 0.0, Range::closedOpen(0.0, 1.0));
    if (v.body.present && !(t.mass_kg < v.body.mass_kg))
      throw tail->valueError("mass_kg",
                             "a number < body.mass_kg = " + formatNumber(v.body.mass_kg) +
                                 " (the tail is part of the vehicle mass)",
                             formatNumber(t.mass_kg));
    tail->finish();
  }

  {
    TableReader op = top.requiredTable("operating_point",
                                       {"speed_mps", "freq_hz", "theta_deg", "tail_angle_deg"});
    OperatingPoint& p = v.operating_point;
    p.speed_mps = op.requiredDouble("speed_mps", Range::positive());
    p.freq_hz = op.requiredDouble("freq_hz", Range::openClosed(0.0, 200.0));
    p.theta_rad = op.requiredDouble("theta_deg", kHalfTurnDeg) * kDeg;
    p.tail_angle_rad = op.optionalDouble("tail_angle_deg", 0.0, kHalfTurnDeg) * kDeg;
    op.finish();
  }

  top.finish();
  return v;
}

VehicleModel parseVehicleTable(const toml::table& root,
                               const std::filesystem::path& file_for_messages) {
  ReadContext context;
  context.file = displayPath(file_for_messages);
  return parseVehicleTable(root, context, std::string());
}

VehicleModel loadVehicleFile(const std::filesystem::path& file) {
  const toml::table root = parseTomlFile(file);
  if (const toml::node* kind = root.get("kind"))
    throw InputError::unknownKey(displayPath(file), static_cast<int>(kind->source().begin.line),
                                 "kind",
                                 "this is a study file, not a vehicle file: run it with "
                                 "`ornithopter run " + displayPath(file) + "`");
  return parseVehicleTable(root, file);
}

void writeVehicleToml(const VehicleModel& v, TomlWriter& out,
                      const std::vector<std::string>& prefix) {
  auto path = [&prefix](std::vector<std::string> parts) {
    std::vector<std::string> p = prefix;
    p.insert(p.end(), parts.begin(), parts.end());
    return p;
  };
  if (!prefix.empty()) out.header(prefix);
  out.string("name", v.name);
  if (!v.description.empty()) out.string("description", v.description);

  out.header(path({"air"}));
  out.number("density_kgpm3", v.air.density_kgpm3);
  out.number("kinematic_viscosity_m2ps", v.air.kinematic_viscosity_m2ps);
  out.number("gravity_mps2", v.air.gravity_mps2);

  const WingModel& w = v.wing;
  out.header(path({"wing"}));
  out.string("planform", nameOf(kPlanforms, w.planform));
  out.number("semispan_m", w.semispan_m);
  out.number("root_chord_m", w.root_chord_m);
  out.scaled("incidence_deg", w.incidence_rad, kDeg);
  out.integer("strips", w.strip_count);
  out.string("structure", nameOf(kStructures, w.structure));
  out.number("p3_aft_of_le_m", w.p3_aft_of_le_m);
  out.number("member_diameter_scale", w.member_diameter_scale);
  out.header(path({"wing", "skin"}));
  out.string("material", w.skin.material);
  out.number("thickness_m", w.skin.thickness_m);
  for (const WingMember& m : w.members) {
    out.arrayHeader(path({"wing", "members"}));
    out.string("name", m.name);
    out.string("material", m.material);
    out.number("diameter_m", m.diameter_m);
    out.numberArray("start_xy_m", {m.start_x_W_m, m.start_y_W_m});
    out.numberArray("end_xy_m", {m.end_x_W_m, m.end_y_W_m});
  }
  out.header(path({"wing", "fe"}));
  out.number("element_size_m", w.fe.element_size_m);
  out.integer("modes", w.fe.mode_count);
  out.number("cutoff_hz", w.fe.cutoff_hz, w.fe.cutoff_hz > 0.0 ? "" : "0 = no cut-off");
  out.number("damping_ratio", w.fe.damping_ratio);
  out.string("p3_cross_axis", nameOf(kCrossAxes, w.fe.p3_cross_axis_normal));
  out.string("p3_joint", nameOf(kP3Joints, w.fe.p3_joint));
  out.string("root_edge", nameOf(kRootEdges, w.fe.root_edge_pinned));
  out.string("inertial_stiffness", nameOf(kInertialStiffness, w.fe.inertial_stiffness));

  for (const Material& m : v.materials) {
    out.header(path({"materials", m.name}));
    out.scaled("youngs_modulus_gpa", m.youngs_modulus_pa, kGpa);
    out.number("poisson_ratio", m.poisson_ratio);
    out.number("density_kgpm3", m.density_kgpm3);
  }

  const AeroParameters& a = v.aero;
  out.header(path({"aero"}));
  out.string("model", nameOf(kAeroModels, a.model));
  out.string("circulation_lag", nameOf(kLags, a.lag));
  if (a.aspect_ratio > 0.0)
    out.number("aspect_ratio", a.aspect_ratio);
  else
    out.comment("aspect_ratio: not given, taken from the planform (b^2/S)");
  out.scaled("zero_lift_angle_deg", a.zero_lift_angle_rad, kDeg);
  out.number("moment_coefficient_ac", a.moment_coefficient_ac);
  out.number("suction_efficiency", a.suction_efficiency);
  out.number("crossflow_drag_coefficient", a.crossflow_drag_coefficient);
  out.boolean("skin_friction", a.skin_friction);
  out.scaled("stall_angle_max_deg", a.stall_angle_max_rad, kDeg);
  out.scaled("stall_angle_min_deg", a.stall_angle_min_rad, kDeg);
  out.scaled("stall_width_deg", a.stall_width_rad, kDeg);
  out.number("separation_lag_tf0", a.separation_lag_tf0);
  out.number("min_speed_mps", a.min_speed_mps);

  out.header(path({"kinematics"}));
  out.scaled("amplitude_deg", v.flapping.amplitude_rad, kDeg);
  out.number("hinge_x_m", v.flapping.hinge_x_B_m);
  out.number("hinge_z_m", v.flapping.hinge_z_B_m);

  if (v.body.present) {
    out.header(path({"body"}));
    out.number("mass_kg", v.body.mass_kg);
    out.number("pitch_inertia_kgm2", v.body.pitch_inertia_kgm2);
    out.number("drag_area_m2", v.body.drag_area_m2);
  }
  if (v.tail.present) {
    const TailModel& t = v.tail;
    out.header(path({"tail"}));
    out.number("area_m2", t.area_m2);
    out.number("aspect_ratio", t.aspect_ratio);
    out.number("zero_lift_drag_coefficient", t.zero_lift_drag_coefficient);
    out.number("oswald_efficiency", t.oswald_efficiency);
    out.number("arm_m", t.arm_m);
    out.number("height_m", t.height_m);
    out.number("mass_kg", t.mass_kg);
    out.number("downwash_factor", t.downwash_factor);
  }

  const OperatingPoint& p = v.operating_point;
  out.header(path({"operating_point"}));
  out.number("speed_mps", p.speed_mps);
  out.number("freq_hz", p.freq_hz);
  out.scaled("theta_deg", p.theta_rad, kDeg);
  out.scaled("tail_angle_deg", p.tail_angle_rad, kDeg);
}

std::string vehicleToToml(const VehicleModel& vehicle) {
  TomlWriter out;
  out.comment("Vehicle " + vehicle.name + ", every value resolved (units in the key suffixes).");
  writeVehicleToml(vehicle, out, {});
  return out.str();
}

void validateVehicle(const VehicleModel& vehicle) {
  const std::string name = "design vehicle";
  toml::table root;
  try {
    root = toml::parse(vehicleToToml(vehicle), name);
  } catch (const toml::parse_error& e) {
    throw InputError::syntax(name, static_cast<int>(e.source().begin.line),
                             std::string(e.description()));
  }
  ReadContext context;
  context.file = name;
  (void)parseVehicleTable(root, context, std::string());
}

}  // namespace orni::studies
