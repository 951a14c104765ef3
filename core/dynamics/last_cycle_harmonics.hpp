// Harmonic content of the last flapping cycle of a tethered run's loads (the `last_cycle` block of
// a simulate summary): first and second harmonics of FV and FH, the first of M, the phases of the
// FV and FH peaks and the half ranges of the flexible tip's deflection and twist. The discrete
// Fourier projections are core/analysis/harmonics.hpp's on the samples of one period.
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "core/analysis/harmonics.hpp"
#include "core/dynamics/load_sample.hpp"

namespace orni {

struct LastCycleHarmonics {
  Harmonic FV_1f, FV_2f, FH_1f, FH_2f, M_1f;  ///< N, N, N, N, N m
  double FV_peak_phase = 0.0, FH_peak_phase = 0.0;  ///< fraction of the period, [0, 1)
  double tip_deflection_amplitude_m = 0.0;          ///< half range over the cycle
  double tip_twist_amplitude_rad = 0.0;
};

/// The last cycle of `loads` (uniform samples, samples_per_cycle per cycle, the last sample ends
/// the cycle): its samples_per_cycle samples before the last one (endpoint excluded). Empty when
/// `loads` holds less than a whole cycle (samples_per_cycle + 1 samples) or samples_per_cycle < 1.
std::optional<LastCycleHarmonics> lastCycleHarmonics(const std::vector<LoadSample>& loads,
                                                     std::size_t samples_per_cycle);

}  // namespace orni
