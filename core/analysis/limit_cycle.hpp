// Limit-cycle analysis of a free flight (paper section 4, Figs. 6-8) on uniformly sampled
// histories (samples_per_cycle per flapping cycle); the bounded-norm trim criterion (paper Eq. 5)
// is in bounded_norm.hpp.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "core/analysis/bounded_norm.hpp"

namespace orni {

/// Single-sided amplitude spectrum of a uniformly sampled signal over a whole number of flapping
/// cycles (rectangular window, so the flapping harmonics fall on bins).
struct Spectrum {
  std::vector<double> freq_hz;
  std::vector<double> amplitude;  ///< |X(f)|: amplitude of the sinusoid at f, signal units
};

/// DFT bins 0 .. max_freq_hz of x (n samples at spacing dt_s), mean removed; with
/// period_samples > 0 also the trend between the first and the last period means.
Spectrum amplitudeSpectrum(const double* x, std::size_t n, double dt_s, double max_freq_hz,
                           std::size_t period_samples = 0);

/// Frequency of the largest non-zero bin.
double dominantFrequency(const Spectrum& s);

/// One period moving average (centred, window = samples_per_cycle samples; ends shortened).
std::vector<double> periodMovingAverage(const std::vector<double>& x, int samples_per_cycle);

struct LimitCycleMetrics {
  double theta_min_rad = 0, theta_max_rad = 0;
  double altitude_p2p_fast_m = 0;   ///< median per-cycle peak-to-peak of h minus its one-period
                                    ///< moving average (the flapping-frequency oscillation)
  double altitude_p2p_slow_m = 0;   ///< peak-to-peak of the moving average after removing its
                                    ///< linear trend (the long-period oscillation)
  double climb_rate_mps = 0;        ///< slope of that linear trend
  double dominant_freq_theta_hz = 0, dominant_freq_h_hz = 0, dominant_freq_delta_hz = 0;
  Spectrum spectrum_delta, spectrum_theta, spectrum_h;  ///< same bins
};

/// Whole cycles of the limit-cycle window of a run with `analysed_cycles` cycles after the
/// transient: the last ones that fit in `window_samples` samples, at least one
/// (FreeFlightOptions::limit_cycle_window_samples).
int limitCycleWindowCycles(int analysed_cycles, int samples_per_cycle, int window_samples);

/// Metrics over samples [first, n) of the histories (first at a cycle boundary).
LimitCycleMetrics analyseLimitCycle(const std::vector<double>& t_s,
                                    const std::vector<double>& delta_M_rad,
                                    const std::vector<double>& theta_rad,
                                    const std::vector<double>& h_m, std::size_t first,
                                    int samples_per_cycle, double freq_hz);

}  // namespace orni
