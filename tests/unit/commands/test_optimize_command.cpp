// The optimize command (studies/runner/commands/optimize_command.hpp): history.csv,
// best_vehicle.toml and study.resolved.toml are byte-identical for any thread count and after a
// resume from an interrupted run's journal (journaled evaluations are replayed, not recomputed; a
// torn last line is dropped), a foreign journal is discarded, and the outputs follow the contract
// (summary keys, names and units rows, no NaN, a best vehicle that loads).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "studies/runner/commands/optimize_command.hpp"
#include "studies/runner/config/study_file.hpp"
#include "studies/runner/config/vehicle_file.hpp"
#include "studies/runner/output/journal_file.hpp"

namespace orni::studies {
namespace {

namespace fs = std::filesystem;

std::string readAll(const fs::path& f) {
  std::ifstream in(f, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::size_t lineCount(const std::string& text) {
  std::size_t n = 0;
  for (const char c : text) n += c == '\n';
  return n;
}

class CommandsOptimize : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() / (std::string("orni_optimize_") + info->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  /// The rigid magpie at 6 Hz (where it trims), tail area and arm, 3 starts of 5 evaluations.
  Study smallStudy(int starts = 3) const {
    const fs::path file = dir_ / "small.toml";
    std::ofstream out(file);
    out << "kind = \"optimize\"\nname = \"small\"\nvehicle = \""
        << (fs::path(ORNI_SOURCE_DIR) / "studies" / "vehicles" / "efw_magpie.toml")
               .generic_string()
        << "\"\n[override]\nwing.structure = \"rigid\"\n"
           "[optimize]\nfreq_hz = 12.0\nmax_evaluations = 5\nstarts = " << starts
        << "\nvariables = [\n  { name = \"tail.area_m2\", lower = 0.004, upper = 0.012 },\n"
           "  { name = \"tail.arm_m\", lower = 0.08, upper = 0.16 },\n]\n"
           "[optimize.trim]\nrefine_in_free_flight = false\n"
           "initial = { theta_mean_deg = 4.3, speed_mps = 13.6, tail_angle_deg = 8.4 }\n";
    out.close();
    return loadStudyFile(file);
  }
  static OptimizeRunOptions quiet(int threads) {
    OptimizeRunOptions o;
    o.threads = threads;
    o.progress = false;
    o.figures = false;
    return o;
  }
  fs::path dir_;
};

constexpr const char* kDeterministicFiles[] = {"history.csv", "best_vehicle.toml",
                                               "study.resolved.toml"};

TEST_F(CommandsOptimize, SameBytesForAnyThreadCount) {
  const Study study = smallStudy();
  ASSERT_EQ(runOptimizeStudy(study, dir_ / "j1", quiet(1)), 0);
  ASSERT_EQ(runOptimizeStudy(study, dir_ / "j2", quiet(2)), 0);
  for (const char* f : kDeterministicFiles) {
    SCOPED_TRACE(f);
    EXPECT_EQ(readAll(dir_ / "j1" / f), readAll(dir_ / "j2" / f));
  }
  EXPECT_FALSE(fs::exists(dir_ / "j1" / kOptimizeJournalName));
  const std::string csv = readAll(dir_ / "j1" / "history.csv");
  EXPECT_EQ(lineCount(csv), 2u + 15u);  // names, units, 3 starts x 5 evaluations
  EXPECT_EQ(csv.rfind("evaluation,start,start_evaluation,stage,tail.area_m2,tail.arm_m,objective,"
                      "feasible,failed,violation,g_trimmed,g_bounded,status,repeat_of,",
                      0),
            0u);
  EXPECT_NE(csv.find("\n-,-,-,-,m^2,m,W,-,-,-,-,-,-,start_evaluation,"), std::string::npos);
  EXPECT_EQ(csv.find("nan"), std::string::npos);

  const std::string summary = readAll(dir_ / "j1" / "summary.json");
  for (const char* key : {"\"kind\": \"optimize\"", "\"status\":", "\"message\":",
                          "\"wall_time_s\":", "\"version\":", "\"converged\":", "\"objective\":",
                          "\"baseline_objective\":", "\"evaluations\": 15", "\"design\":",
                          "\"tail.area_m2\":", "\"constraints_satisfied\":"})
    EXPECT_NE(summary.find(key), std::string::npos) << key;

  // The best design is a vehicle file whose operating point is its trim point.
  const VehicleDefinition best_file = loadVehicleFile(dir_ / "j1" / "best_vehicle.toml");
  const VehicleModel& best = best_file.model;
  EXPECT_EQ(best.name, "small_best");
  EXPECT_EQ(best_file.design_point.freq_hz, 12.0);
}

TEST_F(CommandsOptimize, ResumesAnInterruptedRunWithTheSameBytes) {
  const Study study = smallStudy(2);
  ASSERT_EQ(runOptimizeStudy(study, dir_ / "fresh", quiet(1)), 0);

  // Interrupt a run after 6 computed evaluations (a kill: the journal stays).
  OptimizeRunOptions o = quiet(2);
  int computed = 0;
  o.on_evaluation = [&computed](const opt::EvaluationRecord& r) {
    if (r.source == opt::EvaluationSource::kComputed && ++computed == 6)
      throw std::runtime_error("killed");
  };
  EXPECT_THROW(runOptimizeStudy(study, dir_ / "resumed", o), std::runtime_error);
  const fs::path journal = dir_ / "resumed" / kOptimizeJournalName;
  ASSERT_TRUE(fs::exists(journal));
  EXPECT_GE(lineCount(readAll(journal)), 1u + 6u);
  EXPECT_FALSE(fs::exists(dir_ / "resumed" / "history.csv"));
  {  // a torn last record (killed during a write)
    std::ofstream torn(journal, std::ios::app | std::ios::binary);
    torn << "0123456789abcdef 1,4,ok,0.005";
  }

  // The same study into the same folder: replays the journal, computes the rest.
  OptimizeRunOptions again = quiet(1);
  int recomputed = 0, replayed = 0;
  again.on_evaluation = [&](const opt::EvaluationRecord& r) {
    recomputed += r.source == opt::EvaluationSource::kComputed;
    replayed += r.source == opt::EvaluationSource::kReplayed;
  };
  ASSERT_EQ(runOptimizeStudy(study, dir_ / "resumed", again), 0);
  EXPECT_GE(replayed, 6);
  EXPECT_EQ(replayed + recomputed, 10);
  for (const char* f : kDeterministicFiles) {
    SCOPED_TRACE(f);
    EXPECT_EQ(readAll(dir_ / "fresh" / f), readAll(dir_ / "resumed" / f));
  }
  EXPECT_FALSE(fs::exists(journal));
  EXPECT_NE(readAll(dir_ / "resumed" / "summary.json").find("\"evaluations_resumed\": " +
                                                             std::to_string(replayed)),
            std::string::npos);
}

// Issue 30, item 2: another study's journal with records is refused and kept; --fresh discards.
TEST_F(CommandsOptimize, ForeignJournalIsRefusedThenDiscardedWhenFresh) {
  const Study study = smallStudy(1);
  fs::create_directories(dir_ / "out");
  const std::string foreign =
      "# ornithopter optimize journal v1 fingerprint=0000000000000000 variables=2 "
      "constraints=2 values=15\n0000000000000000 0,an evaluation of another study\n";
  {
    std::ofstream j(dir_ / "out" / kOptimizeJournalName);
    j << foreign;
  }
  OptimizeRunOptions o = quiet(1);
  int replayed = 0;
  o.on_evaluation = [&](const opt::EvaluationRecord& r) {
    replayed += r.source == opt::EvaluationSource::kReplayed;
  };
  EXPECT_THROW(runOptimizeStudy(study, dir_ / "out", o), ForeignJournalError);
  EXPECT_EQ(readAll(dir_ / "out" / kOptimizeJournalName), foreign);
  setFreshRun(true);
  const int rc = runOptimizeStudy(study, dir_ / "out", o);
  setFreshRun(false);
  ASSERT_EQ(rc, 0);
  EXPECT_EQ(replayed, 0);
  EXPECT_FALSE(fs::exists(dir_ / "out" / kOptimizeJournalName));
}

// Issue 14, defect 9: the journal is deleted only when every output, the figure included, is in
// place; a failed figure keeps it, and the same study into the same folder evaluates nothing
// again and draws the figure.
TEST_F(CommandsOptimize, JournalOutlivesAFailedFigure) {
  const Study study = smallStudy(1);
  OptimizeRunOptions with_figure = quiet(1);
  with_figure.figures = true;
  ::setenv("ORNI_GNUPLOT", "/bin/false", 1);
  const int rc = runOptimizeStudy(study, dir_ / "out", with_figure);
  ::unsetenv("ORNI_GNUPLOT");
  ASSERT_EQ(rc, 0);  // the figure is optional: its failure is reported, the run finished
  EXPECT_TRUE(fs::exists(dir_ / "out" / kOptimizeJournalName));
  EXPECT_FALSE(fs::exists(dir_ / "out" / "optimize_convergence.png"));

  OptimizeRunOptions again = with_figure;
  int computed = 0;
  again.on_evaluation = [&computed](const opt::EvaluationRecord& r) {
    computed += r.source == opt::EvaluationSource::kComputed;
  };
  ASSERT_EQ(runOptimizeStudy(study, dir_ / "out", again), 0);
  EXPECT_EQ(computed, 0);
  EXPECT_NE(readAll(dir_ / "out" / "summary.json").find("\"evaluations_computed\": 0"),
            std::string::npos);
  EXPECT_TRUE(fs::exists(dir_ / "out" / "optimize_convergence.png"));
  EXPECT_FALSE(fs::exists(dir_ / "out" / kOptimizeJournalName));
}

}  // namespace
}  // namespace orni::studies
