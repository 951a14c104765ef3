#include "core/analysis/limit_cycle.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace orni {

namespace {
constexpr double kTwoPi = 6.283185307179586;
}  // namespace

int limitCycleWindowCycles(int analysed_cycles, int samples_per_cycle, int window_samples) {
  const int fit = std::max(1, window_samples / std::max(1, samples_per_cycle));
  return std::min(analysed_cycles, fit);
}

Spectrum amplitudeSpectrum(const double* x, std::size_t n, double dt_s, double max_freq_hz,
                           std::size_t period_samples) {
  Spectrum s;
  if (n < 2) return s;
  // Remove the mean and the trend between the first and the last period's means (a climbing or
  // sinking flight would otherwise leak into every bin; a periodic signal has no such trend, so
  // its harmonics are untouched).
  double slope = 0.0;
  if (period_samples > 0 && n >= 2 * period_samples) {
    double m1 = 0.0, m2 = 0.0;
    for (std::size_t i = 0; i < period_samples; ++i) {
      m1 += x[i];
      m2 += x[n - period_samples + i];
    }
    slope = (m2 - m1) / static_cast<double>(period_samples) /
            static_cast<double>(n - period_samples);
  }
  double mean = 0.0;
  for (std::size_t i = 0; i < n; ++i) mean += x[i];
  mean /= static_cast<double>(n);
  const double mid = 0.5 * static_cast<double>(n - 1);
  const double df = 1.0 / (static_cast<double>(n) * dt_s);
  const std::size_t kmax = std::min(n / 2, static_cast<std::size_t>(max_freq_hz / df));
  for (std::size_t k = 0; k <= kmax; ++k) {
    // Rotating phasor (exact restart every 256 samples keeps the recurrence accurate).
    const double w = -kTwoPi * static_cast<double>(k) / static_cast<double>(n);
    double re = 0.0, im = 0.0;
    double cr = 1.0, ci = 0.0;
    const double sr = std::cos(w), si = std::sin(w);
    for (std::size_t i = 0; i < n; ++i) {
      if ((i & 255u) == 0) {
        cr = std::cos(w * static_cast<double>(i));
        ci = std::sin(w * static_cast<double>(i));
      }
      const double v = x[i] - mean - slope * (static_cast<double>(i) - mid);
      re += v * cr;
      im += v * ci;
      const double nr = cr * sr - ci * si;
      ci = cr * si + ci * sr;
      cr = nr;
    }
    const double scale = (k == 0 || 2 * k == n) ? 1.0 : 2.0;
    s.freq_hz.push_back(static_cast<double>(k) * df);
    s.amplitude.push_back(scale * std::hypot(re, im) / static_cast<double>(n));
  }
  return s;
}

double dominantFrequency(const Spectrum& s) {
  double best = -1.0, f = 0.0;
  for (std::size_t k = 1; k < s.amplitude.size(); ++k)
    if (s.amplitude[k] > best) {
      best = s.amplitude[k];
      f = s.freq_hz[k];
    }
  return f;
}

std::vector<double> periodMovingAverage(const std::vector<double>& x, int samples_per_cycle) {
  const std::size_t n = x.size();
  std::vector<double> out(n, 0.0);
  if (n == 0) return out;
  std::vector<double> cum(n + 1, 0.0);
  for (std::size_t i = 0; i < n; ++i) cum[i + 1] = cum[i] + x[i];
  const std::size_t spc = static_cast<std::size_t>(samples_per_cycle);
  const std::size_t half = spc / 2;
  for (std::size_t i = 0; i < n; ++i) {
    std::size_t lo = i >= half ? i - half : 0;
    std::size_t hi = lo + spc;
    if (hi > n) {  // near the end: keep a whole period when there is one
      hi = n;
      lo = n >= spc ? n - spc : 0;
    }
    out[i] = (cum[hi] - cum[lo]) / static_cast<double>(hi - lo);
  }
  return out;
}

LimitCycleMetrics analyseLimitCycle(const std::vector<double>& t_s,
                                    const std::vector<double>& delta_M_rad,
                                    const std::vector<double>& theta_rad,
                                    const std::vector<double>& h_m, std::size_t first,
                                    int samples_per_cycle, double freq_hz) {
  LimitCycleMetrics m;
  const std::size_t n = t_s.size();
  if (first >= n || n - first < static_cast<std::size_t>(samples_per_cycle))
    throw std::invalid_argument("limit-cycle analysis needs at least one cycle after the transient");
  const std::size_t spc = static_cast<std::size_t>(samples_per_cycle);
  const std::size_t cycles = (n - 1 - first) / spc;
  const std::size_t end = first + cycles * spc;  // whole cycles, endpoint excluded
  m.theta_min_rad = *std::min_element(theta_rad.begin() + static_cast<long>(first),
                                      theta_rad.begin() + static_cast<long>(end));
  m.theta_max_rad = *std::max_element(theta_rad.begin() + static_cast<long>(first),
                                      theta_rad.begin() + static_cast<long>(end));
  const std::vector<double> h_win(h_m.begin() + static_cast<long>(first),
                                  h_m.begin() + static_cast<long>(end));
  const std::vector<double> h_avg = periodMovingAverage(h_win, samples_per_cycle);
  std::vector<double> p2p;
  for (std::size_t c = 0; c < cycles; ++c) {
    double lo = 1e300, hi = -1e300;
    for (std::size_t i = c * spc; i < (c + 1) * spc; ++i) {
      const double v = h_win[i] - h_avg[i];
      lo = std::min(lo, v);
      hi = std::max(hi, v);
    }
    p2p.push_back(hi - lo);
  }
  std::nth_element(p2p.begin(), p2p.begin() + static_cast<long>(p2p.size() / 2), p2p.end());
  m.altitude_p2p_fast_m = p2p[p2p.size() / 2];
  const double slope = leastSquaresSlope(h_avg);
  double lo = 1e300, hi = -1e300;
  for (std::size_t i = 0; i < h_avg.size(); ++i) {
    const double v = h_avg[i] - slope * static_cast<double>(i);
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  m.altitude_p2p_slow_m = hi - lo;
  const double dt = 1.0 / (freq_hz * static_cast<double>(spc));
  m.climb_rate_mps = slope / dt;
  const double fmax = std::max(40.0, 4.0 * freq_hz);
  const std::size_t len = end - first;
  m.spectrum_delta = amplitudeSpectrum(delta_M_rad.data() + first, len, dt, fmax, spc);
  m.spectrum_theta = amplitudeSpectrum(theta_rad.data() + first, len, dt, fmax, spc);
  m.spectrum_h = amplitudeSpectrum(h_m.data() + first, len, dt, fmax, spc);
  m.dominant_freq_delta_hz = dominantFrequency(m.spectrum_delta);
  m.dominant_freq_theta_hz = dominantFrequency(m.spectrum_theta);
  m.dominant_freq_h_hz = dominantFrequency(m.spectrum_h);
  return m;
}

}  // namespace orni
