// The aero-map journal (studies/runner/output/aeromap_journal.hpp): records round-trip exactly,
// torn or corrupt lines are never trusted, and reopening keeps only the valid records, in point
// order, of a journal with the same fingerprint.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "studies/runner/output/aeromap_journal.hpp"

namespace orni::studies {
namespace {

namespace fs = std::filesystem;

AeroMapPoint samplePoint() {
  AeroMapPoint p;
  p.status = SimulationStatus::kOk;
  p.message = "periodic steady state reached at cycle 3 (change 4.6e-04, 1e-3), \"quoted\"";
  p.cycles_run = 3;
  p.steady_state_cycle = 3;
  p.last_cycle_change = 4.598539070786259e-04;
  p.mean.FV_N = -0.27854481485727844;
  p.mean.FH_N = 0.1 + 0.2;
  p.mean.M_Nm = 1e-300;
  p.mean.power_aero_W = 10.53251939200516;
  p.mean.power_hinge_W = -0.0;
  return p;
}

std::string readAll(const fs::path& f) {
  std::ifstream in(f, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(OutputAeromapJournal, RecordsRoundTripExactly) {
  const AeroMapPoint p = samplePoint();
  const std::string line = journalRecord(17, p);
  ASSERT_EQ(line.back(), '\n');
  std::size_t index = 0;
  AeroMapPoint q;
  ASSERT_TRUE(parseJournalRecord(std::string_view(line).substr(0, line.size() - 1), 18, &index,
                                 &q));
  EXPECT_EQ(index, 17u);
  EXPECT_EQ(q.status, p.status);
  EXPECT_EQ(q.message, p.message);
  EXPECT_EQ(q.cycles_run, p.cycles_run);
  EXPECT_EQ(q.steady_state_cycle, p.steady_state_cycle);
  EXPECT_EQ(q.last_cycle_change, p.last_cycle_change);
  EXPECT_EQ(q.mean.FV_N, p.mean.FV_N);
  EXPECT_EQ(q.mean.FH_N, p.mean.FH_N);
  EXPECT_EQ(q.mean.M_Nm, p.mean.M_Nm);
  EXPECT_EQ(q.mean.power_aero_W, p.mean.power_aero_W);
  EXPECT_EQ(q.mean.power_hinge_W, 0.0);

  AeroMapPoint failed;
  failed.status = SimulationStatus::kDiverged;
  failed.mean.FV_N = std::numeric_limits<double>::quiet_NaN();
  failed.message = "non-finite loads";
  const std::string l2 = journalRecord(0, failed);
  ASSERT_TRUE(parseJournalRecord(std::string_view(l2).substr(0, l2.size() - 1), 1, &index, &q));
  EXPECT_EQ(q.status, SimulationStatus::kDiverged);
  EXPECT_TRUE(std::isnan(q.mean.FV_N));
  EXPECT_EQ(q.steady_state_cycle, -1);
}

TEST(OutputAeromapJournal, RejectsTornAndCorruptRecords) {
  const std::string full = journalRecord(5, samplePoint());
  const std::string_view line = std::string_view(full).substr(0, full.size() - 1);
  std::size_t index = 0;
  AeroMapPoint q;
  ASSERT_TRUE(parseJournalRecord(line, 6, &index, &q));
  for (std::size_t cut = 0; cut < line.size(); ++cut)
    EXPECT_FALSE(parseJournalRecord(line.substr(0, cut), 6, &index, &q)) << "cut at " << cut;
  std::string flipped(line);
  flipped[30] = flipped[30] == '1' ? '2' : '1';
  EXPECT_FALSE(parseJournalRecord(flipped, 6, &index, &q));
  EXPECT_FALSE(parseJournalRecord(line, 5, &index, &q));  // index 5 of a 5-point map
}

TEST(OutputAeromapJournal, ReopenKeepsOnlyTheValidRecordsInOrderOfTheSameStudy) {
  const fs::path dir = fs::temp_directory_path() / "orni_output_journal";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const fs::path file = dir / "aeromap.journal";
  {
    JournalResume r;
    AeroMapJournal j(file, 0x1234, 5, &r);
    EXPECT_FALSE(r.existed);
    j.append(0, samplePoint());
    EXPECT_THROW(j.append(2, samplePoint()), std::logic_error);  // points come in order
    j.append(1, samplePoint());
    EXPECT_EQ(j.records(), 2u);
  }
  const std::string good = readAll(file);
  {  // a corrupt line in the middle, a record out of order and a torn last record
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    const std::size_t header_end = good.find('\n') + 1;
    const std::size_t first_end = good.find('\n', header_end) + 1;
    const std::string third = journalRecord(2, samplePoint());
    out << good.substr(0, first_end) << "garbage line\n" << good.substr(first_end)
        << journalRecord(3, samplePoint()) << third.substr(0, third.size() / 2);
  }
  {
    JournalResume r;
    AeroMapJournal j(file, 0x1234, 5, &r);
    EXPECT_TRUE(r.existed);
    EXPECT_TRUE(r.fingerprint_matched);
    EXPECT_EQ(r.records, 2u);  // points 0 and 1; 3 follows a gap
    EXPECT_EQ(r.rejected_lines, 3u);
    j.append(2, samplePoint());
  }
  {  // the rewrite dropped the fragments, so the appended record is whole and trusted
    JournalResume r;
    AeroMapJournal j(file, 0x1234, 5, &r);
    EXPECT_EQ(r.records, 3u);
    EXPECT_EQ(r.rejected_lines, 0u);
    std::vector<std::size_t> seen;
    j.replay([&](std::size_t index, const AeroMapPoint& p) {
      seen.push_back(index);
      EXPECT_EQ(p.message, samplePoint().message);
      EXPECT_EQ(p.mean.FV_N, samplePoint().mean.FV_N);
    });
    EXPECT_EQ(seen, (std::vector<std::size_t>{0, 1, 2}));
  }
  // Another fingerprint (or point count): refused and kept (issue 30, item 2) ...
  const std::string finished = readAll(file);
  EXPECT_THROW(AeroMapJournal(file, 0x9999, 5, nullptr), ForeignJournalError);
  EXPECT_EQ(readAll(file), finished);
  {  // ... and discarded by a fresh run (--fresh)
    setFreshRun(true);
    JournalResume r;
    AeroMapJournal j(file, 0x9999, 5, &r);
    setFreshRun(false);
    EXPECT_TRUE(r.existed);
    EXPECT_FALSE(r.fingerprint_matched);
    EXPECT_EQ(r.records, 0u);
    j.remove();
  }
  EXPECT_FALSE(fs::exists(file));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace orni::studies
