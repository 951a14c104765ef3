// The end of a run that failed (the integrator stopped: SimulationStatus::kFailed): its
// summary.json says "failed" with the real cause and no value as a result (docs/design.md 3, 4);
// no CSV of results and no figure is drawn from it, and the outputs an earlier run left in the
// folder under the same names are removed, so that none passes for this run's.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "studies/runner/config/study_file.hpp"

namespace orni::studies {

/// Removes `files` and, for each figure stem, STEM.gp, STEM.png and STEM.svg from `dir`.
void removeRunOutputs(const std::filesystem::path& dir, const std::vector<std::string>& files,
                      const std::vector<std::string>& figure_stems);

/// Prints the cause of the failure on stderr and returns the exit status of a failed run (1).
int reportFailedRun(const Study& study, const std::string& cause,
                    const std::filesystem::path& out_dir);

}  // namespace orni::studies
