// One point of a sweep (kind = "sweep", study_file.hpp): run the point's study of kind trim or
// simulate and reduce it to one row of sweep.csv. No files are written here: the sweep command
// journals, tabulates and plots the rows.
//
// A row is a status (ok, not_converged, diverged, failed), one text cell per result column (a
// number in shortest round-trip form, a word, or "" = no value; never NaN) and a one-line
// message. Which cells are filled:
//   trim      status "ok" (converged) fills every cell; not_converged and failed leave them all
//             empty (there is no trim), the message says why.
//   simulate  tethered: ok and not_converged (the steady-state test did not pass in the given
//             cycles) fill the last-cycle means, exactly what the run's summary.json reports;
//             diverged and failed leave them empty. Free: ok fills every cell; diverged gives
//             bounded = 0 and cycles_run, the rest empty; failed leaves them empty.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "core/dynamics/modal_wing_cache.hpp"
#include "studies/runner/config/study_file.hpp"

namespace orni::studies {

/// A result column of sweep.csv.
struct SweepColumn {
  std::string name;      ///< e.g. "theta_mean_deg"
  std::string unit;      ///< e.g. "deg"; "-" for none
  bool plotted = false;  ///< a panel of the sweep figure
};

/// The result columns of a sweep, between `status` and `message`: they depend on the run kind
/// and, for simulate, on the mode of the base study.
std::vector<SweepColumn> sweepResultColumns(const Study& sweep);

struct SweepPointResult {
  std::string status = "failed";   ///< ok | not_converged | diverged | failed
  std::vector<std::string> cells;  ///< one per result column ("" = no value)
  std::string message;             ///< why (one line)
};

/// Runs `point` (a study of kind `run`: trim or simulate) and tabulates it in the columns of
/// sweepResultColumns. Exceptions become status "failed" with the reason. Thread-safe: it builds
/// its own FlightCoreModel and workspaces; flexible wings come from `modal_wings` (thread-safe;
/// null: built for the point alone).
SweepPointResult runSweepPoint(const Study& point, StudyKind run,
                               ModalWingCache* modal_wings = nullptr);

/// The journal payload of a row: status,cell,...,cell,message (cells never hold commas).
std::string encodeSweepPoint(const SweepPointResult& result);
/// Inverse of encodeSweepPoint for a row of `columns` cells; false when malformed.
bool decodeSweepPoint(std::string_view payload, std::size_t columns, SweepPointResult* result);

}  // namespace orni::studies
