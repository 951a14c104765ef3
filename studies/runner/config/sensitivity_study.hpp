// Sensitivity studies (kind = "sensitivity"): how the model's predictions move when each vehicle
// value the paper does not give is moved over its plausible range, one at a time.
//
// Study file (read by loadStudyFile, study_file.hpp; the reader is sensitivity_study.cpp):
//
//   kind = "sensitivity"
//   vehicle = "../vehicles/efw_magpie.toml"
//   [override]                 optional, as in every study: the base vehicle
//   [sensitivity]
//   parameters = [             required: an array of 1-64 tables { key, low, high }, inline or as
//                              [[sensitivity.parameters]] tables, in the order of the outputs
//     { key = "body.pitch_inertia_kgm2", low = 4e-5, high = 3.2e-4 },
//   ]
//     key   a vehicle key exactly as in [override] (and as a sweep axis names it), distinct per
//           parameter; not "operating_point.*" (the trim's initial guess, set in [trim]) and not a
//           key of the study or of [trim] (the same at every point);
//     low, high  the ends of the plausible range in the key's file units, low < high; each is
//           checked like a sweep axis value: the vehicle with the key at that value must be a
//           valid vehicle (an error names the file, the line of `low` or `high` and the reason).
//   free_flight_cycles = 60    optional, [1, 100000]: the free flight flown from every trim point
//                              (default 60, as the trim's own free-flight check)
//   [sensitivity.free]         optional: the bounded-norm bounds and free-flight settings, the keys
//                              of [simulate.free] (FreeFlightOptions)
//   [trim]                     optional: the settings of every trim, as in a trim study
//
// Any other section ([simulate], [aeromap], [sweep], ...) is an error. The points are the base
// vehicle and, for each parameter, the vehicle with that one key at low and at high (2 P + 1
// points, in the order of sensitivityPointId); each is a study of kind trim, read exactly like a
// trim study with the value written into [override]. The base value of a parameter may lie outside
// [low, high] (the ranges are physical, not centred on today's vehicle): the tornado bars then
// point the same way, and summary.json says so.
#pragma once

#include <cstddef>

namespace orni::studies {

/// Most parameters of one sensitivity study.
inline constexpr std::size_t kMaxSensitivityParameters = 64;

enum class SensitivitySide { kBase, kLow, kHigh };
/// "base", "low", "high".
const char* toString(SensitivitySide side);

/// What point `index` of a sensitivity study is: the base (parameter unused, 0), or parameter
/// `parameter` at its low or high end.
struct SensitivityPointId {
  std::size_t parameter = 0;
  SensitivitySide side = SensitivitySide::kBase;
};

/// 2 * parameters + 1.
std::size_t sensitivityPointCount(std::size_t parameters);
/// Point 0 is the base; parameter i at low is point 1 + 2 i, at high 2 + 2 i.
SensitivityPointId sensitivityPointId(std::size_t index);
std::size_t sensitivityPointIndex(std::size_t parameter, SensitivitySide side);

}  // namespace orni::studies
