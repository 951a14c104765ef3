// `ornithopter trim` and `kind = "trim"` studies: solve paper Eq. (4) with Ceres (trim/), then
// write summary.json, study.resolved.toml, trim_iterations.csv (every periodic run),
// trim_progress.csv (every solver iteration) and the convergence figure (docs/design.md 4).
#pragma once

#include <filesystem>

#include "studies/runner/config/study_file.hpp"
#include "studies/runner/output/json_writer.hpp"
#include "trim/free_flight_check.hpp"

namespace orni::studies {

/// Run a trim study into `out_dir`. Returns the process exit code: 0 when the solve finished,
/// converged or not (the verdict and the reason are in summary.json). Bad input throws InputError
/// (exit 2, mapped by main); other exceptions are failures (exit 1).
int runTrimStudy(const Study& study, const std::filesystem::path& out_dir);

/// summary.json's `free_flight` object of a trim (the free-mode keys of docs/design.md 4).
JsonObject freeFlightObject(const FreeFlightVerification& v);

}  // namespace orni::studies
