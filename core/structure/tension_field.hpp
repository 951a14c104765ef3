// Tension-field (wrinkling) membrane law of the skin: a film that cannot carry compression
// (docs/theory.md 4.7, "A film that wrinkles").
//
// A 0.04 mm film buckles as a panel at about 10-60 N/m of compression on the EFW, and then
// wrinkles on a scale far finer than any practical mesh; its mean surface carries only tension.
// The relaxed strain energy of an isotropic linear film (Pipkin 1986; Steigmann 1990), in the
// principal membrane strains e1 >= e2 of eps = (e_xx, e_yy, gamma_xy):
//
//   taut     (e2 + nu e1 > 0):            W = 1/2 eps^T C eps       (both principal stresses > 0)
//   wrinkled (e1 > 0 >= e2 + nu e1):      W = 1/2 E t e1^2          (uniaxial tension along e1)
//   slack    (e1 <= 0):                   W = 0,
//
// per unit area, C = E t / (1 - nu^2) [1 nu 0; nu 1 0; 0 0 (1 - nu)/2]. W is convex in the
// strain and continuously differentiable (the wrinkled branch meets the taut one at e2 = -nu e1
// with equal value and gradient); the stress is N = dW/d eps, the tangent dN/d eps. A fraction
// kappa of the elastic energy is kept everywhere, W_kappa = (1 - kappa) W + kappa 1/2 eps^T C eps
// (the residual stiffness of Miller & Hedgepeth's wrinkling models): it keeps the Newton matrix of
// a slack region nonsingular and bounds the compression the film carries at kappa C e.
#pragma once

#include <Eigen/Core>

namespace orni::structure {

/// Which state of the film a strain puts it in.
enum class FilmState { kTaut, kWrinkled, kSlack };

/// The residual fraction kappa of the elastic membrane energy a tension-field film keeps. At
/// 1e-4 the wrinkled EFW skin (E t = 4e6 N/m) carries at most 0.4 N/m of compression per 1e-3
/// of compressive strain, far below its panels' buckling loads (10-60 N/m), while its slack
/// in-plane stiffness (400 N/m) stays above its bending stiffness per node (D / h^2 ~ 25 N/m).
inline constexpr double kTensionFieldResidualStiffness = 1e-4;

struct RelaxedMembrane {
  double energy_j_per_m2 = 0.0;                   ///< W_kappa
  Eigen::Vector3d stress_n_per_m = Eigen::Vector3d::Zero();  ///< (N_xx, N_yy, N_xy)
  Eigen::Matrix3d tangent_n_per_m = Eigen::Matrix3d::Zero(); ///< dN / d eps (symmetric)
  FilmState state = FilmState::kTaut;
};

/// The relaxed film at the membrane strain eps (gamma engineering shear) for a film of membrane
/// stiffness E t (N/m) and Poisson ratio nu, keeping the fraction `residual_stiffness` (kappa,
/// in [0, 1]) of the elastic energy.
RelaxedMembrane relaxedMembrane(const Eigen::Vector3d& strain, double et_n_per_m, double nu,
                                double residual_stiffness = kTensionFieldResidualStiffness);

}  // namespace orni::structure
