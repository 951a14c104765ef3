// Running a loaded study of any kind into an output folder: the one path behind `ornithopter run`,
// `simulate`, `trim`, `optimize` and the Python module's ornithopter.run (python/).
#pragma once

#include <filesystem>
#include <string>

#include "studies/runner/config/study_file.hpp"

namespace orni::studies {

/// Runs `study` into `out_dir`, which the caller holds locked; `jobs` threads for the kinds that
/// use them (aeromap, sweep, sensitivity, optimize). Returns the exit code: 0 finished (whatever
/// the physics verdict, which is in summary.json), 1 failed. Bad input throws InputError; a model
/// check of core (InvalidModelError) is rethrown as InputError naming the study's file.
int runStudy(const Study& study, const std::filesystem::path& out_dir, int jobs);

/// `study` (kind trim: a vehicle and its [trim]) made a stability analysis: the periodic-orbit
/// trim with every Floquet multiplier (the full monodromy matrix), no free-flight check (the
/// verdict is Floquet's), its name with "_stability". Throws InputError when the options are
/// not valid.
Study stabilityStudy(Study study);

/// Locks `out_dir` and runs the stability analysis of a stabilityStudy into it (summary kind
/// "stability"), with its HTML report. The exit code as runStudy's.
int runStabilityLocked(const Study& study, const std::filesystem::path& out_dir);

/// Locks `out_dir` (FolderBusyError at once when another run holds it) and runs `study` into it.
int runStudyLocked(const Study& study, const std::filesystem::path& out_dir, int jobs);

}  // namespace orni::studies
