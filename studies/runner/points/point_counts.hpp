// The tally of a point study's rows (sweep, sensitivity): points by status, the run message and
// the counts in summary.json and on the closing line.
#pragma once

#include <cstddef>
#include <limits>
#include <string>
#include <vector>

#include "studies/runner/points/sweep_point.hpp"
#include "studies/runner/output/json_writer.hpp"

namespace orni::studies {

struct PointCounts {
  std::size_t ok = 0, not_converged = 0, diverged = 0, failed = 0;
  std::size_t bounded = 0;  ///< rows whose bounded cell is "1" (countPoints' bounded_column)
};

/// The rows by status: "ok", "not_converged", "diverged", any other is failed. `bounded_column`:
/// the index of the "bounded" cell, or npos (nothing counted as bounded).
PointCounts countPoints(const std::vector<SweepPointResult>& rows,
                        std::size_t bounded_column = std::numeric_limits<std::size_t>::max());

/// "all N points ok", or "K of N points not ok (A not_converged, B diverged, C failed): see the
/// status and message columns of <table>".
std::string pointsMessage(const PointCounts& n, std::size_t points, const std::string& table);

/// summary.json's points, points_ok, points_not_converged, points_diverged, points_failed.
void setPointCounts(JsonObject& summary, const PointCounts& n, std::size_t points);

/// "A ok, B not_converged, C diverged, D failed" (the closing line).
std::string pointCountsText(const PointCounts& n);

}  // namespace orni::studies
