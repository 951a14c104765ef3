// The analysis keys of [simulate] and [trim] with their values in a Study: the
// field table's simulate.* and trim.* entries (`ornithopter keys simulate|trim`), each with a
// getter, so that a sweep finds the settings that differ between its points by comparing values
// (sweep_study.cpp) instead of text. tests/unit/config/test_analysis_fields.cpp fails when a key
// of the field table has no entry here or the other way round, or a getter misses a change.
//
// Private to orni_studies.
#pragma once

#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "studies/runner/config/study_file.hpp"

namespace orni::studies {

/// A value of an analysis key as the study holds it (SI): a number, an integer, a flag, a name
/// (mode, method, control), a pair of bounds or a list of names (the trim's unknowns).
using AnalysisValue = std::variant<double, long long, bool, std::string, std::vector<double>,
                                   std::vector<std::string>>;

/// One key of [simulate] or [trim].
struct AnalysisField {
  std::string_view key;  ///< the field-table key, "trim.freq_hz", "simulate.free.bound_h_m"
  AnalysisValue (*get)(const Study& study) = nullptr;
  /// False when study.resolved.toml leaves the key out for this study: simulate.wing_only in free
  /// flight, simulate.free.* when tethered, trim.refine_* with the periodic method and
  /// trim.periodic.* with the two-stage one.
  bool (*written)(const Study& study) = nullptr;
};

/// The keys of the analysis section of `run` (kSimulate or kTrim), in the order study.resolved.toml
/// writes them (writeSimulateSection, writeTrimSection); empty for any other kind.
const std::vector<AnalysisField>& analysisFields(StudyKind run);

/// The same value as the resolved writer sees it: numbers equal with the same sign (0 and -0 are
/// written differently), everything else equal.
bool sameAnalysisValue(const AnalysisValue& a, const AnalysisValue& b);

}  // namespace orni::studies
