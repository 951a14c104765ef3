// Harmonic content of one sampled period (discrete Fourier projection).
#pragma once

#include <cstddef>

namespace orni {

struct Harmonic {
  double amplitude = 0.0;  ///< a_n in x(t) = mean + sum a_n cos(n w t + phase_n)
  double phase_rad = 0.0;
};

/// Mean of one period sampled uniformly at N points t_i = t0 + i T/N (endpoint excluded). The
/// trapezoid rule on a periodic signal is spectrally accurate.
double periodMean(const double* x, std::size_t n, std::size_t stride = 1);

/// Harmonic `order` (1 = the fundamental) of one period sampled as in periodMean, with phase
/// relative to the start of the period.
Harmonic periodHarmonic(const double* x, std::size_t n, int order, std::size_t stride = 1);

/// Fraction of the period in [0, 1) at which the sampled signal peaks.
double peakPhase(const double* x, std::size_t n, std::size_t stride = 1);

/// Half of (max - min) of the n samples (0 for none).
double periodHalfRange(const double* x, std::size_t n, std::size_t stride = 1);

}  // namespace orni
