// Outputs of the constrained flight test (paper section 4, Fig. 9) of a tethered simulate run:
// zmp.csv (the last cycle) and the "constrained_flight_test" object of summary.json; the figure
// zmp.png/svg (top: C_F,V, C_F,H, C_M,CG over the last cycle; bottom: epsilon against delta_M,
// upstroke and downstroke) is plotting/flight_figures.hpp's. Analysis, and the test of a tethered
// history's last cycle, in core/dynamics/zero_moment_point.hpp.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "core/dynamics/zero_moment_point.hpp"
#include "core/dynamics/tethered_simulation.hpp"
#include "studies/runner/config/study_file.hpp"
#include "studies/runner/output/csv_table.hpp"
#include "studies/runner/output/json_writer.hpp"

namespace orni::studies {

/// zmp.csv: t (s), delta_M (deg), stroke (up|down), CF_V, CF_H, CM_CG, epsilon (empty where
/// undefined), CF_normal (the epsilon denominator); non-finite numbers are empty cells. The zmp
/// figure reads these columns by number (ZmpCsvColumns, plotting/flight_figures.hpp).
CsvTable zmpTable(const ConstrainedFlightTest& test);

/// The "constrained_flight_test" object of summary.json (undefined values are null).
JsonObject zmpSummary(const ConstrainedFlightTest& test);

}  // namespace orni::studies
