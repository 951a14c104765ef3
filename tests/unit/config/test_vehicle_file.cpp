// Vehicle files: the committed vehicles load with the expected SI values, the writer round-trips
// exactly, and the strict reader reports file, line and key in the documented formats.
#include <gtest/gtest.h>
#include <toml++/toml.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include "core/model/frames.hpp"
#include "studies/runner/config/input_error.hpp"
#include "studies/runner/config/toml_access.hpp"
#include "studies/runner/config/vehicle_file.hpp"

namespace orni::studies {
namespace {

namespace fs = std::filesystem;

fs::path vehiclePath(const std::string& name) {
  return fs::path(ORNI_SOURCE_DIR) / "studies" / "vehicles" / name;
}

/// Field-by-field exact equality of two models (doubles compared with ==).
void expectSameVehicle(const VehicleDefinition& file_a, const VehicleDefinition& file_b) {
  const VehicleModel& a = file_a.model;
  const VehicleModel& b = file_b.model;
  EXPECT_EQ(a.name, b.name);
  EXPECT_EQ(a.description, b.description);
  EXPECT_EQ(a.air.density_kgpm3, b.air.density_kgpm3);
  EXPECT_EQ(a.air.kinematic_viscosity_m2ps, b.air.kinematic_viscosity_m2ps);
  EXPECT_EQ(a.air.gravity_mps2, b.air.gravity_mps2);
  EXPECT_EQ(a.wing.planform, b.wing.planform);
  EXPECT_EQ(a.wing.semispan_m, b.wing.semispan_m);
  EXPECT_EQ(a.wing.root_chord_m, b.wing.root_chord_m);
  EXPECT_EQ(a.wing.incidence_rad, b.wing.incidence_rad);
  EXPECT_EQ(a.wing.strip_count, b.wing.strip_count);
  EXPECT_EQ(a.wing.structure, b.wing.structure);
  EXPECT_EQ(a.wing.p3_aft_of_le_m, b.wing.p3_aft_of_le_m);
  EXPECT_EQ(a.wing.skin.material, b.wing.skin.material);
  EXPECT_EQ(a.wing.skin.thickness_m, b.wing.skin.thickness_m);
  ASSERT_EQ(a.wing.members.size(), b.wing.members.size());
  for (std::size_t i = 0; i < a.wing.members.size(); ++i) {
    const WingMember& p = a.wing.members[i];
    const WingMember& q = b.wing.members[i];
    EXPECT_EQ(p.name, q.name);
    EXPECT_EQ(p.material, q.material);
    EXPECT_EQ(p.diameter_m, q.diameter_m);
    EXPECT_EQ(p.start_x_W_m, q.start_x_W_m);
    EXPECT_EQ(p.start_y_W_m, q.start_y_W_m);
    EXPECT_EQ(p.end_x_W_m, q.end_x_W_m);
    EXPECT_EQ(p.end_y_W_m, q.end_y_W_m);
  }
  EXPECT_EQ(a.wing.fe.element_size_m, b.wing.fe.element_size_m);
  EXPECT_EQ(a.wing.fe.max_modes, b.wing.fe.max_modes);
  EXPECT_EQ(a.wing.fe.cutoff_hz, b.wing.fe.cutoff_hz);
  EXPECT_EQ(a.wing.fe.damping_ratio, b.wing.fe.damping_ratio);
  EXPECT_EQ(a.wing.fe.p3_cross_axis_normal, b.wing.fe.p3_cross_axis_normal);
  EXPECT_EQ(a.wing.fe.inertial_stiffness, b.wing.fe.inertial_stiffness);
  ASSERT_EQ(a.materials.size(), b.materials.size());
  for (std::size_t i = 0; i < a.materials.size(); ++i) {
    EXPECT_EQ(a.materials[i].name, b.materials[i].name);
    EXPECT_EQ(a.materials[i].youngs_modulus_pa, b.materials[i].youngs_modulus_pa);
    EXPECT_EQ(a.materials[i].poisson_ratio, b.materials[i].poisson_ratio);
    EXPECT_EQ(a.materials[i].density_kgpm3, b.materials[i].density_kgpm3);
  }
  EXPECT_EQ(a.aero.model, b.aero.model);
  EXPECT_EQ(a.aero.lag, b.aero.lag);
  EXPECT_EQ(a.aero.aspect_ratio, b.aero.aspect_ratio);
  EXPECT_EQ(a.aero.zero_lift_angle_rad, b.aero.zero_lift_angle_rad);
  EXPECT_EQ(a.aero.moment_coefficient_ac, b.aero.moment_coefficient_ac);
  EXPECT_EQ(a.aero.suction_efficiency, b.aero.suction_efficiency);
  EXPECT_EQ(a.aero.crossflow_drag_coefficient, b.aero.crossflow_drag_coefficient);
  EXPECT_EQ(a.aero.skin_friction, b.aero.skin_friction);
  EXPECT_EQ(a.aero.stall_angle_max_rad, b.aero.stall_angle_max_rad);
  EXPECT_EQ(a.aero.stall_angle_min_rad, b.aero.stall_angle_min_rad);
  EXPECT_EQ(a.aero.stall_width_rad, b.aero.stall_width_rad);
  EXPECT_EQ(a.aero.separation_lag_tf0, b.aero.separation_lag_tf0);
  EXPECT_EQ(a.aero.min_speed_mps, b.aero.min_speed_mps);
  EXPECT_EQ(a.flapping.amplitude_rad, b.flapping.amplitude_rad);
  EXPECT_EQ(a.flapping.hinge_x_B_m, b.flapping.hinge_x_B_m);
  EXPECT_EQ(a.flapping.hinge_z_B_m, b.flapping.hinge_z_B_m);
  EXPECT_EQ(a.body.present, b.body.present);
  EXPECT_EQ(a.body.mass_kg, b.body.mass_kg);
  EXPECT_EQ(a.body.pitch_inertia_kgm2, b.body.pitch_inertia_kgm2);
  EXPECT_EQ(a.tail.present, b.tail.present);
  EXPECT_EQ(a.tail.area_m2, b.tail.area_m2);
  EXPECT_EQ(a.tail.aspect_ratio, b.tail.aspect_ratio);
  EXPECT_EQ(a.tail.zero_lift_drag_coefficient, b.tail.zero_lift_drag_coefficient);
  EXPECT_EQ(a.tail.oswald_efficiency, b.tail.oswald_efficiency);
  EXPECT_EQ(a.tail.arm_m, b.tail.arm_m);
  EXPECT_EQ(a.tail.height_m, b.tail.height_m);
  EXPECT_EQ(a.tail.mass_kg, b.tail.mass_kg);
  EXPECT_EQ(a.tail.downwash_factor, b.tail.downwash_factor);
  EXPECT_EQ(file_a.design_point.speed_mps, file_b.design_point.speed_mps);
  EXPECT_EQ(file_a.design_point.freq_hz, file_b.design_point.freq_hz);
  EXPECT_EQ(file_a.design_point.theta_rad, file_b.design_point.theta_rad);
  EXPECT_EQ(file_a.design_point.tail_angle_rad, file_b.design_point.tail_angle_rad);
}

TEST(ConfigVehicleFile, LoadsEfwMagpieInSi) {
  const VehicleDefinition file = loadVehicleFile(vehiclePath("efw_magpie.toml"));
  const VehicleModel& v = file.model;
  EXPECT_EQ(v.name, "efw_magpie");
  EXPECT_DOUBLE_EQ(v.air.density_kgpm3, 1.225);
  EXPECT_DOUBLE_EQ(v.air.kinematic_viscosity_m2ps, 1.5e-5);

  EXPECT_EQ(v.wing.planform, Planform::kQuarterEllipse);
  EXPECT_DOUBLE_EQ(v.wing.semispan_m, 0.27);
  EXPECT_DOUBLE_EQ(v.wing.root_chord_m, 0.104);
  EXPECT_DOUBLE_EQ(v.wing.incidence_rad, 0.0);
  EXPECT_EQ(v.wing.strip_count, 27);
  EXPECT_EQ(v.wing.structure, StructureLevel::kFlexible);
  EXPECT_DOUBLE_EQ(v.wing.p3_aft_of_le_m, 0.052);
  EXPECT_DOUBLE_EQ(v.wing.member_diameter_scale, 1.0);  // Table 1 literal
  EXPECT_EQ(v.wing.skin.material, "SKIN");
  EXPECT_DOUBLE_EQ(v.wing.skin.thickness_m, 4e-5);

  ASSERT_EQ(v.wing.members.size(), 8u);
  EXPECT_EQ(v.wing.members[0].name, "LE1");
  EXPECT_DOUBLE_EQ(v.wing.members[0].diameter_m, 0.002);
  EXPECT_DOUBLE_EQ(v.wing.members[0].end_y_W_m, 0.135);
  EXPECT_EQ(v.wing.members[2].name, "DIAG1");
  EXPECT_DOUBLE_EQ(v.wing.members[2].start_x_W_m, -0.052);
  EXPECT_DOUBLE_EQ(v.wing.members[2].end_y_W_m, 0.0945);
  EXPECT_EQ(v.wing.members[4].name, "STIF1");
  EXPECT_EQ(v.wing.members[4].material, "CFRP_ROD");
  // Stiffener ends lie on the trailing edge to within 1e-6 m, never behind it.
  for (int i = 4; i < 8; ++i) {
    const WingMember& m = v.wing.members[static_cast<std::size_t>(i)];
    const double r = m.end_y_W_m / v.wing.semispan_m;
    const double x_te = -v.wing.root_chord_m * std::sqrt(1.0 - r * r);
    EXPECT_GE(m.end_x_W_m, x_te - 1e-12) << m.name;
    EXPECT_LT(m.end_x_W_m - x_te, 1e-6) << m.name;
  }

  EXPECT_DOUBLE_EQ(v.wing.fe.element_size_m, 0.005);
  EXPECT_EQ(v.wing.fe.max_modes, 24);  // chosen by convergence (the file says why)
  EXPECT_DOUBLE_EQ(v.wing.fe.cutoff_hz, 0.0);
  EXPECT_DOUBLE_EQ(v.wing.fe.damping_ratio, 0.015);
  EXPECT_FALSE(v.wing.fe.p3_cross_axis_normal);  // fitted: "span"

  ASSERT_EQ(v.materials.size(), 4u);
  const Material* le1 = v.findMaterial("LE1");
  ASSERT_NE(le1, nullptr);
  EXPECT_DOUBLE_EQ(le1->youngs_modulus_pa, 250e9);
  EXPECT_DOUBLE_EQ(le1->poisson_ratio, 0.31);
  EXPECT_DOUBLE_EQ(le1->density_kgpm3, 1800.0);
  ASSERT_NE(v.findMaterial("SKIN"), nullptr);
  EXPECT_DOUBLE_EQ(v.findMaterial("SKIN")->youngs_modulus_pa, 100e9);
  EXPECT_DOUBLE_EQ(v.findMaterial("CFRP_ROD")->density_kgpm3, 500.0);

  EXPECT_EQ(v.aero.model, AeroModelKind::kMstTd);
  EXPECT_EQ(v.aero.lag, CirculationLag::kScherer1);
  EXPECT_DOUBLE_EQ(v.aero.aspect_ratio, 5.58);
  EXPECT_DOUBLE_EQ(v.aero.stall_angle_max_rad, 13.0 * kDegToRad);
  EXPECT_DOUBLE_EQ(v.aero.stall_angle_min_rad, -13.0 * kDegToRad);
  EXPECT_DOUBLE_EQ(v.aero.stall_width_rad, 2.0 * kDegToRad);
  EXPECT_DOUBLE_EQ(v.aero.separation_lag_tf0, 6.0);

  EXPECT_DOUBLE_EQ(v.flapping.amplitude_rad, 33.06 * kPi / 180.0);
  EXPECT_NEAR(v.flapping.amplitude_rad, 0.5770, 1e-4);
  EXPECT_DOUBLE_EQ(v.flapping.hinge_x_B_m, 0.015);  // chosen (placement sweep)
  EXPECT_DOUBLE_EQ(v.flapping.hinge_z_B_m, -0.015);

  EXPECT_TRUE(v.body.present);
  EXPECT_DOUBLE_EQ(v.body.mass_kg, 0.118);
  EXPECT_DOUBLE_EQ(v.body.drag_area_m2, 4.0e-4);  // estimated: frontal area x C_D
  EXPECT_DOUBLE_EQ(v.body.pitch_inertia_kgm2, 1.7e-4);  // component budget

  EXPECT_TRUE(v.tail.present);
  EXPECT_DOUBLE_EQ(v.tail.area_m2, 0.007);
  EXPECT_DOUBLE_EQ(v.tail.aspect_ratio, 2.0);
  EXPECT_DOUBLE_EQ(v.tail.zero_lift_drag_coefficient, 0.02);
  EXPECT_DOUBLE_EQ(v.tail.oswald_efficiency, 0.9);
  EXPECT_DOUBLE_EQ(v.tail.arm_m, 0.12);
  EXPECT_DOUBLE_EQ(v.tail.mass_kg, 0.0015);
  EXPECT_DOUBLE_EQ(v.tail.downwash_factor, 0.0);

  EXPECT_DOUBLE_EQ(file.design_point.speed_mps, 10.8);
  EXPECT_DOUBLE_EQ(file.design_point.freq_hz, 12.0);
  EXPECT_DOUBLE_EQ(file.design_point.theta_rad, 9.2 * kDegToRad);
  EXPECT_DOUBLE_EQ(file.design_point.tail_angle_rad, 11.85 * kDegToRad);
}

TEST(ConfigVehicleFile, LoadsRfwTunnelWithDefaults) {
  const VehicleDefinition file = loadVehicleFile(vehiclePath("rfw_tunnel.toml"));
  const VehicleModel& v = file.model;
  EXPECT_EQ(v.name, "rfw_tunnel");
  EXPECT_EQ(v.wing.planform, Planform::kRectangular);
  EXPECT_DOUBLE_EQ(v.wing.root_chord_m, 0.0967742);
  EXPECT_DOUBLE_EQ(v.wing.p3_aft_of_le_m, 0.5 * 0.0967742);  // default
  EXPECT_EQ(v.wing.members.size(), 5u);
  EXPECT_DOUBLE_EQ(v.aero.aspect_ratio, 0.0);  // from the planform
  EXPECT_DOUBLE_EQ(v.aero.min_speed_mps, AeroParameters{}.min_speed_mps);
  EXPECT_FALSE(v.body.present);
  EXPECT_FALSE(v.tail.present);
  EXPECT_DOUBLE_EQ(v.flapping.amplitude_rad, 33.06 * kDegToRad);
  EXPECT_DOUBLE_EQ(v.flapping.hinge_x_B_m, 0.0);
  ASSERT_NE(v.findMaterial("CFRP"), nullptr);
  EXPECT_DOUBLE_EQ(v.findMaterial("CFRP")->youngs_modulus_pa, 135e9);
  EXPECT_DOUBLE_EQ(v.findMaterial("RIPSTOP")->youngs_modulus_pa, 2e9);
  EXPECT_DOUBLE_EQ(file.design_point.speed_mps, 6.0);
  EXPECT_DOUBLE_EQ(file.design_point.freq_hz, 4.0);
  EXPECT_DOUBLE_EQ(file.design_point.theta_rad, 0.0);
}

TEST(ConfigVehicleFile, WriterRoundTripsExactly) {
  for (const char* name : {"efw_magpie.toml", "rfw_tunnel.toml"}) {
    SCOPED_TRACE(name);
    const VehicleDefinition v = loadVehicleFile(vehiclePath(name));
    const std::string text = vehicleToToml(v);
    const toml::table t = toml::parse(std::string_view(text), std::string("resolved.toml"));
    const VehicleDefinition back = parseVehicleTable(t, "resolved.toml");
    expectSameVehicle(v, back);
    EXPECT_EQ(vehicleToToml(back), text);  // idempotent
    // Values appear in file units with their short decimal form.
    EXPECT_NE(text.find("amplitude_deg = 33.06\n"), std::string::npos) << text;
  }
}

TEST(ConfigVehicleFile, WriterRoundTripsModelDefaults) {
  // The struct defaults in radians (not written by a file) survive the degree conversion.
  VehicleDefinition v = loadVehicleFile(vehiclePath("rfw_tunnel.toml"));
  v.model.aero = AeroParameters{};
  v.model.wing.incidence_rad = 0.1;
  v.design_point.theta_rad = -0.3;
  const std::string text = vehicleToToml(v);
  const toml::table t = toml::parse(std::string_view(text), std::string("resolved.toml"));
  expectSameVehicle(v, parseVehicleTable(t, "resolved.toml"));
}

TEST(ConfigVehicleFile, WingFeSettingsRoundTrip) {
  // Non-default [wing.fe] values survive writing and reading; the table is always written.
  VehicleDefinition file = loadVehicleFile(vehiclePath("efw_magpie.toml"));
  VehicleModel& v = file.model;
  v.wing.fe.element_size_m = 0.0035;
  v.wing.fe.max_modes = 37;
  v.wing.fe.cutoff_hz = 240.5;
  v.wing.fe.damping_ratio = 0.02;
  v.wing.fe.p3_cross_axis_normal = false;
  v.wing.fe.inertial_stiffness = InertialStiffness::kSofteningOnly;
  const std::string text = vehicleToToml(file);
  EXPECT_NE(text.find("[wing.fe]\nelement_size_m = 0.0035\nmodes = 37\ncutoff_hz = 240.5\n"
                      "damping_ratio = 0.02\np3_cross_axis = \"span\"\n"
                      "p3_joint = \"universal\"\nroot_edge = \"free\"\n"
                      "inertial_stiffness = \"softening_only\"\n"),
            std::string::npos)
      << text;
  const toml::table t = toml::parse(std::string_view(text), std::string("resolved.toml"));
  const VehicleDefinition back = parseVehicleTable(t, "resolved.toml");
  expectSameVehicle(file, back);
  EXPECT_EQ(vehicleToToml(back), text);
}

TEST(ConfigVehicleFile, WingFeDefaultsWhenAbsent) {
  const char* text = R"(name = "m"
[wing]
planform = "rectangular"
semispan_m = 0.27
root_chord_m = 0.1
strips = 10
[wing.skin]
material = "FILM"
thickness_m = 4e-5
[materials.FILM]
youngs_modulus_gpa = 2.0
poisson_ratio = 0.35
density_kgpm3 = 1000.0
[kinematics]
amplitude_deg = 30.0
[operating_point]
speed_mps = 6.0
freq_hz = 4.0
theta_deg = 0.0
)";
  const toml::table t = toml::parse(std::string_view(text), std::string("mem.toml"));
  const VehicleModel v = parseVehicleTable(t, "mem.toml").model;
  const WingFeSettings d;
  EXPECT_EQ(v.wing.fe.element_size_m, d.element_size_m);
  EXPECT_EQ(v.wing.fe.max_modes, d.max_modes);
  EXPECT_EQ(v.wing.fe.cutoff_hz, d.cutoff_hz);
  EXPECT_EQ(v.wing.fe.damping_ratio, d.damping_ratio);
  EXPECT_EQ(v.wing.fe.p3_cross_axis_normal, d.p3_cross_axis_normal);
  EXPECT_EQ(v.wing.fe.inertial_stiffness, InertialStiffness::kBoth);  // docs/theory.md 4.6
}

TEST(ConfigTomlWriter, NumbersAreShortAndExact) {
  EXPECT_EQ(TomlWriter::floatText(0.1), "0.1");
  EXPECT_EQ(TomlWriter::floatText(250.0), "250.0");
  EXPECT_EQ(TomlWriter::floatText(4e-5), "4e-05");
  EXPECT_EQ(TomlWriter::scaledText(33.06 * kDegToRad, kDegToRad), "33.06");
  EXPECT_EQ(TomlWriter::scaledText(-13.0 * kDegToRad, kDegToRad), "-13.0");
  EXPECT_EQ(TomlWriter::scaledText(175.0 * 1e9, 1e9), "175.0");
  EXPECT_EQ(TomlWriter::keyText("semispan_m"), "semispan_m");
  EXPECT_EQ(TomlWriter::keyText("my rod"), "\"my rod\"");
  EXPECT_EQ(TomlWriter::stringText("a\"b\\c\n"), "\"a\\\"b\\\\c\\n\"");
}

TEST(ConfigTomlAccess, EditDistanceSuggestions) {
  EXPECT_EQ(editDistance("semispn_m", "semispan_m"), 1u);
  EXPECT_EQ(editDistance("", "abc"), 3u);
  EXPECT_EQ(editDistance("FLIM", "FILM"), 1u);  // adjacent transposition
  EXPECT_EQ(editDistance("kitten", "sitting"), 3u);
  EXPECT_EQ(closestMatch("FOIL", {"FILM"}), "");
  EXPECT_EQ(closestMatch("semispn_m", {"planform", "semispan_m", "strips"}), "semispan_m");
  EXPECT_EQ(closestMatch("stall_widht_deg", {"stall_width_deg", "stall_angle_max_deg"}),
            "stall_width_deg");
  EXPECT_EQ(closestMatch("xyzzy", {"planform", "semispan_m"}), "");
}

TEST(ConfigTomlAccess, RangeDescriptions) {
  EXPECT_EQ(Range::openClosed(0, 200).describe(), "a number in (0, 200]");
  EXPECT_EQ(Range::open(0, 90).describe(), "a number in (0, 90)");
  EXPECT_EQ(Range::closedOpen(0, 1).describe(), "a number in [0, 1)");
  EXPECT_EQ(Range::closed(1e-6, 1e5).describe(), "a number in [1e-6, 100000]");
  EXPECT_FALSE(Range::closed(0, 1).contains(std::nan("")));
  EXPECT_TRUE(Range::open(0, 90).contains(45));
  EXPECT_FALSE(Range::open(0, 90).contains(90));
  EXPECT_TRUE(Range::closed(0, 1).contains(1));
}

// --- messages, exactly -------------------------------------------------------------------------

const char* kMinimal = R"(name = "m"
[wing]
planform = "rectangular"
semispan_m = 0.27
root_chord_m = 0.1
strips = 10
[wing.skin]
material = "FILM"
thickness_m = 4e-5
[materials.FILM]
youngs_modulus_gpa = 2.0
poisson_ratio = 0.35
density_kgpm3 = 1000.0
[kinematics]
amplitude_deg = 30.0
[operating_point]
speed_mps = 6.0
freq_hz = 4.0
theta_deg = 0.0
)";

