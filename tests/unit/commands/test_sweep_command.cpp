// The sweep command (studies/runner/commands/sweep_command.hpp): a sweep point equals a direct
// run of the same study, sweep.csv is byte-identical for any thread count, for the resolved study
// and after a resume from a truncated journal (finished points are not recomputed), and a point
// without a result is a row with its status and reason and empty value cells (never NaN).
#include <gtest/gtest.h>

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <regex>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "studies/runner/commands/simulate_command.hpp"
#include "studies/runner/commands/sweep_command.hpp"
#include "studies/runner/points/sweep_point.hpp"
#include "studies/runner/config/study_file.hpp"
#include "studies/runner/output/journal_file.hpp"
#include "studies/runner/output/point_journal.hpp"

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

double number(const std::string& text) {
  double v = 0.0;
  const auto r = std::from_chars(text.data(), text.data() + text.size(), v);
  EXPECT_TRUE(r.ec == std::errc() && r.ptr == text.data() + text.size()) << "'" << text << "'";
  return v;
}

/// The value of "key": number in a summary.json (first occurrence).
double jsonNumber(const std::string& json, const std::string& key) {
  std::smatch m;
  EXPECT_TRUE(std::regex_search(json, m, std::regex("\"" + key + "\": ([-+0-9.eE]+)"))) << key;
  return m.empty() ? 0.0 : number(m[1]);
}

class CommandsSweep : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() / (std::string("orni_sweep_") + info->name());
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
  static SweepRunOptions quiet(int threads) {
    SweepRunOptions o;
    o.threads = threads;
    o.progress = false;
    o.figures = false;
    return o;
  }
  /// The rigid RFW rig, tethered, 3 cycles, over pitch (an analysis key) x flapping amplitude (a
  /// vehicle key): 3 x 2 = 6 cheap points.
  Study rigSweep() const {
    return loadStudyFile(write("rig.toml", "kind = \"sweep\"\n" + vehicle("rfw_tunnel.toml") + R"(
[sweep]
run = "simulate"
axes = [
  { key = "simulate.theta_deg", values = [0, 10, 20] },
  { key = "kinematics.amplitude_deg", values = [25, 30] },
]

[simulate]
cycles = 3
)"));
  }
  fs::path dir_;
};

constexpr std::size_t kRigPoints = 6;

TEST_F(CommandsSweep, PointsEqualDirectRuns) {
  const Study sweep = rigSweep();
  ASSERT_EQ(runSweepStudy(sweep, dir_ / "sweep", quiet(2)), 0);
  const std::vector<std::string> rows = lines(readAll(dir_ / "sweep" / "sweep.csv"));
  ASSERT_EQ(rows.size(), kRigPoints + 2);
  EXPECT_EQ(rows[0].rfind("simulate.theta_deg,kinematics.amplitude_deg,status,FV_mean_N,FH_mean_N,"
                          "M_mean_Nm,power_aero_W,power_hinge_W,cycles_run,steady_cycle,"
                          "last_cycle_change,message",
                          0),
            0u);
  EXPECT_EQ(rows[1], "deg,deg,-,N,N,N m,W,W,-,-,-,-");

  // Two of the points as ordinary simulate studies, run by the simulate command.
  struct Direct {
    std::size_t row;
    const char* theta;
    const char* amplitude;
  };
  for (const Direct& d : {Direct{2 + 1, "0", "30"}, Direct{2 + 4, "20", "25"}}) {
    SCOPED_TRACE(rows[d.row]);
    const fs::path f = write(std::string("direct_") + d.theta + ".toml",
                             "kind = \"simulate\"\n" + vehicle("rfw_tunnel.toml") +
                                 "[override]\nkinematics.amplitude_deg = " + d.amplitude +
                                 "\n[simulate]\ntheta_deg = " + d.theta + "\ncycles = 3\n");
    const fs::path out = dir_ / (std::string("direct_") + d.theta);
    ASSERT_EQ(runSimulateStudy(loadStudyFile(f), out), 0);
    const std::string json = readAll(out / "summary.json");
    const std::vector<std::string> c = cells(rows[d.row], 9);
    EXPECT_EQ(c[0], d.theta);
    EXPECT_EQ(c[1], d.amplitude);
    EXPECT_EQ(
        c[2],
        std::string(json.find("\"status\": \"ok\"") != std::string::npos ? "ok" : "not_converged"));
    EXPECT_EQ(number(c[3]), jsonNumber(json, "FV_N"));
    EXPECT_EQ(number(c[4]), jsonNumber(json, "FH_N"));
    EXPECT_EQ(number(c[5]), jsonNumber(json, "M_Nm"));
    EXPECT_EQ(number(c[6]), jsonNumber(json, "power_W"));
    EXPECT_EQ(number(c[8]), jsonNumber(json, "cycles"));
  }
}

