// `ornithopter simulate` and `kind = "simulate"` studies: run, then write summary.json,
// study.resolved.toml, histories.csv, cycles.csv, the loads figure and, from the last cycle, the
// constrained flight test zmp.csv + zmp figure (paper Fig. 9; architecture.md 4).
#pragma once

#include <filesystem>

#include "studies/runner/config/study_file.hpp"

namespace orni::studies {

/// Run a simulate study into `out_dir`. Returns the process exit code (0 finished, whatever the
/// physics verdict; 1 failed). Bad input throws InputError (exit 2, mapped by main).
int runSimulateStudy(const Study& study, const std::filesystem::path& out_dir);

}  // namespace orni::studies
