// Tables and figures of a sensitivity study (commands/sensitivity_command.hpp): tornado.csv (the
// effects, ranked), one tornado figure per prediction and an overview. The figures read
// tornado.csv, so `ornithopter plot DIR` redraws them from the run folder.
#pragma once

#include <string>
#include <vector>

#include "studies/runner/points/sensitivity_ranking.hpp"
#include "studies/runner/config/study_file.hpp"
#include "studies/runner/output/csv_table.hpp"

namespace orni::studies {

/// Column numbers of tornado.csv (1-based, as gnuplot counts).
struct TornadoCsvColumns {
  static constexpr int kPrediction = 1, kPredictionUnit = 2, kPredictionIndex = 3, kRank = 4,
                       kParameter = 5, kParameterIndex = 6, kLabel = 7, kBase = 8, kLowValue = 9,
                       kHighValue = 10, kDeltaLow = 11, kDeltaHigh = 12, kSwing = 13,
                       kSwingShare = 14;
};

/// tornado.csv: one row per prediction and parameter, the predictions in column order and within
/// each its parameters by rank: prediction, prediction_unit, prediction_index (1-based), rank
/// (1-based), parameter (key), parameter_index (1-based, file order), label (key and range), base,
/// low_value, high_value, delta_low, delta_high, swing (prediction units), swing_share (-).
/// Values that do not exist are empty cells.
CsvTable tornadoTable(const Study& study, const std::vector<PredictionRanking>& rankings);

/// The label of a parameter on a tornado bar: "key: low .. high unit (base b)".
std::string parameterLabel(const SensitivityParameter& p);

/// Figure stem of a prediction's tornado: "tornado_<column name>".
std::string tornadoStem(const PredictionRanking& ranking);

/// The gnuplot body of the tornado of `rankings[k]` (reads tornado.csv): a horizontal bar per
/// parameter from the base value to the low and to the high end's value, largest swing on top;
/// empty when no parameter has a delta (nothing to draw).
std::string tornadoFigure(const Study& study, const std::vector<PredictionRanking>& rankings,
                          std::size_t k);

/// The gnuplot body of the overview (reads tornado.csv): parameters x predictions, each cell the
/// swing as a share of that prediction's largest swing; empty when no swing exists.
std::string overviewFigure(const Study& study, const std::vector<PredictionRanking>& rankings);

}  // namespace orni::studies
