// CSV tables (studies/runner/output/csv_table.hpp), against its header comment and
// docs/design.md 4: a names row, a units row, then the values; numbers in the shortest text that
// reads back to the same double (checked bit for bit with strtod, and against hand-written
// texts); text cells quoted per RFC 4180 when they hold a comma or a double quote, newlines
// refused; columns of unequal length refused without changing the table; row_stride keeps rows
// 0, n, 2n, ...; names and units are cells like any other (a comma in a unit must not add a
// column); CsvStreamWriter (csv_stream.hpp), which promises this format, writes the same bytes.
// The truth is the exact bytes.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "studies/runner/output/csv_stream.hpp"
#include "studies/runner/output/csv_table.hpp"

namespace orni::studies {
namespace {

namespace fs = std::filesystem;

std::uint64_t bitsOf(double v) {
  std::uint64_t b;
  std::memcpy(&b, &v, sizeof b);
  return b;
}

// The shortest "%.Ne" text (printf's correctly rounded digits) that reads back to v.
std::string shortestScientific(double v) {
  char buf[64];
  for (int precision = 0;; ++precision) {
    std::snprintf(buf, sizeof buf, "%.*e", precision, v);
    if (bitsOf(std::strtod(buf, nullptr)) == bitsOf(v)) return buf;
  }
}

TEST(OutputCsvTable, LineCellsReadBackWhatTextCellsWrite) {
  const std::vector<std::string> cells = {"plain", "a, b", "say \"hi\"", "", "N m"};
  std::string line;
  for (std::size_t i = 0; i < cells.size(); ++i) line += (i ? "," : "") + csvTextCell(cells[i]);
  EXPECT_EQ(csvLineCells(line), cells);
  EXPECT_EQ(csvLineCells(line + "\r"), cells);
}

TEST(OutputCsvTable, NamesRowUnitsRowThenValues) {
  CsvTable t;
  t.addColumn("speed_mps", "m/s", {8.0, 10.5});
  t.addTextColumn("status", "-", {"ok", ""});
  t.addColumn("FV_mean_N", "N", {-0.27854481485727844, 1e-300});
  EXPECT_EQ(t.rows(), 2u);
  EXPECT_EQ(t.toString(),
            "speed_mps,status,FV_mean_N\n"
            "m/s,-,N\n"
            "8,ok,-0.27854481485727844\n"
            "10.5,,1e-300\n");
}

TEST(OutputCsvTable, NumbersAreTheShortestRoundTripText) {
  const double inf = std::numeric_limits<double>::infinity();
  const std::vector<double> v = {0.1, 0.1 + 0.2, -0.0, 5e-324, 1.7976931348623157e308,
                                 100.0, 1e21, 1234567.0, 1e-5, inf, -inf};
  CsvTable t;
  t.addColumn("x", "-", v);
  t.addColumn("nan", "-", std::vector<double>(v.size(), std::nan("")));
  EXPECT_EQ(t.toString(),
            "x,nan\n-,-\n"
            "0.1,nan\n0.30000000000000004,nan\n0,nan\n5e-324,nan\n1.7976931348623157e+308,nan\n"
            "100,nan\n1e+21,nan\n1234567,nan\n1e-05,nan\n"
            "inf,nan\n-inf,nan\n");
}

TEST(OutputCsvTable, EveryFiniteDoubleReadsBackBitForBit) {
  constexpr int kSamples = 20000;
  std::mt19937_64 rng(20261202);  // seeded: the same samples every run
  std::vector<double> values;
  while (values.size() < kSamples) {
    const std::uint64_t b = rng();
    double v;
    std::memcpy(&v, &b, sizeof v);
    if (std::isfinite(v) && v != 0.0) values.push_back(v);  // +-0 are written "0" (tested above)
  }
  CsvTable t;
  t.addColumn("v", "-", values);
  const std::string text = t.toString();
  std::size_t pos = text.find('\n', text.find('\n') + 1) + 1;  // after the units row
  for (const double v : values) {
    const std::size_t end = text.find('\n', pos);
    ASSERT_NE(end, std::string::npos);
    const std::string cell = text.substr(pos, end - pos);
    char* stop = nullptr;
    const double back = std::strtod(cell.c_str(), &stop);
    ASSERT_EQ(*stop, '\0') << cell;
    ASSERT_EQ(bitsOf(back), bitsOf(v)) << cell;
    // Shortest: no longer than the shortest round-trip scientific text, and equal to it when
    // scientific. (Shortest counts characters: a large integer may be written in full,
    // 176321889879738023936, not 176321889879738020000, both 21 characters and both exact.)
    const std::string sci = shortestScientific(v);
    ASSERT_LE(cell.size(), sci.size()) << cell << " vs " << sci;
    if (cell.find('e') != std::string::npos) {
      ASSERT_EQ(cell, sci);
    }
    pos = end + 1;
  }
  EXPECT_EQ(pos, text.size());
}

TEST(OutputCsvTable, TextCellsAreQuotedPerRfc4180) {
  EXPECT_EQ(csvTextCell("plain text"), "plain text");
  EXPECT_EQ(csvTextCell(""), "");
  EXPECT_EQ(csvTextCell("a,b"), "\"a,b\"");
  EXPECT_EQ(csvTextCell("say \"hi\""), "\"say \"\"hi\"\"\"");
  EXPECT_EQ(csvTextCell("\""), "\"\"\"\"");
  EXPECT_EQ(csvTextCell(" 'single' ;tab\t"), " 'single' ;tab\t");  // no other character quoted
  CsvTable t;
  t.addTextColumn("message", "-", {"step 1e-3, too small", "\"quoted\""});
  EXPECT_EQ(t.toString(), "message\n-\n\"step 1e-3, too small\"\n\"\"\"quoted\"\"\"\n");
}

TEST(OutputCsvTable, NewlinesInTextCellsThrow) {
  for (const std::string bad : {"two\nlines", "carriage\rreturn", "\r\n"}) {
    try {
      csvTextCell(bad);
      FAIL() << "a newline was accepted";
    } catch (const std::logic_error& e) {
      EXPECT_STREQ(e.what(), "CsvTable: a cell contains a newline");
    }
    CsvTable t;
    EXPECT_THROW(t.addTextColumn("m", "-", {"ok", bad}), std::logic_error);
    EXPECT_EQ(t.toString(), "\n\n");  // nothing added
  }
}

TEST(OutputCsvTable, ColumnOfAnotherLengthThrowsAndLeavesTheTable) {
  CsvTable t;
  t.addColumn("a", "m", {1.0, 2.0});
  const std::string before = t.toString();
  try {
    t.addColumn("b", "s", {1.0});
    FAIL() << "a shorter column was accepted";
  } catch (const std::logic_error& e) {
    EXPECT_STREQ(e.what(), "CsvTable: column 'b' has a different length");
  }
  EXPECT_THROW(t.addTextColumn("c", "-", {"x", "y", "z"}), std::logic_error);
  EXPECT_EQ(t.toString(), before);
  EXPECT_EQ(t.rows(), 2u);
}

TEST(OutputCsvTable, RowStrideKeepsRowsZeroNTwoN) {
  CsvTable t;
  t.addColumn("i", "-", {0, 1, 2, 3, 4});
  EXPECT_EQ(t.toString(2), "i\n-\n0\n2\n4\n");
  EXPECT_EQ(t.toString(3), "i\n-\n0\n3\n");
  EXPECT_EQ(t.toString(9), "i\n-\n0\n");
  EXPECT_EQ(t.toString(1), "i\n-\n0\n1\n2\n3\n4\n");
  EXPECT_EQ(t.toString(0), t.toString(1));  // 0 is taken as 1
}

TEST(OutputCsvTable, EmptyTables) {
  CsvTable none;
  EXPECT_EQ(none.rows(), 0u);
  EXPECT_EQ(none.toString(), "\n\n");
  CsvTable no_rows;
  no_rows.addColumn("a", "m", {});
  no_rows.addTextColumn("b", "-", {});
  EXPECT_EQ(no_rows.rows(), 0u);
  EXPECT_EQ(no_rows.toString(), "a,b\nm,-\n");
}

TEST(OutputCsvTable, NamesAndUnitsAreQuotedLikeCells) {
  // A comma in a name or unit must not shift the header rows against the value rows.
  CsvTable t;
  t.addColumn("load", "N, positive up", {1.0});
  t.addTextColumn("label \"a\"", "-", {"x"});
  EXPECT_EQ(t.toString(), "load,\"label \"\"a\"\"\"\n\"N, positive up\",-\n1,x\n");
  EXPECT_THROW(t.addColumn("two\nlines", "-", {2.0}), std::logic_error);
  EXPECT_THROW(t.addColumn("a", "two\nlines", {2.0}), std::logic_error);
  EXPECT_EQ(t.toString(), "load,\"label \"\"a\"\"\"\n\"N, positive up\",-\n1,x\n");  // unchanged
}

TEST(OutputCsvTable, StreamWriterWritesTheTablesBytes) {
  // CsvStreamWriter (csv_stream.hpp) promises CsvTable's format: the same columns, rows and
  // stride give the same bytes, header cells with a comma or quote included.
  const std::vector<double> a = {0.1 + 0.2, -0.0, 1e-300, 4.0, 5.0};
  const std::vector<double> b = {1.0, 2.0, 3.0, std::nan(""), -1e21};
  CsvTable t;
  t.addColumn("t", "s", a);
  t.addColumn("M, about CG", "N \"m\"", b);
  const fs::path dir = fs::temp_directory_path() / ("orni_csv_stream_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  {
    CsvStreamWriter w(dir / "s.csv", {{"t", "s"}, {"M, about CG", "N \"m\""}}, 2);
    for (std::size_t r = 0; r < a.size(); ++r) {
      const double row[2] = {a[r], b[r]};
      w.row(row);
    }
    w.commit();
  }
  std::ifstream in(dir / "s.csv", std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  fs::remove_all(dir);
  EXPECT_EQ(text.str(), t.toString(2));
  EXPECT_EQ(text.str(), "t,\"M, about CG\"\ns,\"N \"\"m\"\"\"\n0.30000000000000004,1\n1e-300,3\n5,-1e+21\n");
}

}  // namespace
}  // namespace orni::studies
