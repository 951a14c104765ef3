// [trim] study sections (docs/design.md 5): the documented layout, defaults from the vehicle,
// bounds and tolerances, the resolved study round trip, and the study behind `ornithopter trim`.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "core/model/frames.hpp"
#include "studies/runner/config/input_error.hpp"
#include "studies/runner/config/study_file.hpp"

namespace orni::studies {
namespace {

namespace fs = std::filesystem;

fs::path repo() { return fs::path(ORNI_SOURCE_DIR); }

class TrimStudy : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() / (std::string("orni_trim_study_") + info->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path write(const std::string& name, const std::string& text) const {
    std::ofstream(dir_ / name) << text;
    return dir_ / name;
  }
  static std::string efw() {
    return "vehicle = \"" + (repo() / "studies/vehicles/efw_magpie.toml").generic_string() +
           "\"\n";
  }
  fs::path dir_;
};

TEST_F(TrimStudy, ArchitectureLayout) {
  const Study s = loadStudyFile(repo() / "studies" / "examples" / "efw_trim.toml");
  EXPECT_EQ(s.kind, StudyKind::kTrim);
  const TrimOptions& o = s.trim;
  EXPECT_DOUBLE_EQ(o.initial.freq_hz, 12.0);
  ASSERT_EQ(o.unknowns.size(), 3u);
  EXPECT_EQ(o.unknowns[0], TrimUnknown::kThetaMean);
  EXPECT_EQ(o.unknowns[1], TrimUnknown::kSpeed);
  EXPECT_EQ(o.unknowns[2], TrimUnknown::kTailAngle);
  EXPECT_DOUBLE_EQ(o.initial.theta_rad, 10.0 * kDegToRad);
  EXPECT_DOUBLE_EQ(o.initial.speed_mps, 10.0);
  EXPECT_DOUBLE_EQ(o.initial.tail_angle_rad, 10.0 * kDegToRad);
  std::string why;
  EXPECT_TRUE(o.IsValid(&why)) << why;
}

TEST_F(TrimStudy, DefaultsComeFromTheVehicle) {
  const Study s = loadStudyFile(write("t.toml", "kind = \"trim\"\n" + efw()));
  const TrimOptions& o = s.trim;
  const OperatingPoint& op = s.design_point;
  EXPECT_DOUBLE_EQ(o.initial.freq_hz, op.freq_hz);
  EXPECT_DOUBLE_EQ(o.initial.theta_rad, op.theta_rad);
  EXPECT_DOUBLE_EQ(o.initial.speed_mps, op.speed_mps);
  EXPECT_DOUBLE_EQ(o.initial.tail_angle_rad, op.tail_angle_rad);
  EXPECT_EQ(o.unknowns, TrimOptions().unknowns);
  EXPECT_DOUBLE_EQ(o.residual_tol, 1e-4);
  EXPECT_EQ(o.max_iterations, 50);
}

TEST_F(TrimStudy, BoundsTolerancesAndFrequencyUnknown) {
  const Study s = loadStudyFile(write("t.toml", "kind = \"trim\"\n" + efw() +
                                                    "[override]\nbody.mass_kg = 0.2\n"
                                                    "[trim]\n"
                                                    "freq_hz = 8.0\n"
                                                    "unknowns = [\"theta_mean_deg\", \"freq_hz\"]\n"
                                                    "bounds = { freq_hz = [2.0, 20.0], "
                                                    "theta_mean_deg = [0.0, 30.0] }\n"
                                                    "max_iterations = 20\n"
                                                    "residual_tol = 1e-5\n"
                                                    "rel_tol = 1e-7\n"
                                                    "max_cycles = 30\n"));
  const TrimOptions& o = s.trim;
  EXPECT_DOUBLE_EQ(s.vehicle.body.mass_kg, 0.2);
  ASSERT_EQ(o.unknowns.size(), 2u);
  EXPECT_EQ(o.unknowns[1], TrimUnknown::kFreq);
  EXPECT_DOUBLE_EQ(o.initial.freq_hz, 8.0);
  EXPECT_DOUBLE_EQ(o.bounds[trimIndex(TrimUnknown::kFreq)].lower, 2.0);
  EXPECT_DOUBLE_EQ(o.bounds[trimIndex(TrimUnknown::kFreq)].upper, 20.0);
  EXPECT_DOUBLE_EQ(o.bounds[trimIndex(TrimUnknown::kThetaMean)].upper, 30.0 * kDegToRad);
  EXPECT_DOUBLE_EQ(o.bounds[trimIndex(TrimUnknown::kSpeed)].upper, 30.0);  // default
  EXPECT_EQ(o.max_iterations, 20);
  EXPECT_DOUBLE_EQ(o.residual_tol, 1e-5);
  EXPECT_DOUBLE_EQ(o.simulation.rel_tol, 1e-7);
  EXPECT_EQ(o.simulation.cycles, 30);
  EXPECT_TRUE(o.simulation.stop_when_steady);
}

TEST_F(TrimStudy, ResolvedStudyRoundTrip) {
  const std::string text0 = "kind = \"trim\"\nname = \"rt\"\n" + efw() +
                            "[trim]\nfreq_hz = 7.5\n"
                            "unknowns = [\"speed_mps\", \"tail_angle_deg\", \"theta_mean_deg\"]\n"
                            "initial = { theta_mean_deg = 12.3 }\n"
                            "bounds = { tail_angle_deg = [-5.5, 33.3] }\n"
                            "derivative_cycles = 4\n";
  const Study a = loadStudyFile(write("t.toml", text0));
  const std::string text = resolvedStudyToml(a);
  EXPECT_NE(text.find("[trim]"), std::string::npos);
  const Study b = loadStudyFile(write("resolved.toml", text));
  EXPECT_EQ(resolvedStudyToml(b), text);  // fixed point
  const TrimOptions &x = a.trim, &y = b.trim;
  EXPECT_EQ(x.unknowns, y.unknowns);
  for (TrimUnknown u : kAllTrimUnknowns) {
    EXPECT_EQ(unknownValue(x.initial, u), unknownValue(y.initial, u)) << trimUnknownName(u);
    EXPECT_EQ(x.bounds[trimIndex(u)].lower, y.bounds[trimIndex(u)].lower);
    EXPECT_EQ(x.bounds[trimIndex(u)].upper, y.bounds[trimIndex(u)].upper);
  }
  EXPECT_EQ(x.max_iterations, y.max_iterations);
  EXPECT_EQ(x.residual_tol, y.residual_tol);
  EXPECT_EQ(x.function_tol, y.function_tol);
  EXPECT_EQ(x.simulation.rel_tol, y.simulation.rel_tol);
  EXPECT_EQ(x.simulation.steady_tol, y.simulation.steady_tol);
  EXPECT_EQ(x.simulation.cycles, y.simulation.cycles);
  EXPECT_EQ(y.derivative_cycles, 4);
  EXPECT_EQ(y.initial.theta_rad, 12.3 * kDegToRad);
}

TEST_F(TrimStudy, ErrorsNameTheKey) {
  struct Bad {
    std::string trim_section, key;
  };
  const Bad cases[] = {
      {"unknowns = [\"theta_mean_deg\", \"theta_mean_deg\"]\n", "trim.unknowns"},
      {"unknowns = []\n", "trim.unknowns"},
      {"unknowns = \"theta_mean_deg\"\n", "trim.unknowns"},
      {"bounds = { theta_mean_deg = [10.0, 10.01] }\ninitial = { theta_mean_deg = 10.0 }\n",
       "trim.bounds.theta_mean_deg"},
      {"bounds = { speed_mps = [0.0, 20.0] }\n", "trim.bounds.speed_mps"},
      {"bounds = { speed_mps = [11.0, 20.0] }\n", "trim.bounds.speed_mps"},  // op point 10.8
      {"bounds = { theta_mean_deg = [-10.0, 40.0, 50.0] }\n", "trim.bounds.theta_mean_deg"},
      {"freq_hz = 0.0\n", "trim.freq_hz"},
      {"residual_tol = 0.5\n", "trim.residual_tol"},
      {"max_iterations = 0\n", "trim.max_iterations"},
      {"unknowns = [\"freq_hz\"]\nfreq_hz = 50.0\n", "trim.freq_hz"},  // outside [1, 40]
  };
  for (const Bad& c : cases) {
    const fs::path f = write("bad.toml", "kind = \"trim\"\n" + efw() + "[trim]\n" + c.trim_section);
    try {
      (void)loadStudyFile(f);
      ADD_FAILURE() << "accepted: " << c.trim_section;
    } catch (const InputError& e) {
      EXPECT_EQ(e.key(), c.key) << e.what();
      EXPECT_GT(e.line(), 0) << e.what();
    }
  }
}

TEST_F(TrimStudy, StudyBehindTheTrimCommand) {
  const Study s = studyFromVehicle(repo() / "studies/vehicles/efw_magpie.toml", StudyKind::kTrim);
  EXPECT_EQ(s.kind, StudyKind::kTrim);
  EXPECT_DOUBLE_EQ(s.trim.initial.speed_mps, s.design_point.speed_mps);
  EXPECT_THROW(studyFromVehicle(repo() / "studies/vehicles/rfw_tunnel.toml", StudyKind::kTrim),
               InputError);
}

}  // namespace
}  // namespace orni::studies
