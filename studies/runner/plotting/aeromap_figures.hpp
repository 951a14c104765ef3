// Figures of an aero map in the manner of paper Fig. 5 (mean vertical and horizontal constraint
// forces against flight speed, flapping frequency and mean pitch): one figure per quantity
// (aeromap_FV, aeromap_FH, aeromap_M, aeromap_power; PNG and SVG), one panel per frequency, the
// quantity against theta with one line per speed (and dash type per tail angle). The scripts read
// aeromap.csv, so `ornithopter plot RUN_DIR` redraws them.
#pragma once

#include <filesystem>
#include <string>

#include "studies/runner/config/study_file.hpp"

namespace orni::studies {

/// Column numbers of aeromap.csv (1-based, as gnuplot counts).
struct AeromapCsvColumns {
  static constexpr int kSpeed = 1, kFreq = 2, kTheta = 3, kTail = 4;
  static constexpr int kFV = 5, kFH = 6, kM = 7, kPower = 8, kPowerAero = 9;
};

/// The gnuplot body of the figure of `column` (one of AeromapCsvColumns) with y label `ylabel`.
std::string aeromapFigureScript(const Study& study, int column, const std::string& what,
                                const std::string& ylabel);

/// Draws the four figures into `dir` (which holds aeromap.csv).
void drawAeromapFigures(const std::filesystem::path& dir, const Study& study);

}  // namespace orni::studies