TEST_F(CommandsSweep, SameBytesForAnyThreadCountAndForTheResolvedStudy) {
  const Study sweep = rigSweep();
  for (int j : {1, 2, 3})
    ASSERT_EQ(runSweepStudy(sweep, dir_ / ("j" + std::to_string(j)), quiet(j)), 0);
  const std::string csv = readAll(dir_ / "j1" / "sweep.csv");
  EXPECT_EQ(csv, readAll(dir_ / "j2" / "sweep.csv"));
  EXPECT_EQ(csv, readAll(dir_ / "j3" / "sweep.csv"));
  EXPECT_EQ(readAll(dir_ / "j1" / "study.resolved.toml"),
            readAll(dir_ / "j2" / "study.resolved.toml"));
  EXPECT_FALSE(std::regex_search(csv, std::regex("(^|,)-?(nan|inf)(,|$)", std::regex::icase)));
  EXPECT_FALSE(fs::exists(dir_ / "j1" / kSweepJournalName));
  const std::string summary = readAll(dir_ / "j2" / "summary.json");
  for (const char* key : {"\"kind\": \"sweep\"", "\"run\": \"simulate\"", "\"mode\": \"tethered\"",
                          "\"points\": 6", "\"threads\": 2", "\"status\":", "\"message\":",
                          "\"wall_time_s\":", "\"version\":", "\"points_ok\":"})
    EXPECT_NE(summary.find(key), std::string::npos) << key;

  const Study again = loadStudyFile(dir_ / "j1" / "study.resolved.toml");
  ASSERT_EQ(runSweepStudy(again, dir_ / "again", quiet(2)), 0);
  EXPECT_EQ(readAll(dir_ / "again" / "sweep.csv"), csv);
  EXPECT_EQ(readAll(dir_ / "again" / "study.resolved.toml"),
            readAll(dir_ / "j1" / "study.resolved.toml"));
}

