// The [optimize] section of a study file (config/optimize_section.hpp): keys and defaults, the
// inline and the [[optimize.variables]] forms, groups, the trim of every design, the resolved study
// as a fixed point, and errors that name file, line and key.
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

class ConfigOptimizeSection : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() / (std::string("orni_optcfg_") + info->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  fs::path write(const std::string& name, const std::string& text) const {
    const fs::path file = dir_ / name;
    std::ofstream out(file);
    out << text;
    return file;
  }
  static std::string head() {
    return "kind = \"optimize\"\nvehicle = \"" +
           (fs::path(ORNI_SOURCE_DIR) / "studies" / "vehicles" / "efw_magpie.toml")
               .generic_string() +
           "\"\n";
  }
  fs::path dir_;
};

TEST_F(ConfigOptimizeSection, InlineVariablesAndDefaults) {
  const Study s = loadStudyFile(write("a.toml", head() + R"([optimize]
freq_hz = 6.0
variables = [
  { name = "tail.area_m2", lower = 0.004, upper = 0.012 },
  { name = "stif", fields = ["wing.members.STIF*.diameter_m"], lower = 2e-4, upper = 8e-4 },
]
)"));
  EXPECT_EQ(s.kind, StudyKind::kOptimize);
  const OptimizeSettings& o = s.optimize();
  EXPECT_EQ(o.optimizer.algorithm, opt::Algorithm::kCobyla);
  EXPECT_EQ(o.optimizer.max_evaluations, 100);
  EXPECT_EQ(o.optimizer.starts, 1);
  EXPECT_EQ(o.problem.objective, opt::DesignObjective::kPower);
  EXPECT_TRUE(o.problem.constraints.bounded);
  EXPECT_TRUE(o.problem.warm_start);
  EXPECT_EQ(o.problem.trim.initial.freq_hz, 6.0);
  ASSERT_EQ(o.space.size(), 2);
  EXPECT_EQ(o.space.variables[0].initial, 0.007);  // the vehicle's value
  EXPECT_EQ(o.space.variables[1].fields.size(), 4u);
  EXPECT_EQ(o.space.variables[1].initial, 4e-4);
}

TEST_F(ConfigOptimizeSection, TableFormEveryKeyAndResolvedFixedPoint) {
  const fs::path file = write("b.toml", head() + R"([override]
wing.structure = "flexible"
[optimize]
algorithm = "isres"
objective = "weighted"
max_evaluations = 40
starts = 3
seed = 7
freq_hz = 12.0
initial_step = 0.2
xtol = 1e-3
ftol_rel = 1e-5
constraint_tol = 1e-5
warm_start = false
polish_evaluations = 10
population = 12
[optimize.constraints]
bounded = false
pitch_amplitude_max_deg = 10.0
tip_deflection_max_m = 0.02
structural_mass_max_kg = 0.01
[optimize.weights]
power_per_W = 1.0
pitch_amplitude_per_deg = 0.1
[optimize.trim]
max_iterations = 20
initial = { theta_mean_deg = 9.2, speed_mps = 10.8, tail_angle_deg = 11.85 }
[[optimize.variables]]
name = "tail_arm"
fields = ["tail.arm_m"]
lower = 0.08
upper = 0.16
initial = 0.1
[[optimize.variables]]
name = "diag"
fields = ["wing.members.DIAG1.diameter_m", "wing.members.DIAG2.diameter_m"]
lower = 2e-4
upper = 8e-4
)");
  const Study s = loadStudyFile(file);
  const OptimizeSettings& o = s.optimize();
  EXPECT_EQ(o.optimizer.algorithm, opt::Algorithm::kIsres);
  EXPECT_EQ(o.optimizer.starts, 3);
  EXPECT_EQ(o.optimizer.seed, 7);
  EXPECT_EQ(o.optimizer.polish_evaluations, 10);
  EXPECT_EQ(o.optimizer.population, 12);
  EXPECT_EQ(o.problem.objective, opt::DesignObjective::kWeighted);
  EXPECT_EQ(o.problem.weights.pitch_amplitude_per_deg, 0.1);
  EXPECT_FALSE(o.problem.constraints.bounded);
  EXPECT_NEAR(o.problem.constraints.pitch_amplitude_max_rad, 10.0 * kDegToRad, 1e-15);
  EXPECT_EQ(o.problem.constraints.tip_deflection_max_m, 0.02);
  EXPECT_EQ(o.problem.trim.max_iterations, 20);
  EXPECT_EQ(o.problem.trim.initial.freq_hz, 12.0);
  EXPECT_NEAR(o.problem.trim.initial.theta_rad, 9.2 * kDegToRad, 1e-15);
  EXPECT_EQ(o.space.variables[0].initial, 0.1);
  EXPECT_EQ(o.space.variables[1].fields.size(), 2u);

  // study.resolved.toml is a study that loads into the same settings and writes itself again.
  const std::string text = resolvedStudyToml(s);
  EXPECT_NE(text.find("[[optimize.variables]]"), std::string::npos);
  EXPECT_NE(text.find("[optimize.trim.bounds]"), std::string::npos);
  const Study back = loadStudyFile(write("study.resolved.toml", text));
  EXPECT_EQ(resolvedStudyToml(back), text);
  EXPECT_EQ(back.optimize().space.variables[1].fields[1].name, "wing.members.DIAG2.diameter_m");
  EXPECT_EQ(back.optimize().problem.trim.max_iterations, 20);

  // The inline form and defaults round-trip too.
  const Study a = loadStudyFile(write("a.toml", head() + R"([optimize]
variables = [{ name = "tail.aspect_ratio", lower = 1.0, upper = 4.0 }]
)"));
  const std::string ta = resolvedStudyToml(a);
  EXPECT_EQ(resolvedStudyToml(loadStudyFile(write("a.resolved.toml", ta))), ta);
}

TEST_F(ConfigOptimizeSection, ErrorsNameFileLineAndKey) {
  struct Case {
    const char* body;
    const char* key;
    int line;
    const char* says;
  };
  const std::string v = "variables = [{ name = \"tail.area_m2\", lower = 0.004, upper = 0.012 }]\n";
  const Case cases[] = {
      {"", "optimize", 1, "missing required key 'optimize'"},
      {"[optimize]\n", "optimize.variables", 3, "missing required key"},
      {"[optimize]\nvariables = []\n", "optimize.variables", 4, "at least one design variable"},
      {"[optimize]\nvariables = [{ name = \"tail.span_m\", lower = 1, upper = 2 }]\n",
       "optimize.variables[0].name", 4, "unknown design field"},
      {"[optimize]\nvariables = [{ name = \"s\", fields = [\"wing.members.STIF9.diameter_m\"], "
       "lower = 1e-4, upper = 1e-3 }]\n",
       "optimize.variables[0].fields", 4, "no member named 'STIF9'"},
      {"[optimize]\nvariables = [{ name = \"tail.area_m2\", lower = 0.01, upper = 0.004 }]\n",
       "optimize.variables[0].upper", 4, "an upper bound > lower"},
      {"[optimize]\nvariables = [{ name = \"tail.area_m2\", lower = 0.0, upper = 0.01 }]\n",
       "optimize.variables[0].lower", 4,
       "expected a number in [1e-6, 100] (the range of tail.area_m2), got 0.0"},
      {"[optimize]\nvariables = [{ name = \"tail.area_m2\", lower = 0.008, upper = 0.01 }]\n",
       "optimize.variables[0].lower", 4, "containing the vehicle's value 0.007"},
      {"[optimize]\nvariables = [{ name = \"tail.area_m2\", lower = 0.004, upper = 0.01, "
       "initial = 0.02 }]\n",
       "optimize.variables[0].initial", 4, "an initial value inside [0.004, 0.01]"},
      {"[optimize]\nvariables = [{ name = \"a\", fields = [\"tail.area_m2\"], lower = 0.004, "
       "upper = 0.01 }, { name = \"b\", fields = [\"tail.area_m2\"], lower = 0.004, upper = 0.01 "
       "}]\n",
       "optimize.variables[1].fields", 4, "tail.area_m2 twice"},
      {"[optimize]\nvariables = [{ name = \"le\", fields = [\"wing.members.LE*.diameter_m\"], "
       "lower = 1e-4, upper = 3e-3 }]\n",
       "optimize.variables[0].initial", 4, "the vehicle's values of the group differ"},
      {"[optimize]\nalgorithm = \"nelder\"\n", "optimize.algorithm", 4, "\"cobyla\""},
      {"[optimize]\nalgorithm = \"bobyqa\"\n", "optimize.algorithm", 4, "bobyqa needs at least 2"},
      {"[optimize]\npopulation = 10\n", "optimize.population", 4, "only used by algorithm"},
      {"[optimize]\nmax_evaluations = 1\n", "optimize.max_evaluations", 4, "[2, 1000000]"},
      {"[optimize]\nmax_evals = 10\n", "optimize.max_evals", 4, "allowed keys: algorithm"},
      {"[optimize.weights]\npower_per_W = 2\n[optimize]\n", "optimize.weights", 3,
       "only used with objective = \"weighted\""},
      {"[override]\nwing.structure = \"rigid\"\n[optimize.constraints]\ntip_deflection_max_m = "
       "0.01\n[optimize]\n",
       "optimize.constraints.tip_deflection_max_m", 6, "0 (off) for a rigid wing"},
      {"[optimize.trim]\nfreq_hz = 10\n[optimize]\n", "optimize.trim.freq_hz", 4,
       "optimize.freq_hz"},
      {"[optimize.trim]\nbounds = { speed_mps = [12, 30] }\n[optimize]\n",
       "optimize.trim.bounds.speed_mps", 4, "containing the initial value 10.8"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.body);
    std::string text = head() + c.body;
    // Every case but the first two gets a variable unless it defines its own (appended at the
    // [optimize] table that closes the body).
    const std::string b = c.body;
    if (!b.empty() && b != "[optimize]\n" && b.find("variables") == std::string::npos) text += v;
    try {
      (void)loadStudyFile(write("bad.toml", text));
      ADD_FAILURE() << "accepted";
    } catch (const InputError& e) {
      const std::string what = e.what();
      EXPECT_EQ(e.key(), c.key) << what;
      EXPECT_EQ(e.line(), c.line) << what;
      EXPECT_NE(what.find(c.says), std::string::npos) << what;
      EXPECT_NE(what.find("bad.toml"), std::string::npos) << what;
    }
  }
}

TEST_F(ConfigOptimizeSection, SectionOnlyInOptimizeStudies) {
  const std::string efw =
      (fs::path(ORNI_SOURCE_DIR) / "studies" / "vehicles" / "efw_magpie.toml").generic_string();
  try {
    (void)loadStudyFile(write("t.toml", "kind = \"trim\"\nvehicle = \"" + efw +
                                            "\"\n[optimize]\nmax_evaluations = 3\n"));
    ADD_FAILURE() << "accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "optimize");
    EXPECT_EQ(e.line(), 3);
  }
  EXPECT_NO_THROW((void)loadStudyFile(fs::path(ORNI_SOURCE_DIR) / "studies" / "paper" /
                                      "optimize_magpie.toml"));
}

}  // namespace
}  // namespace orni::studies
