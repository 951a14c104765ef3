#include "studies/runner/plotting/figure_rows.hpp"

namespace orni::studies {

std::string figureEvery(std::size_t rows, std::size_t first_row, std::size_t rows_per_cycle) {
  if (rows <= kFigureRows) return "";
  const std::size_t shown = rows > first_row ? rows - first_row : 0;
  std::size_t k = shown > kFigureRows ? (shown + kFigureRows - 1) / kFigureRows : 1;
  if (rows_per_cycle > 0 && 4 * k > rows_per_cycle)
    k = ((k + rows_per_cycle - 2) / rows_per_cycle) * rows_per_cycle + 1;
  return " every " + std::to_string(k) + "::" + std::to_string(first_row);
}

std::size_t historyRowOf(std::size_t sample, std::size_t history_every) {
  if (history_every < 1) history_every = 1;
  return (sample + history_every - 1) / history_every;
}

std::size_t historyRowsPerCycle(std::size_t samples_per_cycle, std::size_t history_every) {
  if (history_every < 1 || samples_per_cycle % history_every != 0) return 0;
  return samples_per_cycle / history_every;
}

}  // namespace orni::studies
