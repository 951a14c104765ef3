// Tension-field membrane law (tension_field.hpp, docs/theory.md 4.7).
#include "core/structure/tension_field.hpp"

#include <cmath>

namespace orni::structure {

RelaxedMembrane relaxedMembrane(const Eigen::Vector3d& strain, double et_n_per_m, double nu,
                                double residual_stiffness) {
  Eigen::Matrix3d c;
  c << 1.0, nu, 0.0, nu, 1.0, 0.0, 0.0, 0.0, 0.5 * (1.0 - nu);
  c *= et_n_per_m / (1.0 - nu * nu);
  const Eigen::Vector3d n_elastic = c * strain;
  const double w_elastic = 0.5 * strain.dot(n_elastic);

  // Principal strains: e1,2 = m +- r, m the mean, r the radius of Mohr's circle.
  const double m = 0.5 * (strain(0) + strain(1));
  const double a = 0.5 * (strain(0) - strain(1));
  const double b = 0.5 * strain(2);
  const double r = std::hypot(a, b);
  const double e1 = m + r;
  const double e2 = m - r;

  RelaxedMembrane out;
  if (e1 <= 0.0) {
    out.state = FilmState::kSlack;
  } else if (e2 + nu * e1 > 0.0) {
    out.state = FilmState::kTaut;
    out.energy_j_per_m2 = w_elastic;
    out.stress_n_per_m = n_elastic;
    out.tangent_n_per_m = c;
  } else {
    // Wrinkled: uniaxial tension E t e1 along the first principal direction. Here
    // r = (e1 - e2) / 2 >= (1 + nu) e1 / 2 > 0, so the derivatives of r exist.
    out.state = FilmState::kWrinkled;
    const Eigen::Vector3d de1(0.5 + 0.5 * a / r, 0.5 - 0.5 * a / r, 0.5 * b / r);  // (c^2, s^2, cs)
    // d2 r / d eps2 = J^T [b^2 -ab; -ab a^2] J / r^3, J = d(a, b)/d eps = [1/2 -1/2 0; 0 0 1/2].
    Eigen::Matrix<double, 2, 3> j;
    j << 0.5, -0.5, 0.0, 0.0, 0.0, 0.5;
    Eigen::Matrix2d hr;
    hr << b * b, -a * b, -a * b, a * a;
    const Eigen::Matrix3d d2e1 = j.transpose() * hr * j / (r * r * r);
    out.energy_j_per_m2 = 0.5 * et_n_per_m * e1 * e1;
    out.stress_n_per_m = et_n_per_m * e1 * de1;
    out.tangent_n_per_m = et_n_per_m * (de1 * de1.transpose() + e1 * d2e1);
  }
  const double k = residual_stiffness;
  out.energy_j_per_m2 = (1.0 - k) * out.energy_j_per_m2 + k * w_elastic;
  out.stress_n_per_m = (1.0 - k) * out.stress_n_per_m + k * n_elastic;
  out.tangent_n_per_m = (1.0 - k) * out.tangent_n_per_m + k * c;
  return out;
}

}  // namespace orni::structure
