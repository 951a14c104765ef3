// Sweep study files (kind = "sweep", study_file.hpp): axes in file order (not TOML's alphabetical
// table order), the full factorial with the first axis outermost, axis values applied exactly like
// [override] (vehicle keys) or the run's section (analysis keys), defaults that follow swept keys,
// the resolved study that re-runs the same points, and errors located at the axis at fault.
#include <gtest/gtest.h>

#include <filesystem>
#include <algorithm>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "core/model/frames.hpp"
#include "studies/runner/config/input_error.hpp"
#include "studies/runner/config/study_file.hpp"
#include "studies/runner/config/study_reader.hpp"
#include "studies/runner/config/toml_access.hpp"

namespace orni::studies {
namespace {

namespace fs = std::filesystem;

fs::path repo() { return fs::path(ORNI_SOURCE_DIR); }

/// The keys that vary between a sweep's points although no axis sets them, found as sweeps found
/// them before issue 15 (each point's resolved sections written as TOML, lines diffed): the
/// reference the field comparison of SweepSettings::derived_keys must reproduce, order included.
/// Bare header parts only (the vehicles used here quote none).
std::vector<std::string> textualDerivedKeys(const Study& s) {
  auto lines = [&](const Study& study) {
    TomlWriter out;
    writeStudySections(study, s.sweep().run, out);
    std::vector<std::string> result;
    std::istringstream in(out.str());
    for (std::string l; std::getline(in, l);) result.push_back(l);
    return result;
  };
  const std::vector<std::string> base = lines(s);
  std::vector<bool> varies(base.size(), false);
  for (const Study& p : s.sweep().points) {
    const std::vector<std::string> l = lines(p);
    if (l.size() != base.size()) continue;
    for (std::size_t i = 0; i < l.size(); ++i)
      if (l[i] != base[i]) varies[i] = true;
  }
  std::vector<std::string> swept;
  const std::string section = s.sweep().run == StudyKind::kTrim ? "trim." : "simulate.";
  for (const SweepAxis& a : s.sweep().axes)
    swept.push_back(a.key.rfind(section, 0) == 0 ? a.key : "vehicle." + a.key);
  std::vector<std::string> derived;
  std::string header;
  for (std::size_t i = 0; i < base.size(); ++i) {
    const std::string& l = base[i];
    if (!l.empty() && l[0] == '[') {
      const std::size_t open = l.find_first_not_of('['), close = l.find(']');
      header = l.substr(open, close - open);
      continue;
    }
    const std::size_t eq = l.find(" = ");
    if (l.empty() || l[0] == '#' || eq == std::string::npos || !varies[i]) continue;
    const std::string key = (header.empty() ? "" : header + ".") + l.substr(0, eq);
    if (std::find(swept.begin(), swept.end(), key) == swept.end() &&
        std::find(derived.begin(), derived.end(), key) == derived.end())
      derived.push_back(key);
  }
  return derived;
}

class ConfigSweepStudy : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() / (std::string("orni_sweep_study_") + info->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path write(const std::string& name, const std::string& text) const {
    std::ofstream(dir_ / name) << text;
    return dir_ / name;
  }
  static std::string vehicle(const std::string& file) {
    return "vehicle = \"" + (repo() / "studies/vehicles" / file).generic_string() + "\"\n";
  }
  static InputError errorOf(const fs::path& f) {
    try {
      (void)loadStudyFile(f);
    } catch (const InputError& e) {
      return e;
    }
    ADD_FAILURE() << f << " was accepted";
    return InputError("", 0, "", "");
  }
  fs::path dir_;
};

TEST_F(ConfigSweepStudy, AxesKeepFileOrderAndTheFirstIsOutermost) {
  // "tail.arm_m" sorts after "body.mass_kg": a TOML table would iterate them the other way round.
  const Study s =
      loadStudyFile(write("s.toml", "kind = \"sweep\"\n" + vehicle("efw_magpie.toml") + R"(
[sweep]
run = "trim"
axes = [
  { key = "tail.arm_m", values = [0.10, 0.12, 0.14] },
  { key = "body.mass_kg", values = "0.1:0.12:2" },
]
)"));
  EXPECT_EQ(s.kind, StudyKind::kSweep);
  EXPECT_EQ(s.name, "s");
  ASSERT_EQ(s.sweep().axes.size(), 2u);
  EXPECT_EQ(s.sweep().run, StudyKind::kTrim);
  EXPECT_EQ(s.sweep().axes[0].key, "tail.arm_m");
  EXPECT_EQ(s.sweep().axes[1].key, "body.mass_kg");
  EXPECT_FALSE(s.sweep().axes[0].values.spec.has_value());
  ASSERT_TRUE(s.sweep().axes[1].values.spec.has_value());
  EXPECT_EQ(s.sweep().axes[1].values.values, (std::vector<double>{0.1, 0.12}));
  ASSERT_EQ(s.sweep().points.size(), 6u);
  const double arm[] = {0.10, 0.10, 0.12, 0.12, 0.14, 0.14};
  const double mass[] = {0.1, 0.12, 0.1, 0.12, 0.1, 0.12};
  for (std::size_t i = 0; i < 6; ++i) {
    SCOPED_TRACE(i);
    const Study& p = s.sweep().points[i];
    EXPECT_EQ(p.kind, StudyKind::kTrim);
    EXPECT_EQ(p.vehicle.tail.arm_m, arm[i]);
    EXPECT_EQ(p.vehicle.body.mass_kg, mass[i]);
    EXPECT_EQ(p.vehicle.tail.area_m2, 0.007);  // siblings kept, like [override]
  }
  // The base study is the study without the axes.
  EXPECT_EQ(s.vehicle.tail.arm_m, 0.12);
  EXPECT_EQ(s.vehicle.body.mass_kg, 0.118);
}

TEST_F(ConfigSweepStudy, ValuesApplyLikeOverridesAndAnalysisKeys) {
  const Study s =
      loadStudyFile(write("s.toml", "kind = \"sweep\"\n" + vehicle("efw_magpie.toml") + R"(
[override]
tail.arm_m = 0.2          # replaced by the axis at every point
tail.area_m2 = 0.008      # kept

[sweep]
run = "trim"
axes = [
  { key = "trim.freq_hz", values = [8, 9.5] },
  { key = "tail.arm_m", values = 0.11 },
  { key = "wing.strips", values = "20:30:3" },
  { key = "trim.initial.speed_mps", values = [7] },
]

[trim]
freq_hz = 12.0
max_iterations = 20
initial = { theta_mean_deg = 12.0 }
)"));
  ASSERT_EQ(s.sweep().points.size(), 6u);
  for (std::size_t i = 0; i < 6; ++i) {
    SCOPED_TRACE(i);
    const Study& p = s.sweep().points[i];
    EXPECT_EQ(p.trim.initial.freq_hz, i < 3 ? 8.0 : 9.5);
    EXPECT_EQ(p.vehicle.tail.arm_m, 0.11);
    EXPECT_EQ(p.vehicle.tail.area_m2, 0.008);
    EXPECT_EQ(p.vehicle.wing.strip_count, 20 + 5 * static_cast<int>(i % 3));  // integers
    EXPECT_EQ(p.trim.initial.speed_mps, 7.0);
    EXPECT_DOUBLE_EQ(p.trim.initial.theta_rad, 12.0 * kDegToRad);  // the section's other keys
    EXPECT_EQ(p.trim.max_iterations, 20);
  }
  EXPECT_EQ(s.trim.initial.freq_hz, 12.0);  // the base
  EXPECT_EQ(s.vehicle.tail.arm_m, 0.2);
  EXPECT_TRUE(s.sweep().derived_keys.empty());
}

TEST_F(ConfigSweepStudy, SimulateSweepOfTetheredAndFreeRuns) {
  const Study t =
      loadStudyFile(write("t.toml", "kind = \"sweep\"\n" + vehicle("rfw_tunnel.toml") + R"(
[sweep]
run = "simulate"
axes = [{ key = "simulate.theta_deg", values = [0, 20] }, { key = "kinematics.amplitude_deg", values = [25, 30] }]
[simulate]
cycles = 3
)"));
  ASSERT_EQ(t.sweep().points.size(), 4u);
  EXPECT_EQ(t.sweep().run, StudyKind::kSimulate);
  EXPECT_EQ(t.sweep().points[0].kind, StudyKind::kSimulate);
  EXPECT_EQ(t.sweep().points[3].point.theta_rad, 20.0 * kDegToRad);
  EXPECT_DOUBLE_EQ(t.sweep().points[3].vehicle.flapping.amplitude_rad, 30.0 * kDegToRad);
  EXPECT_EQ(t.sweep().points[3].simulate().options.cycles, 3);

  const Study f =
      loadStudyFile(write("f.toml", "kind = \"sweep\"\n" + vehicle("efw_magpie.toml") + R"(
[sweep]
run = "simulate"
axes = [{ key = "simulate.free.bound_theta_deg", values = [30, 40] }]
[simulate]
mode = "free"
cycles = 5
)"));
  EXPECT_EQ(f.sweep().base_simulate.options.mode, FlightMode::kFree);
  EXPECT_DOUBLE_EQ(f.sweep().points[0].simulate().options.free.bounds.theta_rad, 30.0 * kDegToRad);
}

TEST_F(ConfigSweepStudy, DefaultsFollowTheSweptKeysAndTheResolvedStudyReproducesThePoints) {
  // No freq_hz in [trim]: each point trims at its own operating_point.freq_hz. The resolved study
  // cannot fix trim.freq_hz to the base's 12 Hz, so it leaves it to its default.
  const fs::path file = write("s.toml", "kind = \"sweep\"\n" + vehicle("efw_magpie.toml") + R"(
[sweep]
run = "trim"
axes = [{ key = "operating_point.freq_hz", values = "6:8:3" }, { key = "tail.arm_m", values = [0.1, 0.12] }]
)");
  const Study s = loadStudyFile(file);
  ASSERT_EQ(s.sweep().points.size(), 6u);
  EXPECT_EQ(s.sweep().points[0].trim.initial.freq_hz, 6.0);
  EXPECT_EQ(s.sweep().points[5].trim.initial.freq_hz, 8.0);
  EXPECT_EQ(s.sweep().derived_keys, (std::vector<std::string>{"trim.freq_hz"}));
  const std::string text = resolvedStudyToml(s);
  EXPECT_NE(text.find("kind = \"sweep\""), std::string::npos);
  EXPECT_NE(text.find("[[sweep.axes]]\nkey = \"operating_point.freq_hz\"\nvalues = \"6:8:3\""),
            std::string::npos);
  EXPECT_NE(text.find("[trim]\n# freq_hz: not fixed here"), std::string::npos);
  EXPECT_NE(text.find("[vehicle.tail]"), std::string::npos);

  const fs::path again_file = write("study.resolved.toml", text);
  const Study again = loadStudyFile(again_file);
  EXPECT_EQ(resolvedStudyToml(again), text);
  ASSERT_EQ(again.sweep().points.size(), s.sweep().points.size());
  for (std::size_t i = 0; i < s.sweep().points.size(); ++i) {
    SCOPED_TRACE(i);
    const Study& a = s.sweep().points[i];
    const Study& b = again.sweep().points[i];
    EXPECT_EQ(b.trim.initial.freq_hz, a.trim.initial.freq_hz);
    EXPECT_EQ(b.trim.initial.speed_mps, a.trim.initial.speed_mps);
    EXPECT_EQ(b.vehicle.tail.arm_m, a.vehicle.tail.arm_m);
    EXPECT_EQ(b.design_point.freq_hz, a.design_point.freq_hz);
  }
}

TEST_F(ConfigSweepStudy, VehicleDefaultsThatFollowTheSweptKeysAreComparedByField) {
  // A magpie without wing.p3_aft_of_le_m: it defaults to half the root chord, so it follows a
  // swept wing.root_chord_m; trim.freq_hz follows operating_point.freq_hz. The analysis section
  // comes first, as the resolved study writes it.
  std::ifstream in(repo() / "studies/vehicles/efw_magpie.toml");
  std::string text, line;
  while (std::getline(in, line))
    if (line.rfind("p3_aft_of_le_m", 0) != 0) text += line + "\n";
  write("magpie_no_p3.toml", text);
  const Study s = loadStudyFile(
      write("s.toml", "kind = \"sweep\"\nvehicle = \"magpie_no_p3.toml\"\n" + std::string(R"(
[sweep]
run = "trim"
axes = [{ key = "wing.root_chord_m", values = [0.104, 0.12] }, { key = "operating_point.freq_hz", values = [6, 7] }]
)")));
  ASSERT_EQ(s.sweep().points.size(), 4u);
  EXPECT_EQ(s.sweep().points[3].vehicle.wing.p3_aft_of_le_m, 0.06);
  EXPECT_EQ(s.sweep().derived_keys,
            (std::vector<std::string>{"trim.freq_hz", "vehicle.wing.p3_aft_of_le_m"}));
  EXPECT_EQ(s.sweep().derived_keys, textualDerivedKeys(s));
  const std::string resolved = resolvedStudyToml(s);
  EXPECT_NE(resolved.find("# p3_aft_of_le_m: not fixed here"), std::string::npos);
}

TEST_F(ConfigSweepStudy, DerivedKeysAreThoseOfTheLineComparison) {
  // The committed sweeps and those of this file: the field comparison gives the list the line
  // comparison gave (written into study.resolved.toml: its bytes must not change).
  for (const char* file : {"studies/examples/trim_sweep_freq.toml",
                           "studies/paper/sweep_tail_arm_area.toml",
                           "studies/paper/placement_sweep_magpie.toml"}) {
    SCOPED_TRACE(file);
    const Study s = loadStudyFile(repo() / file);
    EXPECT_EQ(s.sweep().derived_keys, textualDerivedKeys(s));
  }
  const Study t =
      loadStudyFile(write("t.toml", "kind = \"sweep\"\n" + vehicle("efw_magpie.toml") + R"(
[sweep]
run = "simulate"
axes = [{ key = "operating_point.speed_mps", values = [8, 9] }, { key = "wing.semispan_m", values = [0.27, 0.3] }]
)"));
  EXPECT_EQ(t.sweep().derived_keys, textualDerivedKeys(t));
  EXPECT_EQ(t.sweep().derived_keys, (std::vector<std::string>{"simulate.speed_mps"}));
}

TEST_F(ConfigSweepStudy, ExamplesLoad) {
  const Study f = loadStudyFile(repo() / "studies/examples/trim_sweep_freq.toml");
  EXPECT_EQ(f.sweep().run, StudyKind::kTrim);
  ASSERT_EQ(f.sweep().points.size(), 7u);
  for (std::size_t i = 0; i < 7; ++i)
    EXPECT_EQ(f.sweep().points[i].trim.initial.freq_hz, 10.0 + static_cast<double>(i));
  const Study t = loadStudyFile(repo() / "studies/paper/sweep_tail_arm_area.toml");
  ASSERT_EQ(t.sweep().axes.size(), 2u);
  EXPECT_EQ(t.sweep().axes[0].key, "tail.arm_m");
  EXPECT_EQ(t.sweep().axes[1].key, "tail.area_m2");
  ASSERT_EQ(t.sweep().points.size(), 9u);
  EXPECT_EQ(t.sweep().points[1].vehicle.tail.area_m2, 0.007);
  EXPECT_EQ(t.sweep().points[3].vehicle.tail.arm_m, 0.12);
}

TEST_F(ConfigSweepStudy, ErrorsNameTheAxisAtFault) {
  const std::string head =
      "kind = \"sweep\"\n" + vehicle("efw_magpie.toml") + "[sweep]\nrun = \"trim\"\n";
  // line 5: axes; a bad value on its own line is named at that line
  const InputError v =
      errorOf(write("v.toml", head + "axes = [{ key = \"body.mass_kg\", values = [\n"
                                     "  0.1,\n  0.0,\n] }]\n"));
  EXPECT_EQ(v.key(), "sweep.axes[0].values");
  EXPECT_EQ(v.line(), 7);
  // Checked at the axis against body.mass_kg's entry of the field table, quoted as written.
  EXPECT_NE(std::string(v.what()).find("each value in [1e-5, 1000] (the range of body.mass_kg), "
                                       "got 0.0 at index 1"),
            std::string::npos)
      << v.what();

  const InputError k =
      errorOf(write("k.toml", head + "axes = [{ key = \"tail.arm\", values = 1 }]\n"));
  EXPECT_EQ(k.key(), "sweep.axes[0].key");
  EXPECT_EQ(k.line(), 5);
  EXPECT_NE(std::string(k.what()).find("did you mean 'arm_m'"), std::string::npos) << k.what();

  const InputError w =
      errorOf(write("w.toml", head + "axes = [{ key = \"vehicle.tail.arm_m\", values = 1 }]\n"));
  EXPECT_EQ(w.key(), "sweep.axes[0].key");
  EXPECT_NE(std::string(w.what()).find("without 'vehicle.'"), std::string::npos) << w.what();

  // A whole table is not a value to sweep.
  const InputError t = errorOf(write("t.toml", head + "axes = [{ key = \"tail\", values = 1 }]\n"));
  EXPECT_EQ(t.key(), "sweep.axes[0].values");
  EXPECT_NE(std::string(t.what()).find("expected a table"), std::string::npos) << t.what();

  // An integer key given a fraction.
  const InputError i =
      errorOf(write("i.toml", head + "axes = [{ key = \"wing.strips\", values = \"20:21:3\" }]\n"));
  EXPECT_EQ(i.key(), "sweep.axes[0].values");
  EXPECT_NE(std::string(i.what()).find("(wing.strips is an integer), got 20.5"), std::string::npos)
      << i.what();

  // [simulate.free] keys need a free [simulate].
  const InputError f = errorOf(write("f.toml", "kind = \"sweep\"\n" + vehicle("efw_magpie.toml") +
                                                   "[sweep]\nrun = \"simulate\"\naxes = [{ key = "
                                                   "\"simulate.free.bound_h_m\", values = 2 }]\n"));
  EXPECT_EQ(f.key(), "sweep.axes[0].key");

  // The base study's own faults are ordinary study-file errors.
  const InputError b =
      errorOf(write("b.toml", head + "axes = [{ key = \"trim.freq_hz\", values = 6 }]\n"
                                     "[trim]\nmax_iterations = 0\n"));
  EXPECT_EQ(b.key(), "trim.max_iterations");
  EXPECT_EQ(b.line(), 7);
}

TEST(ConfigSweepKeys, UnitsAndAnalysisKeys) {
  EXPECT_EQ(keyUnit("tail.arm_m"), "m");
  EXPECT_EQ(keyUnit("tail.area_m2"), "m^2");
  EXPECT_EQ(keyUnit("trim.freq_hz"), "Hz");
  EXPECT_EQ(keyUnit("trim.initial.speed_mps"), "m/s");
  EXPECT_EQ(keyUnit("simulate.theta_deg"), "deg");
  EXPECT_EQ(keyUnit("body.pitch_inertia_kgm2"), "kg m^2");
  EXPECT_EQ(keyUnit("body.mass_kg"), "kg");
  EXPECT_EQ(keyUnit("materials.LE1.youngs_modulus_gpa"), "GPa");
  EXPECT_EQ(keyUnit("air.density_kgpm3"), "kg/m^3");
  EXPECT_EQ(keyUnit("wing.strips"), "-");
  EXPECT_EQ(keyUnit("simulate.free.bound_Q_degps"), "deg/s");
  EXPECT_TRUE(isAnalysisKey("trim.freq_hz", StudyKind::kTrim));
  EXPECT_FALSE(isAnalysisKey("trim.freq_hz", StudyKind::kSimulate));
  EXPECT_FALSE(isAnalysisKey("tail.arm_m", StudyKind::kTrim));
  EXPECT_FALSE(isAnalysisKey("trimmer.x", StudyKind::kTrim));
}

}  // namespace
}  // namespace orni::studies
