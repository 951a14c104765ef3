// The output table (studies/runner/output/output_schema.hpp) against the files the paper studies
// committed under results/paper: every summary.json value and CSV column of every run folder is
// described (with the run's kind among the entry's kinds), every CSV units row agrees with the
// table, and every entry is held by at least one file (no stale entries). Folders without a
// summary.json are not run folders (results/literal_wing_investigation.sh writes one) and are
// not checked.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "studies/runner/output/json_reader.hpp"
#include "studies/runner/output/output_schema.hpp"

namespace orni::studies {
namespace {

namespace fs = std::filesystem;

std::string readFile(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

/// One CSV line's cells (RFC 4180 quoting).
std::vector<std::string> csvCells(const std::string& line) {
  std::vector<std::string> cells(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted) {
      if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') cells.back() += '"', ++i;
      else if (c == '"') quoted = false;
      else cells.back() += c;
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      cells.emplace_back();
    } else if (c != '\r') {
      cells.back() += c;
    }
  }
  return cells;
}

struct Finding {
  std::string file, path, kind, problem;
};

struct Walk {
  std::set<const OutputSpec*> used;
  std::vector<Finding> findings;
  int values = 0, columns = 0;

  void check(const std::string& file, const std::string& path, const std::string& kind,
             const std::string* unit) {
    const OutputSpec* o = findOutput(file, path);
    if (o == nullptr) {
      findings.push_back({file, path, kind, "not in the output table"});
      return;
    }
    used.insert(o);
    if (!outputKindListed(o->kinds, kind))
      findings.push_back({file, path, kind, "kind not listed (" + std::string(o->kinds) + ")"});
    if (unit != nullptr && o->unit != "per key" && *unit != o->unit)
      findings.push_back({file, path, kind, "unit row '" + *unit + "', table '" +
                                                std::string(o->unit) + "'"});
  }

  void summary(const JsonValue& v, const std::string& path, const std::string& kind) {
    if (v.type == JsonValue::Type::kObject) {
      for (const auto& [k, m] : v.members) summary(m, path.empty() ? k : path + "." + k, kind);
    } else if (v.type == JsonValue::Type::kArray) {
      bool nested = false;
      for (const JsonValue& e : v.items)
        if (!e.isScalar()) nested = true, summary(e, path + "[]", kind);
      if (!nested) {
        ++values;
        check("summary.json", path + "[]", kind, nullptr);
      }
    } else {
      ++values;
      check("summary.json", path, kind, nullptr);
    }
  }
};

TEST(OutputSchema, DescribesEveryValueAndColumnThePaperStudiesWrite) {
  const fs::path paper = fs::path(ORNI_SOURCE_DIR) / "results" / "paper";
  ASSERT_TRUE(fs::is_directory(paper));
  Walk walk;
  int runs = 0;
  std::vector<fs::path> folders;
  for (const auto& e : fs::directory_iterator(paper))
    if (e.is_directory() && fs::exists(e.path() / "summary.json")) folders.push_back(e.path());
  std::sort(folders.begin(), folders.end());
  for (const fs::path& folder : folders) {
    const JsonValue s = parseJson(readFile(folder / "summary.json"));
    const JsonValue* kind_value = s.find("kind");
    ASSERT_NE(kind_value, nullptr) << folder;
    const std::string kind = kind_value->text;
    ++runs;
    walk.summary(s, "", kind);
    for (const auto& f : fs::directory_iterator(folder)) {
      if (f.path().extension() != ".csv") continue;
      std::ifstream in(f.path());
      std::string names_line, units_line;
      std::getline(in, names_line);
      std::getline(in, units_line);
      const std::vector<std::string> names = csvCells(names_line), units = csvCells(units_line);
      ASSERT_EQ(names.size(), units.size()) << f.path();
      for (std::size_t c = 0; c < names.size(); ++c) {
        ++walk.columns;
        walk.check(f.path().filename().string(), names[c], kind, &units[c]);
      }
    }
  }
  std::string report;
  for (const Finding& f : walk.findings)
    report += "  " + f.file + " " + f.path + " (" + f.kind + "): " + f.problem + "\n";
  EXPECT_TRUE(walk.findings.empty()) << walk.findings.size() << " findings:\n" << report;
  std::string stale;
  for (const OutputSpec& o : outputTable())
    if (walk.used.count(&o) == 0) stale += "  " + std::string(o.file) + " " + std::string(o.path) + "\n";
  EXPECT_TRUE(stale.empty()) << "entries no committed file holds:\n" << stale;
  EXPECT_GE(runs, 20);
  std::printf("%d run folders: %d summary values, %d CSV columns, %zu of %zu entries used\n", runs,
              walk.values, walk.columns, walk.used.size(), outputTable().size());
}

TEST(OutputSchema, PlaceholdersMatchFieldKeysAndOneName) {
  // <key> spans the dots of a field-table key, with a wildcard material name; <output> is one name.
  const OutputSpec* k = findOutput("summary.json", "parameters.materials.LE1.youngs_modulus_gpa.low");
  ASSERT_NE(k, nullptr);
  EXPECT_EQ(k->path, "parameters.<key>.low");
  EXPECT_EQ(findOutput("summary.json", "parameters.not.a.key.low"), nullptr);
  const OutputSpec* o = findOutput("summary.json", "predictions.speed_mps.effects.tail.area_m2.swing");
  ASSERT_NE(o, nullptr);
  EXPECT_EQ(o->path, "predictions.<output>.effects.<key>.swing");
  EXPECT_EQ(findOutput("aeromap.csv", "no_such_column"), nullptr);
}

TEST(OutputSchema, ListingHasEveryEntryAndFiltersByKind) {
  const std::string all = outputListing("", false);
  for (const OutputSpec& o : outputTable())
    EXPECT_NE(all.find(std::string(o.path)), std::string::npos) << o.path;
  const std::string trim = outputListing("trim", true);
  EXPECT_NE(trim.find("#### summary.json"), std::string::npos);
  EXPECT_EQ(trim.find("#### aeromap.csv"), std::string::npos);
}

}  // namespace
}  // namespace orni::studies
