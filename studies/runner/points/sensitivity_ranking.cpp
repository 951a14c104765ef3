#include "studies/runner/points/sensitivity_ranking.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <stdexcept>

#include "studies/runner/config/sensitivity_study.hpp"

namespace orni::studies {

namespace {

/// Sort key of an effect: with a swing first (largest first), then the largest |delta|.
double magnitude(const SensitivityEffect& e) {
  if (e.swing) return *e.swing;
  double m = -1.0;
  if (e.delta_low) m = std::max(m, std::fabs(*e.delta_low));
  if (e.delta_high) m = std::max(m, std::fabs(*e.delta_high));
  return m;
}

}  // namespace

std::optional<double> cellNumber(const std::string& cell) {
  if (cell.empty()) return std::nullopt;
  double v = 0.0;
  const auto r = std::from_chars(cell.data(), cell.data() + cell.size(), v);
  if (r.ec != std::errc() || r.ptr != cell.data() + cell.size() || !std::isfinite(v))
    throw std::invalid_argument("not a number cell: '" + cell + "'");
  return v;
}

std::vector<PredictionRanking> rankSensitivity(std::size_t parameters,
                                               const std::vector<SweepPointResult>& rows) {
  const std::vector<SensitivityColumn>& columns = sensitivityResultColumns();
  if (rows.size() != sensitivityPointCount(parameters))
    throw std::invalid_argument("rankSensitivity: one row per point expected");
  for (const SweepPointResult& r : rows)
    if (r.cells.size() != columns.size())
      throw std::invalid_argument("rankSensitivity: one cell per result column expected");

  std::vector<PredictionRanking> rankings;
  for (std::size_t c = 0; c < columns.size(); ++c) {
    if (!columns[c].prediction) continue;
    PredictionRanking p;
    p.column = c;
    p.base = cellNumber(rows[0].cells[c]);
    for (std::size_t i = 0; i < parameters; ++i) {
      SensitivityEffect e;
      e.parameter = i;
      e.low_value = cellNumber(rows[sensitivityPointIndex(i, SensitivitySide::kLow)].cells[c]);
      e.high_value = cellNumber(rows[sensitivityPointIndex(i, SensitivitySide::kHigh)].cells[c]);
      if (p.base && e.low_value) e.delta_low = *e.low_value - *p.base;
      if (p.base && e.high_value) e.delta_high = *e.high_value - *p.base;
      if (e.low_value && e.high_value) e.swing = std::fabs(*e.high_value - *e.low_value);
      p.ranked.push_back(e);
    }
    double largest = 0.0;
    for (const SensitivityEffect& e : p.ranked)
      if (e.swing) largest = std::max(largest, *e.swing);
    for (SensitivityEffect& e : p.ranked)
      if (e.swing) e.swing_share = largest > 0.0 ? *e.swing / largest : 0.0;
    std::stable_sort(p.ranked.begin(), p.ranked.end(),
                     [](const SensitivityEffect& a, const SensitivityEffect& b) {
                       if (a.swing.has_value() != b.swing.has_value()) return a.swing.has_value();
                       return magnitude(a) > magnitude(b);
                     });
    rankings.push_back(std::move(p));
  }
  return rankings;
}

}  // namespace orni::studies
