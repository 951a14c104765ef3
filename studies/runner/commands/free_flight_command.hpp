// The free-flight branch of `ornithopter simulate --mode free` (paper section 4, Figs. 6-8):
// summary.json with the bounded-norm verdict and the limit-cycle metrics, histories.csv,
// spectra.csv and the figures flight (time histories and spectra), cycle (the last flapping cycle,
// Fig. 6) and phase (pitch phase portrait, Fig. 8).
#pragma once

#include <filesystem>

#include "core/dynamics/modal_wing_cache.hpp"
#include "studies/runner/config/study_file.hpp"
#include "studies/runner/output/json_writer.hpp"

namespace orni::studies {

/// Exit code 0 whenever the run finished, bounded, not bounded or diverged (the verdict is in
/// summary.json); 1 when the simulation itself failed.
/// `trim_point` (may be null): the "trim_point" object of summary.json when the study flies at its
/// trim ([simulate] at_trim). `as_given` (may be null): the study as the user gave it, written as
/// study.resolved.toml (with at_trim, `study` holds the solved trim point, `as_given` the initial
/// guess, so that the resolved study solves the same trim again: a fixed point, the same bytes).
/// `modal_wings` (may be null): where a flexible wing's modes come from (the trim's).
int runFreeFlightStudy(const Study& study, const std::filesystem::path& out_dir,
                       const JsonObject* trim_point = nullptr, const Study* as_given = nullptr,
                       ModalWingCache* modal_wings = nullptr);

}  // namespace orni::studies
