// The HTML report of a run (studies/runner/output/html_report.hpp) and the small JSON reader it
// reads summary.json with; the console switch of library calls (console.hpp) and the figures
// switch (plotting/gnuplot.hpp). The browser check of real reports is tests/support/
// check_reports.sh (cli.paper_results); here: the page's content from a folder's files.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "studies/runner/output/console.hpp"
#include "studies/runner/output/html_report.hpp"
#include "studies/runner/output/json_reader.hpp"
#include "studies/runner/plotting/gnuplot.hpp"

namespace orni::studies {
namespace {

namespace fs = std::filesystem;

std::string readAll(const fs::path& f) {
  std::ifstream in(f, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

void writeText(const fs::path& f, const std::string& text) { std::ofstream(f) << text; }

class HtmlReportTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("orni_html_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_ / "run");
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

TEST(JsonReader, ReadsWhatTheWriterWrites) {
  const JsonValue v = parseJson(
      R"({"kind": "trim", "n": -1.5e-3, "ok": true, "none": null, "list": [1, "a\"b", [2]],)"
      R"( "nested": {"x_m": 2}, "u": "\u00e9\ud83d\ude00"})");
  ASSERT_EQ(v.type, JsonValue::Type::kObject);
  EXPECT_EQ(v.members.front().first, "kind");  // file order kept
  EXPECT_EQ(v.find("n")->text, "-1.5e-3");      // numbers keep their text
  EXPECT_TRUE(v.find("ok")->boolean);
  EXPECT_EQ(v.find("none")->type, JsonValue::Type::kNull);
  EXPECT_EQ(v.find("list")->items[1].text, "a\"b");
  EXPECT_EQ(v.find("nested")->find("x_m")->text, "2");
  EXPECT_EQ(v.find("u")->text, "\xc3\xa9\xf0\x9f\x98\x80");  // UTF-8, surrogate pair joined
  EXPECT_EQ(v.find("missing"), nullptr);
}

TEST(JsonReader, BadTextThrowsWithTheOffset) {
  for (const char* bad : {"{", "{\"a\" 1}", "[1,]", "\"open", "{} x", "-", "[1 2]"}) {
    try {
      (void)parseJson(bad);
      ADD_FAILURE() << "accepted: " << bad;
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find("at byte"), std::string::npos) << e.what();
    }
  }
  std::string deep(1000, '[');
  EXPECT_THROW((void)parseJson(deep), std::runtime_error);  // no stack overflow
}

TEST_F(HtmlReportTest, ShowsStatusNumbersWithUnitsFiguresAndFiles) {
  const fs::path run = dir_ / "run";
  writeText(run / "summary.json",
            R"({"kind": "trim", "status": "not_converged", "message": "a <b> & c",)"
            R"( "converged": false, "theta_mean_deg": 9.2123456789, "mean": {"FV_N": 1.5}})");
  writeText(run / "study.resolved.toml", "kind = \"trim\"\nname = \"my_trim\"\n[trim]\n");
  writeText(run / "trim_iterations.csv", "a\n-\n1\n");
  writeText(run / "trim_convergence.gp", "plot 1\n");
  writeText(run / "trim_convergence.png", "png");
  writeText(run / "periodic_orbit.gp", "plot 1\n");  // a script without its figure
  writeText(run / ".ornithopter.lock", "");            // hidden: not listed
  writeRunReport(run);
  const std::string page = readAll(run / "index.html");
  EXPECT_NE(page.find("<h1>my_trim</h1>"), std::string::npos);  // the study's name
  EXPECT_NE(page.find("status bad\">no<"), std::string::npos) << "converged: no";
  EXPECT_NE(page.find("a &lt;b&gt; &amp; c"), std::string::npos);  // escaped
  EXPECT_EQ(page.find("<b>"), std::string::npos);
  EXPECT_NE(page.find("title=\"9.2123456789\">9.21235</td><td>deg</td>"), std::string::npos);
  EXPECT_NE(page.find("FV_N</td><td class=\"num\" title=\"1.5\">1.5</td><td>N</td>"),
            std::string::npos);
  EXPECT_NE(page.find("<img src=\"trim_convergence.png\""), std::string::npos);
  EXPECT_NE(page.find("href=\"periodic_orbit.gp\""), std::string::npos);  // not drawn, listed
  EXPECT_NE(page.find("href=\"trim_iterations.csv\""), std::string::npos);
  EXPECT_NE(page.find("href=\"study.resolved.toml\""), std::string::npos);
  EXPECT_EQ(page.find("ornithopter.lock"), std::string::npos);
  EXPECT_EQ(page.find("http"), std::string::npos) << "self-contained: no network address";
  EXPECT_EQ(page.find("<script"), std::string::npos);
  // The same files give the same bytes.
  writeRunReport(run);
  EXPECT_EQ(readAll(run / "index.html"), page);
}

TEST_F(HtmlReportTest, SetPageLinksEachRunWithItsStatus) {
  const fs::path run = dir_ / "run";
  writeText(run / "summary.json", R"({"kind": "simulate", "status": "ok", "message": "fine"})");
  writeRunReport(run);
  fs::create_directories(dir_ / "unfinished");
  writeSetReport(dir_, {run, dir_ / "unfinished"});
  const std::string page = readAll(dir_ / "index.html");
  EXPECT_NE(page.find("href=\"run/index.html\""), std::string::npos);
  EXPECT_NE(page.find("status good\">ok<"), std::string::npos);
  EXPECT_NE(page.find("no summary.json"), std::string::npos);
  EXPECT_EQ(page.find("unfinished/index.html"), std::string::npos);  // no report to link
}

TEST_F(HtmlReportTest, NoSummaryIsAnError) {
  EXPECT_THROW(writeRunReport(dir_ / "run"), std::runtime_error);
  writeText(dir_ / "run" / "summary.json", "{\"kind\": ");
  EXPECT_THROW(writeRunReport(dir_ / "run"), std::runtime_error);
}

TEST_F(HtmlReportTest, FiguresOffWritesTheScriptOnlyAndMissingGnuplotIsANote) {
  const fs::path run = dir_ / "run";
  {
    const FiguresScope off(false);
    drawFigure(run, "fig", "plot x");
    EXPECT_TRUE(fs::exists(run / "fig.gp"));
    EXPECT_FALSE(fs::exists(run / "fig.png"));
    const FiguresScope on(true);  // cannot turn them back on inside
    EXPECT_FALSE(figuresWanted());
  }
  EXPECT_TRUE(figuresWanted());
  ::setenv("ORNI_GNUPLOT", (dir_ / "no-such-gnuplot").c_str(), 1);
  EXPECT_FALSE(gnuplotAvailable());
  EXPECT_NO_THROW(drawFigure(run, "fig2", "plot x"));  // skipped with a note, not an error
  EXPECT_TRUE(fs::exists(run / "fig2.gp"));
  EXPECT_FALSE(fs::exists(run / "fig2.png"));
  ::setenv("ORNI_GNUPLOT", "sh", 1);  // found on PATH
  EXPECT_TRUE(gnuplotAvailable());
  ::unsetenv("ORNI_GNUPLOT");
}

TEST(Console, QuietDiscardsEverything) {
  EXPECT_FALSE(consoleQuiet());
  setConsoleQuiet(true);
  std::ostream& out = consoleOut();
  EXPECT_NE(&out, &std::cout);
  out << "discarded " << 1.5 << "\n";
  EXPECT_TRUE(out.good());
  EXPECT_NE(&consoleErr(), &std::cerr);
  setConsoleQuiet(false);
  EXPECT_EQ(&consoleOut(), &std::cout);
  EXPECT_EQ(&consoleErr(), &std::cerr);
}

TEST(Console, CaptureKeepsCompleteLinesForTheCaller) {
  setConsoleQuiet(true);
  setConsoleCapture(true);
  (void)takeConsoleLines();
  consoleOut() << "result " << 1 << "\npartial";
  consoleErr() << "note\n";
  consoleCaptureProgress("progress 3/10");
  const std::vector<ConsoleLine> lines = takeConsoleLines();
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(lines[0].text, "result 1");
  EXPECT_EQ(lines[0].kind, ConsoleLine::Kind::kResult);
  EXPECT_EQ(lines[1].text, "note");
  EXPECT_EQ(lines[1].kind, ConsoleLine::Kind::kNote);
  EXPECT_EQ(lines[2].kind, ConsoleLine::Kind::kProgress);
  EXPECT_TRUE(takeConsoleLines().empty());
  consoleOut() << "\n";  // ends "partial"
  EXPECT_EQ(takeConsoleLines().at(0).text, "partial");
  setConsoleCapture(false);
  consoleOut() << "dropped\n";
  EXPECT_TRUE(takeConsoleLines().empty());
  setConsoleQuiet(false);
}

}  // namespace
}  // namespace orni::studies