std::string replaced(const std::string& from, const std::string& to) {
  std::string s = kMinimal;
  const std::size_t at = s.find(from);
  if (at == std::string::npos) throw std::logic_error("test text not found: " + from);
  return s.replace(at, from.size(), to);
}

std::string errorOf(const std::string& text) {
  try {
    const toml::table t = toml::parse(std::string_view(text), std::string("mem.toml"));
    (void)parseVehicleTable(t, "mem.toml");
  } catch (const InputError& e) {
    return e.what();
  }
  return "accepted";
}

TEST(ConfigVehicleMessages, MinimalVehicleLoads) { EXPECT_EQ(errorOf(kMinimal), "accepted"); }

TEST(ConfigVehicleMessages, Formats) {
  EXPECT_EQ(errorOf(replaced("semispan_m = 0.27", "semispan_m = -1")),
            "mem.toml:4: key 'wing.semispan_m': expected a number in [0.005, 20], got -1");
  EXPECT_EQ(errorOf(replaced("semispan_m = 0.27", "semispan_m = \"wide\"")),
            "mem.toml:4: key 'wing.semispan_m': expected a number in [0.005, 20], got a string "
            "\"wide\"");
  EXPECT_EQ(errorOf(replaced("semispan_m = 0.27", "semispn_m = 0.27")),
            "mem.toml:4: unknown key 'wing.semispn_m' (did you mean 'semispan_m'?)");
  EXPECT_EQ(errorOf(replaced("root_chord_m = 0.1\n", "")),
            "mem.toml:2: missing required key 'wing.root_chord_m' (expected a number in "
            "[0.002, 10])");
  EXPECT_EQ(errorOf(replaced("strips = 10", "strips = 1000")),
            "mem.toml:6: key 'wing.strips': expected an integer in [1, 500], got 1000");
  EXPECT_EQ(errorOf(replaced("strips = 10", "strips = 10.0")),
            "mem.toml:6: key 'wing.strips': expected an integer in [1, 500], got a float 10.0");
  EXPECT_EQ(errorOf(replaced("planform = \"rectangular\"", "planform = \"rectangle\"")),
            "mem.toml:3: key 'wing.planform': expected one of \"rectangular\" or "
            "\"quarter_ellipse\", got a string \"rectangle\" (did you mean \"rectangular\"?)");
  EXPECT_EQ(errorOf(replaced("root_chord_m = 0.1", "root_chord_m = -inf")),
            "mem.toml:5: key 'wing.root_chord_m': expected a finite number in [0.002, 10], "
            "got -inf");
  EXPECT_EQ(errorOf(replaced("material = \"FILM\"", "material = \"FOIL\"")),
            "mem.toml:8: key 'wing.skin.material': expected the name of a [materials.NAME] table "
            "(\"FILM\"), got an unknown material \"FOIL\"");
  EXPECT_EQ(errorOf(replaced("amplitude_deg = 30.0", "amplitude_deg = 90")),
            "mem.toml:15: key 'kinematics.amplitude_deg': expected a number in (0, 90), got 90");
}

