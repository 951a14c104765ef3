// `ornithopter aeromap VEHICLE.toml --speed A:B:N --freq A:B:N --theta A:B:N [--tail A:B:N]` and
// `kind = "aeromap"` studies: the cycle-mean tethered loads over a grid (paper Fig. 5), built by
// trim/aero_map.hpp on `threads` threads. Writes aeromap.csv, summary.json, study.resolved.toml
// and the figures aeromap_{FV,FH,M,power}.png/svg (docs/design.md 4). Resumable: finished points
// go to DIR/aeromap.journal (output/aeromap_journal.hpp) as they finish; a re-run of the same
// study into the same folder takes them over and computes only the rest, then removes the journal
// once every output, figures included, is in place.
//
// aeromap.csv: one row per point in point order (speed outermost, then frequency, theta, tail);
// columns speed_mps, freq_hz, theta_deg, tail_angle_deg, FV_mean_N, FH_mean_N, M_mean_Nm, power_W
// (hinge power: the mechanical power the flapping drive delivers), power_aero_W, status,
// steady_cycle, cycles_run, last_cycle_change, message. The load and power cells are filled only
// for status "ok"; for not_converged, diverged and failed points they are empty (never NaN) and
// status and message say why. steady_cycle is empty when no steady state was reached.
// The bytes of aeromap.csv depend only on the study (not on -j, nor on a resume).
#pragma once

#include <filesystem>
#include <string>

#include "studies/runner/config/study_file.hpp"
#include "trim/aero_map.hpp"

namespace orni::studies {

struct AeromapRunOptions {
  int threads = 1;              ///< worker threads, [1, 1024]
  bool progress = true;         ///< progress line with ETA on stderr
  bool figures = true;          ///< draw the figures (gnuplot)
  /// Observer of each computed point (tests count them); called after the journal append.
  AeroMapPointCallback on_point;
};

/// Journal file name in the output folder.
inline constexpr const char* kAeromapJournalName = "aeromap.journal";

/// Run an aeromap study into `out_dir`. Returns the process exit code (0 finished, whatever the
/// points' verdicts; 1 failed: the journal or an output could not be written).
int runAeromapStudy(const Study& study, const std::filesystem::path& out_dir,
                    const AeromapRunOptions& options = {});

}  // namespace orni::studies
