// CSV tables with a names row and a units row (docs/design.md 4; OpenFAST habit).
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace orni::studies {

/// A text cell as CSV holds it: quoted (RFC 4180) when it has a comma or a double quote; throws
/// std::logic_error for a newline.
std::string csvTextCell(const std::string& text);

/// The cells of one line of such a table (a names or units row), quotes resolved: the inverse of
/// csvTextCell over a line; a trailing '\r' is dropped.
std::vector<std::string> csvLineCells(const std::string& line);

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

/// A table of one row per element of `rows`, declared column by column with how a row gives its
/// cell: `number(name, f)` (f(row) -> double, shortest round-trip) or `text(name, f)` (f(row) ->
/// std::string, "" = empty cell); the unit from the output table, or given for a column the
/// study names. The column list is the table's one declaration of its layout:
///   CsvTable t = RowTable("floquet.csv", multipliers)
///                    .number("modulus", [](const FloquetMultiplier& m) { return m.modulus; })
///                    .text("label", [](const FloquetMultiplier& m) { return m.label; })
///                    .table();
template <class Row>
class RowTable {
 public:
  RowTable(std::string file, std::vector<Row> rows)
      : table_(std::move(file)), rows_(std::move(rows)) {}
  template <class F>
  RowTable& number(std::string name, F f) {
    table_.addColumn(std::move(name), numbers(f));
    return *this;
  }
  template <class F>
  RowTable& number(std::string name, std::string unit, F f) {
    table_.addColumn(std::move(name), std::move(unit), numbers(f));
    return *this;
  }
  template <class F>
  RowTable& text(std::string name, F f) {
    table_.addTextColumn(std::move(name), texts(f));
    return *this;
  }
  template <class F>
  RowTable& text(std::string name, std::string unit, F f) {
    table_.addTextColumn(std::move(name), std::move(unit), texts(f));
    return *this;
  }
  CsvTable table() { return std::move(table_); }

 private:
  template <class F>
  std::vector<double> numbers(F& f) const {
    std::vector<double> v;
    v.reserve(rows_.size());
    for (const Row& r : rows_) v.push_back(static_cast<double>(f(r)));
    return v;
  }
  template <class F>
  std::vector<std::string> texts(F& f) const {
    std::vector<std::string> v;
    v.reserve(rows_.size());
    for (const Row& r : rows_) v.push_back(f(r));
    return v;
  }
  CsvTable table_;
  std::vector<Row> rows_;
};

/// 0, 1, ..., n - 1: the rows of a RowTable over parallel arrays.
std::vector<std::size_t> rowIndices(std::size_t n);

}  // namespace orni::studies
