// The append-only journal file (studies/runner/output/journal_file.hpp), against the contract in
// its header comment: a new file holds the header line only; records appended survive a reopen
// with the same header and reach `keep` in file order; a torn last line and every refused line are
// dropped, counted and removed from the file before the next append; a different header (another
// run's fingerprint) with records is refused and kept, started afresh only with --fresh;
// reopening is atomic (a failure while reading leaves the old bytes and no temporary file); append
// after remove() throws; appends from several threads never interleave. The truth is the exact
// file bytes.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "studies/runner/output/journal_file.hpp"

namespace orni::studies {
namespace {

namespace fs = std::filesystem;

const std::string kHeader = "orni-journal v1 fingerprint=00000000deadbeef";

std::string readAll(const fs::path& f) {
  std::ifstream in(f, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

void writeRaw(const fs::path& f, const std::string& bytes) {
  fs::create_directories(f.parent_path());
  std::ofstream(f, std::ios::binary) << bytes;
}

// Names of every entry in `dir` (to see that no temporary file is left behind).
std::set<std::string> entries(const fs::path& dir) {
  std::set<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.insert(e.path().filename().string());
  return names;
}

class OutputJournalFileTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("orni_journal_file_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    file_ = dir_ / "journal.txt";
  }
  void TearDown() override { fs::remove_all(dir_); }
  // A keep() that records every line offered and keeps them all.
  JournalFile::KeepLine recordAll() {
    return [this](std::string_view line) {
      offered_.emplace_back(line);
      return true;
    };
  }
  fs::path dir_, file_;
  std::vector<std::string> offered_;
};

TEST_F(OutputJournalFileTest, NewFileHoldsTheHeaderOnly) {
  const fs::path nested = dir_ / "a" / "b" / "journal.txt";  // parent folders do not exist yet
  JournalFile::Reading r;
  r.existed = r.header_matched = true;
  r.rejected_lines = 99;
  JournalFile j(nested, kHeader, recordAll(), &r);
  EXPECT_FALSE(r.existed);
  EXPECT_FALSE(r.header_matched);
  EXPECT_EQ(r.rejected_lines, 0u);
  EXPECT_TRUE(offered_.empty());
  EXPECT_EQ(j.path(), nested);
  EXPECT_EQ(readAll(nested), kHeader + "\n");
  EXPECT_EQ(entries(nested.parent_path()), std::set<std::string>{"journal.txt"});
}

TEST_F(OutputJournalFileTest, AppendsSurviveAReopenInFileOrder) {
  {
    JournalFile j(file_, kHeader, recordAll(), nullptr);
    j.append("point 2 ok\n");
    j.append("point 0 ok\n");
    EXPECT_EQ(readAll(file_), kHeader + "\npoint 2 ok\npoint 0 ok\n");  // visible before close
  }
  JournalFile::Reading r;
  JournalFile j(file_, kHeader, recordAll(), &r);
  EXPECT_TRUE(r.existed);
  EXPECT_TRUE(r.header_matched);
  EXPECT_EQ(r.rejected_lines, 0u);
  EXPECT_EQ(offered_, (std::vector<std::string>{"point 2 ok", "point 0 ok"}));
  j.append("point 1 ok\n");
  EXPECT_EQ(readAll(file_), kHeader + "\npoint 2 ok\npoint 0 ok\npoint 1 ok\n");
}

TEST_F(OutputJournalFileTest, TornLastLineIsDroppedBeforeTheNextAppend) {
  writeRaw(file_, kHeader + "\npoint 0 ok\npoint 1 o");  // killed in the middle of a write
  JournalFile::Reading r;
  JournalFile j(file_, kHeader, recordAll(), &r);
  EXPECT_TRUE(r.header_matched);
  EXPECT_EQ(r.rejected_lines, 1u);
  EXPECT_EQ(offered_, std::vector<std::string>{"point 0 ok"});  // the fragment is never offered
  EXPECT_EQ(readAll(file_), kHeader + "\npoint 0 ok\n");
  j.append("point 1 ok\n");
  EXPECT_EQ(readAll(file_), kHeader + "\npoint 0 ok\npoint 1 ok\n");
}

TEST_F(OutputJournalFileTest, RefusedLinesAreCountedAndRemoved) {
  writeRaw(file_, kHeader + "\ngood 1\ncorrupt\n\ngood 2\n");
  JournalFile::Reading r;
  JournalFile j(file_, kHeader,
                [this](std::string_view line) {
                  offered_.emplace_back(line);
                  return line.substr(0, 5) == "good ";
                },
                &r);
  // Every complete line is offered, the empty one too, in file order.
  EXPECT_EQ(offered_, (std::vector<std::string>{"good 1", "corrupt", "", "good 2"}));
  EXPECT_EQ(r.rejected_lines, 2u);
  EXPECT_EQ(readAll(file_), kHeader + "\ngood 1\ngood 2\n");
}

// Issue 30, item 2: another run's finished records are refused, never deleted (the CLI exits 2
// naming the folder and --fresh); the file keeps its bytes and no temporary file is left.
TEST_F(OutputJournalFileTest, AnotherRunsJournalIsRefusedAndKept) {
  const std::string other = "orni-journal v1 fingerprint=0000000000000001\npoint 0 ok\n";
  writeRaw(file_, other);
  try {
    JournalFile j(file_, kHeader, recordAll(), nullptr);
    FAIL() << "another run's journal was opened";
  } catch (const ForeignJournalError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(dir_.string()), std::string::npos) << what;  // the folder
    EXPECT_NE(what.find("--fresh"), std::string::npos) << what;      // the way out
    EXPECT_NE(what.find("1 finished record"), std::string::npos) << what;
  }
  EXPECT_TRUE(offered_.empty());
  EXPECT_EQ(readAll(file_), other);
  EXPECT_EQ(entries(dir_), std::set<std::string>{"journal.txt"});
}

// With --fresh (setFreshRun) any journal there is discarded, a matching one too.
TEST_F(OutputJournalFileTest, AFreshRunDiscardsAnyJournal) {
  setFreshRun(true);
  for (const std::string& bytes :
       {std::string("orni-journal v1 fingerprint=0000000000000001\npoint 0 ok\n"),
        kHeader + "\npoint 0 ok\n"}) {
    writeRaw(file_, bytes);
    offered_.clear();
    JournalFile::Reading r;
    { JournalFile j(file_, kHeader, recordAll(), &r); }
    EXPECT_TRUE(r.existed);
    EXPECT_FALSE(r.header_matched);
    EXPECT_EQ(r.rejected_lines, 0u);  // records of a discarded journal are not "rejected"
    EXPECT_TRUE(offered_.empty());
    EXPECT_EQ(readAll(file_), kHeader + "\n");
  }
  setFreshRun(false);
}

TEST_F(OutputJournalFileTest, HeaderMustBeACompleteIdenticalLine) {
  // Without records after the first line there is nothing to lose: started afresh.
  const std::vector<std::string> empty_of_records = {
      "",               // empty file
      kHeader,          // torn header: no newline
      kHeader + " \n",  // trailing blank
  };
  for (const std::string& bytes : empty_of_records) {
    writeRaw(file_, bytes);
    offered_.clear();
    JournalFile::Reading r;
    { JournalFile j(file_, kHeader, recordAll(), &r); }
    EXPECT_TRUE(r.existed) << '[' << bytes << ']';
    EXPECT_FALSE(r.header_matched) << '[' << bytes << ']';
    EXPECT_TRUE(offered_.empty()) << '[' << bytes << ']';
    EXPECT_EQ(readAll(file_), kHeader + "\n") << '[' << bytes << ']';
  }
  // With records: another run's journal, refused and kept.
  const std::vector<std::string> foreign = {
      kHeader + "\r\nrec\n",  // CRLF line end
      kHeader.substr(1) + "\nrec\n",
  };
  for (const std::string& bytes : foreign) {
    writeRaw(file_, bytes);
    offered_.clear();
    EXPECT_THROW(JournalFile(file_, kHeader, recordAll(), nullptr), ForeignJournalError)
        << '[' << bytes << ']';
    EXPECT_TRUE(offered_.empty()) << '[' << bytes << ']';
    EXPECT_EQ(readAll(file_), bytes) << '[' << bytes << ']';
  }
}

TEST_F(OutputJournalFileTest, FailureWhileReopeningLeavesTheOldBytes) {
  const std::string before = kHeader + "\npoint 0 ok\npoint 1 ok\npoint 2 o";
  writeRaw(file_, before);
  int calls = 0;
  EXPECT_THROW(JournalFile(file_, kHeader,
                           [&calls](std::string_view) -> bool {
                             if (++calls == 2) throw std::runtime_error("parser failed");
                             return true;
                           },
                           nullptr),
               std::runtime_error);
  EXPECT_EQ(calls, 2);
  EXPECT_EQ(readAll(file_), before);                                  // not rewritten
  EXPECT_EQ(entries(dir_), std::set<std::string>{"journal.txt"});  // no temporary file left
}

TEST_F(OutputJournalFileTest, RemoveDeletesTheFileAndAppendThenThrows) {
  JournalFile j(file_, kHeader, recordAll(), nullptr);
  j.append("point 0 ok\n");
  j.remove();
  EXPECT_FALSE(fs::exists(file_));
  try {
    j.append("point 1 ok\n");
    FAIL() << "append after remove() did not throw";
  } catch (const std::logic_error& e) {
    EXPECT_EQ(std::string(e.what()), "journal " + file_.string() + ": append after remove");
  }
  EXPECT_FALSE(fs::exists(file_));  // the failed append did not re-create it
  EXPECT_NO_THROW(j.remove());      // a second remove() is harmless
}

TEST_F(OutputJournalFileTest, UnwritablePathThrowsNamingIt) {
  // The journal's path is an existing folder: the rewritten file cannot be put in its place.
  fs::create_directories(file_);
  try {
    JournalFile j(file_, kHeader, recordAll(), nullptr);
    FAIL() << "a journal over a folder was opened";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(file_.string()), std::string::npos) << e.what();
  }
  EXPECT_TRUE(fs::is_directory(file_));
  EXPECT_EQ(entries(dir_), std::set<std::string>{"journal.txt"});  // no temporary file left
  // Its parent is a regular file: the folder cannot be created.
  writeRaw(dir_ / "plain", "x");
  EXPECT_THROW(JournalFile(dir_ / "plain" / "journal.txt", kHeader, recordAll(), nullptr),
               std::runtime_error);
}

TEST_F(OutputJournalFileTest, ConcurrentAppendsNeverInterleave) {
  constexpr int kThreads = 4, kLinesPerThread = 300;
  const std::string padding(200, 'x');  // long lines make a torn interleaving likely if unlocked
  auto lineOf = [&padding](int t, int i) {
    return "t" + std::to_string(t) + " i" + std::to_string(i) + " " + padding;
  };
  {
    JournalFile j(file_, kHeader, recordAll(), nullptr);
    std::vector<std::thread> threads;
    for (int t = 0; t < kThreads; ++t)
      threads.emplace_back([&j, &lineOf, t] {
        for (int i = 0; i < kLinesPerThread; ++i) j.append(lineOf(t, i) + "\n");
      });
    for (std::thread& th : threads) th.join();
  }
  JournalFile::Reading r;
  JournalFile j(file_, kHeader, recordAll(), &r);
  EXPECT_EQ(r.rejected_lines, 0u);
  ASSERT_EQ(offered_.size(), static_cast<std::size_t>(kThreads * kLinesPerThread));
  std::vector<int> next(kThreads, 0);  // each thread's lines appear whole and in its own order
  for (const std::string& line : offered_) {
    const int t = line.at(1) - '0';
    ASSERT_TRUE(t >= 0 && t < kThreads) << line;
    ASSERT_EQ(line, lineOf(t, next[t])) << "interleaved or reordered";
    ++next[t];
  }
}

TEST(OutputJournalHex16, SixteenLowerCaseHexDigits) {
  EXPECT_EQ(hex16(0), "0000000000000000");
  EXPECT_EQ(hex16(0xDEADBEEFull), "00000000deadbeef");
  EXPECT_EQ(hex16(0x0123456789ABCDEFull), "0123456789abcdef");
  EXPECT_EQ(hex16(UINT64_MAX), "ffffffffffffffff");
}

}  // namespace
}  // namespace orni::studies
