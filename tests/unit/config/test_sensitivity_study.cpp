// Sensitivity study files (kind = "sensitivity", config/sensitivity_study.hpp): the points are the
// base vehicle and each parameter at its low and high end, in file order, applied exactly like an
// [override] and nothing else changed; the base values come from the resolved vehicle; the
// resolved study re-runs the same points; errors are located at the parameter at fault (the files
// in tests/data/bad cover one per rule).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "core/model/frames.hpp"
#include "studies/runner/config/input_error.hpp"
#include "studies/runner/config/sensitivity_study.hpp"
#include "studies/runner/config/study_file.hpp"

namespace orni::studies {
namespace {

namespace fs = std::filesystem;

fs::path repo() { return fs::path(ORNI_SOURCE_DIR); }

class ConfigSensitivityStudy : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() / (std::string("orni_sensitivity_study_") + info->name());
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

double modulusGpa(const VehicleModel& v, const std::string& material) {
  const Material* m = v.findMaterial(material);
  EXPECT_NE(m, nullptr) << material;
  return m ? m->youngs_modulus_pa / 1e9 : 0.0;
}

TEST(ConfigSensitivityPoints, IndexAndIdAreInverse) {
  EXPECT_EQ(sensitivityPointCount(3), 7u);
  EXPECT_EQ(sensitivityPointIndex(0, SensitivitySide::kBase), 0u);
  EXPECT_EQ(sensitivityPointIndex(0, SensitivitySide::kLow), 1u);
  EXPECT_EQ(sensitivityPointIndex(0, SensitivitySide::kHigh), 2u);
  EXPECT_EQ(sensitivityPointIndex(2, SensitivitySide::kHigh), 6u);
  for (std::size_t i = 0; i < 7; ++i) {
    const SensitivityPointId id = sensitivityPointId(i);
    EXPECT_EQ(sensitivityPointIndex(id.parameter, id.side), i);
  }
  EXPECT_STREQ(toString(sensitivityPointId(0).side), "base");
  EXPECT_STREQ(toString(sensitivityPointId(3).side), "low");
  EXPECT_STREQ(toString(sensitivityPointId(4).side), "high");
}

TEST_F(ConfigSensitivityStudy, PointsMoveOneKeyAtATimeInFileOrder) {
  // "wing.fe.damping_ratio" sorts after "body.*": file order must win over TOML's table order.
  const Study s =
      loadStudyFile(write("s.toml", "kind = \"sensitivity\"\n" + vehicle("efw_magpie.toml") + R"(
[override]
tail.area_m2 = 0.008        # the base vehicle, kept at every point

[sensitivity]
parameters = [
  { key = "wing.fe.damping_ratio", low = 0.005, high = 0.05 },
  { key = "body.pitch_inertia_kgm2", low = 4e-5, high = 3.2e-4 },
  { key = "materials.CFRP_ROD.youngs_modulus_gpa", low = 100, high = 400 },
  { key = "wing.strips", low = 20, high = 30 },
]

[trim]
freq_hz = 12.0
max_iterations = 20
)"));
  EXPECT_EQ(s.kind, StudyKind::kSensitivity);
  EXPECT_EQ(s.name, "s");
  const SensitivitySettings& set = s.sensitivity();
  ASSERT_EQ(set.parameters.size(), 4u);
  EXPECT_EQ(set.parameters[0].key, "wing.fe.damping_ratio");
  EXPECT_EQ(set.parameters[1].key, "body.pitch_inertia_kgm2");
  EXPECT_EQ(set.free_flight_cycles, 60);  // the default: the trim's own check
  ASSERT_EQ(set.points.size(), 9u);

  const Study& base = set.points[0];
  EXPECT_EQ(base.kind, StudyKind::kTrim);
  EXPECT_EQ(base.vehicle.tail.area_m2, 0.008);
  // The parameters' base values are the base vehicle's, in file units.
  EXPECT_EQ(set.parameters[0].base, base.vehicle.wing.fe.damping_ratio);
  EXPECT_EQ(set.parameters[1].base, base.vehicle.body.pitch_inertia_kgm2);
  EXPECT_DOUBLE_EQ(set.parameters[2].base, modulusGpa(base.vehicle, "CFRP_ROD"));
  EXPECT_EQ(set.parameters[3].base, base.vehicle.wing.strip_count);

  for (std::size_t i = 0; i < set.points.size(); ++i) {
    SCOPED_TRACE(i);
    const Study& p = set.points[i];
    const SensitivityPointId id = sensitivityPointId(i);
    const bool low = id.side == SensitivitySide::kLow;
    auto expect = [&](std::size_t k, double lo, double hi, double base_value) {
      return i > 0 && id.parameter == k ? (low ? lo : hi) : base_value;
    };
    EXPECT_EQ(p.kind, StudyKind::kTrim);
    EXPECT_EQ(p.trim.initial.freq_hz, 12.0);
    EXPECT_EQ(p.trim.max_iterations, 20);
    EXPECT_EQ(p.vehicle.tail.area_m2, 0.008);
    EXPECT_EQ(p.vehicle.wing.fe.damping_ratio,
              expect(0, 0.005, 0.05, base.vehicle.wing.fe.damping_ratio));
    EXPECT_EQ(p.vehicle.body.pitch_inertia_kgm2,
              expect(1, 4e-5, 3.2e-4, base.vehicle.body.pitch_inertia_kgm2));
    EXPECT_DOUBLE_EQ(modulusGpa(p.vehicle, "CFRP_ROD"),
                     expect(2, 100, 400, modulusGpa(base.vehicle, "CFRP_ROD")));
    EXPECT_DOUBLE_EQ(modulusGpa(p.vehicle, "LE1"), modulusGpa(base.vehicle, "LE1"));
    EXPECT_EQ(p.vehicle.wing.strip_count, expect(3, 20, 30, base.vehicle.wing.strip_count));
  }
}

TEST_F(ConfigSensitivityStudy, ResolvedStudyReproducesThePoints) {
  const Study s =
      loadStudyFile(write("s.toml", "kind = \"sensitivity\"\n" + vehicle("efw_magpie.toml") + R"(
[sensitivity]
free_flight_cycles = 30

[[sensitivity.parameters]]
key = "aero.suction_efficiency"
low = 0.5
high = 1.0

[[sensitivity.parameters]]
key = "kinematics.hinge_x_m"
low = 0.01
high = 0.042

[sensitivity.free]
bound_theta_deg = 30.0
)"));
  ASSERT_EQ(s.sensitivity().points.size(), 5u);
  EXPECT_EQ(s.sensitivity().free_flight_cycles, 30);
  EXPECT_DOUBLE_EQ(s.sensitivity().free.bounds.theta_rad, 30.0 * kDegToRad);
  const std::string resolved = resolvedStudyToml(s);
  EXPECT_NE(resolved.find("kind = \"sensitivity\""), std::string::npos);
  EXPECT_NE(resolved.find("[[sensitivity.parameters]]"), std::string::npos);
  EXPECT_NE(resolved.find("[sensitivity.free]"), std::string::npos);
  const Study again = loadStudyFile(write("study.resolved.toml", resolved));
  EXPECT_EQ(again.name, s.name);
  EXPECT_EQ(resolvedStudyToml(again), resolved);  // a fixed point
  ASSERT_EQ(again.sensitivity().points.size(), 5u);
  for (std::size_t i = 0; i < 5; ++i) {
    SCOPED_TRACE(i);
    EXPECT_EQ(again.sensitivity().points[i].vehicle.aero.suction_efficiency,
              s.sensitivity().points[i].vehicle.aero.suction_efficiency);
    EXPECT_EQ(again.sensitivity().points[i].vehicle.flapping.hinge_x_B_m,
              s.sensitivity().points[i].vehicle.flapping.hinge_x_B_m);
  }
  EXPECT_EQ(again.sensitivity().points[3].vehicle.flapping.hinge_x_B_m, 0.01);
  EXPECT_DOUBLE_EQ(again.sensitivity().free.bounds.theta_rad, 30.0 * kDegToRad);
}

TEST_F(ConfigSensitivityStudy, ErrorsNameTheParameterAtFault) {
  const std::string head = "kind = \"sensitivity\"\n" + vehicle("efw_magpie.toml");
  {  // a value the vehicle rejects: at that end, with the loader's reason
    const InputError e = errorOf(write("a.toml", head + R"(
[sensitivity]
parameters = [
  { key = "body.pitch_inertia_kgm2", low = 4e-5, high = 3.2e-4 },
  { key = "body.pitch_inertia_kgm2x", low = 1, high = 2 },
]
)"));
    EXPECT_EQ(e.key(), "sensitivity.parameters[1].key");
    EXPECT_EQ(e.line(), 7);
    EXPECT_NE(std::string(e.what()).find("did you mean"), std::string::npos) << e.what();
  }
  {
    const InputError e = errorOf(write("b.toml", head + R"(
[sensitivity]
parameters = [{ key = "wing.fe.damping_ratio", low = 0.01, high = 1.0 }]
)"));
    EXPECT_EQ(e.key(), "sensitivity.parameters[0].high");
    EXPECT_NE(std::string(e.what()).find("damping_ratio"), std::string::npos) << e.what();
  }
  {  // study keys are not vehicle keys
    const InputError e = errorOf(write("c.toml", head + R"(
[sensitivity]
parameters = [{ key = "vehicle.body.mass_kg", low = 0.1, high = 0.12 }]
)"));
    EXPECT_EQ(e.key(), "sensitivity.parameters[0].key");
    EXPECT_NE(std::string(e.what()).find("without 'vehicle.'"), std::string::npos) << e.what();
  }
  {  // an empty array of parameters
    const InputError e = errorOf(write("d.toml", head + "[sensitivity]\nparameters = []\n"));
    EXPECT_EQ(e.key(), "sensitivity.parameters");
  }
  {  // a wrong kind of [trim] value is an ordinary study error
    const InputError e = errorOf(write("e.toml", head + R"(
[sensitivity]
parameters = [{ key = "body.drag_area_m2", low = 0.0, high = 1e-3 }]
[trim]
max_iterations = 0
)"));
    EXPECT_EQ(e.key(), "trim.max_iterations");
  }
}

TEST_F(ConfigSensitivityStudy, PaperStudyLoads) {
  const Study s = loadStudyFile(repo() / "studies/paper/sensitivity_magpie.toml");
  EXPECT_EQ(s.kind, StudyKind::kSensitivity);
  EXPECT_EQ(s.name, "sensitivity_magpie");
  EXPECT_GE(s.sensitivity().parameters.size(), 7u);
  EXPECT_EQ(s.sensitivity().points.size(), 2 * s.sensitivity().parameters.size() + 1);
  for (const SensitivityParameter& p : s.sensitivity().parameters) {
    SCOPED_TRACE(p.key);
    EXPECT_LT(p.low, p.high);
    EXPECT_TRUE(std::isfinite(p.base));
    if (p.key.find("youngs_modulus_gpa") != std::string::npos) {
      EXPECT_LT(p.high, 600.0);  // a carbon rod's modulus
    }
    if (p.key == "body.drag_area_m2") {
      EXPECT_LE(p.high, 1e-3);  // the study's high end: C_D 0.4 on 0.0025 m^2
    }
  }
  EXPECT_EQ(s.trim.initial.freq_hz, 12.0);
}

}  // namespace
}  // namespace orni::studies
