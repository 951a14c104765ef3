// Tension-field membrane law (tension_field.hpp, docs/theory.md 4.7).
#include "core/structure/tension_field.hpp"

#include <cmath>

namespace orni::structure {

bool FilmLaw::IsValid(std::string* why) const {
  if (!(residual_stiffness > 0.0 && residual_stiffness <= 1.0)) {
    if (why != nullptr)
      *why = "the film's residual stiffness (kappa) " + std::to_string(residual_stiffness) +
           " is outside (0, 1]";
    return false;
  }
  if (!(compression_cap_n_per_m >= 0.0 && std::isfinite(compression_cap_n_per_m))) {
    if (why != nullptr)
      *why = "the film's compression cap " + std::to_string(compression_cap_n_per_m) +
           " N/m is not a finite value >= 0";
    return false;
  }
  return true;
}

RelaxedMembrane relaxedMembrane(const Eigen::Vector3d& strain, double et_n_per_m, double nu,
                                const FilmLaw& law, FilmOutput output) {
  const bool with_tangent = output == FilmOutput::kWithTangent;
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

  // The cap's strains: c_cap = Nc (1 - nu^2) / (E t), s_cap = (1 - nu) Nc / (E t) (header).
  const double nc = law.compression_cap_n_per_m;
  const double c_cap = nc * (1.0 - nu * nu) / et_n_per_m;
  const double s_cap = (1.0 - nu) * nc / et_n_per_m;
  const Eigen::Vector3d trace_gradient(1.0, 1.0, 0.0);  // d (e_xx + e_yy) / d eps

  RelaxedMembrane out;
  if (e1 <= -s_cap) {
    // Slack: an isotropic compression Nc (nothing for the pure tension field).
    out.state = FilmState::kSlack;
    out.energy_j_per_m2 = -nc * (2.0 * m) - 0.5 * nc * c_cap - 0.5 * nc * s_cap * (1.0 - nu);
    out.stress_n_per_m = -nc * trace_gradient;
  } else if (e2 + nu * e1 > -c_cap) {
    out.state = FilmState::kTaut;
    out.energy_j_per_m2 = w_elastic;
    out.stress_n_per_m = n_elastic;
    if (with_tangent) out.tangent_n_per_m = c;
  } else {
    // Wrinkled: tension T = E t e1 + (1 - nu) Nc along the first principal direction, less Nc
    // isotropically (principal stresses E t e1 - nu Nc and -Nc). Here r = (e1 - e2) / 2 >=
    // ((1 + nu) e1 + c_cap) / 2 > 0 (as e1 > -s_cap), so the derivatives of r exist.
    out.state = FilmState::kWrinkled;
    const Eigen::Vector3d de1(0.5 + 0.5 * a / r, 0.5 - 0.5 * a / r, 0.5 * b / r);  // (c^2, s^2, cs)
    const double tension = et_n_per_m * e1 + (1.0 - nu) * nc;
    out.energy_j_per_m2 =
        0.5 * et_n_per_m * e1 * e1 + (1.0 - nu) * nc * e1 - nc * (2.0 * m) - 0.5 * nc * c_cap;
    out.stress_n_per_m = tension * de1 - nc * trace_gradient;
    if (with_tangent) {
      // d2 r / d eps2 = J^T [b^2 -ab; -ab a^2] J / r^3, J = d(a, b)/d eps = [1/2 -1/2 0; 0 0 1/2].
      Eigen::Matrix<double, 2, 3> j;
      j << 0.5, -0.5, 0.0, 0.0, 0.0, 0.5;
      Eigen::Matrix2d hr;
      hr << b * b, -a * b, -a * b, a * a;
      const Eigen::Matrix3d d2e1 = j.transpose() * hr * j / (r * r * r);
      out.tangent_n_per_m = et_n_per_m * de1 * de1.transpose() + tension * d2e1;
    }
  }
  const double k = law.residual_stiffness;
  out.energy_j_per_m2 = (1.0 - k) * out.energy_j_per_m2 + k * w_elastic;
  out.stress_n_per_m = (1.0 - k) * out.stress_n_per_m + k * n_elastic;
  if (with_tangent) out.tangent_n_per_m = (1.0 - k) * out.tangent_n_per_m + k * c;
  return out;
}

}  // namespace orni::structure
