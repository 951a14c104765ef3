#include "studies/runner/output/csv_table.hpp"

#include <stdexcept>
#include <utility>

#include "studies/runner/output/atomic_file.hpp"
#include "studies/runner/output/output_schema.hpp"

namespace orni::studies {

std::string csvTextCell(const std::string& text) {
  if (text.find_first_of("\n\r") != std::string::npos)
    throw std::logic_error("CsvTable: a cell contains a newline");
  if (text.find_first_of(",\"") == std::string::npos) return text;
  std::string q = "\"";
  for (const char c : text) q += (c == '"') ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

std::vector<std::string> csvLineCells(const std::string& line) {
  std::vector<std::string> cells(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted) {
      if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
        cells.back() += '"';
        ++i;
      } else if (c == '"') {
        quoted = false;
      } else {
        cells.back() += c;
      }
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

void CsvTable::add(std::string name, std::string unit, std::vector<std::string> cells) {
  if (!columns_.empty() && cells.size() != columns_.front().size())
    throw std::logic_error("CsvTable: column '" + name + "' has a different length");
  if (!file_.empty()) demandDeclaredColumn(file_, name, unit);  // output_schema.hpp
  // Names and units are cells too: a comma or quote in them must not shift the header rows.
  std::string name_cell = csvTextCell(name), unit_cell = csvTextCell(unit);
  names_.push_back(std::move(name_cell));
  units_.push_back(std::move(unit_cell));
  columns_.push_back(std::move(cells));
}

void CsvTable::addColumn(std::string name, std::string unit, const std::vector<double>& values) {
  std::vector<std::string> cells;
  cells.reserve(values.size());
  for (const double v : values) cells.push_back(formatShortest(v));
  add(std::move(name), std::move(unit), std::move(cells));
}

void CsvTable::addColumn(std::string name, const std::vector<double>& values) {
  std::string unit = declaredColumnUnit(file_, name);
  addColumn(std::move(name), std::move(unit), values);
}

void CsvTable::addTextColumn(std::string name, std::vector<std::string> cells) {
  std::string unit = declaredColumnUnit(file_, name);
  addTextColumn(std::move(name), std::move(unit), std::move(cells));
}

void CsvTable::addTextColumn(std::string name, std::string unit, std::vector<std::string> cells) {
  for (std::string& c : cells) c = csvTextCell(c);
  add(std::move(name), std::move(unit), std::move(cells));
}

std::vector<std::size_t> rowIndices(std::size_t n) {
  std::vector<std::size_t> v(n);
  for (std::size_t i = 0; i < n; ++i) v[i] = i;
  return v;
}

std::size_t CsvTable::rows() const { return columns_.empty() ? 0 : columns_.front().size(); }

std::string CsvTable::toString(std::size_t row_stride) const {
  if (row_stride < 1) row_stride = 1;
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
  for (std::size_t r = 0; r < rows(); r += row_stride) {
    for (std::size_t c = 0; c < columns_.size(); ++c) {
      if (c) out += ',';
      out += columns_[c][r];
    }
    out += '\n';
  }
  return out;
}

}  // namespace orni::studies
