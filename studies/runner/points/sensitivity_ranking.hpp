// The effects of a sensitivity study (config/sensitivity_study.hpp): per prediction, how far each
// parameter's low and high ends move it from the base vehicle's value, and the parameters ranked
// by their swing |high - low| (the order of the bars of a tornado figure). No I/O.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "studies/runner/points/sensitivity_point.hpp"

namespace orni::studies {

/// One parameter's effect on one prediction (prediction units); nullopt where a point has no
/// value (its trim did not converge, its free flight diverged, ...).
struct SensitivityEffect {
  std::size_t parameter = 0;          ///< index into the study's parameters (file order)
  std::optional<double> low_value;    ///< the prediction with the key at low
  std::optional<double> high_value;   ///< ... at high
  std::optional<double> delta_low;    ///< low_value - base (needs both)
  std::optional<double> delta_high;   ///< high_value - base
  std::optional<double> swing;        ///< |high_value - low_value| (needs both)
  std::optional<double> swing_share;  ///< swing / the largest swing of this prediction (0
                                      ///< when every swing is 0)
};

/// One prediction (a column of sensitivityResultColumns with prediction = true).
struct PredictionRanking {
  std::size_t column = 0;      ///< index into sensitivityResultColumns()
  std::optional<double> base;  ///< the base vehicle's value
  /// Every parameter, by swing (largest first); parameters without a swing follow, ordered by
  /// their largest |delta| and then by file order; ties keep file order.
  std::vector<SensitivityEffect> ranked;
};

/// The number in a result cell; nullopt for an empty cell. Throws std::invalid_argument for any
/// other text than a number written by formatShortest.
std::optional<double> cellNumber(const std::string& cell);

/// The rankings of every prediction, in column order. `rows` has one row per point in the order
/// of sensitivityPointId (2 parameters + 1 rows); each row has one cell per result column.
std::vector<PredictionRanking> rankSensitivity(std::size_t parameters,
                                               const std::vector<SweepPointResult>& rows);

}  // namespace orni::studies
