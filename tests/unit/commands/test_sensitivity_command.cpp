// The sensitivity command (studies/runner/commands/sensitivity_command.hpp) on a cheap study: a
// frozen rigid-wing magpie (tests/data/sensitivity/magpie_rigid_fixture.toml), one parameter (the pitch inertia), no free-flight refinement of the
// trim, short free flights. The pitch inertia does not enter paper Eq. (4) nor the tethered run, so
// the trim point and the Fig. 9 ranges of the three points must be the same bytes while the free
// flight's pitch swing moves (falls with a larger inertia); the outputs are the same for any
// thread count and after a crash and resume without recomputing journaled points.
#include <gtest/gtest.h>

#include <charconv>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "studies/runner/commands/sensitivity_command.hpp"
#include "studies/runner/commands/trim_command.hpp"
#include "studies/runner/config/study_file.hpp"

namespace orni::studies {
namespace {

namespace fs = std::filesystem;

fs::path repo() { return fs::path(ORNI_SOURCE_DIR); }

std::string readAll(const fs::path& f) {
  std::ifstream in(f, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) out.push_back(l);
  return out;
}

/// The first `n` comma-separated cells of a CSV row (the message, last, may hold quoted commas).
std::vector<std::string> cells(const std::string& row, std::size_t n) {
  std::vector<std::string> c;
  std::size_t start = 0;
  while (c.size() < n) {
    const std::size_t comma = row.find(',', start);
    c.push_back(row.substr(start, comma == std::string::npos ? comma : comma - start));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return c;
}

/// The value of "key": number in a summary.json (first occurrence).
std::string jsonValue(const std::string& json, const std::string& key) {
  std::smatch m;
  EXPECT_TRUE(std::regex_search(json, m, std::regex("\"" + key + "\": ([-+0-9.eE]+)"))) << key;
  return m.empty() ? std::string() : std::string(m[1]);
}

double number(const std::string& text) {
  double v = 0.0;
  const auto r = std::from_chars(text.data(), text.data() + text.size(), v);
  EXPECT_TRUE(r.ec == std::errc() && r.ptr == text.data() + text.size()) << "'" << text << "'";
  return v;
}

class CommandsSensitivity : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() / (std::string("orni_sensitivity_") + info->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  static SensitivityRunOptions quiet(int threads) {
    SensitivityRunOptions o;
    o.threads = threads;
    o.progress = false;
    o.figures = false;
    return o;
  }
  /// The study; `sensitivity` = false gives the trim study of its base vehicle.
  Study study(int free_flight_cycles = 12, bool sensitivity = true) const {
    const fs::path f = dir_ / (sensitivity ? "inertia.toml" : "trim.toml");
    std::ofstream(f) << "kind = \"" << (sensitivity ? "sensitivity" : "trim") << "\"\nvehicle = \""
                     << (repo() / "tests/data/sensitivity/magpie_rigid_fixture.toml").generic_string()
                     << "\"\n"
                     << (sensitivity ? "[sensitivity]\nfree_flight_cycles = " +
                                           std::to_string(free_flight_cycles) +
                                           "\nparameters = [{ key = \"body.pitch_inertia_kgm2\", "
                                           "low = 1e-4, high = 3.2e-4 }]\n"
                                     : std::string())
                     << R"(
[trim]
freq_hz = 12.0
initial = { theta_mean_deg = 10.0, speed_mps = 10.0, tail_angle_deg = 10.0 }
refine_in_free_flight = false
)";
    return loadStudyFile(f);
  }
  fs::path dir_;
};

// Columns of sensitivity.csv (0-based): point, parameter, side, value, value_unit, status, then
// the results in the order of sensitivityResultColumns().
constexpr std::size_t kStatus = 5, kTheta = 6, kTail = 8, kPitchSwing = 10, kAltitude = 11,
                      kNormRatio = 13, kCFVMin = 14, kCMMax = 19, kHingeEq4 = 21, kThetaMin = 23,
                      kCells = 26;

TEST_F(CommandsSensitivity, InertiaMovesTheFreeFlightButNotTheTrim) {
  ASSERT_EQ(runSensitivityStudy(study(), dir_ / "out", quiet(2)), 0);
  const std::vector<std::string> rows = lines(readAll(dir_ / "out" / "sensitivity.csv"));
  ASSERT_EQ(rows.size(), 3u + 2u);
  std::vector<std::vector<std::string>> c;
  for (std::size_t i = 2; i < rows.size(); ++i) c.push_back(cells(rows[i], kCells));
  EXPECT_EQ(c[0][2], "base");
  EXPECT_EQ(c[1][1], "body.pitch_inertia_kgm2");
  EXPECT_EQ(c[1][2], "low");
  EXPECT_EQ(c[2][2], "high");
  EXPECT_EQ(c[1][4], "kg m^2");
  for (const auto& r : c) {
    ASSERT_EQ(r[kStatus], "ok") << r.back();
    for (std::size_t k : {kTheta, kTail, kCFVMin, kCMMax}) {
      EXPECT_EQ(r[k], c[0][k]) << k;  // no inertia in Eq. (4) nor in the tethered run
      EXPECT_FALSE(r[k].empty());
    }
  }
  // The forced pitch swing falls as the inertia rises (low < base = 3e-4 < high is not assumed:
  // only the two ends are compared).
  EXPECT_GT(number(c[1][kPitchSwing]), number(c[2][kPitchSwing]));

  const std::string tornado = readAll(dir_ / "out" / "tornado.csv");
  EXPECT_EQ(lines(tornado).size(), 14u + 2u);  // 14 predictions x 1 parameter
  EXPECT_NE(tornado.find("\ntheta_mean_deg,deg,1,1,body.pitch_inertia_kgm2,1,"), std::string::npos);
  const std::string summary = readAll(dir_ / "out" / "summary.json");
  for (const char* key : {"\"kind\": \"sensitivity\"", "\"status\": \"ok\"", "\"points\": 3",
                          "\"parameters\":", "\"base_inside_range\":", "\"predictions\":",
                          "\"pitch_swing_deg\":", "\"ranking\":", "\"delta_low\":"})
    EXPECT_NE(summary.find(key), std::string::npos) << key;
  // The base predictions by name under "base" (results/README.template.md reads base.<name>).
  const std::size_t base = summary.find("\"base\": {");
  ASSERT_NE(base, std::string::npos);
  EXPECT_EQ(jsonValue(summary.substr(base), "theta_mean_deg"), c[0][kTheta]);
  EXPECT_EQ(jsonValue(summary.substr(base), "pitch_swing_deg"), c[0][kPitchSwing]);
  EXPECT_FALSE(std::regex_search(readAll(dir_ / "out" / "sensitivity.csv"),
                                 std::regex("(^|,)-?(nan|inf)(,|$)", std::regex::icase)));
  EXPECT_FALSE(fs::exists(dir_ / "out" / kSensitivityJournalName));
}

TEST_F(CommandsSensitivity, BaseEqualsATrimStudyOfTheSameVehicle) {
  // At 60 free-flight cycles (the trim's own check) the base row is the trim study's summary:
  // the trim point, its free-flight check and the stage-1 hinge power, to the last digit.
  ASSERT_EQ(runSensitivityStudy(study(60), dir_ / "sens", quiet(2)), 0);
  ASSERT_EQ(runTrimStudy(study(60, false), dir_ / "trim"), 0);
  const std::vector<std::string> base =
      cells(lines(readAll(dir_ / "sens" / "sensitivity.csv"))[2], kCells);
  const std::string json = readAll(dir_ / "trim" / "summary.json");
  ASSERT_EQ(base[kStatus], "ok") << base.back();
  EXPECT_EQ(base[kTheta], jsonValue(json, "theta_mean_deg"));
  EXPECT_EQ(base[kTheta + 1], jsonValue(json, "speed_mps"));
  EXPECT_EQ(base[kTail], jsonValue(json, "tail_angle_deg"));
  EXPECT_EQ(base[kNormRatio], jsonValue(json, "norm_ratio_max"));
  EXPECT_EQ(base[kAltitude], jsonValue(json, "altitude_p2p_m"));
  EXPECT_EQ(base[kThetaMin], jsonValue(json, "theta_min_deg"));
  EXPECT_EQ(base[kThetaMin + 1], jsonValue(json, "theta_max_deg"));
  EXPECT_EQ(base[kHingeEq4], jsonValue(json, "hinge_power_W"));
  EXPECT_DOUBLE_EQ(number(base[kPitchSwing]),
                   number(base[kThetaMin + 1]) - number(base[kThetaMin]));
}

TEST_F(CommandsSensitivity, SameBytesForAnyThreadCountAndAfterAResume) {
  const Study s = study();
  ASSERT_EQ(runSensitivityStudy(s, dir_ / "j1", quiet(1)), 0);
  const std::string csv = readAll(dir_ / "j1" / "sensitivity.csv");

  // A run that dies after its second point is journaled (on_point follows the journal append).
  SensitivityRunOptions crash = quiet(2);
  std::size_t calls = 0;
  crash.on_point = [&](std::size_t, const SweepPointResult&) {
    if (++calls == 2) throw std::runtime_error("simulated crash");
  };
  const fs::path out = dir_ / "crashed";
  EXPECT_THROW(runSensitivityStudy(s, out, crash), std::runtime_error);
  ASSERT_TRUE(fs::exists(out / kSensitivityJournalName));
  EXPECT_FALSE(fs::exists(out / "sensitivity.csv"));

  std::size_t recomputed = 0;
  SensitivityRunOptions resume = quiet(2);
  resume.on_point = [&](std::size_t, const SweepPointResult&) { ++recomputed; };
  ASSERT_EQ(runSensitivityStudy(s, out, resume), 0);
  EXPECT_LE(recomputed, 1u);  // the two journaled points (or more, if a third finished) are kept
  EXPECT_EQ(readAll(out / "sensitivity.csv"), csv);
  EXPECT_EQ(readAll(out / "tornado.csv"), readAll(dir_ / "j1" / "tornado.csv"));
  EXPECT_FALSE(fs::exists(out / kSensitivityJournalName));
}

}  // namespace
}  // namespace orni::studies
