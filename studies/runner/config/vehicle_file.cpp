#include "studies/runner/config/vehicle_file.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <utility>

#include "core/model/frames.hpp"
#include "core/model/vehicle_validation.hpp"

namespace orni::studies {

namespace {

// File units -> SI: si = file_value * factor (and the writer inverts exactly this product).
constexpr double kDeg = orni::kDegToRad;
constexpr double kGpa = 1e9;

const std::vector<std::pair<std::string, Planform>> kPlanforms = {
    {"rectangular", Planform::kRectangular}, {"quarter_ellipse", Planform::kQuarterEllipse}};
const std::vector<std::pair<std::string, StructureLevel>> kStructures = {
    {"rigid", StructureLevel::kRigid}, {"flexible", StructureLevel::kFlexible}};
const std::vector<std::pair<std::string, AeroModelKind>> kAeroModels = {
    {"mst-td", AeroModelKind::kMstTd}, {"delaurier1993", AeroModelKind::kDeLaurier1993}};
const std::vector<std::pair<std::string, CirculationLag>> kLags = {
    {"scherer", CirculationLag::kScherer1}, {"jones", CirculationLag::kJones2}};
/// Cross axis n_u of the universal joint at P3 (docs/theory.md 2.6): the wing normal z_W or y_W.
const std::vector<std::pair<std::string, bool>> kCrossAxes = {{"normal", true}, {"span", false}};
/// The joint at P3 (docs/theory.md 2.6, WingFeSettings::p3_joint).
const std::vector<std::pair<std::string, P3Joint>> kP3Joints = {
    {"universal", P3Joint::kUniversal},
    {"spherical", P3Joint::kSpherical},
    {"revolute_x", P3Joint::kRevoluteX},
    {"clamped", P3Joint::kClamped}};
/// The root chord's support: free (attached at P2 and P3 only) or pinned along y_W = 0.
const std::vector<std::pair<std::string, bool>> kRootEdges = {{"free", false}, {"pinned", true}};
/// Stiffness of the inertial loads on the modes (docs/theory.md 4.6).
const std::vector<std::pair<std::string, InertialStiffness>> kInertialStiffness = {
    {"both", InertialStiffness::kBoth},
    {"softening_only", InertialStiffness::kSofteningOnly},
    {"none", InertialStiffness::kNone}};

template <typename E>
std::string nameOf(const std::vector<std::pair<std::string, E>>& choices, E value) {
  for (const auto& c : choices)
    if (c.second == value) return c.first;
  return choices.front().first;
}

using orni::field;

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
    mat.youngs_modulus_pa = m.requiredDouble(field("materials.*.youngs_modulus_gpa")) * kGpa;
    mat.poisson_ratio = m.requiredDouble(field("materials.*.poisson_ratio"));
    mat.density_kgpm3 = m.requiredDouble(field("materials.*.density_kgpm3"));
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
  wing.semispan_m = w.requiredDouble(field("wing.semispan_m"));
  wing.root_chord_m = w.requiredDouble(field("wing.root_chord_m"));
  if (auto d = w.maybeDouble(field("wing.incidence_deg"))) wing.incidence_rad = *d * kDeg;
  wing.strip_count = w.requiredInt(field("wing.strips"));
  wing.structure = w.optionalEnum("structure", StructureLevel::kRigid, kStructures);
  wing.p3_aft_of_le_m = w.optionalDouble(field("wing.p3_aft_of_le_m"), 0.5 * wing.root_chord_m);
  wing.member_diameter_scale =
      w.optionalDouble(field("wing.member_diameter_scale"), wing.member_diameter_scale);

  TableReader skin = w.requiredTable("skin", {"material", "thickness_m", "pretension_N_per_m"});
  wing.skin.material = requireMaterial(skin, v.materials);
  wing.skin.thickness_m = skin.requiredDouble(field("wing.skin.thickness_m"));
  wing.skin.pretension_N_per_m = skin.optionalDouble(field("wing.skin.pretension_N_per_m"),
                                                     wing.skin.pretension_N_per_m);
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
    member.diameter_m = m.requiredDouble(field("wing.members[].diameter_m"));
    const std::vector<double> start = m.requiredPair(field("wing.members[].start_xy_m"));
    const std::vector<double> end = m.requiredPair(field("wing.members[].end_xy_m"));
    // Inside the planform and of nonzero length: core's model checks (vehicleProblems).
    member.start_x_W_m = start[0];
    member.start_y_W_m = start[1];
    member.end_x_W_m = end[0];
    member.end_y_W_m = end[1];
    m.finish();
    wing.members.push_back(std::move(member));
  }

