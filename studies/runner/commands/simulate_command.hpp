// `ornithopter simulate` and `kind = "simulate"` studies: run, then write summary.json,
// study.resolved.toml, histories.csv, cycles.csv, the loads figure and, from the last cycle, the
// constrained flight test zmp.csv + zmp figure (paper Fig. 9; docs/design.md 4).
#pragma once

#include <filesystem>
#include <optional>
#include <vector>

#include "core/dynamics/tethered_simulation.hpp"
#include "studies/runner/commands/constrained_flight_output.hpp"
#include "studies/runner/config/study_file.hpp"
#include "studies/runner/output/csv_stream.hpp"
#include "studies/runner/output/json_writer.hpp"

namespace orni::studies {

/// Run a simulate study into `out_dir`. Returns the process exit code (0 finished, whatever the
/// physics verdict; 1 failed). Bad input throws InputError (exit 2, mapped by main).
int runSimulateStudy(const Study& study, const std::filesystem::path& out_dir);

/// histories.csv's columns (name, unit), in order.
constexpr int kHistoryColumns = 20;
const std::vector<CsvColumn>& historyColumns();
/// One histories.csv row (kHistoryColumns values, file units) of the sample at `t_s`.
void historyRow(double t_s, double delta_M_rad, const LoadSample& loads, double* row);

/// summary.json of a tethered run of `study` (its point and wing_only) on `model` with the
/// run's options `opts` (samples_per_cycle), history `history` (at least its last cycle) and
/// constrained flight test `cft`; `trim_point` the at_trim trim ("trim_point"), or null. The one
/// summary of `ornithopter simulate` and the Python module's ornithopter.simulate.
JsonObject tetheredSummary(const Study& study, const FlightCoreModel& model,
                           const SimulationSummary& s, const SimulationOptions& opts,
                           const TimeHistory& history,
                           const std::optional<ConstrainedFlightTest>& cft, double wall_s,
                           const JsonObject* trim_point);

}  // namespace orni::studies
