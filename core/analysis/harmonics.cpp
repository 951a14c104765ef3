#include "core/analysis/harmonics.hpp"

#include <algorithm>

#include <cmath>

#include "core/model/frames.hpp"

namespace orni {

double periodMean(const double* x, std::size_t n, std::size_t stride) {
  double s = 0.0;
  for (std::size_t i = 0; i < n; ++i) s += x[i * stride];
  return n ? s / static_cast<double>(n) : 0.0;
}

Harmonic periodHarmonic(const double* x, std::size_t n, int order, std::size_t stride) {
  double c = 0.0, s = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double a = 2.0 * kPi * order * static_cast<double>(i) / static_cast<double>(n);
    c += x[i * stride] * std::cos(a);
    s += x[i * stride] * std::sin(a);
  }
  c *= 2.0 / static_cast<double>(n);
  s *= 2.0 / static_cast<double>(n);
  Harmonic h;
  h.amplitude = std::hypot(c, s);
  h.phase_rad = std::atan2(-s, c);  // x = A cos(w t + phase)
  return h;
}

double peakPhase(const double* x, std::size_t n, std::size_t stride) {
  std::size_t best = 0;
  for (std::size_t i = 1; i < n; ++i)
    if (x[i * stride] > x[best * stride]) best = i;
  return n ? static_cast<double>(best) / static_cast<double>(n) : 0.0;
}

double periodHalfRange(const double* x, std::size_t n, std::size_t stride) {
  if (n == 0) return 0.0;
  double lo = x[0], hi = x[0];
  for (std::size_t i = 1; i < n; ++i) {
    lo = std::min(lo, x[i * stride]);
    hi = std::max(hi, x[i * stride]);
  }
  return 0.5 * (hi - lo);
}

}  // namespace orni