  // [wing.fe]: finite-element and modal settings, every key optional (docs/theory.md 2.5, 3.4, 3.5).
  if (std::optional<TableReader> fe = w.optionalTable(
          "fe", {"element_size_m", "modes", "cutoff_hz", "damping_ratio", "p3_cross_axis",
                 "p3_joint", "root_edge", "inertial_stiffness", "nonlinear",
                 "static_shapes_pa"})) {
    WingFeSettings& f = wing.fe;
    f.element_size_m = fe->optionalDouble(field("wing.fe.element_size_m"), f.element_size_m);
    f.max_modes = fe->optionalInt(field("wing.fe.modes"), f.max_modes);
    f.cutoff_hz = fe->optionalDouble(field("wing.fe.cutoff_hz"), f.cutoff_hz);
    f.damping_ratio =
        fe->optionalDouble(field("wing.fe.damping_ratio"), f.damping_ratio);
    f.p3_cross_axis_normal =
        fe->optionalEnum("p3_cross_axis", f.p3_cross_axis_normal, kCrossAxes);
    f.p3_joint = fe->optionalEnum("p3_joint", f.p3_joint, kP3Joints);
    f.root_edge_pinned = fe->optionalEnum("root_edge", f.root_edge_pinned, kRootEdges);
    f.inertial_stiffness =
        fe->optionalEnum("inertial_stiffness", f.inertial_stiffness, kInertialStiffness);
    f.nonlinear = fe->optionalBool("nonlinear", f.nonlinear);
    if (fe->has("static_shapes_pa"))
      f.static_shapes_pa = fe->requiredNumberArray("static_shapes_pa", 0,
                                                   field("wing.fe.static_shapes_pa").range);
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
  a.aspect_ratio = r->optionalDouble(field("aero.aspect_ratio"), a.aspect_ratio);
  if (auto d = r->maybeDouble(field("aero.zero_lift_angle_deg"))) a.zero_lift_angle_rad = *d * kDeg;
  a.moment_coefficient_ac =
      r->optionalDouble(field("aero.moment_coefficient_ac"), a.moment_coefficient_ac);
  a.suction_efficiency =
      r->optionalDouble(field("aero.suction_efficiency"), a.suction_efficiency);
  a.crossflow_drag_coefficient = r->optionalDouble(field("aero.crossflow_drag_coefficient"),
                                                    a.crossflow_drag_coefficient);
  a.skin_friction = r->optionalBool("skin_friction", a.skin_friction);
  if (auto d = r->maybeDouble(field("aero.stall_angle_max_deg")))
    a.stall_angle_max_rad = *d * kDeg;
  if (auto d = r->maybeDouble(field("aero.stall_angle_min_deg")))
    a.stall_angle_min_rad = *d * kDeg;
  if (auto d = r->maybeDouble(field("aero.stall_width_deg"))) a.stall_width_rad = *d * kDeg;
  a.separation_lag_tf0 =
      r->optionalDouble(field("aero.separation_lag_tf0"), a.separation_lag_tf0);
  a.min_speed_mps = r->optionalDouble(field("aero.min_speed_mps"), a.min_speed_mps);
  r->finish();
}

/// "a.b[2].c" -> {"a", "b", "[2]", "c"}.
std::vector<std::string> pathParts(const std::string& key) {
  std::vector<std::string> parts;
  std::string cur;
  for (std::size_t i = 0; i < key.size(); ++i) {
    const char ch = key[i];
    if (ch == '.' || ch == '[') {
      if (!cur.empty()) parts.push_back(cur);
      cur.clear();
      if (ch == '[') {
        const std::size_t close = key.find(']', i);
        parts.push_back(key.substr(i, close - i + 1));
        i = close;
      }
    } else {
      cur += ch;
    }
  }
  if (!cur.empty()) parts.push_back(cur);
  return parts;
}

/// An InputError for a problem found by core's model checks: at the node of its key when the file
/// has it (the value as written), else at the innermost table on its path (a default at fault).
InputError problemError(const toml::table& root, const std::shared_ptr<const ReadContext>& ctx,
                        const std::string& root_path, const orni::ModelProblem& problem) {
  const toml::table* table = &root;
  std::string table_path = root_path;
  const std::vector<std::string> parts = pathParts(problem.key);
  std::size_t i = 0;
  for (; i + 1 < parts.size(); ++i) {
    const toml::node* next = nullptr;
    std::string next_path = table_path;
    if (parts[i + 1].front() == '[') {  // an array element: "members", "[2]"
      const toml::node* arr = table->get(parts[i]);
      const toml::array* a = arr ? arr->as_array() : nullptr;
      const std::size_t index = std::stoul(parts[i + 1].substr(1));
      next = a && index < a->size() ? a->get(index) : nullptr;
      next_path += (next_path.empty() ? "" : ".") + parts[i] + parts[i + 1];
      if (next && next->is_table() && i + 2 < parts.size()) {
        table = next->as_table();
        table_path = next_path;
        ++i;
        continue;
      }
      break;
    }
    next = table->get(parts[i]);
    if (!next || !next->is_table()) break;
    table = next->as_table();
    table_path += (table_path.empty() ? "" : ".") + parts[i];
  }
  std::vector<std::string> keys;
  for (const auto& kv : *table) keys.emplace_back(kv.first.str());
  const TableReader reader(*table, table_path, ctx, keys);
  const std::string local = i + 1 == parts.size() ? parts.back() : parts[i];
  std::string got = problem.got;
  if (i + 1 == parts.size()) {
    const toml::node* node = table->get(local);
    if (node && node->is_number()) {
      // The value as written instead of its SI round trip ("9.2", not "9.200000000000001").
      const std::size_t space = got.find(' ');
      got = sourceText(*node) + (space == std::string::npos ? std::string() : got.substr(space));
    } else if (!node) {
      got += " (the default)";
    }
    return reader.valueError(local, problem.expected, got);
  }
  // The key's table is absent: the value at fault is a default; name the full key.
  const std::string rest = problem.key.substr(problem.key.find(local));
  return InputError::wrongValue(reader.fileOf(local), reader.lineOf(local),
                                reader.keyPath(rest), problem.expected, got + " (the default)");
}

}  // namespace

