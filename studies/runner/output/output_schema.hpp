// The output half of the field table (docs/outputs.md): every summary.json value and every CSV
// column that a run writes, declared once with its unit and meaning. `ornithopter keys --outputs`
// lists it; the writers hold to it (writeSummary, summary_file.hpp, refuses an undeclared value;
// CsvTable and declaredColumns an undeclared column or another unit); a test
// (tests/unit/output/test_output_schema.cpp) walks every file the paper studies
// committed under results/paper and fails on a value or column the table does not describe, on a
// CSV unit row that disagrees with it, and on an entry no file holds.
#pragma once

#include <set>
#include <string>
#include <string_view>
#include <vector>

namespace orni::studies {

struct OutputSpec {
  std::string_view file;     ///< "summary.json" or a CSV file name ("aeromap.csv")
  std::string_view kinds;    ///< run kinds whose folders hold it, comma-separated ("trim,optimize")
  /// A CSV column's name, or a JSON path: '.' between object keys, "[]" for an array's elements.
  /// Placeholders: <key> an input key of the field table (it may span dots, e.g.
  /// materials.LE1.youngs_modulus_gpa); any other <...> one name (<output> a sensitivity study's
  /// predicted output, <variable> an optimisation's design variable, w_<mode> the columns w_1,
  /// w_2, ...).
  std::string_view path;
  std::string_view unit;     ///< as a CSV's units row writes it; "-" none; "per key" the key's unit
  std::string_view meaning;
};

/// Every entry, grouped by file (summary.json first), in the order of the listing.
const std::vector<OutputSpec>& outputTable();

/// The entry describing `path` (a concrete column name or JSON path) of `file`, or nullptr.
const OutputSpec* findOutput(std::string_view file, std::string_view path);

/// The unit the table declares for column `column` of the CSV file `file`: what the CSV writers
/// (CsvTable, csv_stream.hpp) write in the units row when the code names no unit. Throws
/// std::logic_error (a programming error) when the table has no entry or a "per key" /
/// "per variable" one.
std::string declaredColumnUnit(std::string_view file, std::string_view column);

/// The check every CSV writer (CsvTable, CsvStreamWriter) makes of each column it writes: throws
/// std::logic_error (a programming error) when the table has no entry for column `column` of the
/// file `file` or declares another unit than `unit` ("per key" / "per variable" entries take the
/// writer's).
void demandDeclaredColumn(std::string_view file, std::string_view column, std::string_view unit);

/// True when `kinds` (an OutputSpec's list) names `kind`.
bool outputKindListed(std::string_view kinds, std::string_view kind);

/// What checkRunFolder found in one run folder.
struct OutputCheck {
  std::string kind;                     ///< summary.json's kind
  int summary_values = 0, csv_columns = 0;
  std::vector<std::string> findings;    ///< "FILE PATH: problem", one per undescribed output
  std::set<const OutputSpec*> used;     ///< the entries that described something
};

/// Checks the text of a summary.json against the table, as checkRunFolder does (summary values
/// only). Throws std::runtime_error when it is not JSON or names no kind.
OutputCheck checkSummaryText(const std::string& json_text);

/// Checks a finished run folder against the table: every summary.json value and every column of
/// every *.csv must have an entry whose kinds include the run's kind, and a CSV's units row must
/// agree with the entry (except "per key" / "per variable"). Throws std::runtime_error when the
/// folder has no readable summary.json.
OutputCheck checkRunFolder(const std::string& run_dir);

/// The run kinds the table names, in order of first appearance.
std::vector<std::string_view> outputKinds();

/// The listing of `ornithopter keys --outputs [KIND]`: aligned text, or Markdown tables
/// (docs/outputs.md), one per file; `kind` non-empty: only what runs of that kind write.
std::string outputListing(std::string_view kind, bool markdown);

}  // namespace orni::studies
