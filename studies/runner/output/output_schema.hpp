// The output half of the field table (docs/outputs.md): every summary.json value and every CSV
// column that a run writes, declared once with its unit and meaning. `ornithopter keys --outputs`
// lists it; a test (tests/unit/output/test_output_schema.cpp) walks every file the paper studies
// committed under results/paper and fails on a value or column the table does not describe, on a
// CSV unit row that disagrees with it, and on an entry no file holds.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace orni::studies {

struct OutputSpec {
  std::string_view file;     ///< "summary.json" or a CSV file name ("aeromap.csv")
  std::string_view kinds;    ///< run kinds whose folders hold it, comma-separated ("trim,optimize")
  /// A CSV column's name, or a JSON path: '.' between object keys, "[]" for an array's elements.
  /// Placeholders: <key> an input key of the field table (it may span dots, e.g.
  /// materials.LE1.youngs_modulus_gpa), <output> one name (a sensitivity study's predicted output).
  std::string_view path;
  std::string_view unit;     ///< as a CSV's units row writes it; "-" none; "per key" the key's unit
  std::string_view meaning;
};

/// Every entry, grouped by file (summary.json first), in the order of the listing.
const std::vector<OutputSpec>& outputTable();

/// The entry describing `path` (a concrete column name or JSON path) of `file`, or nullptr.
const OutputSpec* findOutput(std::string_view file, std::string_view path);

/// True when `kinds` (an OutputSpec's list) names `kind`.
bool outputKindListed(std::string_view kinds, std::string_view kind);

/// The run kinds the table names, in order of first appearance.
std::vector<std::string_view> outputKinds();

/// The listing of `ornithopter keys --outputs [KIND]`: aligned text, or Markdown tables
/// (docs/outputs.md), one per file; `kind` non-empty: only what runs of that kind write.
std::string outputListing(std::string_view kind, bool markdown);

}  // namespace orni::studies