VehicleDefinition parseVehicleTable(const toml::table& root, const ReadContext& context,
                                    const std::string& root_path) {
  auto ctx = std::make_shared<const ReadContext>(context);
  TableReader top(root, root_path, ctx,
                  {"name", "description", "air", "wing", "materials", "aero", "kinematics", "body",
                   "tail", "operating_point"});
  VehicleDefinition definition;
  VehicleModel& v = definition.model;
  v.name = top.requiredString("name");
  v.description = top.optionalString("description", "", true);

  if (std::optional<TableReader> air =
          top.optionalTable("air", {"density_kgpm3", "kinematic_viscosity_m2ps", "gravity_mps2"})) {
    v.air.density_kgpm3 =
        air->optionalDouble(field("air.density_kgpm3"), v.air.density_kgpm3);
    v.air.kinematic_viscosity_m2ps = air->optionalDouble(field("air.kinematic_viscosity_m2ps"),
                                                     v.air.kinematic_viscosity_m2ps);
    v.air.gravity_mps2 =
        air->optionalDouble(field("air.gravity_mps2"), v.air.gravity_mps2);
    air->finish();
  }

  v.materials = readMaterials(top);
  readWing(top, v);
  readAero(top, v.aero);

  {
    TableReader k = top.requiredTable("kinematics", {"amplitude_deg", "hinge_x_m", "hinge_z_m"});
    v.flapping.amplitude_rad = k.requiredDouble(field("kinematics.amplitude_deg")) * kDeg;
    FlappingKinematics& f = v.flapping;
    f.hinge_x_B_m = k.optionalDouble(field("kinematics.hinge_x_m"), f.hinge_x_B_m);
    f.hinge_z_B_m = k.optionalDouble(field("kinematics.hinge_z_m"), f.hinge_z_B_m);
    k.finish();
  }

  std::optional<TableReader> body =
      top.optionalTable("body", {"mass_kg", "pitch_inertia_kgm2", "drag_area_m2"});
  if (body) {
    v.body.present = true;
    v.body.mass_kg = body->requiredDouble(field("body.mass_kg"));
    v.body.pitch_inertia_kgm2 = body->requiredDouble(field("body.pitch_inertia_kgm2"));
    v.body.drag_area_m2 = body->optionalDouble(field("body.drag_area_m2"), v.body.drag_area_m2);
    body->finish();
  }

  std::optional<TableReader> tail = top.optionalTable(
      "tail", {"area_m2", "aspect_ratio", "zero_lift_drag_coefficient", "oswald_efficiency",
               "arm_m", "height_m", "mass_kg", "downwash_factor"});
  if (tail) {
    TailModel& t = v.tail;
    t.present = true;
    t.area_m2 = tail->requiredDouble(field("tail.area_m2"));
    t.aspect_ratio = tail->requiredDouble(field("tail.aspect_ratio"));
    t.zero_lift_drag_coefficient =
        tail->requiredDouble(field("tail.zero_lift_drag_coefficient"));
    t.oswald_efficiency =
        tail->optionalDouble(field("tail.oswald_efficiency"), t.oswald_efficiency);
    t.arm_m = tail->requiredDouble(field("tail.arm_m"));
    t.height_m = tail->optionalDouble(field("tail.height_m"), t.height_m);
    t.mass_kg = tail->optionalDouble(field("tail.mass_kg"), t.mass_kg);
    t.downwash_factor = tail->optionalDouble(field("tail.downwash_factor"), t.downwash_factor);
    tail->finish();
  }

  {
    TableReader op = top.requiredTable("operating_point",
                                       {"speed_mps", "freq_hz", "theta_deg", "tail_angle_deg"});
    OperatingPoint& p = definition.design_point;
    p.speed_mps = op.requiredDouble(field("operating_point.speed_mps"));
    p.freq_hz = op.requiredDouble(field("operating_point.freq_hz"));
    p.theta_rad = op.requiredDouble(field("operating_point.theta_deg")) * kDeg;
    if (auto d = op.maybeDouble(field("operating_point.tail_angle_deg")))
      p.tail_angle_rad = *d * kDeg;
    op.finish();
  }

  top.finish();
  // The rules that tie keys together (and every range once more): core's model checks, reported
  // at the file, line and key they concern.
  const std::vector<orni::ModelProblem> problems = orni::definitionProblems(definition);
  if (!problems.empty()) throw problemError(root, ctx, root_path, problems.front());
  return definition;
}

