// Outputs of the constrained flight test (paper section 4, Fig. 9) of a tethered simulate run:
// zmp.csv (the last cycle) and the "constrained_flight_test" object of summary.json; the figure
// zmp.png/svg (top: C_F,V, C_F,H, C_M,CG over the last cycle; bottom: epsilon against delta_M,
// upstroke and downstroke) is plotting/flight_figures.hpp's. Analysis in
// core/dynamics/zero_moment_point.hpp.
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

/// Column numbers of zmp.csv (1-based, as gnuplot counts).
struct ZmpCsvColumns {
  static constexpr int kT = 1, kDelta = 2, kStroke = 3, kCFV = 4, kCFH = 5, kCM = 6,
                       kEpsilon = 7, kCFNormal = 8;
};

/// The constrained flight test of the last whole cycle of `history` (samples_per_cycle samples,
/// endpoint excluded); nullopt when the history holds less than one whole cycle.
std::optional<ConstrainedFlightTest> lastCycleConstrainedFlightTest(
    const Study& study, const FlightCoreModel& model, const TimeHistory& history,
    int samples_per_cycle);

/// zmp.csv: t (s), delta_M (deg), stroke (up|down), CF_V, CF_H, CM_CG, epsilon (empty where
/// undefined), CF_normal (the epsilon denominator); non-finite numbers are empty cells.
CsvTable zmpTable(const ConstrainedFlightTest& test);

/// The "constrained_flight_test" object of summary.json (undefined values are null).
JsonObject zmpSummary(const ConstrainedFlightTest& test);

}  // namespace orni::studies
