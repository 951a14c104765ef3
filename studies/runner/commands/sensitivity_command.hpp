// `kind = "sensitivity"` studies (config/sensitivity_study.hpp): the base vehicle and, for each
// parameter the paper does not give, the vehicle with that value at the low and at the high end of
// its plausible range, each trimmed, flown freely and held tethered at its trim
// (points/sensitivity_point.hpp); how far each end moves each prediction from the base.
//
// Points run on `threads` threads (core/grid/point_pool.hpp) and are stored by point index, so the
// outputs do not depend on the thread count. Resumable like a sweep: finished points go to
// DIR/sensitivity.journal (output/point_journal.hpp) as they finish; a re-run of the same study
// into the same folder takes them over and computes only the rest, then removes the journal.
//
// Outputs (docs/design.md 4):
//   sensitivity.csv     one row per point (base, then each parameter low and high): point,
//                       parameter (key; empty for the base), side (base|low|high), value (file
//                       units of the key, given in value_unit), value_unit, status, the result
//                       columns (sensitivity_point.hpp; empty = no value, never NaN), message. Its
//                       bytes depend only on the study (not on -j, nor on a resume).
//   tornado.csv         per prediction its parameters ranked by swing (sensitivity_figures.hpp).
//   summary.json        kind "sensitivity", status (ok when every point is ok, else
//                       not_converged), message, wall_time_s, version, points and the counts by
//                       status, parameters {key: unit, low, high, base, base_inside_range},
//                       base {status, message, every result column by name: theta_mean_deg,
//                       ..., bounded}, predictions {name: unit, label,
//                       base, ranking (keys by swing), effects {key: low_value, high_value,
//                       delta_low, delta_high, swing, swing_share}} (null where no value).
//   study.resolved.toml the study resolved; re-runs the same points.
//   tornado_<prediction>.png/svg  one tornado per prediction with a value;
//   sensitivity_overview.png/svg  swing shares, parameters x predictions.
#pragma once

#include <cstddef>
#include <filesystem>
#include <functional>

#include "studies/runner/points/sweep_point.hpp"
#include "studies/runner/config/study_file.hpp"

namespace orni::studies {

struct SensitivityRunOptions {
  int threads = 1;       ///< worker threads, [1, 1024]
  bool progress = true;  ///< progress line with ETA on stderr
  bool figures = true;   ///< draw the figures (gnuplot)
  /// Observer of each computed point (tests count them; an exception here stops the run like a
  /// crash); called after the journal append, serialised.
  std::function<void(std::size_t index, const SweepPointResult& result)> on_point;
};

/// Journal file name in the output folder.
inline constexpr const char* kSensitivityJournalName = "sensitivity.journal";

/// Run a sensitivity study into `out_dir`. Returns the process exit code (0 finished, whatever the
/// points' verdicts). Throws (main: exit 1) when the journal or an output cannot be written.
int runSensitivityStudy(const Study& study, const std::filesystem::path& out_dir,
                        const SensitivityRunOptions& options = {});

}  // namespace orni::studies
