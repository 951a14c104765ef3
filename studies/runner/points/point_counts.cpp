#include "studies/runner/points/point_counts.hpp"

#include <cstdio>

namespace orni::studies {

PointCounts countPoints(const std::vector<SweepPointResult>& rows, std::size_t bounded_column) {
  PointCounts n;
  for (const SweepPointResult& r : rows) {
    if (r.status == "ok")
      ++n.ok;
    else if (r.status == "not_converged")
      ++n.not_converged;
    else if (r.status == "diverged")
      ++n.diverged;
    else
      ++n.failed;
    if (bounded_column < r.cells.size() && r.cells[bounded_column] == "1") ++n.bounded;
  }
  return n;
}

std::string pointsMessage(const PointCounts& n, std::size_t points, const std::string& table) {
  char buf[300];
  if (n.ok == points)
    std::snprintf(buf, sizeof buf, "all %zu points ok", points);
  else
    std::snprintf(buf, sizeof buf,
                  "%zu of %zu points not ok (%zu not_converged, %zu diverged, %zu failed): see the "
                  "status and message columns of %s",
                  points - n.ok, points, n.not_converged, n.diverged, n.failed, table.c_str());
  return buf;
}

void setPointCounts(JsonObject& summary, const PointCounts& n, std::size_t points) {
  summary.set("points", static_cast<long>(points))
      .set("points_ok", static_cast<long>(n.ok))
      .set("points_not_converged", static_cast<long>(n.not_converged))
      .set("points_diverged", static_cast<long>(n.diverged))
      .set("points_failed", static_cast<long>(n.failed));
}

std::string pointCountsText(const PointCounts& n) {
  return std::to_string(n.ok) + " ok, " + std::to_string(n.not_converged) + " not_converged, " +
         std::to_string(n.diverged) + " diverged, " + std::to_string(n.failed) + " failed";
}

}  // namespace orni::studies
