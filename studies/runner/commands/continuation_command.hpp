// Studies of kind "continuation" (trim/trim_continuation.hpp): the branch of periodic trims over
// one parameter with the Floquet stability of every point. Writes into the output folder
// (docs/design.md 4):
//   continuation.csv       one row per point in branch order: point number, event ("" or fold,
//                          branch_point, period_doubling, neimark_sacker), the parameter, the trim
//                          point (frequency, cycle-mean theta and airspeed, tail angle, CG shift),
//                          aerodynamic power, max |mu|, stable, the leading multiplier and its
//                          label, the periodic residual, the corrector's iterations, arclength;
//   summary.json           status, message, the parameter and range, counts, the events, the
//                          stable stretches, the start trim, period maps, times;
//   continuation.png/.svg  the branch (control, theta, airspeed, power and max |mu| against the
//                          parameter): stable solid, unstable dashed, events marked;
//   study.resolved.toml    the study with every default.
// Resumable: continuation.journal holds every accepted point (exact numbers); a killed run
// started again continues after the last regular point with the same output bytes.
#pragma once

#include <filesystem>

#include "studies/runner/config/study_file.hpp"

namespace orni::studies {

/// The journal's file name in the output folder.
inline constexpr const char* kContinuationJournalName = "continuation.journal";

/// Run the continuation study into `out_dir`. Returns 0 when the run finished (completed or not:
/// the status and reason are in summary.json), 1 when the start trim failed. Bad input throws
/// InputError (exit 2). `threads` difference each point's Jacobian (the same bytes for any count).
int runContinuationStudy(const Study& study, const std::filesystem::path& out_dir,
                         int threads = 1);

}  // namespace orni::studies
