// Trim studies with [trim] method = "periodic" (`ornithopter trim --method periodic`) and
// `ornithopter stability`: the periodic orbit of free flight and its Floquet multipliers
// (trim/periodic_trim.hpp). Writes into the output folder (docs/design.md 4):
//   summary.json          the trim contract keys (freq_hz, theta_mean_deg, speed_mps,
//                         tail_angle_deg, residual, free_flight) plus method, periodic_residual,
//                         floquet {multipliers [{modulus, argument_deg, ...}], stable,
//                         max_modulus, margin, ...}, the orbit's start state, its cycle means, the
//                         Eq. (4) start and the solver's counts; kind "stability" for the
//                         subcommand;
//   study.resolved.toml   the study with every default (re-runs the same trim);
//   periodic_orbit.csv    one period of the orbit from flap phase 0 (body states, loads, power);
//   periodic_iterations.csv  the Newton iterations (scaled residual, step, period maps);
//   floquet.csv           the multipliers by modulus: value, continuous exponent, damping ratio,
//                         period, label and dominant states;
//   floquet_multipliers.png/.svg  the multipliers in the complex plane with the unit circle;
//   periodic_orbit.png/.svg       theta, airspeed, W and altitude over the period.
#pragma once

#include <filesystem>

#include "studies/runner/config/study_file.hpp"

namespace orni::studies {

/// What the run is called in summary.json: a trim study, or the stability subcommand.
enum class PeriodicRunKind { kTrim, kStability };

/// Run the periodic trim of `study` (study.trim.method must be periodic) into `out_dir`. Returns 0
/// when the solve finished, converged or not (the verdict and the reason are in summary.json).
/// Bad input throws InputError (exit 2); other exceptions are failures (exit 1).
int runPeriodicTrimStudy(const Study& study, const std::filesystem::path& out_dir,
                         PeriodicRunKind kind = PeriodicRunKind::kTrim);

}  // namespace orni::studies
