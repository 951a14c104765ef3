#include "studies/runner/output/csv_stream.hpp"

#include <stdexcept>
#include <utility>

#include "studies/runner/output/csv_table.hpp"
#include "studies/runner/output/output_schema.hpp"

namespace orni::studies {

std::vector<CsvColumn> declaredColumns(std::string_view file,
                                       const std::vector<std::string>& names) {
  std::vector<CsvColumn> columns;
  columns.reserve(names.size());
  for (const std::string& n : names) columns.push_back({n, declaredColumnUnit(file, n)});
  return columns;
}

CsvStreamWriter::CsvStreamWriter(std::filesystem::path path, std::vector<CsvColumn> columns,
                                 std::size_t row_stride)
    : file_(std::move(path)), columns_(columns.size()), stride_(row_stride < 1 ? 1 : row_stride) {
  if (columns.empty()) throw std::logic_error("CsvStreamWriter: no columns");
  std::string names, units;
  for (std::size_t c = 0; c < columns.size(); ++c) {
    if (c) {
      names += ',';
      units += ',';
    }
    names += csvTextCell(columns[c].name);  // as CsvTable writes its header rows
    units += csvTextCell(columns[c].unit);
  }
  file_.write(names + '\n' + units + '\n');
}

void CsvStreamWriter::row(const double* values) {
  if (offered_++ % stride_ != 0) return;
  line_.clear();
  for (std::size_t c = 0; c < columns_; ++c) {
    if (c) line_ += ',';
    appendShortest(&line_, values[c]);
  }
  line_ += '\n';
  file_.write(line_);
  ++written_;
}

void CsvStreamWriter::textRow(const std::vector<std::string>& cells) {
  if (cells.size() != columns_) throw std::logic_error("CsvStreamWriter: wrong cell count");
  if (offered_++ % stride_ != 0) return;
  line_.clear();
  for (std::size_t c = 0; c < columns_; ++c) {
    if (c) line_ += ',';
    line_ += csvTextCell(cells[c]);
  }
  line_ += '\n';
  file_.write(line_);
  ++written_;
}

void CsvStreamWriter::commit() { file_.commit(); }

}  // namespace orni::studies
