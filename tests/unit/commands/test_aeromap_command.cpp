// The aeromap command (studies/runner/commands/aeromap_command.hpp): aeromap.csv is byte-identical
// for any thread count and after a resume from a torn journal (the journal's finished points are
// not recomputed), a foreign journal is discarded, and points without a result are rows with their
// status and reason and empty value cells (never NaN).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <mutex>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "studies/runner/commands/aeromap_command.hpp"
#include "studies/runner/config/study_file.hpp"
#include "studies/runner/output/aeromap_journal.hpp"
#include "studies/runner/output/journal_file.hpp"

namespace orni::studies {
namespace {

namespace fs = std::filesystem;

/// 3 speeds x 2 frequencies x 3 pitches = 18 points of the EFW.
Study smallMap() {
  return aeromapStudyFromVehicle(
      fs::path(ORNI_SOURCE_DIR) / "studies" / "vehicles" / "efw_magpie.toml",
      gridAxis(parseGridSpec("10:14:3")), gridAxis(parseGridSpec("10:16:2")),
      gridAxis(parseGridSpec("0:15:3")), std::nullopt);
}
constexpr std::size_t kPoints = 18;

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

class CommandsAeromap : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() / (std::string("orni_aeromap_") + info->name());
    fs::remove_all(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  static AeromapRunOptions quiet(int threads) {
    AeromapRunOptions o;
    o.threads = threads;
    o.progress = false;
    o.figures = false;
    return o;
  }
  fs::path dir_;
};

TEST_F(CommandsAeromap, SameBytesForAnyThreadCount) {
  const Study study = smallMap();
  ASSERT_EQ(runAeromapStudy(study, dir_ / "j1", quiet(1)), 0);
  ASSERT_EQ(runAeromapStudy(study, dir_ / "j2", quiet(2)), 0);
  ASSERT_EQ(runAeromapStudy(study, dir_ / "j3", quiet(3)), 0);
  const std::string csv = readAll(dir_ / "j1" / "aeromap.csv");
  EXPECT_EQ(lines(csv).size(), kPoints + 2);
  EXPECT_EQ(csv, readAll(dir_ / "j2" / "aeromap.csv"));
  EXPECT_EQ(csv, readAll(dir_ / "j3" / "aeromap.csv"));
  EXPECT_EQ(readAll(dir_ / "j1" / "study.resolved.toml"),
            readAll(dir_ / "j2" / "study.resolved.toml"));
  EXPECT_FALSE(fs::exists(dir_ / "j1" / kAeromapJournalName));
  const std::vector<std::string> rows = lines(csv);
  EXPECT_EQ(rows[0].rfind("speed_mps,freq_hz,theta_deg,tail_angle_deg,FV_mean_N,FH_mean_N,"
                          "M_mean_Nm,power_W,power_aero_W,status,",
                          0),
            0u);
  EXPECT_EQ(rows[1].rfind("m/s,Hz,deg,deg,N,N,N m,W,W,-,", 0), 0u);
  EXPECT_EQ(rows[2].rfind("10,10,0,11.85,", 0), 0u);   // first point
  EXPECT_EQ(rows[3].rfind("10,10,7.5,11.85,", 0), 0u);  // theta varies faster than f
  EXPECT_EQ(rows[5].rfind("10,16,0,11.85,", 0), 0u);
  EXPECT_EQ(rows.back().rfind("14,16,15,11.85,", 0), 0u);  // last point

  // The resolved study re-runs the same map.
  const Study again = loadStudyFile(dir_ / "j1" / "study.resolved.toml");
  ASSERT_EQ(runAeromapStudy(again, dir_ / "again", quiet(2)), 0);
  EXPECT_EQ(csv, readAll(dir_ / "again" / "aeromap.csv"));
  EXPECT_EQ(readAll(dir_ / "j1" / "study.resolved.toml"),
            readAll(dir_ / "again" / "study.resolved.toml"));
}

TEST_F(CommandsAeromap, ResumesFromATornJournalWithoutRecomputing) {
  const Study study = smallMap();
  ASSERT_EQ(runAeromapStudy(study, dir_ / "reference", quiet(2)), 0);
  const std::string reference = readAll(dir_ / "reference" / "aeromap.csv");

  // A run that dies after its last point is journaled (the callback follows the journal append),
  // so the journal holds every point.
  const fs::path out = dir_ / "crashed";
  AeromapRunOptions crash = quiet(2);
  std::size_t calls = 0;
  crash.on_point = [&](std::size_t, const AeroMapPoint&) {
    if (++calls == kPoints) throw std::runtime_error("simulated crash");
  };
  EXPECT_THROW(runAeromapStudy(study, out, crash), std::runtime_error);
  const fs::path journal = out / kAeromapJournalName;
  ASSERT_TRUE(fs::exists(journal));
  EXPECT_FALSE(fs::exists(out / "aeromap.csv"));
  const std::vector<std::string> all = lines(readAll(journal));
  ASSERT_EQ(all.size(), kPoints + 1);  // header + one line per point

  // Keep the header, half of the points and half of the next line (a torn write).
  const std::size_t kept = kPoints / 2;
  std::set<std::size_t> finished;
  {
    std::ofstream cut(journal, std::ios::binary | std::ios::trunc);
    cut << all[0] << "\n";
    for (std::size_t i = 1; i <= kept; ++i) {
      cut << all[i] << "\n";
      std::size_t index = 0;
      AeroMapPoint p;
      ASSERT_TRUE(parseJournalRecord(all[i], kPoints, &index, &p));
      finished.insert(index);
    }
    cut << all[kept + 1].substr(0, all[kept + 1].size() / 2);
  }
  ASSERT_EQ(finished.size(), kept);

  AeromapRunOptions resume = quiet(2);
  std::mutex m;
  std::set<std::size_t> computed;
  resume.on_point = [&](std::size_t index, const AeroMapPoint&) {
    std::lock_guard<std::mutex> lock(m);
    computed.insert(index);
  };
  ASSERT_EQ(runAeromapStudy(study, out, resume), 0);
  EXPECT_EQ(computed.size(), kPoints - kept);
  for (const std::size_t i : finished) EXPECT_EQ(computed.count(i), 0u) << "recomputed " << i;
  EXPECT_EQ(readAll(out / "aeromap.csv"), reference);
  EXPECT_FALSE(fs::exists(journal));
  const std::string summary = readAll(out / "summary.json");
  EXPECT_NE(summary.find("\"points_resumed\": " + std::to_string(kept)), std::string::npos);
  EXPECT_NE(summary.find("\"points_computed\": " + std::to_string(kPoints - kept)),
            std::string::npos);
}

// Issue 30, item 2: refused and kept (ForeignJournalError: exit 2 naming --fresh), then
// discarded with --fresh.
TEST_F(CommandsAeromap, JournalOfAnotherStudyIsRefusedThenDiscardedWhenFresh) {
  Study study = smallMap();
  const fs::path out = dir_ / "out";
  {  // a journal of the same grid with other options (another fingerprint)
    Study other = study;
    other.aeromap().options.steady_tol = 2e-3;
    AeromapRunOptions crash = quiet(1);
    crash.on_point = [](std::size_t, const AeroMapPoint&) {
      throw std::runtime_error("simulated crash");
    };
    EXPECT_THROW(runAeromapStudy(other, out, crash), std::runtime_error);
    ASSERT_TRUE(fs::exists(out / kAeromapJournalName));
  }
  AeromapRunOptions run = quiet(2);
  std::size_t computed = 0;
  run.on_point = [&](std::size_t, const AeroMapPoint&) { ++computed; };
  const std::string others = readAll(out / kAeromapJournalName);
  EXPECT_THROW(runAeromapStudy(study, out, run), ForeignJournalError);
  EXPECT_EQ(readAll(out / kAeromapJournalName), others);
  EXPECT_EQ(computed, 0u);
  setFreshRun(true);
  const int rc = runAeromapStudy(study, out, run);
  setFreshRun(false);
  ASSERT_EQ(rc, 0);
  EXPECT_EQ(computed, kPoints);
}

TEST_F(CommandsAeromap, PointsWithoutAResultHaveEmptyCellsAndAReason) {
  Study study = smallMap();
  study.aeromap().options.cycles = 1;  // one cycle cannot show a steady state
  ASSERT_EQ(runAeromapStudy(study, dir_, quiet(2)), 0);
  const std::string csv = readAll(dir_ / "aeromap.csv");
  EXPECT_EQ(csv.find("nan"), std::string::npos);
  const std::vector<std::string> rows = lines(csv);
  ASSERT_EQ(rows.size(), kPoints + 2);
  for (std::size_t r = 2; r < rows.size(); ++r) {
    SCOPED_TRACE(rows[r]);
    // speed, freq, theta, tail, then five empty value cells, the status, no steady cycle, 1 cycle
    EXPECT_NE(rows[r].find(",,,,,,not_converged,,1,,periodic steady state not reached"),
              std::string::npos);
  }
  const std::string summary = readAll(dir_ / "summary.json");
  EXPECT_NE(summary.find("\"status\": \"not_converged\""), std::string::npos);
  EXPECT_NE(summary.find("\"points_not_converged\": 18"), std::string::npos);
  EXPECT_NE(summary.find("\"points_ok\": 0"), std::string::npos);
}

}  // namespace
}  // namespace orni::studies
