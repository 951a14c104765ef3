// CSV tables with a names row and a units row (architecture.md 4; OpenFAST habit).
#pragma once

#include <string>
#include <vector>

namespace orni::studies {

class CsvTable {
 public:
  /// Add a column; every column must end up with the same number of rows.
  void addColumn(std::string name, std::string unit, std::vector<double> values);
  std::size_t rows() const;
  /// Text: names row, units row, then the values (shortest round-trip formatting).
  std::string toString() const;

 private:
  std::vector<std::string> names_, units_;
  std::vector<std::vector<double>> columns_;
};

}  // namespace orni::studies
