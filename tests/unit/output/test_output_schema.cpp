// The output table (studies/runner/output/output_schema.hpp) against the files the paper studies
// committed under results/paper: every summary.json value and CSV column of every run folder is
// described (with the run's kind among the entry's kinds), every CSV units row agrees with the
// table, and every entry of the run kinds the paper studies use is held by at least one file (no
// stale entries). Folders without a summary.json are not run folders
// (results/literal_wing_investigation.sh writes one) and are not checked. The run kinds the paper
// does not use (modes, stability, the periodic trim) are checked by the CLI tests that run them
// (`ornithopter keys --outputs --check DIR`).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <unistd.h>
#include <set>
#include <string>
#include <vector>

#include "studies/runner/output/output_schema.hpp"
#include "studies/runner/output/csv_table.hpp"
#include "studies/runner/output/summary_file.hpp"

namespace orni::studies {
namespace {

namespace fs = std::filesystem;

TEST(OutputSchema, DescribesEveryValueAndColumnThePaperStudiesWrite) {
  const fs::path paper = fs::path(ORNI_SOURCE_DIR) / "results" / "paper";
  ASSERT_TRUE(fs::is_directory(paper));
  std::vector<fs::path> folders;
  for (const auto& e : fs::directory_iterator(paper))
    if (e.is_directory() && fs::exists(e.path() / "summary.json")) folders.push_back(e.path());
  std::sort(folders.begin(), folders.end());
  std::set<const OutputSpec*> used;
  std::string report;
  int values = 0, columns = 0;
  for (const fs::path& folder : folders) {
    const OutputCheck c = checkRunFolder(folder.string());
    used.insert(c.used.begin(), c.used.end());
    values += c.summary_values;
    columns += c.csv_columns;
    for (const std::string& f : c.findings)
      report += "  " + folder.filename().string() + ": " + f + "\n";
  }
  EXPECT_TRUE(report.empty()) << report;
  // Stale entries: an entry of a file the paper's runs write that no committed file holds.
  std::string stale;
  // The kinds the paper studies do not run (modes; stability, whose files the periodic trim also
  // writes) are checked by the CLI tests that run them (`keys --outputs --check`).
  for (const OutputSpec& o : outputTable()) {
    if (outputKindListed(o.kinds, "modes") || outputKindListed(o.kinds, "stability")) continue;
    // The paper sweeps only trims: a sweep of simulations' columns (tethered: the means, cycles,
    // steady-state cycle; free: cycles_run) are checked by tests/regression/cli_sweep.sh.
    const bool simulate_sweep_column =
        o.file == "sweep.csv" && (o.path == "FV_mean_N" || o.path == "FH_mean_N" ||
                                  o.path == "M_mean_Nm" || o.path == "cycles_run" ||
                                  o.path == "steady_cycle" || o.path == "last_cycle_change");
    if (simulate_sweep_column) continue;
    if (used.count(&o) == 0) stale += "  " + std::string(o.file) + " " + std::string(o.path) + "\n";
  }
  EXPECT_TRUE(stale.empty()) << "entries no committed file holds:\n" << stale;
  EXPECT_GE(folders.size(), 20u);
  std::printf("%zu run folders: %d summary values, %d CSV columns, %zu of %zu entries used\n",
              folders.size(), values, columns, used.size(), outputTable().size());
}

TEST(OutputSchema, PlaceholdersMatchFieldKeysAndOneName) {
  // <key> spans the dots of a field-table key, with a wildcard material name; <output> is one name.
  const OutputSpec* k =
      findOutput("summary.json", "parameters.materials.LE1.youngs_modulus_gpa.low");
  ASSERT_NE(k, nullptr);
  EXPECT_EQ(k->path, "parameters.<key>.low");
  EXPECT_EQ(findOutput("summary.json", "parameters.not.a.key.low"), nullptr);
  const OutputSpec* o =
      findOutput("summary.json", "predictions.speed_mps.effects.tail.area_m2.swing");
  ASSERT_NE(o, nullptr);
  EXPECT_EQ(o->path, "predictions.<output>.effects.<key>.swing");
  EXPECT_EQ(findOutput("aeromap.csv", "no_such_column"), nullptr);
  EXPECT_EQ(findOutput("summary.json", "no_such_value"), nullptr);
}

TEST(OutputSchema, ListingHasEveryEntryAndFiltersByKind) {
  const std::string all = outputListing("", false);
  for (const OutputSpec& o : outputTable())
    EXPECT_NE(all.find(std::string(o.path)), std::string::npos) << o.path;
  const std::string trim = outputListing("trim", true);
  EXPECT_NE(trim.find("#### summary.json"), std::string::npos);
  EXPECT_EQ(trim.find("#### aeromap.csv"), std::string::npos);
}

TEST(OutputSchema, CheckNamesAnUndescribedValueAndAWrongUnit) {
  const fs::path dir =
      fs::temp_directory_path() / ("orni_output_check_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  {
    std::ofstream(dir / "summary.json")
        << R"({"kind": "aeromap", "status": "ok", "bogus_value": 1})";
    std::ofstream(dir / "aeromap.csv") << "speed_mps,freq_hz\nm/s,rad/s\n1,2\n";
  }
  const OutputCheck c = checkRunFolder(dir.string());
  fs::remove_all(dir);
  ASSERT_EQ(c.findings.size(), 2u);
  EXPECT_NE(c.findings[0].find("bogus_value: not in the output table"), std::string::npos);
  EXPECT_NE(c.findings[1].find("freq_hz: units row 'rad/s', the table 'Hz'"), std::string::npos);
  EXPECT_THROW(checkRunFolder((dir / "missing").string()), std::runtime_error);
}

// The one summary writer refuses what the table does not declare for the run's kind, and writes
// nothing then; a null or [] where the table declares an object's or the elements' values (a
// failed run's mean, a failed periodic trim's multipliers) passes.
TEST(OutputSchema, SummaryWriterRefusesAnUndeclaredValueAndWritesNothing) {
  const fs::path dir =
      fs::temp_directory_path() / ("orni_summary_writer_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  JsonObject undeclared = summaryHeader("simulate", "ok", "m", 0.1);
  undeclared.set("speed_mps", 10.0).set("speed_kmh", 36.0);
  try {
    writeSummary(dir, undeclared);
    ADD_FAILURE() << "an undeclared value was written";
  } catch (const std::logic_error& e) {
    EXPECT_NE(std::string(e.what()).find("speed_kmh: not in the output table"), std::string::npos)
        << e.what();
  }
  EXPECT_FALSE(fs::exists(dir / "summary.json"));

  JsonObject other_kind = summaryHeader("modes", "ok", "m", 0.1);
  other_kind.set("speed_mps", 10.0);  // a simulate/trim value, not a modes one
  EXPECT_THROW(writeSummary(dir, other_kind), std::logic_error);
  JsonObject unknown_null = summaryHeader("simulate", "failed", "m", 0.1);
  unknown_null.setNull("averages");
  EXPECT_THROW(writeSummary(dir, unknown_null), std::logic_error);
  EXPECT_FALSE(fs::exists(dir / "summary.json"));

  JsonObject failed = summaryHeader("simulate", "failed", "the run threw", 0.1);
  failed.set("mode", "tethered").setNull("mean");
  writeSummary(dir, failed);
  EXPECT_TRUE(checkRunFolder(dir.string()).findings.empty());
  JsonObject no_orbit = summaryHeader("trim", "not_converged", "no orbit", 0.1);
  no_orbit.set("floquet", JsonObject().set("valid", false).setObjects("multipliers", {}));
  writeSummary(dir, no_orbit);  // [] where the table declares the elements' values
  JsonObject empty_unknown = summaryHeader("trim", "not_converged", "no orbit", 0.1);
  empty_unknown.setObjects("orbits", {});
  EXPECT_THROW(writeSummary(dir, empty_unknown), std::logic_error);
  fs::remove_all(dir);
}

// The CSV writers hold every column to the table: a column it does not declare for that file, or
// one written in another unit than the declared, is a programming error.
TEST(OutputSchema, CsvWriterRefusesAnUndeclaredColumnOrAnotherUnit) {
  const std::vector<double> one = {1.0};
  CsvTable declared("aeromap.csv");
  declared.addColumn("freq_hz", one);  // the declared unit
  declared.addColumn("FV_mean_N", "N", one);
  EXPECT_THROW(declared.addColumn("FV_mean_N", "kN", one), std::logic_error);
  EXPECT_THROW(declared.addColumn("lift_mean", "N", one), std::logic_error);
  EXPECT_THROW(CsvTable("modes.csv").addColumn("FV_mean_N", "N", one), std::logic_error);
  // "per key" columns take the writer's unit: a sweep axis in its key's unit.
  CsvTable("sweep.csv").addColumn("body.mass_kg", "kg", one);
  CsvTable unnamed;  // no file: a table of its own (tests, figures' data), not checked
  unnamed.addColumn("anything", "furlong", one);
}

}  // namespace
}  // namespace orni::studies