TEST_F(CommandsSweep, ResumesFromATruncatedJournalWithoutRecomputing) {
  const Study sweep = rigSweep();
  ASSERT_EQ(runSweepStudy(sweep, dir_ / "reference", quiet(1)), 0);
  const std::string reference = readAll(dir_ / "reference" / "sweep.csv");

  // A run that dies after its last point is journaled (on_point follows the journal append).
  const fs::path out = dir_ / "crashed";
  SweepRunOptions crash = quiet(2);
  std::size_t calls = 0;
  crash.on_point = [&](std::size_t, const SweepPointResult&) {
    if (++calls == kRigPoints) throw std::runtime_error("simulated crash");
  };
  EXPECT_THROW(runSweepStudy(sweep, out, crash), std::runtime_error);
  const fs::path journal = out / kSweepJournalName;
  ASSERT_TRUE(fs::exists(journal));
  EXPECT_FALSE(fs::exists(out / "sweep.csv"));
  const std::vector<std::string> all = lines(readAll(journal));
  ASSERT_EQ(all.size(), kRigPoints + 1);  // header + one line per point
  EXPECT_EQ(all[0].rfind("# ornithopter sweep journal v1 fingerprint=", 0), 0u);

  // Keep the header, two points and half of the next line (a write torn by a kill).
  const std::size_t kept = 2;
  std::set<std::size_t> finished;
  {
    std::ofstream cut(journal, std::ios::binary | std::ios::trunc);
    cut << all[0] << "\n";
    for (std::size_t i = 1; i <= kept; ++i) {
      cut << all[i] << "\n";
      std::size_t index = 0;
      std::string_view payload;
      ASSERT_TRUE(parsePointJournalRecord(all[i], kRigPoints, &index, &payload));
      finished.insert(index);
    }
    cut << all[kept + 1].substr(0, all[kept + 1].size() / 2);
  }
  SweepRunOptions resume = quiet(2);
  std::mutex m;
  std::set<std::size_t> computed;
  resume.on_point = [&](std::size_t index, const SweepPointResult&) {
    std::lock_guard<std::mutex> lock(m);
    computed.insert(index);
  };
  ASSERT_EQ(runSweepStudy(sweep, out, resume), 0);
  EXPECT_EQ(computed.size(), kRigPoints - kept);
  for (const std::size_t i : finished) EXPECT_EQ(computed.count(i), 0u) << "recomputed " << i;
  EXPECT_EQ(readAll(out / "sweep.csv"), reference);
  EXPECT_FALSE(fs::exists(journal));
  const std::string summary = readAll(out / "summary.json");
  EXPECT_NE(summary.find("\"points_resumed\": 2"), std::string::npos);
  EXPECT_NE(summary.find("\"points_computed\": 4"), std::string::npos);

  // A journal of another study (here: 4 cycles) is refused and kept, and discarded with --fresh
  // (issue 30, item 2).
  const Study other =
      loadStudyFile(write("other.toml", "kind = \"sweep\"\n" + vehicle("rfw_tunnel.toml") + R"(
[sweep]
run = "simulate"
axes = [{ key = "simulate.theta_deg", values = [0, 10, 20] }, { key = "kinematics.amplitude_deg", values = [25, 30] }]
[simulate]
cycles = 4
)"));
  SweepRunOptions die = quiet(1);
  die.on_point = [](std::size_t, const SweepPointResult&) { throw std::runtime_error("crash"); };
  EXPECT_THROW(runSweepStudy(other, out, die), std::runtime_error);
  const std::string others = readAll(journal);
  EXPECT_THROW(runSweepStudy(sweep, out, resume), ForeignJournalError);
  EXPECT_EQ(readAll(journal), others);
  computed.clear();
  setFreshRun(true);
  const int fresh_rc = runSweepStudy(sweep, out, resume);
  setFreshRun(false);
  ASSERT_EQ(fresh_rc, 0);
  EXPECT_EQ(computed.size(), kRigPoints);
  EXPECT_EQ(readAll(out / "sweep.csv"), reference);
}

TEST_F(CommandsSweep, PointsWithoutAResultHaveTheirStatusAndReasonAndEmptyCells) {
  // A frozen rigid-wing magpie (tests/data/sensitivity/magpie_rigid_fixture.toml: a contract
  // fixture that does not move with the paper vehicle) trims at 12 Hz; at 10 kg it cannot, within
  // 10 iterations. Eq. (4) only: the fixture's rigid-wing free flight at that trim does not settle
  // (the verdict column says "unbounded", which is all this contract test needs).
  const Study sweep = loadStudyFile(
      write("trim.toml", "kind = \"sweep\"\nvehicle = \"" +
                             (repo() / "tests/data/sensitivity/magpie_rigid_fixture.toml")
                                 .generic_string() +
                             "\"\n" + R"(
[sweep]
run = "trim"
axes = [{ key = "body.mass_kg", values = [0.118, 10.0] }]
[trim]
freq_hz = 12.0
max_iterations = 10
refine_in_free_flight = false
initial = { theta_mean_deg = 5.4, speed_mps = 12.3, tail_angle_deg = 8.4 }
)"));
  ASSERT_EQ(runSweepStudy(sweep, dir_, quiet(2)), 0);
  const std::string csv = readAll(dir_ / "sweep.csv");
  EXPECT_FALSE(std::regex_search(csv, std::regex("(^|,)-?(nan|inf)(,|$)", std::regex::icase)));
  const std::vector<std::string> rows = lines(csv);
  ASSERT_EQ(rows.size(), 4u);
  EXPECT_EQ(rows[0].rfind("body.mass_kg,status,theta_mean_deg,speed_mps,tail_angle_deg,freq_hz,"
                          "power_aero_W,",
                          0),
            0u);
  const std::vector<std::string> ok = cells(rows[2], 17);
  EXPECT_EQ(ok[1], "ok");
  EXPECT_NEAR(number(ok[2]), 5.44, 0.05);   // theta (the fixture's Eq. (4) trim)
  EXPECT_NEAR(number(ok[3]), 12.25, 0.05);  // U
  EXPECT_EQ(ok[5], "12");
  EXPECT_LT(std::abs(number(ok[11])), 1e-4);  // scaled residual
  EXPECT_FALSE(ok[14].empty());               // the free-flight verdict
  // 10 kg: status and reason, every value cell empty (19 of them).
  EXPECT_EQ(rows[3].rfind("10,not_converged,,,,,,,,,,,,,,,,,,,,\"", 0), 0u) << rows[3];
  EXPECT_NE(rows[3].find("tolerance"), std::string::npos);
  const std::string summary = readAll(dir_ / "summary.json");
  EXPECT_NE(summary.find("\"status\": \"not_converged\""), std::string::npos);
  EXPECT_NE(summary.find("\"points_ok\": 1"), std::string::npos);
  EXPECT_NE(summary.find("\"points_not_converged\": 1"), std::string::npos);
  EXPECT_NE(summary.find("\"points_bounded\":"), std::string::npos);
}

TEST(CommandsSweepPoint, JournalPayloadRoundTrips) {
  SweepPointResult r;
  r.status = "not_converged";
  r.cells = {"1.25", "", "bounded", "-3e-07"};
  r.message = "stalled, at a bound: \"tail\"";
  SweepPointResult back;
  ASSERT_TRUE(decodeSweepPoint(encodeSweepPoint(r), 4, &back));
  EXPECT_EQ(back.status, r.status);
  EXPECT_EQ(back.cells, r.cells);
  EXPECT_EQ(back.message, r.message);
  r.message = "stalled";  // a message may hold commas, so only a comma-free one shows this:
  EXPECT_FALSE(decodeSweepPoint(encodeSweepPoint(r), 5, &back));  // another column count
  EXPECT_FALSE(decodeSweepPoint("exploded,1,2,3,4,msg", 4, &back));
  EXPECT_FALSE(decodeSweepPoint("ok,1,2", 4, &back));
}

}  // namespace
}  // namespace orni::studies

