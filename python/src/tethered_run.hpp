// ornithopter.simulate's tethered path: the CLI's simulateTethered and summary (tetheredSummary),
// the histories into one NumPy array owned by Python (no copy per sample, nor at the end), with
// the GIL released and Ctrl-C checked once per flapping cycle.
#pragma once

#include <pybind11/pybind11.h>

#include "studies/runner/config/study_file.hpp"
#include "vehicle_object.hpp"

namespace orni::python {

/// Runs the tethered simulate study `study` (kind simulate, mode tethered, not at_trim) whose
/// vehicle is `vehicle`'s. Returns (summary.json text, histories array of shape (samples,
/// kHistoryColumns) in histories.csv's columns and units, or None when `histories` is false: the
/// run then samples nothing and the summary has no "last_cycle" nor "constrained_flight_test").
pybind11::tuple simulateTetheredStudy(const VehicleObject& vehicle, const studies::Study& study,
                                      bool histories);

}  // namespace orni::python
