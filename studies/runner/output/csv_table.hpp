// CSV tables with a names row and a units row (docs/design.md 4; OpenFAST habit).
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace orni::studies {

/// A text cell as CSV holds it: quoted (RFC 4180) when it has a comma or a double quote; throws
/// std::logic_error for a newline.
std::string csvTextCell(const std::string& text);

/// Column names and units are written like text cells (csvTextCell): quoted when they hold a
/// comma or a double quote, std::logic_error for a newline.
class CsvTable {
 public:
  /// A table of the file `file` ("aeromap.csv"): the columns added without a unit take theirs
  /// from the output table (output_schema.hpp). Empty: every column must name its unit.
  explicit CsvTable(std::string file = {}) : file_(std::move(file)) {}

  /// Add a column of numbers (shortest round-trip formatting); every column must end up with the
  /// same number of rows.
  void addColumn(std::string name, std::string unit, const std::vector<double>& values);
  /// The same with the unit the output table declares for this file's column `name`
  /// (std::logic_error when it declares none: a column of a name the study chooses, such as a
  /// sweep axis, names its unit).
  void addColumn(std::string name, const std::vector<double>& values);
  /// Add a column of text cells as they are ("" = empty cell, e.g. no value). A cell with a comma
  /// or a double quote is quoted (RFC 4180); newlines are not allowed (std::logic_error).
  void addTextColumn(std::string name, std::string unit, std::vector<std::string> cells);
  void addTextColumn(std::string name, std::vector<std::string> cells);  ///< unit as addColumn
  std::size_t rows() const;
  /// Text: names row, units row, then the values (with row_stride n: rows 0, n, 2n, ... only).
  std::string toString(std::size_t row_stride = 1) const;

 private:
  void add(std::string name, std::string unit, std::vector<std::string> cells);
  std::string file_;
  std::vector<std::string> names_, units_;
  std::vector<std::vector<std::string>> columns_;  // formatted cells
};

}  // namespace orni::studies
