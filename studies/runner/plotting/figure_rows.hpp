// How much of a long histories.csv a figure reads. gnuplot keeps every point it reads, so a figure
// of a long run reads at most kFigureRows rows per curve: the rows it shows (a gnuplot `every`
// start) and, when they are more, every k-th of them. Short files (every committed paper study)
// are read whole and their scripts do not change.
#pragma once

#include <cstddef>
#include <string>

namespace orni::studies {

/// Most rows of a data file one curve of a figure reads (8 per pixel column of a 1200-pixel
/// figure; gnuplot's memory and drawing time then stay those of a short run).
constexpr std::size_t kFigureRows = 10000;

/// A gnuplot `every` clause (with a leading space; after the `skip` of the header rows) that
/// reads rows [first_row, rows) of a file of `rows` data rows, every k-th, k the smallest that
/// keeps at most kFigureRows of them; empty when the file has at most kFigureRows rows (the whole
/// file is read). With rows_per_cycle > 0 a k above a quarter of it becomes the next multiple of it
/// plus one: the rows read then walk through the flapping cycle one row at a time, so a curve
/// traces the whole cycle (its envelope) in slow motion; any other k above a quarter would draw
/// an aliased zigzag, a multiple of the cycle one phase only.
std::string figureEvery(std::size_t rows, std::size_t first_row, std::size_t rows_per_cycle);

/// The first row of histories.csv at or after sample `sample` when it keeps every
/// `history_every`-th sample from sample 0.
std::size_t historyRowOf(std::size_t sample, std::size_t history_every);

/// Rows of histories.csv per flapping cycle; 0 when history_every does not divide
/// samples_per_cycle (the rows do not repeat with the cycle).
std::size_t historyRowsPerCycle(std::size_t samples_per_cycle, std::size_t history_every);

}  // namespace orni::studies
