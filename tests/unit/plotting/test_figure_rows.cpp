// How much of a long histories.csv a figure reads (studies/runner/plotting/figure_rows.hpp): short
// files whole (the committed figures' scripts do not change), long ones at most kFigureRows rows
// per curve from the first row shown, with a stride that walks through the flapping cycle.
#include <gtest/gtest.h>

#include <cstddef>
#include <string>

#include "studies/runner/plotting/figure_rows.hpp"

namespace orni::studies {
namespace {

std::size_t strideOf(const std::string& every) {  // " every K::R" -> K
  return std::stoul(every.substr(7, every.find("::") - 7));
}

TEST(PlottingFigureRows, ShortFilesAreReadWhole) {
  EXPECT_EQ(figureEvery(kFigureRows, 0, 100), "");
  EXPECT_EQ(figureEvery(3001, 600, 50), "");  // paper Figs. 6-8: 60 cycles x 50 rows
}

TEST(PlottingFigureRows, LongFilesReadAtMostKFigureRowsFromTheFirstShown) {
  // 10 000 RFW cycles, the last 3 shown: 300 rows from row 999 700.
  EXPECT_EQ(figureEvery(1000001, 999700, 100), " every 1::999700");
  // The whole of a 10 000-cycle flight: every 101st row (the cycle plus one).
  const std::string all = figureEvery(1000001, 0, 100);
  EXPECT_EQ(all, " every 101::0");
  for (const std::size_t rows : {10001u, 25000u, 200001u, 1000001u, 9999999u}) {
    for (const std::size_t per_cycle : {0u, 7u, 50u, 100u, 1000u}) {
      const std::string e = figureEvery(rows, 0, per_cycle);
      ASSERT_FALSE(e.empty());
      const std::size_t k = strideOf(e);
      EXPECT_LE((rows + k - 1) / k, kFigureRows) << rows << " rows, k " << k;
      // A stride above a quarter cycle advances one row per cycle: no aliasing, no stroboscope.
      if (per_cycle > 0 && 4 * k > per_cycle) {
        EXPECT_EQ(k % per_cycle, 1u % per_cycle) << k;
      }
    }
  }
}

TEST(PlottingFigureRows, HistoryRows) {
  EXPECT_EQ(historyRowOf(700, 1), 700u);
  EXPECT_EQ(historyRowOf(700, 3), 234u);  // rows are samples 0, 3, 6, ...: 702 is the first
  EXPECT_EQ(historyRowsPerCycle(100, 2), 50u);
  EXPECT_EQ(historyRowsPerCycle(100, 3), 0u);
}

}  // namespace
}  // namespace orni::studies