namespace orni::studies {
namespace {

// Issue 14, defect 9: a run stopped while its figure is drawn (here: gnuplot fails) keeps the
// journal, and the same study into the same folder computes no point again.
TEST_F(CommandsSweep, JournalOutlivesAFailedFigure) {
  const Study sweep = rigSweep();
  SweepRunOptions with_figure = quiet(2);
  with_figure.figures = true;
  ::setenv("ORNI_GNUPLOT", "/bin/false", 1);
  EXPECT_THROW(runSweepStudy(sweep, dir_ / "out", with_figure), std::runtime_error);
  ::unsetenv("ORNI_GNUPLOT");
  EXPECT_TRUE(fs::exists(dir_ / "out" / kSweepJournalName));
  EXPECT_FALSE(fs::exists(dir_ / "out" / "sweep.png"));

  SweepRunOptions again = with_figure;
  std::size_t computed = 0;
  again.on_point = [&computed](std::size_t, const SweepPointResult&) { ++computed; };
  ASSERT_EQ(runSweepStudy(sweep, dir_ / "out", again), 0);
  EXPECT_EQ(computed, 0u);
  const std::string summary = readAll(dir_ / "out" / "summary.json");
  EXPECT_EQ(jsonNumber(summary, "points_computed"), 0.0);
  EXPECT_EQ(jsonNumber(summary, "points_resumed"), static_cast<double>(kRigPoints));
  EXPECT_TRUE(fs::exists(dir_ / "out" / "sweep.png"));
  EXPECT_FALSE(fs::exists(dir_ / "out" / kSweepJournalName));
}

}  // namespace
}  // namespace orni::studies
