// One writer per output folder (studies/runner/output/folder_lock.hpp; issue 14, defect 6): a
// second lock of a held folder fails at once naming the holder's pid; a lock file nobody holds
// (a killed run's) is taken over; releasing removes the file; taking the lock clears the
// temporary files and drawing folders a killed writer left, and nothing else.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <optional>
#include <string>

#include "studies/runner/output/folder_lock.hpp"

namespace orni::studies {
namespace {

namespace fs = std::filesystem;

class OutputFolderLockTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("orni_folder_lock_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

TEST_F(OutputFolderLockTest, SecondWriterIsRefusedWithTheHoldersPid) {
  std::optional<OutputFolderLock> first(std::in_place, dir_ / "run");
  EXPECT_TRUE(fs::exists(dir_ / "run" / kFolderLockName));
  try {
    OutputFolderLock second(dir_ / "run");
    FAIL() << "a second lock of a held folder was granted";
  } catch (const FolderBusyError& e) {
    EXPECT_EQ(e.holderPid(), static_cast<long>(::getpid()));
    EXPECT_NE(std::string(e.what()).find("pid " + std::to_string(::getpid())), std::string::npos)
        << e.what();
  }
  first.reset();
  EXPECT_FALSE(fs::exists(dir_ / "run" / kFolderLockName));
  EXPECT_NO_THROW(OutputFolderLock again(dir_ / "run"));
}

TEST_F(OutputFolderLockTest, StaleLockFileIsTakenOver) {
  fs::create_directories(dir_);
  std::ofstream(dir_ / kFolderLockName) << "999999999\n";
  EXPECT_NO_THROW(OutputFolderLock lock(dir_));
  EXPECT_FALSE(fs::exists(dir_ / kFolderLockName));
}

TEST_F(OutputFolderLockTest, ClearsAKilledWritersLeftoversOnly) {
  fs::create_directories(dir_ / ".plot-loads-4242.3");
  std::ofstream(dir_ / ".plot-loads-4242.3" / "loads.png.tmp") << "partial";
  std::ofstream(dir_ / "summary.json.tmp.4242.7") << "partial";
  std::ofstream(dir_ / "summary.json") << "{}";
  std::ofstream(dir_ / "notes.tmp.txt") << "the user's";
  { OutputFolderLock lock(dir_); }
  EXPECT_FALSE(fs::exists(dir_ / ".plot-loads-4242.3"));
  EXPECT_FALSE(fs::exists(dir_ / "summary.json.tmp.4242.7"));
  EXPECT_TRUE(fs::exists(dir_ / "summary.json"));
  EXPECT_TRUE(fs::exists(dir_ / "notes.tmp.txt"));
}

}  // namespace
}  // namespace orni::studies
