// Figure scripts of trim runs (gnuplot bodies for drawFigure, gnuplot.hpp): the two-stage trim's
// convergence, the periodic orbit and its Floquet multipliers, and a continuation branch. Each
// reads the CSV files its run writes beside it, by column number, so `ornithopter plot RUN_DIR`
// redraws it.
#pragma once

#include <string>

#include "studies/runner/config/study_file.hpp"
#include "trim/periodic_trim.hpp"
#include "trim/trim_solver.hpp"

namespace orni::studies {

/// The residual per iteration (log scale, with every residual run) and the unknowns per
/// iteration (reads trim_progress.csv and trim_iterations.csv); `tol` the residual tolerance.
std::string trimConvergenceFigure(const Study& study, const TrimSummary& s, double tol);

/// theta, airspeed, W and altitude over one period of the orbit (reads periodic_orbit.csv).
std::string periodicOrbitFigure(const Study& study, const PeriodicTrimSummary& s);

/// The multipliers in the complex plane with the unit circle, and a zoom on the leading one
/// (reads floquet.csv); needs s.floquet_valid.
std::string floquetMultiplierFigure(const Study& study, const PeriodicTrimSummary& s);

/// Control, theta, airspeed and max |mu| along the branch over `parameter` (in
/// `parameter_unit`), stable solid, unstable dashed, events circled (reads continuation.csv).
std::string continuationBranchFigure(const Study& study, PeriodicControl parameter,
                                     const std::string& parameter_unit, PeriodicControl control,
                                     const std::string& status);

}  // namespace orni::studies