TEST(ConfigVehicleMessages, WingFeFormats) {
  auto withFe = [](const std::string& lines) {
    return replaced("[materials.FILM]", "[wing.fe]\n" + lines + "[materials.FILM]");
  };
  EXPECT_EQ(errorOf(withFe("")), "accepted");
  EXPECT_EQ(errorOf(withFe("element_size_m = 0.002\nmodes = 200\ncutoff_hz = 0\n"
                           "damping_ratio = 0\np3_cross_axis = \"span\"\n")),
            "accepted");
  for (const char* model : {"both", "softening_only", "none"})
    EXPECT_EQ(errorOf(withFe(std::string("inertial_stiffness = \"") + model + "\"\n")),
              "accepted");
  EXPECT_EQ(errorOf(withFe("inertial_stiffness = \"softening\"\n")),
            "mem.toml:11: key 'wing.fe.inertial_stiffness': expected one of \"both\", "
            "\"softening_only\" or \"none\", got a string \"softening\"");
  EXPECT_EQ(errorOf(withFe("element_size_m = 0.0\n")),
            "mem.toml:11: key 'wing.fe.element_size_m': expected a number in [0.001, 20], got 0");
  EXPECT_EQ(errorOf(withFe("element_size_m = 0.3\n")),
            "mem.toml:11: key 'wing.fe.element_size_m': expected a number in [0.001, 0.27] (at "
            "most wing.semispan_m), got 0.3");
  EXPECT_EQ(errorOf(withFe("modes = 201\n")),
            "mem.toml:11: key 'wing.fe.modes': expected an integer in [1, 200], got 201");
  EXPECT_EQ(errorOf(withFe("modes = 12.0\n")),
            "mem.toml:11: key 'wing.fe.modes': expected an integer in [1, 200], got a float 12.0");
  EXPECT_EQ(errorOf(withFe("cutoff_hz = -1\n")),
            "mem.toml:11: key 'wing.fe.cutoff_hz': expected a number in [0, 100000], got -1");
  EXPECT_EQ(errorOf(withFe("damping_ratio = 1\n")),
            "mem.toml:11: key 'wing.fe.damping_ratio': expected a number in [0, 1), got 1");
  EXPECT_EQ(errorOf(withFe("p3_cross_axis = \"norml\"\n")),
            "mem.toml:11: key 'wing.fe.p3_cross_axis': expected one of \"normal\" or \"span\", "
            "got a string \"norml\" (did you mean \"normal\"?)");
  EXPECT_EQ(errorOf(withFe("mode = 12\n")),
            "mem.toml:11: unknown key 'wing.fe.mode' (did you mean 'modes'?)");
}

TEST(ConfigVehicleMessages, IntegersAcceptedForFloats) {
  EXPECT_EQ(errorOf(replaced("speed_mps = 6.0", "speed_mps = 6")), "accepted");
}

TEST(ConfigVehicleMessages, SyntaxErrorsBecomeInputErrors) {
  const fs::path dir = fs::temp_directory_path() / "orni_config_syntax";
  fs::create_directories(dir);
  const fs::path file = dir / "broken.toml";
  {
    std::ofstream out(file);
    out << "name = \"x\"\n[wing\nsemispan_m = 1\n";
  }
  try {
    (void)loadVehicleFile(file);
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.line(), 2);
    EXPECT_EQ(e.file(), file.string());
    EXPECT_NE(std::string(e.what()).find("broken.toml:2: TOML syntax error: "), std::string::npos)
        << e.what();
  }
  try {
    (void)loadVehicleFile(dir / "absent.toml");
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.line(), 0);
    EXPECT_NE(std::string(e.what()).find("absent.toml: cannot open file"), std::string::npos);
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace orni::studies
