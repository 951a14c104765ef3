// A CSV table written row by row as a run makes it (the format of CsvTable, csv_table.hpp: a
// names row, a units row, numbers in shortest round-trip form), through an AtomicFileWriter: the
// rows of a long run never sit in memory, and the file is complete (commit) or absent.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "studies/runner/output/atomic_file.hpp"

namespace orni::studies {

struct CsvColumn {
  std::string name, unit;
};

/// The columns `names` of the CSV file `file` with the units the output table declares for them
/// (output_schema.hpp; std::logic_error for a column it does not describe).
std::vector<CsvColumn> declaredColumns(std::string_view file,
                                       const std::vector<std::string>& names);

class CsvStreamWriter {
 public:
  /// Opens the temporary file and writes the two header rows. With row_stride n (>= 1) only rows
  /// 0, n, 2n, ... of those offered are written (CsvTable::toString(n)).
  CsvStreamWriter(std::filesystem::path path, std::vector<CsvColumn> columns,
                  std::size_t row_stride = 1);
  std::size_t columns() const { return columns_; }
  /// Data rows written so far (after the stride).
  std::size_t rowsWritten() const { return written_; }
  /// Offers the next row: values[c] for column c < columns().
  void row(const double* values);
  /// Offers the next row of text cells (one per column, as CsvTable::addTextColumn writes them:
  /// "" = empty cell); std::logic_error for another cell count.
  void textRow(const std::vector<std::string>& cells);
  /// Puts the file in place (AtomicFileWriter::commit).
  void commit();

 private:
  AtomicFileWriter file_;
  std::size_t columns_, stride_;
  std::size_t offered_ = 0, written_ = 0;
  std::string line_;
};

}  // namespace orni::studies