VehicleDefinition parseVehicleTable(const toml::table& root,
                                    const std::filesystem::path& file_for_messages) {
  ReadContext context;
  context.file = displayPath(file_for_messages);
  return parseVehicleTable(root, context, std::string());
}

VehicleDefinition loadVehicleFile(const std::filesystem::path& file) {
  const toml::table root = parseTomlFile(file);
  if (const toml::node* kind = root.get("kind"))
    throw InputError::unknownKey(displayPath(file), static_cast<int>(kind->source().begin.line),
                                 "kind",
                                 "this is a study file, not a vehicle file: run it with "
                                 "`ornithopter run " + displayPath(file) + "`");
  return parseVehicleTable(root, file);
}

void writeVehicleToml(const VehicleDefinition& definition, TomlWriter& out,
                      const std::vector<std::string>& prefix) {
  const VehicleModel& v = definition.model;
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
  out.number("pretension_N_per_m", w.skin.pretension_N_per_m);
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
  out.integer("modes", w.fe.max_modes);
  out.number("cutoff_hz", w.fe.cutoff_hz, w.fe.cutoff_hz > 0.0 ? "" : "0 = no cut-off");
  out.number("damping_ratio", w.fe.damping_ratio);
  out.string("p3_cross_axis", nameOf(kCrossAxes, w.fe.p3_cross_axis_normal));
  out.string("p3_joint", nameOf(kP3Joints, w.fe.p3_joint));
  out.string("root_edge", nameOf(kRootEdges, w.fe.root_edge_pinned));
  out.string("inertial_stiffness", nameOf(kInertialStiffness, w.fe.inertial_stiffness));
  out.boolean("nonlinear", w.fe.nonlinear);
  if (!w.fe.static_shapes_pa.empty()) out.numberArray("static_shapes_pa", w.fe.static_shapes_pa);

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

  const OperatingPoint& p = definition.design_point;
  out.header(path({"operating_point"}));
  out.number("speed_mps", p.speed_mps);
  out.number("freq_hz", p.freq_hz);
  out.scaled("theta_deg", p.theta_rad, kDeg);
  out.scaled("tail_angle_deg", p.tail_angle_rad, kDeg);
}

std::string vehicleToToml(const VehicleDefinition& vehicle) {
  TomlWriter out;
  out.comment("Vehicle " + vehicle.model.name + ", every value resolved (units in the key suffixes).");
  writeVehicleToml(vehicle, out, {});
  return out.str();
}

}  // namespace orni::studies
