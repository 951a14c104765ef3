#include "core/model/vehicle_validation.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "core/model/field_table.hpp"
#include "core/model/invalid_model_error.hpp"
#include "core/model/wing_geometry.hpp"

namespace orni {

namespace {

/// Tolerance of the "member inside the planform" check at the trailing edge (m): trailing-edge
/// points are written rounded to a few digits.
constexpr double kPlanformTolerance_m = 1e-9;

class Checker {
 public:
  explicit Checker(std::vector<ModelProblem>* out) : out_(out) {}

  /// An SI number against the table entry of `table_key`, reported at `key` (default: the same).
  void number(const char* table_key, double si, const std::string& key = {}) {
    const FieldSpec& f = field(table_key);
    if (f.siRange().contains(si)) return;
    add(key.empty() ? std::string(table_key) : key, f.expected(), fileText(f, si));
  }
  void integer(const char* table_key, int value) {
    const FieldSpec& f = field(table_key);
    if (f.range.contains(static_cast<double>(value))) return;
    add(table_key, f.expected(), std::to_string(value));
  }
  void add(std::string key, std::string expected, std::string got) {
    out_->push_back(ModelProblem{std::move(key), std::move(expected), std::move(got)});
  }
  static std::string fileText(const FieldSpec& f, double si) {
    return displayNumber(f.si_per_unit == 1.0 ? si : si / f.si_per_unit);
  }

