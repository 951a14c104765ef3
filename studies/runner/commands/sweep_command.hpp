// `kind = "sweep"` studies (docs/design.md 5): another kind (trim, or simulate tethered or free)
// run at every point of a grid of vehicle or analysis values, one row per point. Points run on
// `threads` threads (core/grid/point_pool.hpp), results are stored by point index, so the outputs
// do not depend on the thread count. Resumable like an aero map: finished points go to
// DIR/sweep.journal (output/point_journal.hpp) as they finish; a re-run of the same study into
// the same folder takes them over and computes only the rest, then removes the journal once
// every output, figures included, is in place.
//
// Outputs (docs/design.md 4):
//   sweep.csv           one row per point in point order (first axis outermost): the axis values
//                       (columns named by their keys, units from the key suffixes), status, the
//                       run's result columns (points/sweep_point.hpp: which cells a point of
//                       each status fills; empty = no value, never NaN), message. Its bytes
//                       depend only on the study (not on -j, nor on a resume).
//   summary.json        kind "sweep", status (ok when every point is ok, else not_converged),
//                       message, wall_time_s, version, run, mode (simulate), points and the
//                       counts by status, points_bounded (trim and free flight), axes.
//   study.resolved.toml the sweep with its base study resolved; re-runs the same points.
//   sweep.png/svg       each plotted result column against the first axis, one line per value
//                       of the other axes (when some point has a value).
#pragma once

#include <cstddef>
#include <filesystem>
#include <functional>

#include "studies/runner/points/sweep_point.hpp"
#include "studies/runner/config/study_file.hpp"

namespace orni::studies {

struct SweepRunOptions {
  int threads = 1;       ///< worker threads, [1, 1024]
  bool progress = true;  ///< progress line with ETA on stderr
  bool figures = true;   ///< draw the figure (gnuplot)
  /// Observer of each computed point (tests count them; an exception here stops the run like a
  /// crash); called after the journal append, serialised.
  std::function<void(std::size_t index, const SweepPointResult& result)> on_point;
};

/// Journal file name in the output folder.
inline constexpr const char* kSweepJournalName = "sweep.journal";

/// Run a sweep study into `out_dir`. Returns the process exit code (0 finished, whatever the
/// points' verdicts; 1 failed: the journal or an output could not be written).
int runSweepStudy(const Study& study, const std::filesystem::path& out_dir,
                  const SweepRunOptions& options = {});

}  // namespace orni::studies
