// The free-flight branch of `ornithopter simulate --mode free` (paper section 4, Figs. 6-8):
// summary.json with the bounded-norm verdict and the limit-cycle metrics, histories.csv,
// spectra.csv and the figures flight (time histories and spectra), cycle (the last flapping cycle,
// Fig. 6) and phase (pitch phase portrait, Fig. 8).
#pragma once

#include <filesystem>

#include "studies/runner/config/study_file.hpp"

namespace orni::studies {

/// Exit code 0 whenever the run finished, bounded, not bounded or diverged (the verdict is in
/// summary.json); 1 when the simulation itself failed.
int runFreeFlightStudy(const Study& study, const std::filesystem::path& out_dir);

}  // namespace orni::studies
