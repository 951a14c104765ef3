#include "studies/runner/output/csv_table.hpp"

#include <stdexcept>

#include "studies/runner/output/atomic_file.hpp"

namespace orni::studies {

void CsvTable::addColumn(std::string name, std::string unit, std::vector<double> values) {
  if (!columns_.empty() && values.size() != columns_.front().size())
    throw std::logic_error("CsvTable: column '" + name + "' has a different length");
  names_.push_back(std::move(name));
  units_.push_back(std::move(unit));
  columns_.push_back(std::move(values));
}

std::size_t CsvTable::rows() const { return columns_.empty() ? 0 : columns_.front().size(); }

std::string CsvTable::toString() const {
  std::string out;
  auto row = [&out](const std::vector<std::string>& cells) {
    for (std::size_t i = 0; i < cells.size(); ++i) {
      if (i) out += ',';
      out += cells[i];
    }
    out += '\n';
  };
  row(names_);
  row(units_);
  for (std::size_t r = 0; r < rows(); ++r) {
    for (std::size_t c = 0; c < columns_.size(); ++c) {
      if (c) out += ',';
      out += formatShortest(columns_[c][r]);
    }
    out += '\n';
  }
  return out;
}

}  // namespace orni::studies
