// A run owns its output folder (studies/runner/output/run_outputs.hpp, issue 30 item 3): the
// first file a run writes into its locked folder removes an earlier run's outputs (this program's
// names only: never a journal, a subfolder or a user's file), a refused run (nothing written)
// removes nothing, `plot` takes only the figures of the summary's kind; and an interrupted run's
// summary says "interrupted" (interrupted_run.hpp, item 4). The truth is the folder's files.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>

#include "studies/runner/output/atomic_file.hpp"
#include "studies/runner/output/folder_lock.hpp"
#include "studies/runner/output/interrupted_run.hpp"
#include "studies/runner/output/run_outputs.hpp"

namespace orni::studies {
namespace {

namespace fs = std::filesystem;

std::string readAll(const fs::path& f) {
  std::ifstream in(f, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::set<std::string> entries(const fs::path& dir) {
  std::set<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.insert(e.path().filename().string());
  return names;
}

class OutputRunOutputsTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("orni_run_outputs_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_ / "sub");
    // An earlier tethered run and an aero map's leftovers, a journal, the user's files.
    for (const char* f : {"summary.json", "study.resolved.toml", "cycles.csv", "zmp.csv",
                          "loads.png", "loads.svg", "loads.gp", "aeromap.csv",
                          "aeromap_FV.gp", "tornado_theta_mean_deg.png", "aeromap.journal",
                          "notes.txt", "my.csv", "sub/cycles.csv"})
      std::ofstream(dir_ / f) << "x";
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

TEST_F(OutputRunOutputsTest, RemovesOnlyThisProgramsOutputNames) {
  EXPECT_EQ(removeEarlierRunOutputs(dir_), 10);
  EXPECT_EQ(entries(dir_),
            (std::set<std::string>{"aeromap.journal", "notes.txt", "my.csv", "sub"}));
  EXPECT_TRUE(fs::exists(dir_ / "sub" / "cycles.csv"));  // never inside a subfolder
}

TEST_F(OutputRunOutputsTest, TheRunsFirstFileClaimsTheFolderOnce) {
  {
    const OutputFolderLock lock(dir_);
    EXPECT_TRUE(fs::exists(dir_ / "cycles.csv"));  // locking alone removes nothing
    writeFileAtomic(dir_ / "summary.json", "{\"kind\": \"simulate\"}\n");
    EXPECT_FALSE(fs::exists(dir_ / "cycles.csv"));
    EXPECT_TRUE(fs::exists(dir_ / "aeromap.journal"));
    writeFileAtomic(dir_ / "loads.gp", "new");  // a later file of the run removes nothing more
    EXPECT_EQ(readAll(dir_ / "summary.json"), "{\"kind\": \"simulate\"}\n");
  }
  // Another lock for a redraw (`plot`) never claims.
  std::ofstream(dir_ / "zmp.csv") << "x";
  {
    const OutputFolderLock lock(dir_, FolderUse::kRedraw);
    writeFileAtomic(dir_ / "loads.png", "redrawn");
  }
  EXPECT_TRUE(fs::exists(dir_ / "zmp.csv"));
}

TEST_F(OutputRunOutputsTest, FiguresOfTheSummarysKind) {
  std::ofstream(dir_ / "summary.json")
      << "{\n  \"kind\": \"sensitivity\",\n  \"status\": \"ok\"\n}\n";
  EXPECT_EQ(summaryKind(dir_), "sensitivity");
  EXPECT_TRUE(isFigureOfKind("sensitivity", "tornado_theta_mean_deg"));
  EXPECT_TRUE(isFigureOfKind("sensitivity", "sensitivity_overview"));
  EXPECT_FALSE(isFigureOfKind("sensitivity", "loads"));
  EXPECT_TRUE(isFigureOfKind("simulate", "zmp"));
  EXPECT_FALSE(isFigureOfKind("simulate", "aeromap_FV"));
  EXPECT_TRUE(isFigureOfKind("", "anything"));  // no summary: every figure, as before
  EXPECT_EQ(summaryKind(dir_ / "sub"), "");
}

TEST_F(OutputRunOutputsTest, InterruptedRunSummary) {
  // A summary the run wrote (it was drawing its figures): status and message replaced, the rest
  // kept.
  std::ofstream(dir_ / "summary.json")
      << "{\n  \"kind\": \"optimize\",\n  \"status\": \"ok\",\n"
         "  \"message\": \"done, \\\"best\\\"\",\n  \"points\": 3\n}\n";
  markRunInterrupted(dir_, "optimize");
  const std::string s = readAll(dir_ / "summary.json");
  EXPECT_NE(s.find("\"status\": \"interrupted\""), std::string::npos) << s;
  EXPECT_EQ(s.find("\"ok\""), std::string::npos) << s;
  EXPECT_EQ(s.find("best"), std::string::npos) << s;
  EXPECT_NE(s.find("\"message\": \"interrupted by "), std::string::npos) << s;
  EXPECT_NE(s.find("\"points\": 3"), std::string::npos) << s;
  // No summary yet: one of its own.
  fs::remove(dir_ / "summary.json");
  markRunInterrupted(dir_, "aeromap");
  const std::string t = readAll(dir_ / "summary.json");
  EXPECT_NE(t.find("\"kind\": \"aeromap\""), std::string::npos) << t;
  EXPECT_NE(t.find("\"status\": \"interrupted\""), std::string::npos) << t;
}

}  // namespace
}  // namespace orni::studies
