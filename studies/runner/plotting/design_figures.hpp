// Figure scripts of design runs (gnuplot bodies for drawFigure, gnuplot.hpp): an optimisation's
// convergence and a parameter sweep. Each reads the CSV file its run writes beside it
// (history.csv, sweep.csv), by column number, so `ornithopter plot RUN_DIR` redraws it.
#pragma once

#include <string>
#include <vector>

#include "core/grid/sweep_grid.hpp"
#include "optimize/design_problem.hpp"
#include "studies/runner/points/sweep_point.hpp"
#include "studies/runner/config/study_file.hpp"

namespace orni::studies {

/// The objective per evaluation (feasible, infeasible, best feasible so far) and the largest
/// constraint violation (reads history.csv, whose layout follows the problem's variables,
/// constraints and values).
std::string optimizeConvergenceFigure(const Study& study, const orni::opt::DesignProblem& p,
                                      const orni::opt::OptimizerSummary& s);

/// One panel per plotted column with a value somewhere, the column against the first axis, one
/// line per combination of the other axes' values (reads sweep.csv). Empty when nothing to plot.
std::string sweepFigure(const Study& study, const SweepGrid& grid,
                        const std::vector<SweepColumn>& columns,
                        const std::vector<SweepPointResult>& rows);

}  // namespace orni::studies
