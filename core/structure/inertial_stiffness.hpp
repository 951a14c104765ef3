// The modal stiffness of the inertial loads on the moving wing frame (docs/theory.md 3.6, 4.3,
// 4.6): spin softening K_w(w) from the inertia invariants and geometric stiffening K_G(p) from the
// unit inertial stress states, combined as the vehicle's wing.fe.inertial_stiffness asks:
//   K_inertial = sum_kl w_k w_l spin_kl + sum_j p_j linear_j,
// spin_kl = [P_kl - delta_kl sum_j P_jj] (softening; sum_j P_jj is the translational part of
// M_qq, docs/theory.md 3.6, so that the softening is exactly that of the nodal masses) + K^_G of
// w_k w_l (stiffening, split evenly between (k, l) and (l, k)); linear_j = K^_G of the
// acceleration loads (a_O - g_W) and alpha whose K^_G is not zero (for the flat wing: the
// in-plane ones (a_O - g_W)_x, _y and alpha_z).
#pragma once

#include <array>
#include <vector>

#include "core/model/vehicle_model.hpp"
#include "core/structure/geometric_stiffness.hpp"
#include "core/structure/inertia_invariants.hpp"

namespace orni::structure {

struct ModalInertialStiffness {
  /// spin[3k + l] (M x M): K_w(w) + K_G(w) = sum_kl w_k w_l spin[3k + l], (rad/s)^-2 per unit
  /// generalised stiffness.
  std::array<Eigen::MatrixXd, 9> spin;
  /// The acceleration loads (kLoadAccelX .. kLoadAlphaZ) with a nonzero K^_G, ascending; empty
  /// unless geometric stiffening is on.
  std::vector<InertialLoad> linear_loads;
  /// (n M) x M: block j (rows j M .. j M + M - 1) = K^_G of linear_loads[j].
  Eigen::MatrixXd linear_stack;

  const Eigen::MatrixXd& spinAbout(int k, int l) const {
    return spin[static_cast<std::size_t>(3 * k + l)];
  }
};

/// Combines the invariants (softening) and the modal geometric stiffness (stiffening) per
/// `model`. `kg` may be empty only when the model has no stiffening. A K^_G counts as zero when
/// its largest entry is below 1e-12 of the largest entry of all K^_G (docs/theory.md 4.6: only
/// in-plane loads stress a flat wing). Throws std::invalid_argument for an empty `kg` with
/// stiffening on or for sizes that do not match.
ModalInertialStiffness modalInertialStiffness(const InertiaInvariants& invariants,
                                              const ModalGeometricStiffness& kg,
                                              InertialStiffness model);

/// The value of an acceleration load parameter (kLoadAccelX .. kLoadAlphaZ) from a_O - g_W
/// (m/s^2) and alpha (rad/s^2), W components.
inline double linearLoadValue(InertialLoad load, const Eigen::Vector3d& a_O_minus_g_W,
                              const Eigen::Vector3d& alpha_W) {
  return load < kLoadAlphaX ? a_O_minus_g_W[load - kLoadAccelX] : alpha_W[load - kLoadAlphaX];
}

}  // namespace orni::structure
