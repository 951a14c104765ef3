#include "core/dynamics/chordwise_weights.hpp"

#include <cmath>
#include <stdexcept>

#include "core/model/frames.hpp"

namespace orni {

ChordwiseWeights flatPlateChordwiseWeights(const std::array<double, 4>& x) {
  if (!(x[0] == 0.0 && x[1] > x[0] && x[2] > x[1] && x[3] > x[2] && std::isfinite(x[3])))
    throw std::invalid_argument(
        "chordwise weights: node positions must increase strictly from 0 (L, Q, T, E)");
  const double c = x[3];
  ChordwiseWeights w;
  // On [xi_k, xi_k+1] with xi = (1 - cos t)/2 the hat functions are A + B cos t; the loadings per
  // unit dt are Birnbaum (1 + cos t)/pi and elliptic 2 sin^2 t/pi (each integrates to 1).
  // Antiderivatives: I1 = sin t, I2 = t/2 + sin 2t/4 (cos^2), S0 = t/2 - sin 2t/4 (sin^2),
  // S1 = sin^3 t/3 (sin^2 cos).
  const auto I1 = [](double t) { return std::sin(t); };
  const auto I2 = [](double t) { return 0.5 * t + 0.25 * std::sin(2.0 * t); };
  const auto S0 = [](double t) { return 0.5 * t - 0.25 * std::sin(2.0 * t); };
  const auto S1 = [](double t) { const double s = std::sin(t); return s * s * s / 3.0; };
  for (int k = 0; k < 3; ++k) {
    const double xa = x[k] / c, xb = x[k + 1] / c, h = xb - xa;
    const double ta = std::acos(1.0 - 2.0 * xa), tb = std::acos(1.0 - 2.0 * xb);
    const double i0 = tb - ta, i1 = I1(tb) - I1(ta), i2 = I2(tb) - I2(ta);
    const double s0 = S0(tb) - S0(ta), s1 = S1(tb) - S1(ta);
    // Node k: N = (xb - xi)/h = (xb - 1/2)/h + cos t/(2h); node k+1: (1/2 - xa)/h - cos t/(2h).
    const double A[2] = {(xb - 0.5) / h, (0.5 - xa) / h};
    const double B[2] = {0.5 / h, -0.5 / h};
    for (int s = 0; s < 2; ++s) {
      w.force[k + s] += (A[s] * (i0 + i1) + B[s] * (i1 + i2)) / kPi;
      w.mid_chord[k + s] += 2.0 * (A[s] * s0 + B[s] * s1) / kPi;
    }
  }
  for (int i = 0; i < 4; ++i) {
    w.reference_aft_m += w.force[i] * x[i];
    w.mid_chord_aft_m += w.mid_chord[i] * x[i];
  }
  const double arm = w.mid_chord_aft_m - w.reference_aft_m;
  for (int i = 0; i < 4; ++i) w.moment[i] = (w.force[i] - w.mid_chord[i]) / arm;
  return w;
}

}  // namespace orni
