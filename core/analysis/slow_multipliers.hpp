// The slowest motion of a transient sampled once a period (e.g. the cycle means of a free flight)
// by a linear-prediction fit of order two with a constant (Prony's method):
//
//   y_k = a1 y_{k-1} + a2 y_{k-2} + b,   least squares over the sequence,
//
// whose characteristic roots z^2 - a1 z - a2 = 0 are the multipliers of the motion left in y and
// whose fixed point b / (1 - a1 - a2) is the value y settles to. Exact for a linear system once
// every motion but one complex pair (or two real modes) has decayed: the phugoid of a flapping
// vehicle, whose Floquet multipliers (floquet.hpp) are the slowest by far (magpie: |mu| ~0.98
// against ~0.3 for the short period and < 0.25 for the wing). A sequence that holds more than
// that, or noise only, fits badly: relative_residual says how well.
#pragma once

#include <complex>
#include <limits>
#include <vector>

namespace orni {

struct SlowMultiplierFit {
  bool ok = false;  ///< at least 8 values with a spread above rounding and a solvable fit
  /// The two roots, |mu[0]| >= |mu[1]| (a complex pair: conjugates, mu[0] with Im >= 0).
  std::complex<double> mu[2];
  double modulus = std::numeric_limits<double>::quiet_NaN();  ///< |mu[0]|: < 1 decays
  /// The fixed point of the fitted recursion (NaN when a1 + a2 = 1: no fixed point).
  double limit = std::numeric_limits<double>::quiet_NaN();
  /// RMS of the fit's residual over the RMS of y about its mean: ~0 for a clean two-root motion.
  double relative_residual = std::numeric_limits<double>::quiet_NaN();
  double a1 = 0.0, a2 = 0.0;  ///< the recursion's coefficients
};

/// A fit is used (its multiplier and fixed point trusted) when its relative_residual is at most
/// this: a settling free flight of the magpie fits to 2e-4 - 1e-3 (rigid and flexible wing, any
/// stretch of 60-600 cycles while the phugoid is above the integrator's noise), a stretch left
/// with noise only to 0.07 and more.
constexpr double kCleanSlowFitResidual = 0.01;

/// Fit of the sequence y (one value a period, oldest first); ok false for fewer than 8 values, a
/// constant sequence or a singular fit.
SlowMultiplierFit fitSlowMultipliers(const std::vector<double>& y);

/// The value another sequence z of the same motion (the same periods) settles to under the fitted
/// recursion: z_k = a1 z_{k-1} + a2 z_{k-2} + c with c by least squares (the mean of
/// z_k - a1 z_{k-1} - a2 z_{k-2}), limit c / (1 - a1 - a2). NaN without a fit, for fewer than 3
/// values or when a1 + a2 = 1.
double settledValue(const SlowMultiplierFit& fit, const std::vector<double>& z);

}  // namespace orni
