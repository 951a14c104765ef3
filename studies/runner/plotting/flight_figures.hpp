// Figure scripts of flight runs (gnuplot bodies for drawFigure, gnuplot.hpp): the free flight's
// paper Figs. 6-8, the tethered loads of paper Fig. 2 and the constrained flight test of Fig. 9.
// Each reads the CSV files its run writes beside it (histories.csv, spectra.csv, zmp.csv), by
// column number, so `ornithopter plot RUN_DIR` redraws it.
#pragma once

#include <cstddef>
#include <string>

#include "core/dynamics/simulation_result.hpp"
#include "core/dynamics/zero_moment_point.hpp"
#include "studies/runner/config/study_file.hpp"

namespace orni::studies {

/// Paper Fig. 7 layout: delta_M, theta and h against time (left) and, `with_spectra`, their
/// spectra (right); `skip` selects the rows of histories.csv (figure_rows.hpp).
std::string freeFlightFigure(const Study& study, bool with_spectra, const std::string& skip);
/// Paper Fig. 6: the last flapping cycle (`cycles` run), delta_M and theta, downstroke shaded.
std::string freeFlightCycleFigure(const Study& study, int cycles, const std::string& skip);
/// Paper Fig. 8: the pitch phase portrait (theta, Q) from t_from on.
std::string freeFlightPhaseFigure(const Study& study, double t_from, const std::string& skip);

/// Paper Fig. 2 layout: delta_M, FV, FH and M over the last (at most three) cycles of a tethered
/// run whose histories.csv has `rows` rows.
std::string tetheredLoadsFigure(const Study& study, const SimulationSummary& s, std::size_t rows);

/// Column numbers of zmp.csv (1-based, as gnuplot counts), in the order zmpTable writes them
/// (commands/constrained_flight_output.hpp).
struct ZmpCsvColumns {
  static constexpr int kT = 1, kDelta = 2, kStroke = 3, kCFV = 4, kCFH = 5, kCM = 6,
                       kEpsilon = 7, kCFNormal = 8;
};

/// The constrained flight test (reads zmp.csv); `cycle` is the 1-based cycle shown.
std::string zmpFigureScript(const Study& study, const ConstrainedFlightTest& test, int cycle);

}  // namespace orni::studies
