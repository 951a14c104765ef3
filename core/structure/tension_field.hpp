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
//
// A wrinkled film still carries some compression across its wrinkles: about their buckling load
// (a panel of the EFW's 0.04 mm skin between its stiffeners buckles at 10-60 N/m). The law may keep
// a compression cap Nc >= 0 for it: the film may shorten by a wrinkling strain omega >= 0 along its
// second principal direction at the cost Nc omega, W_Nc(eps) = min_omega W_el(eps + omega) + Nc
// omega (an inf-convolution of convex functions: convex, C1), which gives, with c = Nc (1 -
// nu^2) / (E t) and s = (1 - nu) Nc / (E t):
//
//   taut     (e2 + nu e1 > -c):  W = 1/2 eps^T C eps
//   wrinkled (between):          W = 1/2 E t e1^2 + (1 - nu) Nc e1 - Nc (e_xx + e_yy) - Nc c / 2,
//                                principal stresses E t e1 - nu Nc along e1 and -Nc across
//   slack    (e1 <= -s):         W = -Nc (e_xx + e_yy) - Nc c / 2 - (1 - nu)^2 Nc^2 / (2 E t),
//                                an isotropic compression Nc
//
// (Nc = 0 is the tension field above; the constants make W continuous.) Kappa is mixed in as above.
#pragma once

#include <string>

#include <Eigen/Core>

namespace orni::structure {

/// Which state of the film a strain puts it in.
enum class FilmState { kTaut, kWrinkled, kSlack };

/// The residual fraction kappa of the elastic membrane energy a tension-field film keeps. At
/// 1e-4 the wrinkled EFW skin (E t = 4e6 N/m) carries at most 0.4 N/m of compression per 1e-3
/// of compressive strain, far below its panels' buckling loads (10-60 N/m), while its slack
/// in-plane stiffness (400 N/m) stays above its bending stiffness per node (D / h^2 ~ 25 N/m).
inline constexpr double kTensionFieldResidualStiffness = 1e-4;

/// The film law's parameters.
struct FilmLaw {
  /// kappa, the residual fraction of the elastic energy, in (0, 1].
  double residual_stiffness = kTensionFieldResidualStiffness;
  /// Nc (N/m, >= 0): the compression a wrinkled film keeps (its wrinkles' buckling load); 0 is
  /// the tension field of Pipkin.
  double compression_cap_n_per_m = 0.0;
  /// False with a reason naming the parameter when kappa is outside (0, 1] or Nc negative or not
  /// finite.
  bool IsValid(std::string* why) const;
};

/// What relaxedMembrane computes: energy and stress (an internal force, a line search) or also the
/// tangent (a Newton matrix).
enum class FilmOutput { kEnergyAndStress, kWithTangent };

struct RelaxedMembrane {
  double energy_j_per_m2 = 0.0;                   ///< W_kappa
  Eigen::Vector3d stress_n_per_m = Eigen::Vector3d::Zero();  ///< (N_xx, N_yy, N_xy)
  Eigen::Matrix3d tangent_n_per_m = Eigen::Matrix3d::Zero(); ///< dN / d eps (symmetric)
  FilmState state = FilmState::kTaut;
};

/// The relaxed film at the membrane strain eps (gamma engineering shear) for a film of membrane
/// stiffness E t (N/m) and Poisson ratio nu with the law `law` (kappa in [0, 1] here: 0 is the
/// pure relaxed energy, for checks). With kEnergyAndStress the tangent is left zero.
RelaxedMembrane relaxedMembrane(const Eigen::Vector3d& strain, double et_n_per_m, double nu,
                                const FilmLaw& law = {},
                                FilmOutput output = FilmOutput::kWithTangent);

}  // namespace orni::structure