 private:
  std::vector<ModelProblem>* out_;
};

std::string pointText(double x, double y) {
  return "[" + displayNumber(x) + ", " + displayNumber(y) + "]";
}

std::string materialNames(const VehicleModel& v) {
  std::string s;
  for (std::size_t i = 0; i < v.materials.size(); ++i)
    s += (i ? ", " : "") + std::string("\"") + v.materials[i].name + "\"";
  return s;
}

void checkMaterialName(Checker& c, const VehicleModel& v, const std::string& key,
                       const std::string& name) {
  if (v.findMaterial(name)) return;
  c.add(key, "the name of a [materials.NAME] table (" + materialNames(v) + ")",
        "an unknown material \"" + name + "\"");
}

/// The wing mesh's crossing test (core/structure/wing_mesh.cpp, buildWingMesh): two members may
/// share end points, end on one another or overlap collinearly, but not cross in their interiors
/// (away from their ends by more than the mesh's snap tolerance). Checked here so that the error
/// names the member's key and line (the mesher's own error, "invalid model: buildWingMesh", names
/// neither). Only between members whose points are valid, on a wing whose sizes are.
void checkMemberCrossings(Checker& c, const WingModel& w, const std::vector<bool>& valid) {
  const FieldSpec& h = field("wing.fe.element_size_m");
  if (!h.siRange().contains(w.fe.element_size_m) ||
      !field("wing.semispan_m").siRange().contains(w.semispan_m) ||
      !field("wing.root_chord_m").siRange().contains(w.root_chord_m))
    return;
  const double snap =
      std::min(1e-3 * w.fe.element_size_m, 1e-4 * std::min(w.semispan_m, w.root_chord_m));
  auto cross2 = [](double ax, double ay, double bx, double by) { return ax * by - ay * bx; };
  for (std::size_t j = 1; j < w.members.size(); ++j) {
    for (std::size_t i = 0; i < j; ++i) {
      if (!valid[i] || !valid[j]) continue;
      const WingMember& a = w.members[i];
      const WingMember& b = w.members[j];
      const double rx = a.end_x_W_m - a.start_x_W_m, ry = a.end_y_W_m - a.start_y_W_m;
      const double sx = b.end_x_W_m - b.start_x_W_m, sy = b.end_y_W_m - b.start_y_W_m;
      const double la = std::hypot(rx, ry), lb = std::hypot(sx, sy);
      if (!(la > snap && lb > snap)) continue;
      const double denom = cross2(rx, ry, sx, sy);
      if (std::abs(denom) <= 1e-12 * la * lb) continue;  // parallel or collinear
      const double qx = b.start_x_W_m - a.start_x_W_m, qy = b.start_y_W_m - a.start_y_W_m;
      const double t = cross2(qx, qy, sx, sy) / denom;
      const double u = cross2(qx, qy, rx, ry) / denom;
      const double ta = snap / la, tb = snap / lb;
      if (t > ta && t < 1.0 - ta && u > tb && u < 1.0 - tb) {
        c.add("wing.members[" + std::to_string(j) + "].start_xy_m",
              "a member that crosses no other member between their end points (members may "
              "share end points or end on one another), but '" + b.name + "' crosses '" +
                  a.name + "' (wing.members[" + std::to_string(i) + "]) at " +
                  pointText(a.start_x_W_m + t * rx, a.start_y_W_m + t * ry) + " m",
              pointText(b.start_x_W_m, b.start_y_W_m) + " to " +
                  pointText(b.end_x_W_m, b.end_y_W_m));
        return;  // one crossing is enough to say
      }
    }
  }
}

void checkMembers(Checker& c, const VehicleModel& v) {
  const WingModel& w = v.wing;
  std::vector<bool> valid(w.members.size(), true);
  for (std::size_t i = 0; i < w.members.size(); ++i) {
    const WingMember& m = w.members[i];
    const std::string at = "wing.members[" + std::to_string(i) + "].";
    if (m.name.empty()) c.add(at + "name", "a non-empty string", "an empty string");
    for (std::size_t j = 0; j < i; ++j)
      if (w.members[j].name == m.name)
        c.add(at + "name", "a unique member name (also wing.members[" + std::to_string(j) + "])",
              "\"" + m.name + "\"");
    checkMaterialName(c, v, at + "material", m.material);
    c.number("wing.members[].diameter_m", m.diameter_m, at + "diameter_m");
    const double pts[2][2] = {{m.start_x_W_m, m.start_y_W_m}, {m.end_x_W_m, m.end_y_W_m}};
    const char* names[2] = {"start_xy_m", "end_xy_m"};
    for (int k = 0; k < 2; ++k) {
      const double x = pts[k][0], y = pts[k][1];
      const std::string key = at + names[k];
      const FieldSpec& f = field(std::string("wing.members[].") + names[k]);
      if (!f.range.contains(x) || !f.range.contains(y)) {
        c.add(key, f.expected(), pointText(x, y));
        valid[i] = false;
        continue;
      }
      const bool y_ok = y >= 0.0 && y <= w.semispan_m;
      const double chord = y_ok ? chordAt(w, y) : 0.0;
      if (y_ok && x <= 0.0 && x >= -chord - kPlanformTolerance_m) continue;
      valid[i] = false;
      std::string expected = "a point [x_W, y_W] inside the planform (0 <= y_W <= " +
                             displayNumber(w.semispan_m) + ", -c(y_W) <= x_W <= 0";
      if (y_ok) expected += " with -c(y_W) = " + displayNumber(-chord);
      c.add(key, expected + ")", pointText(x, y));
    }
    if (m.start_x_W_m == m.end_x_W_m && m.start_y_W_m == m.end_y_W_m)
      c.add(at + "end_xy_m", "a point different from start_xy_m (nonzero member length)",
            pointText(m.end_x_W_m, m.end_y_W_m));
  }
  checkMemberCrossings(c, w, valid);
}

void checkWing(Checker& c, const VehicleModel& v) {
  const WingModel& w = v.wing;
  c.number("wing.semispan_m", w.semispan_m);
  c.number("wing.root_chord_m", w.root_chord_m);
  c.number("wing.incidence_deg", w.incidence_rad);
  if (w.structure == StructureLevel::kFlexible && w.incidence_rad != 0.0)
    c.add("wing.incidence_deg", "0 for a flexible wing (the flexible wing model is flat)",
          Checker::fileText(field("wing.incidence_deg"), w.incidence_rad));
  c.integer("wing.strips", w.strip_count);
  c.number("wing.p3_aft_of_le_m", w.p3_aft_of_le_m);
  if (field("wing.p3_aft_of_le_m").siRange().contains(w.p3_aft_of_le_m) &&
      !(w.p3_aft_of_le_m <= w.root_chord_m))
    c.add("wing.p3_aft_of_le_m",
          "a number in [0, " + displayNumber(w.root_chord_m) + "] (on the root chord)",
          displayNumber(w.p3_aft_of_le_m));
  c.number("wing.member_diameter_scale", w.member_diameter_scale);
  checkMaterialName(c, v, "wing.skin.material", w.skin.material);
  c.number("wing.skin.thickness_m", w.skin.thickness_m);
  c.number("wing.skin.pretension_N_per_m", w.skin.pretension_N_per_m);
  checkMembers(c, v);

  const WingFeSettings& fe = w.fe;
  const FieldSpec& h = field("wing.fe.element_size_m");
  if (!h.siRange().contains(fe.element_size_m)) {
    c.add("wing.fe.element_size_m", h.expected(), displayNumber(fe.element_size_m));
  } else if (!(fe.element_size_m <= w.semispan_m)) {
    c.add("wing.fe.element_size_m",
          "a number in [" + displayNumber(h.range.lo) + ", " + displayNumber(w.semispan_m) +
              "] (at most wing.semispan_m)",
          displayNumber(fe.element_size_m));
  } else if (w.structure == StructureLevel::kFlexible &&
             field("wing.semispan_m").siRange().contains(w.semispan_m) &&
             field("wing.root_chord_m").siRange().contains(w.root_chord_m) &&
             !(estimatedMeshNodes(w) <= kMaxWingMeshNodes)) {
    const double h_min = std::sqrt(estimatedMeshNodes(w) / kMaxWingMeshNodes) * fe.element_size_m;
    c.add("wing.fe.element_size_m",
          "an element size giving at most " + displayNumber(kMaxWingMeshNodes) +
              " mesh nodes on this wing (>= " + displayNumber(std::ceil(h_min * 1e5) / 1e5) + ")",
          displayNumber(fe.element_size_m) + " (about " +
              displayNumber(std::round(estimatedMeshNodes(w))) + " nodes)");
  }
  c.integer("wing.fe.modes", fe.max_modes);
  c.number("wing.fe.cutoff_hz", fe.cutoff_hz);
  c.number("wing.fe.damping_ratio", fe.damping_ratio);
  const FieldSpec& shapes = field("wing.fe.static_shapes_pa");
  for (double p : fe.static_shapes_pa)
    if (!shapes.siRange().contains(p)) c.add("wing.fe.static_shapes_pa", shapes.expected(),
                                             displayNumber(p));
  if (fe.static_shapes_pa.size() > static_cast<std::size_t>(kMaxStaticShapesOfAWing))
    c.add("wing.fe.static_shapes_pa",
          "at most " + std::to_string(kMaxStaticShapesOfAWing) + " pressures",
          std::to_string(fe.static_shapes_pa.size()) + " pressures");
  if (!fe.static_shapes_pa.empty() && !fe.nonlinear)
    c.add("wing.fe.static_shapes_pa",
          "[] on the linear wing (static shapes need wing.fe.nonlinear = true)",
          std::to_string(fe.static_shapes_pa.size()) + " pressures");
}

void checkMaterials(Checker& c, const VehicleModel& v) {
  for (std::size_t i = 0; i < v.materials.size(); ++i) {
    const Material& m = v.materials[i];
    const std::string at = "materials." + m.name + ".";
    if (m.name.empty()) c.add("materials", "material names that are not empty", "\"\"");
    for (std::size_t j = 0; j < i; ++j)
      if (v.materials[j].name == m.name)
        c.add("materials." + m.name, "a material name used once", "\"" + m.name + "\" twice");
    c.number("materials.*.youngs_modulus_gpa", m.youngs_modulus_pa, at + "youngs_modulus_gpa");
    c.number("materials.*.poisson_ratio", m.poisson_ratio, at + "poisson_ratio");
    c.number("materials.*.density_kgpm3", m.density_kgpm3, at + "density_kgpm3");
  }
}

void checkAero(Checker& c, const AeroParameters& a) {
  if (a.aspect_ratio != 0.0) c.number("aero.aspect_ratio", a.aspect_ratio);  // 0 = from planform
  c.number("aero.zero_lift_angle_deg", a.zero_lift_angle_rad);
  c.number("aero.moment_coefficient_ac", a.moment_coefficient_ac);
  c.number("aero.suction_efficiency", a.suction_efficiency);
  c.number("aero.crossflow_drag_coefficient", a.crossflow_drag_coefficient);
  c.number("aero.stall_angle_max_deg", a.stall_angle_max_rad);
  c.number("aero.stall_angle_min_deg", a.stall_angle_min_rad);
  c.number("aero.stall_width_deg", a.stall_width_rad);
  c.number("aero.separation_lag_tf0", a.separation_lag_tf0);
  c.number("aero.min_speed_mps", a.min_speed_mps);
}

}  // namespace

double estimatedMeshNodes(const WingModel& wing) {
  const double h = wing.fe.element_size_m;
  return 2.2 * halfWingArea(wing) / (h * h);
}

std::string ModelProblem::message() const {
  return "key '" + key + "': expected " + expected + ", got " + got;
}

std::vector<ModelProblem> vehicleProblems(const VehicleModel& v) {
  std::vector<ModelProblem> problems;
  Checker c(&problems);
  c.number("air.density_kgpm3", v.air.density_kgpm3);
  c.number("air.kinematic_viscosity_m2ps", v.air.kinematic_viscosity_m2ps);
  c.number("air.gravity_mps2", v.air.gravity_mps2);
  if (v.materials.empty()) c.add("materials", "at least one [materials.NAME] table", "none");
  checkWing(c, v);
  checkMaterials(c, v);
  checkAero(c, v.aero);
  c.number("kinematics.amplitude_deg", v.flapping.amplitude_rad);
  c.number("kinematics.hinge_x_m", v.flapping.hinge_x_B_m);
  c.number("kinematics.hinge_z_m", v.flapping.hinge_z_B_m);
  if (v.body.present) {
    c.number("body.mass_kg", v.body.mass_kg);
    c.number("body.pitch_inertia_kgm2", v.body.pitch_inertia_kgm2);
    c.number("body.drag_area_m2", v.body.drag_area_m2);
  }
  if (v.tail.present) {
    const TailModel& t = v.tail;
    c.number("tail.area_m2", t.area_m2);
    c.number("tail.aspect_ratio", t.aspect_ratio);
    c.number("tail.zero_lift_drag_coefficient", t.zero_lift_drag_coefficient);
    c.number("tail.oswald_efficiency", t.oswald_efficiency);
    c.number("tail.arm_m", t.arm_m);
    c.number("tail.height_m", t.height_m);
    c.number("tail.mass_kg", t.mass_kg);
    c.number("tail.downwash_factor", t.downwash_factor);
    if (v.body.present && !(t.mass_kg < v.body.mass_kg))
      c.add("tail.mass_kg",
            "a number < body.mass_kg = " + displayNumber(v.body.mass_kg) +
                " (the tail is part of the vehicle mass)",
            displayNumber(t.mass_kg));
  }
  return problems;
}

std::vector<ModelProblem> designPointProblems(const OperatingPoint& p) {
  std::vector<ModelProblem> problems;
  Checker c(&problems);
  c.number("operating_point.speed_mps", p.speed_mps);
  c.number("operating_point.freq_hz", p.freq_hz);
  c.number("operating_point.theta_deg", p.theta_rad);
  c.number("operating_point.tail_angle_deg", p.tail_angle_rad);
  return problems;
}

std::vector<ModelProblem> definitionProblems(const VehicleDefinition& definition) {
  std::vector<ModelProblem> problems = vehicleProblems(definition.model);
  for (ModelProblem& p : designPointProblems(definition.design_point))
    problems.push_back(std::move(p));
  return problems;
}

void requireValidVehicle(const VehicleModel& vehicle) {
  const std::vector<ModelProblem> problems = vehicleProblems(vehicle);
  if (!problems.empty())
    throw InvalidModelError("invalid vehicle" +
                            (vehicle.name.empty() ? std::string() : " '" + vehicle.name + "'") +
                            ": " + problems.front().message());
}

}  // namespace orni
