// [trim] method and [trim.periodic] (studies/runner/config/trim_section.hpp): the periodic
// method's values and defaults, the resolved study round trip, and the errors (file, line, key).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "studies/runner/config/input_error.hpp"
#include "studies/runner/points/sweep_point.hpp"
#include "studies/runner/config/study_file.hpp"

namespace orni::studies {
namespace {

namespace fs = std::filesystem;

class ConfigTrimMethod : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() / (std::string("orni_trim_method_") + info->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  /// A trim study of the magpie with `body` after the vehicle line (line 3 on).
  fs::path study(const std::string& body, const std::string& kind = "trim") const {
    const fs::path file = dir_ / "s.toml";
    std::ofstream out(file);
    out << "kind = \"" << kind << "\"\nvehicle = \""
        << (fs::path(ORNI_SOURCE_DIR) / "studies" / "vehicles" / "efw_magpie.toml").generic_string()
        << "\"\n"
        << body;
    return file;
  }
  /// The InputError of loading `body`, or a failure.
  InputError errorOf(const std::string& body, const std::string& kind = "trim") const {
    try {
      loadStudyFile(study(body, kind));
    } catch (const InputError& e) {
      return e;
    }
    ADD_FAILURE() << "no error for:\n" << body;
    return InputError("", 0, "", "");
  }

  fs::path dir_;
};

TEST_F(ConfigTrimMethod, DefaultIsTwoStage) {
  const Study s = loadStudyFile(study("[trim]\nfreq_hz = 12.0\n"));
  EXPECT_EQ(s.trim.method, TrimMethod::kTwoStage);
  EXPECT_DOUBLE_EQ(s.trim.residual_tol, 1e-4);
  EXPECT_EQ(resolvedStudyToml(s).find("[trim.periodic]"), std::string::npos);
  EXPECT_NE(resolvedStudyToml(s).find("refine_cycles"), std::string::npos);
}

TEST_F(ConfigTrimMethod, PeriodicWithItsStartDefaultsAndTable) {
  const Study s = loadStudyFile(study(
      "[trim]\nfreq_hz = 12.0\nmethod = \"periodic\"\n[trim.periodic]\ncontrol = \"freq_hz\"\n"
      "residual_tol = 1e-9\nrel_tol = 2e-6\nmax_iterations = 30\nhistory_samples = 64\n"
      "floquet = false\nmultipliers = 0\n"));
  const TrimOptions& o = s.trim;
  EXPECT_EQ(o.method, TrimMethod::kPeriodic);
  // The Eq. (4) start's looser defaults (usePeriodicMethod).
  EXPECT_DOUBLE_EQ(o.residual_tol, 1e-3);
  EXPECT_DOUBLE_EQ(o.simulation.rel_tol, 1e-4);
  EXPECT_DOUBLE_EQ(o.simulation.steady_tol, 1e-3);
  EXPECT_EQ(o.periodic.control, PeriodicControl::kFrequency);
  EXPECT_DOUBLE_EQ(o.periodic.residual_tol, 1e-9);
  EXPECT_DOUBLE_EQ(o.periodic.rel_tol, 2e-6);
  EXPECT_EQ(o.periodic.max_iterations, 30);
  EXPECT_EQ(o.periodic.history_samples, 64);
  EXPECT_FALSE(o.periodic.floquet);
  EXPECT_EQ(o.periodic.multipliers, 0);
}

TEST_F(ConfigTrimMethod, StartTolerancesGivenWinOverThePeriodicDefaults) {
  const Study s = loadStudyFile(
      study("[trim]\nmethod = \"periodic\"\nresidual_tol = 1e-5\nrel_tol = 1e-6\n"));
  EXPECT_DOUBLE_EQ(s.trim.residual_tol, 1e-5);
  EXPECT_DOUBLE_EQ(s.trim.simulation.rel_tol, 1e-6);
  EXPECT_DOUBLE_EQ(s.trim.simulation.steady_tol, 1e-3);
}

TEST_F(ConfigTrimMethod, ResolvedPeriodicStudyIsAFixedPoint) {
  const Study s = loadStudyFile(study(
      "[trim]\nfreq_hz = 12.0\nmethod = \"periodic\"\n[trim.periodic]\nmultipliers = 4\n"));
  const std::string text = resolvedStudyToml(s);
  EXPECT_NE(text.find("method = \"periodic\""), std::string::npos);
  EXPECT_NE(text.find("[trim.periodic]"), std::string::npos);
  EXPECT_EQ(text.find("refine_cycles"), std::string::npos);
  const fs::path again = dir_ / "resolved.toml";
  {
    std::ofstream out(again);
    out << text;
  }
  const Study r = loadStudyFile(again);
  EXPECT_EQ(r.trim.method, TrimMethod::kPeriodic);
  EXPECT_EQ(r.trim.periodic.multipliers, 4);
  EXPECT_DOUBLE_EQ(r.trim.residual_tol, s.trim.residual_tol);
  EXPECT_EQ(resolvedStudyToml(r), text);
}

TEST_F(ConfigTrimMethod, BadValuesNameFileLineAndKey) {
  struct Case {
    std::string body, key;
    int line;
  };
  const Case cases[] = {
      {"[trim]\nmethod = \"periodc\"\n", "trim.method", 4},
      {"[trim]\nmethod = 2\n", "trim.method", 4},
      {"[trim]\nmethod = \"periodic\"\nrefine_cycles = 60\n", "trim.refine_cycles", 5},
      {"[trim]\nmethod = \"periodic\"\nrefine_in_free_flight = false\n",
       "trim.refine_in_free_flight", 5},
      {"[trim]\nfreq_hz = 12.0\n[trim.periodic]\nmultipliers = 3\n", "trim.periodic", 5},
      {"[trim]\nmethod = \"periodic\"\n[trim.periodic]\ncontrol = \"elevator\"\n",
       "trim.periodic.control", 6},
      {"[trim]\nmethod = \"periodic\"\n[trim.periodic]\nresidual_tol = 0.5\n",
       "trim.periodic.residual_tol", 6},
      {"[trim]\nmethod = \"periodic\"\n[trim.periodic]\nrel_tol = 0.1\n", "trim.periodic.rel_tol",
       6},
      {"[trim]\nmethod = \"periodic\"\n[trim.periodic]\nmultipliers = -1\n",
       "trim.periodic.multipliers", 6},
      {"[trim]\nmethod = \"periodic\"\n[trim.periodic]\nhistory_samples = 4\n",
       "trim.periodic.history_samples", 6},
      {"[trim]\nmethod = \"periodic\"\n[trim.periodic]\nmultiplier = 4\n",
       "trim.periodic.multiplier", 6},
  };
  for (const Case& c : cases) {
    const InputError e = errorOf(c.body);
    EXPECT_EQ(e.key(), c.key) << c.body << "\n" << e.what();
    EXPECT_EQ(e.line(), c.line) << c.body << "\n" << e.what();
    EXPECT_NE(std::string(e.what()).find("s.toml"), std::string::npos) << e.what();
  }
}

TEST_F(ConfigTrimMethod, ExampleStudyLoads) {
  const Study s =
      loadStudyFile(fs::path(ORNI_SOURCE_DIR) / "studies" / "examples" / "efw_periodic_trim.toml");
  EXPECT_EQ(s.trim.method, TrimMethod::kPeriodic);
  EXPECT_EQ(s.trim.periodic.multipliers, PeriodicTrimOptions{}.multipliers);
  EXPECT_DOUBLE_EQ(s.trim.periodic.rel_tol, PeriodicTrimOptions{}.rel_tol);
}

TEST_F(ConfigTrimMethod, SweepsRunPeriodicTrimsSensitivityStudiesRejectThem) {
  const Study sweep = loadStudyFile(study(
      "[trim]\nmethod = \"periodic\"\n[sweep]\nrun = \"trim\"\n"
      "axes = [{ key = \"trim.freq_hz\", values = [11, 12] }]\n",
      "sweep"));
  EXPECT_EQ(sweep.trim.method, TrimMethod::kPeriodic);
  const std::vector<SweepColumn> columns = sweepResultColumns(sweep);
  ASSERT_GE(columns.size(), 2u);
  EXPECT_EQ(columns[columns.size() - 2].name, "max_modulus");
  EXPECT_EQ(columns.back().name, "floquet_stable");
  const InputError sens = errorOf(
      "[trim]\nmethod = \"periodic\"\n[sensitivity]\n"
      "parameters = [{ key = \"body.mass_kg\", low = 0.1, high = 0.13 }]\n",
      "sensitivity");
  EXPECT_EQ(sens.key(), "trim.method") << sens.what();
}

}  // namespace
}  // namespace orni::studies
