#include "core/analysis/slow_multipliers.hpp"

#include <Eigen/Dense>

#include <cmath>
#include <limits>
#include <utility>

namespace orni {

SlowMultiplierFit fitSlowMultipliers(const std::vector<double>& y) {
  SlowMultiplierFit f;
  const Eigen::Index n = static_cast<Eigen::Index>(y.size());
  if (n < 8) return f;
  // Centred and scaled: the fit then sees values of order one whatever the units.
  double mean = 0.0;
  for (double v : y) mean += v;
  mean /= static_cast<double>(n);
  double rms = 0.0;
  for (double v : y) rms += (v - mean) * (v - mean);
  rms = std::sqrt(rms / static_cast<double>(n));
  if (!(rms > 1e-14 * std::max(1.0, std::abs(mean)))) return f;
  Eigen::MatrixXd A(n - 2, 3);
  Eigen::VectorXd r(n - 2);
  for (Eigen::Index k = 2; k < n; ++k) {
    A(k - 2, 0) = (y[static_cast<std::size_t>(k - 1)] - mean) / rms;
    A(k - 2, 1) = (y[static_cast<std::size_t>(k - 2)] - mean) / rms;
    A(k - 2, 2) = 1.0;
    r(k - 2) = (y[static_cast<std::size_t>(k)] - mean) / rms;
  }
  const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(A);
  if (qr.rank() < 3) return f;
  const Eigen::Vector3d c = qr.solve(r);
  const double a1 = c(0), a2 = c(1), b = c(2);
  f.a1 = a1;
  f.a2 = a2;
  const std::complex<double> disc = std::sqrt(std::complex<double>(a1 * a1 + 4.0 * a2, 0.0));
  f.mu[0] = 0.5 * (a1 + disc);
  f.mu[1] = 0.5 * (a1 - disc);
  if (std::abs(f.mu[1]) > std::abs(f.mu[0])) std::swap(f.mu[0], f.mu[1]);
  if (f.mu[0].imag() < 0.0) f.mu[0] = std::conj(f.mu[0]), f.mu[1] = std::conj(f.mu[1]);
  f.modulus = std::abs(f.mu[0]);
  const double den = 1.0 - a1 - a2;
  if (den != 0.0) f.limit = mean + rms * b / den;
  f.relative_residual = (A * c - r).norm() / std::sqrt(static_cast<double>(n - 2));
  f.ok = std::isfinite(f.modulus);
  return f;
}

double settledValue(const SlowMultiplierFit& fit, const std::vector<double>& z) {
  const double den = 1.0 - fit.a1 - fit.a2;
  if (!fit.ok || z.size() < 3 || den == 0.0) return std::numeric_limits<double>::quiet_NaN();
  double c = 0.0;
  for (std::size_t k = 2; k < z.size(); ++k) c += z[k] - fit.a1 * z[k - 1] - fit.a2 * z[k - 2];
  return c / static_cast<double>(z.size() - 2) / den;
}

}  // namespace orni
