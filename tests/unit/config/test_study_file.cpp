// Study files: kinds, [simulate], [override] merging (errors point at the study file), the study
// behind `ornithopter simulate VEHICLE.toml`, and the resolved study round trip.
#include <gtest/gtest.h>
#include <toml++/toml.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <variant>

#include "core/model/frames.hpp"
#include "studies/runner/config/input_error.hpp"
#include "studies/runner/config/study_file.hpp"
#include "studies/runner/config/study_sections.hpp"
#include "studies/runner/config/vehicle_file.hpp"

namespace orni::studies {
namespace {

namespace fs = std::filesystem;

fs::path repo() { return fs::path(ORNI_SOURCE_DIR); }
fs::path vehiclePath(const std::string& name) { return repo() / "studies" / "vehicles" / name; }

/// A scratch folder per test, removed afterwards.
class ConfigStudyFile : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() / (std::string("orni_config_") + info->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  /// Writes a study into the scratch folder; `vehicle` is inserted as an absolute path.
  fs::path writeStudy(const std::string& name, const std::string& text) const {
    const fs::path file = dir_ / name;
    std::ofstream out(file);
    out << text;
    return file;
  }
  static std::string efw() { return vehiclePath("efw_magpie.toml").generic_string(); }

  fs::path dir_;
};

TEST_F(ConfigStudyFile, KindNames) {
  for (StudyKind k : {StudyKind::kSimulate, StudyKind::kModes, StudyKind::kAeromap,
                      StudyKind::kTrim, StudyKind::kOptimize, StudyKind::kSweep}) {
    const auto parsed = parseStudyKind(toString(k));
    ASSERT_TRUE(parsed.has_value());
    EXPECT_EQ(*parsed, k);
  }
  EXPECT_EQ(toString(StudyKind::kAeromap), "aeromap");
  EXPECT_FALSE(parseStudyKind("simulation").has_value());
}

TEST_F(ConfigStudyFile, LoadsExampleStudy) {
  const Study s = loadStudyFile(repo() / "studies" / "examples" / "rfw_theta20.toml");
  EXPECT_EQ(s.kind, StudyKind::kSimulate);
  EXPECT_EQ(s.name, "rfw_theta20");
  EXPECT_EQ(s.vehicle_path, fs::path("../vehicles/rfw_tunnel.toml"));
  EXPECT_EQ(s.vehicle.name, "rfw_tunnel");
  EXPECT_DOUBLE_EQ(s.vehicle.aero.stall_width_rad, 2.0 * kDegToRad);
  EXPECT_EQ(s.simulate().options.mode, FlightMode::kTethered);
  EXPECT_EQ(s.simulate().options.cycles, 10);
  EXPECT_DOUBLE_EQ(s.point.theta_rad, 20.0 * kDegToRad);
  EXPECT_DOUBLE_EQ(s.point.speed_mps, 6.0);  // from the vehicle's operating point
  EXPECT_DOUBLE_EQ(s.point.freq_hz, 4.0);
  EXPECT_DOUBLE_EQ(s.design_point.theta_rad, 0.0);  // the vehicle is not changed
}

TEST_F(ConfigStudyFile, LoadsPaperStudies) {
  const Study a = loadStudyFile(repo() / "studies" / "paper" / "fig2_rfw_theta0.toml");
  const Study b = loadStudyFile(repo() / "studies" / "paper" / "fig2_rfw_theta20.toml");
  EXPECT_EQ(a.name, "fig2_rfw_theta0");
  EXPECT_DOUBLE_EQ(a.point.theta_rad, 0.0);
  EXPECT_DOUBLE_EQ(b.point.theta_rad, 20.0 * kDegToRad);
  for (const Study* s : {&a, &b}) {
    EXPECT_DOUBLE_EQ(s->point.speed_mps, 6.0);
    EXPECT_DOUBLE_EQ(s->point.freq_hz, 4.0);
    EXPECT_EQ(s->simulate().options.cycles, 10);
    EXPECT_EQ(s->simulate().options.mode, FlightMode::kTethered);
  }
}

TEST_F(ConfigStudyFile, DefaultsAndNameFromStem) {
  const fs::path f = writeStudy("my_trim.toml", "kind = \"trim\"\nvehicle = \"" + efw() + "\"\n");
  const Study s = loadStudyFile(f);
  EXPECT_EQ(s.kind, StudyKind::kTrim);
  EXPECT_EQ(s.name, "my_trim");
  EXPECT_EQ(s.point.theta_rad, s.design_point.theta_rad);
  // A trim study has no [simulate] settings (its settings are the shared `trim`).
  EXPECT_TRUE(std::holds_alternative<std::monostate>(s.settings));
  EXPECT_THROW((void)s.simulate(), std::logic_error);
}

TEST_F(ConfigStudyFile, OutputFiguresSwitch) {
  EXPECT_TRUE(loadStudyFile(writeStudy("on.toml", "kind = \"trim\"\nvehicle = \"" + efw() + "\"\n"))
                  .figures);
  const fs::path f = writeStudy(
      "off.toml", "kind = \"trim\"\nvehicle = \"" + efw() + "\"\n[output]\nfigures = false\n");
  const Study s = loadStudyFile(f);
  EXPECT_FALSE(s.figures);
  // The resolved study keeps it (not the default), and reads back the same.
  const std::string text = resolvedStudyToml(s);
  EXPECT_NE(text.find("[output]\nfigures = false"), std::string::npos) << text;
  EXPECT_FALSE(loadStudyFile(writeStudy("study.resolved.toml", text)).figures);
  // Checked like every key: a typo and a wrong type are errors naming the key.
  for (const char* bad : {"[output]\nfigure = false\n", "[output]\nfigures = \"no\"\n"}) {
    try {
      (void)loadStudyFile(writeStudy("bad_output.toml", "kind = \"trim\"\nvehicle = \"" + efw() +
                                                            "\"\n" + bad));
      ADD_FAILURE() << bad << " was accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("output.figure"), std::string::npos) << e.what();
    }
  }
}

TEST_F(ConfigStudyFile, OverridesApply) {
  const fs::path f = writeStudy("ovr.toml", "kind = \"simulate\"\nvehicle = \"" + efw() + R"("

[override]
tail.arm_m = 0.2
aero.model = "delaurier1993"

[override.wing]
semispan_m = 0.3
members = [{ name = "SPAR", material = "LE1", diameter_m = 0.002, start_xy_m = [0.0, 0.0], end_xy_m = [0.0, 0.3] }]

[override.materials.NEW]
youngs_modulus_gpa = 1.0
poisson_ratio = 0.3
density_kgpm3 = 900.0

[simulate]
mode = "free"
speed_mps = 10
cycles = 20
rel_tol = 1e-7
)");
  const Study s = loadStudyFile(f);
  const VehicleModel base = loadVehicleFile(vehiclePath("efw_magpie.toml")).model;
  EXPECT_DOUBLE_EQ(s.vehicle.tail.arm_m, 0.2);
  EXPECT_DOUBLE_EQ(s.vehicle.tail.area_m2, base.tail.area_m2);  // siblings kept
  EXPECT_EQ(s.vehicle.aero.model, AeroModelKind::kDeLaurier1993);
  EXPECT_DOUBLE_EQ(s.vehicle.aero.aspect_ratio, 5.58);
  EXPECT_DOUBLE_EQ(s.vehicle.wing.semispan_m, 0.3);
  EXPECT_DOUBLE_EQ(s.vehicle.wing.root_chord_m, 0.104);
  ASSERT_EQ(s.vehicle.wing.members.size(), 1u);  // arrays are replaced
  EXPECT_EQ(s.vehicle.wing.members[0].name, "SPAR");
  EXPECT_EQ(s.vehicle.materials.size(), 5u);
  EXPECT_DOUBLE_EQ(s.vehicle.findMaterial("NEW")->youngs_modulus_pa, 1e9);
  EXPECT_EQ(s.simulate().options.mode, FlightMode::kFree);
  EXPECT_EQ(s.simulate().options.cycles, 20);
  EXPECT_DOUBLE_EQ(s.simulate().options.rel_tol, 1e-7);
  EXPECT_DOUBLE_EQ(s.point.speed_mps, 10.0);
  EXPECT_DOUBLE_EQ(s.point.freq_hz, 12.0);
  EXPECT_DOUBLE_EQ(s.point.tail_angle_rad, 11.85 * kDegToRad);
}

InputError errorOfStudy(const fs::path& f) {
  try {
    (void)loadStudyFile(f);
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << f << " was accepted";
  return InputError("", 0, "", "");
}

TEST_F(ConfigStudyFile, OverrideErrorsPointAtTheStudy) {
  const fs::path f = writeStudy("bad_ovr.toml", "kind = \"simulate\"\nvehicle = \"" + efw() +
                                                    "\"\n\n[override]\ntail.arm_m = -0.1\n");
  const InputError e = errorOfStudy(f);
  EXPECT_EQ(e.file(), f.string());
  EXPECT_EQ(e.line(), 5);
  EXPECT_EQ(e.key(), "override.tail.arm_m");
  EXPECT_EQ(std::string(e.what()),
            f.string() + ":5: key 'override.tail.arm_m': expected a number in (0, 20], got -0.1");

  const fs::path g = writeStudy("typo_ovr.toml", "kind = \"simulate\"\nvehicle = \"" + efw() +
                                                     "\"\n[override.tail]\narm_mm = 0.1\n");
  const InputError e2 = errorOfStudy(g);
  EXPECT_EQ(e2.line(), 4);
  EXPECT_EQ(std::string(e2.what()),
            g.string() + ":4: unknown key 'override.tail.arm_mm' (did you mean 'arm_m'?)");
}

TEST_F(ConfigStudyFile, ErrorsInTheVehicleNameTheVehicle) {
  // A fault in the vehicle file itself (vehicle path relative to the study) names the vehicle.
  const fs::path bad_vehicle = dir_ / "v.toml";
  {
    std::ofstream out(bad_vehicle);
    std::ifstream in(vehiclePath("efw_magpie.toml"));
    out << in.rdbuf();
    out << "\n[fuselage]\nlength_m = 0.18\n";
  }
  const fs::path f = writeStudy("s.toml", "kind = \"simulate\"\nvehicle = \"v.toml\"\n");
  const InputError e = errorOfStudy(f);
  EXPECT_EQ(fs::path(e.file()).filename(), "v.toml");
  EXPECT_EQ(e.key(), "fuselage");
}

// A free flight of the nonlinear wing without a rel_tol flies at 1e-5 (its verdicts are not
// converged at the default 1e-4: kNonlinearWingFreeFlightRelTol); a given rel_tol, the tethered
// mode and the linear wing keep theirs.
TEST_F(ConfigStudyFile, NonlinearWingFreeFlightDefaultsToATighterTolerance) {
  const std::string table3 = vehiclePath("efw_magpie_table3.toml").generic_string();
  auto relTol = [&](const std::string& name, const std::string& vehicle, const std::string& sim) {
    return loadStudyFile(writeStudy(name, "kind = \"simulate\"\nvehicle = \"" + vehicle +
                                              "\"\n[simulate]\n" + sim))
        .simulate()
        .options.rel_tol;
  };
  EXPECT_EQ(relTol("n1.toml", table3, "mode = \"free\"\n"), kNonlinearWingFreeFlightRelTol);
  EXPECT_EQ(kNonlinearWingFreeFlightRelTol, 1e-5);
  EXPECT_EQ(relTol("n2.toml", table3, "mode = \"free\"\nrel_tol = 1e-4\n"), 1e-4);
  EXPECT_EQ(relTol("n3.toml", table3, "mode = \"tethered\"\n"), 1e-4);
  EXPECT_EQ(relTol("n4.toml", efw(), "mode = \"free\"\n"), 1e-4);
  // The mode set after reading (`simulate --mode free`): applyWingTolerance.
  Study s =
      loadStudyFile(writeStudy("n5.toml", "kind = \"simulate\"\nvehicle = \"" + table3 + "\"\n"));
  EXPECT_EQ(s.simulate().options.rel_tol, 1e-4);
  s.simulate().options.mode = FlightMode::kFree;
  applyWingTolerance(s);
  EXPECT_EQ(s.simulate().options.rel_tol, 1e-5);
}

TEST_F(ConfigStudyFile, SimulateSectionRules) {
  const fs::path a = writeStudy(
      "a.toml", "kind = \"aeromap\"\nvehicle = \"" + efw() + "\"\n[simulate]\ncycles = 3\n");
  const InputError ea = errorOfStudy(a);
  EXPECT_EQ(ea.key(), "simulate");
  EXPECT_EQ(ea.line(), 3);

  const fs::path b = writeStudy("b.toml", "kind = \"simulate\"\nvehicle = \"" + efw() +
                                              "\"\n[simulate]\nsamples_per_cycle = 4\n");
  const InputError eb = errorOfStudy(b);
  EXPECT_EQ(eb.key(), "simulate.samples_per_cycle");
  EXPECT_EQ(std::string(eb.what()),
            b.string() +
                ":4: key 'simulate.samples_per_cycle': expected an integer in [8, 100000], "
                "got 4");

  // sampled_loads: one of its two words, and read into the options.
  const fs::path s1 = writeStudy("s1.toml", "kind = \"simulate\"\nvehicle = \"" + efw() +
                                                "\"\n[simulate]\nsampled_loads = \"fast\"\n");
  const InputError es = errorOfStudy(s1);
  EXPECT_EQ(es.key(), "simulate.sampled_loads");
  EXPECT_EQ(es.line(), 4);
  EXPECT_NE(std::string(es.what()).find("interpolated"), std::string::npos) << es.what();
  const fs::path s2 =
      writeStudy("s2.toml", "kind = \"simulate\"\nvehicle = \"" + efw() +
                                "\"\n[simulate]\nsampled_loads = \"evaluated\"\n");
  EXPECT_FALSE(loadStudyFile(s2).simulate().options.interpolate_sampled_loads);
  const fs::path s3 = writeStudy("s3.toml", "kind = \"simulate\"\nvehicle = \"" + efw() + "\"\n");
  EXPECT_TRUE(loadStudyFile(s3).simulate().options.interpolate_sampled_loads);  // "interpolated"

  const fs::path c = writeStudy(
      "c.toml", "kind = \"simulate\"\nvehicle = \"" + efw() + "\"\n[simulate]\nrel_tol = 0.5\n");
  EXPECT_EQ(errorOfStudy(c).key(), "simulate.rel_tol");

  const fs::path d =
      writeStudy("d.toml", "kind = \"simulate\"\nname = \"a/b\"\nvehicle = \"" + efw() + "\"\n");
  EXPECT_EQ(errorOfStudy(d).key(), "name");
}

TEST_F(ConfigStudyFile, AeromapSection) {
  const fs::path f = writeStudy("map.toml", "kind = \"aeromap\"\nvehicle = \"" + efw() + R"("
[aeromap]
speed_mps = "10:20:6"
freq_hz = [10, 12.5, 15]
theta_deg = 7
cycles = 25
steady_tol = 2e-3
)");
  const Study s = loadStudyFile(f);
  EXPECT_EQ(s.kind, StudyKind::kAeromap);
  const AeromapSettings& a = s.aeromap();
  ASSERT_TRUE(a.speed_mps.spec.has_value());
  EXPECT_EQ(a.speed_mps.values, (std::vector<double>{10, 12, 14, 16, 18, 20}));
  EXPECT_FALSE(a.freq_hz.spec.has_value());
  EXPECT_EQ(a.freq_hz.values, (std::vector<double>{10, 12.5, 15}));
  EXPECT_EQ(a.theta_deg.values, (std::vector<double>{7}));
  // The tail defaults to the vehicle's operating point (11.85 deg), exactly in SI.
  ASSERT_EQ(a.tail_angle_deg.values.size(), 1u);
  EXPECT_EQ(a.tail_angle_deg.values[0], 11.85);
  EXPECT_EQ(a.tail_angle_deg.values[0] * kDegToRad, s.design_point.tail_angle_rad);
  EXPECT_EQ(a.options.cycles, 25);
  EXPECT_EQ(a.options.steady_tol, 2e-3);
  EXPECT_TRUE(a.options.stop_when_steady);
  EXPECT_FALSE(a.options.record_history);
  EXPECT_EQ(a.options.rel_tol, SimulationOptions{}.rel_tol);

  // The resolved study writes the section back; it reloads to the same map and is a fixed point.
  const std::string text = resolvedStudyToml(s);
  for (const char* expected :
       {"[aeromap]\n", "speed_mps = \"10:20:6\"\n", "freq_hz = [10.0, 12.5, 15.0]\n",
        "theta_deg = [7.0]\n", "tail_angle_deg = [11.85]\n", "cycles = 25", "steady_tol = 0.002\n"})
    EXPECT_NE(text.find(expected), std::string::npos) << expected << "\n" << text;
  const Study back = loadStudyFile(writeStudy("study.resolved.toml", text));
  EXPECT_EQ(back.aeromap().speed_mps.values, a.speed_mps.values);
  EXPECT_EQ(back.aeromap().freq_hz.values, a.freq_hz.values);
  EXPECT_EQ(back.aeromap().theta_deg.values, a.theta_deg.values);
  EXPECT_EQ(back.aeromap().tail_angle_deg.values, a.tail_angle_deg.values);
  EXPECT_EQ(back.aeromap().options.cycles, a.options.cycles);
  EXPECT_EQ(back.aeromap().options.steady_tol, a.options.steady_tol);
  EXPECT_EQ(resolvedStudyToml(back), text);
}

TEST_F(ConfigStudyFile, LoadsPaperAeromapStudy) {
  const Study s = loadStudyFile(repo() / "studies" / "paper" / "fig5_efw_aeromap.toml");
  EXPECT_EQ(s.kind, StudyKind::kAeromap);
  EXPECT_EQ(s.name, "fig5_efw_aeromap");
  const AeromapSettings& a = s.aeromap();
  EXPECT_EQ(a.speed_mps.values.size() * a.freq_hz.values.size() * a.theta_deg.values.size() *
                a.tail_angle_deg.values.size(),
            180u);
  EXPECT_EQ(a.theta_deg.values, (std::vector<double>{0, 5, 10, 15, 20}));
}

TEST_F(ConfigStudyFile, AeromapSectionRules) {
  const std::string head = "kind = \"aeromap\"\nvehicle = \"" + efw() + "\"\n";
  struct Case {
    const char* body;
    const char* key;
    int line;
    const char* says;
  };
  const Case cases[] = {
      {"", "aeromap", 1, "missing required key 'aeromap'"},
      {"[aeromap]\nspeed_mps = \"10:20\"\nfreq_hz = 12\ntheta_deg = 0\n", "aeromap.speed_mps", 4,
       "(three fields separated by ':' are needed)"},
      {"[aeromap]\nspeed_mps = 10\nfreq_hz = \"10:20:1\"\ntheta_deg = 0\n", "aeromap.freq_hz", 5,
       "(N = 1 needs A == B)"},
      {"[aeromap]\nspeed_mps = 10\nfreq_hz = 12\ntheta_deg = \"0:90:4\"\n", "aeromap.theta_deg",
       6, "(value 90)"},
      {"[aeromap]\nspeed_mps = 10\nfreq_hz = 12\ntheta_deg = []\n", "aeromap.theta_deg", 6,
       "got an empty array"},
      {"[aeromap]\nspeed_mps = [10, 0]\nfreq_hz = 12\ntheta_deg = 0\n", "aeromap.speed_mps", 4,
       "at index 1"},
      {"[aeromap]\nspeed_mps = true\nfreq_hz = 12\ntheta_deg = 0\n", "aeromap.speed_mps", 4,
       "got a boolean true"},
      {"[aeromap]\nspeed_mps = 10\nfreq_hz = 12\n", "aeromap.theta_deg", 3,
       "missing required key 'aeromap.theta_deg'"},
      {"[aeromap]\nspeed_mps = 10\nfreq_hz = 12\ntheta_deg = 0\ntail_deg = 3\n",
       "aeromap.tail_deg", 7, "unknown key 'aeromap.tail_deg'"},
      {"[aeromap]\nspeed_mps = 10\nfreq_hz = 12\ntheta_deg = 0\ncycles = 0\n", "aeromap.cycles",
       7, "expected an integer in [1, 100000], got 0"},
  };
  int n = 0;
  for (const Case& c : cases) {
    SCOPED_TRACE(c.body);
    const fs::path f = writeStudy("rules" + std::to_string(n++) + ".toml", head + c.body);
    const InputError e = errorOfStudy(f);
    EXPECT_EQ(e.key(), c.key);
    EXPECT_EQ(e.line(), c.line);
    EXPECT_NE(std::string(e.what()).find(c.says), std::string::npos) << e.what();
  }
  const fs::path in_simulate = writeStudy(
      "sim.toml", "kind = \"simulate\"\nvehicle = \"" + efw() + "\"\n[aeromap]\nspeed_mps = 10\n");
  const InputError e = errorOfStudy(in_simulate);
  EXPECT_EQ(e.key(), "aeromap");
  EXPECT_EQ(e.line(), 3);
}

TEST_F(ConfigStudyFile, AeromapStudyFromVehicle) {
  const Study s = aeromapStudyFromVehicle(
      vehiclePath("efw_magpie.toml"), gridAxis(parseGridSpec("10:20:6")),
      gridAxis(parseGridSpec("12:12:1")), gridAxis(parseGridSpec("0:20:5")), std::nullopt);
  EXPECT_EQ(s.kind, StudyKind::kAeromap);
  EXPECT_EQ(s.name, "efw_magpie_aeromap");
  EXPECT_EQ(s.aeromap().tail_angle_deg.values, (std::vector<double>{11.85}));
  EXPECT_EQ(s.aeromap().options.cycles, 40);
  const Study back = loadStudyFile(writeStudy("r.toml", resolvedStudyToml(s)));
  EXPECT_EQ(resolvedStudyToml(back), resolvedStudyToml(s));
}

TEST_F(ConfigStudyFile, KindSettingsOfAnotherKindAreALogicError) {
  const Study map = aeromapStudyFromVehicle(
      vehiclePath("efw_magpie.toml"), gridAxis(parseGridSpec("10:20:6")),
      gridAxis(parseGridSpec("12:12:1")), gridAxis(parseGridSpec("0:20:5")), std::nullopt);
  EXPECT_NO_THROW((void)map.aeromap());
  try {
    (void)map.sweep();
    FAIL() << "sweep() of an aeromap study";
  } catch (const std::logic_error& e) {
    EXPECT_EQ(std::string(e.what()),
              "Study::sweep(): this study is kind \"aeromap\", it has no [sweep] settings");
  }
  Study simulate = studyFromVehicle(vehiclePath("efw_magpie.toml"));
  EXPECT_THROW((void)simulate.aeromap(), std::logic_error);
  EXPECT_THROW((void)simulate.calibrate(), std::logic_error);
  EXPECT_THROW((void)simulate.optimize(), std::logic_error);
  EXPECT_THROW((void)simulate.sensitivity(), std::logic_error);
  EXPECT_THROW((void)simulate.continuation(), std::logic_error);
}

TEST_F(ConfigStudyFile, StudyFromVehicle) {
  const Study s = studyFromVehicle(vehiclePath("efw_magpie.toml"));
  EXPECT_EQ(s.kind, StudyKind::kSimulate);
  EXPECT_EQ(s.name, "efw_magpie");
  EXPECT_EQ(s.vehicle.name, "efw_magpie");
  EXPECT_EQ(s.point.freq_hz, 12.0);
  EXPECT_EQ(s.point.tail_angle_rad, s.design_point.tail_angle_rad);
  EXPECT_EQ(s.simulate().options.cycles, SimulationOptions{}.cycles);
  EXPECT_EQ(s.vehicle_path, vehiclePath("efw_magpie.toml"));
}

void expectSameStudy(const Study& a, const Study& b) {
  EXPECT_EQ(a.kind, b.kind);
  EXPECT_EQ(a.name, b.name);
  EXPECT_EQ(a.vehicle_path, b.vehicle_path);
  EXPECT_EQ(vehicleToToml({a.vehicle, a.design_point}),
            vehicleToToml({b.vehicle, b.design_point}));  // exact (writer test)
  EXPECT_EQ(a.point.speed_mps, b.point.speed_mps);
  EXPECT_EQ(a.point.freq_hz, b.point.freq_hz);
  EXPECT_EQ(a.point.theta_rad, b.point.theta_rad);
  EXPECT_EQ(a.point.tail_angle_rad, b.point.tail_angle_rad);
  if (a.kind != StudyKind::kSimulate) return;
  EXPECT_EQ(a.simulate().wing_only, b.simulate().wing_only);
  EXPECT_EQ(a.simulate().at_trim, b.simulate().at_trim);
  EXPECT_EQ(a.simulate().history_every, b.simulate().history_every);
  EXPECT_EQ(a.simulate().options.mode, b.simulate().options.mode);
  EXPECT_EQ(a.simulate().options.cycles, b.simulate().options.cycles);
  EXPECT_EQ(a.simulate().options.rel_tol, b.simulate().options.rel_tol);
  EXPECT_EQ(a.simulate().options.abs_tol, b.simulate().options.abs_tol);
  EXPECT_EQ(a.simulate().options.steady_tol, b.simulate().options.steady_tol);
  EXPECT_EQ(a.simulate().options.samples_per_cycle, b.simulate().options.samples_per_cycle);
  EXPECT_EQ(a.simulate().options.separation_abs_tol, b.simulate().options.separation_abs_tol);
  const FreeFlightOptions &fa = a.simulate().options.free, &fb = b.simulate().options.free;
  EXPECT_EQ(fa.bounds.U_mps, fb.bounds.U_mps);
  EXPECT_EQ(fa.bounds.W_mps, fb.bounds.W_mps);
  EXPECT_EQ(fa.bounds.theta_rad, fb.bounds.theta_rad);
  EXPECT_EQ(fa.bounds.Q_radps, fb.bounds.Q_radps);
  EXPECT_EQ(fa.bounds.h_m, fb.bounds.h_m);
  EXPECT_EQ(fa.transient_fraction, fb.transient_fraction);
  EXPECT_EQ(fa.divergence_ratio, fb.divergence_ratio);
  EXPECT_EQ(fa.initial_altitude_m, fb.initial_altitude_m);
}

TEST_F(ConfigStudyFile, ResolvedStudyRoundTrips) {
  const fs::path ovr = writeStudy("ovr.toml", "kind = \"simulate\"\nvehicle = \"" + efw() + R"("
[override]
tail.arm_m = 0.14
[simulate]
mode = "free"
theta_deg = 8.7
steady_tol = 3e-5
)");
  const fs::path trim = writeStudy("t.toml", "kind = \"trim\"\nvehicle = \"" + efw() + "\"\n");
  for (const fs::path& file : {repo() / "studies" / "examples" / "rfw_theta20.toml", ovr, trim}) {
    SCOPED_TRACE(file.string());
    const Study s = loadStudyFile(file);
    const std::string text = resolvedStudyToml(s);

    // The [vehicle] part alone reproduces the vehicle through parseVehicleTable.
    const toml::table doc = toml::parse(std::string_view(text), std::string("resolved.toml"));
    ASSERT_NE(doc.get_as<toml::table>("vehicle"), nullptr);
    const VehicleDefinition v =
        parseVehicleTable(*doc.get_as<toml::table>("vehicle"), "resolved.toml");
    EXPECT_EQ(vehicleToToml(v), vehicleToToml({s.vehicle, s.design_point}));
    EXPECT_EQ(v.model.tail.arm_m, s.vehicle.tail.arm_m);

    // The whole document is itself a study that loads into the same Study.
    const fs::path again = writeStudy("study.resolved.toml", text);
    const Study back = loadStudyFile(again);
    expectSameStudy(s, back);
    EXPECT_EQ(resolvedStudyToml(back), text);
  }
}

TEST_F(ConfigStudyFile, FreeFlightSection) {
  const fs::path f = writeStudy("free.toml", "kind = \"simulate\"\nvehicle = \"" + efw() + R"("
[simulate]
mode = "free"
cycles = 30

[simulate.free]
bound_speed_mps = 1.5
bound_W_mps = 2.5
bound_theta_deg = 35
bound_Q_degps = 900
bound_h_m = 0.4
transient_fraction = 0.25
divergence_ratio = 8
initial_altitude_m = 50
)");
  const Study s = loadStudyFile(f);
  const FreeFlightOptions& o = s.simulate().options.free;
  EXPECT_EQ(s.simulate().options.mode, FlightMode::kFree);
  EXPECT_EQ(o.bounds.U_mps, 1.5);
  EXPECT_EQ(o.bounds.W_mps, 2.5);
  EXPECT_EQ(o.bounds.theta_rad, 35 * kDegToRad);
  EXPECT_EQ(o.bounds.Q_radps, 900 * kDegToRad);
  EXPECT_EQ(o.bounds.h_m, 0.4);
  EXPECT_EQ(o.transient_fraction, 0.25);
  EXPECT_EQ(o.divergence_ratio, 8.0);
  EXPECT_EQ(o.initial_altitude_m, 50.0);

  // Written back in full, reloaded to the same options, a fixed point.
  const std::string text = resolvedStudyToml(s);
  for (const char* expected :
       {"[simulate.free]\n", "bound_speed_mps = 1.5\n", "bound_W_mps = 2.5\n",
        "bound_theta_deg = 35.0\n", "bound_Q_degps = 900.0", "bound_h_m = 0.4\n",
        "transient_fraction = 0.25\n", "divergence_ratio = 8.0\n",
        "initial_altitude_m = 50.0\n"})
    EXPECT_NE(text.find(expected), std::string::npos) << expected << "\n" << text;
  const Study back = loadStudyFile(writeStudy("study.resolved.toml", text));
  expectSameStudy(s, back);
  EXPECT_EQ(resolvedStudyToml(back), text);

  // Defaults: a free study without [simulate.free] still writes every option.
  const Study d = loadStudyFile(writeStudy(
      "d.toml", "kind = \"simulate\"\nvehicle = \"" + efw() + "\"\n[simulate]\nmode = \"free\"\n"));
  const FreeFlightOptions defaults;
  EXPECT_EQ(d.simulate().options.free.bounds.theta_rad, defaults.bounds.theta_rad);
  const std::string dtext = resolvedStudyToml(d);
  EXPECT_NE(dtext.find("bound_theta_deg = 40.0\n"), std::string::npos) << dtext;
  EXPECT_NE(dtext.find("bound_Q_degps = 0.0"), std::string::npos) << dtext;
  const Study dback = loadStudyFile(writeStudy("d.resolved.toml", dtext));
  expectSameStudy(d, dback);
  // A tethered study writes no [simulate.free] (it would be rejected on reading).
  EXPECT_EQ(resolvedStudyToml(loadStudyFile(repo() / "studies" / "examples" / "rfw_theta20.toml"))
                .find("[simulate.free]"),
            std::string::npos);
}

TEST_F(ConfigStudyFile, FreeFlightSectionRules) {
  const std::string head = "kind = \"simulate\"\nvehicle = \"" + efw() + "\"\n";
  struct Case {
    const char* body;
    const char* key;
    int line;
    const char* says;
  };
  const Case cases[] = {
      {"[simulate]\ncycles = 3\n[simulate.free]\nbound_h_m = 1\n", "simulate.free", 5,
       "only allowed with mode = \"free\""},
      {"[simulate.free]\nbound_h_m = 1\n", "simulate.free", 3, "only allowed with mode"},
      {"[simulate]\nmode = \"free\"\n[simulate.free]\nbound_speed_mps = 0\n",
       "simulate.free.bound_speed_mps", 6, "expected a number in [0.001, 100], got 0"},
      {"[simulate]\nmode = \"free\"\n[simulate.free]\nbound_Q_degps = -1\n",
       "simulate.free.bound_Q_degps", 6, "expected a number in [0, 1000000], got -1"},
      {"[simulate]\nmode = \"free\"\n[simulate.free]\ntransient_fraction = 0.95\n",
       "simulate.free.transient_fraction", 6, "expected a number in [0, 0.9]"},
      {"[simulate]\nmode = \"free\"\n[simulate.free]\ndivergence_ratio = 1\n",
       "simulate.free.divergence_ratio", 6, "expected a number in (1, 1000000], got 1"},
      {"[simulate]\nmode = \"free\"\n[simulate.free]\ninitial_altitude_m = -5.0\n",
       "simulate.free.initial_altitude_m", 6, "expected a number in (0, 10000], got -5.0"},
      {"[simulate]\nmode = \"free\"\n[simulate.free]\nbound_theta_deg = \"40\"\n",
       "simulate.free.bound_theta_deg", 6, "got a string"},
      {"[simulate]\nmode = \"free\"\n[simulate.free]\nbound_U_mps = 2\n",
       "simulate.free.bound_U_mps", 6, "unknown key 'simulate.free.bound_U_mps'"},
      {"[simulate]\nmode = \"free\"\nfree = 3\n", "simulate.free", 5, "got an integer 3"},
  };
  int n = 0;
  for (const Case& c : cases) {
    SCOPED_TRACE(c.body);
    const fs::path f = writeStudy("free" + std::to_string(n++) + ".toml", head + c.body);
    const InputError e = errorOfStudy(f);
    EXPECT_EQ(e.key(), c.key);
    EXPECT_EQ(e.line(), c.line);
    EXPECT_NE(std::string(e.what()).find(c.says), std::string::npos) << e.what();
  }
}

TEST_F(ConfigStudyFile, LoadsPaperFig6To9Studies) {
  const Study free = loadStudyFile(repo() / "studies" / "paper" / "fig6_8_free_flight.toml");
  const Study cft =
      loadStudyFile(repo() / "studies" / "paper" / "fig9_constrained_flight_test.toml");
  EXPECT_EQ(free.simulate().options.mode, FlightMode::kFree);
  EXPECT_EQ(free.simulate().options.cycles, 60);
  EXPECT_EQ(cft.simulate().options.mode, FlightMode::kTethered);
  EXPECT_GE(cft.simulate().options.cycles, 10);
  for (const Study* s : {&free, &cft}) {
    // The honest vehicle flies its own trim at 12 Hz (at_trim: solved first); the point in the
    // file is the trim's initial guess near that trim, not the paper's Table 3.
    EXPECT_EQ(s->kind, StudyKind::kSimulate);
    EXPECT_EQ(s->vehicle.name, "efw_magpie");
    EXPECT_TRUE(s->simulate().at_trim);
    EXPECT_DOUBLE_EQ(s->point.theta_rad, 15.0 * kDegToRad);
    EXPECT_DOUBLE_EQ(s->point.freq_hz, 12.0);
    EXPECT_DOUBLE_EQ(s->point.speed_mps, 15.0);
    EXPECT_DOUBLE_EQ(s->point.tail_angle_rad, 18.0 * kDegToRad);
  }
}

TEST_F(ConfigStudyFile, ResolvedStudyContents) {
  const Study s = loadStudyFile(repo() / "studies" / "examples" / "rfw_theta20.toml");
  const std::string text = resolvedStudyToml(s);
  for (const char* expected :
       {"kind = \"simulate\"\n", "name = \"rfw_theta20\"\n",
        "vehicle_source = \"../vehicles/rfw_tunnel.toml\"", "[simulate]\n", "mode = \"tethered\"\n",
        "theta_deg = 20.0\n", "cycles = 10\n", "samples_per_cycle = 100\n", "[vehicle]\n",
        "[vehicle.wing]\n", "[[vehicle.wing.members]]\n", "[vehicle.materials.CFRP]\n",
        "youngs_modulus_gpa = 135.0\n", "amplitude_deg = 33.06\n", "[vehicle.operating_point]\n"})
    EXPECT_NE(text.find(expected), std::string::npos) << expected << "\n" << text;
  EXPECT_EQ(text.find("[vehicle.body]"), std::string::npos);
}

// An error a later stage finds in a vehicle value points at the line that wrote it: the study's
// [override] when it sets the key, else the vehicle file; a default has no line.
TEST_F(ConfigStudyFile, VehicleKeyErrorNamesTheLineThatWroteTheValue) {
  const fs::path overridden = writeStudy(
      "o.toml", "kind = \"modes\"\nvehicle = \"" + efw() +
                    "\"\n[override]\nwing.fe.element_size_m = 6e-3\n");
  const InputError in_override =
      vehicleKeyError(loadStudyFile(overridden), "wing.fe.element_size_m", "coarser", "6e-3");
  EXPECT_EQ(in_override.file(), overridden.generic_string());
  EXPECT_EQ(in_override.line(), 4);
  EXPECT_EQ(in_override.key(), "override.wing.fe.element_size_m");

  const fs::path plain = writeStudy("p.toml", "kind = \"modes\"\nvehicle = \"" + efw() + "\"\n");
  const Study study = loadStudyFile(plain);
  const InputError in_vehicle = vehicleKeyError(study, "wing.semispan_m", "shorter", "0.35");
  EXPECT_EQ(in_vehicle.file(), efw());
  EXPECT_GT(in_vehicle.line(), 0);
  EXPECT_EQ(in_vehicle.key(), "wing.semispan_m");

  const InputError defaulted = vehicleKeyError(study, "wing.skin.pretension_N_per_m", "-", "0");
  EXPECT_EQ(defaulted.line(), 0);
  EXPECT_EQ(inputFileOf(study), plain.generic_string());
}

}  // namespace
}  // namespace orni::studies
