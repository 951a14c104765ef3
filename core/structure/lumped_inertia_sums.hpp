// The wing's inertial loads as nodal sums over the lumped FE mesh (docs/theory.md 4.4, level L3 of
// 4.5), evaluated in O(M^2) instead of O(nodes M). Every node's position, velocity and
// acceleration in the rotating W frame is linear in the generalised vector c = [1, q] (or
// [0, q'], [0, q'']) through G_p = [x_p, Phi_p] (3 x (1 + M)), so every sum the loads need is a
// bilinear form sum_p m_p (G_p a)(G_p b)^T = [a^T B_kl b]_kl with B_kl = sum_p m_p G_p(k,:)^T
// G_p(l,:), precomputed once per wing. The result equals the per-node loop (the reference kept in
// tests/unit/structure/test_lumped_inertia_sums.cpp) up to round-off, with the terms of order q^2
// that the invariants' linear level (L2) drops.
#pragma once

#include <vector>

#include "core/structure/fe_types.hpp"

namespace orni::structure {

/// The precomputed sums of one wing's lumped mesh; positions from the W origin (x_p = node
/// position + Phi_p q).
struct LumpedInertiaSums {
  Eigen::Matrix3Xd first_moments;           ///< sum_p m_p G_p: [sum m x_p, sum m Phi_p] (3 x (1+M))
  /// [B_00 B_01 ... B_22] side by side ((1+M) x 9(1+M)): B_kl is block 3k + l, so one product
  /// c^T B gives c^T B_kl for all nine (k, l).
  Eigen::MatrixXd second_moments;
  Eigen::MatrixXd modal_mass;               ///< sum_p m_p Phi_p^T Phi_p (M x M): trace of B's q block
  Mat3 rotary_W_kgm2 = Mat3::Zero();        ///< sum_p J_p, the nodes' rigid rotary inertia

  int modeCount() const { return static_cast<int>(first_moments.cols()) - 1; }
  bool empty() const { return first_moments.cols() == 0; }
};

LumpedInertiaSums lumpedInertiaSums(const Eigen::VectorXd& nodal_mass_kg,
                                    const std::vector<Mat3>& nodal_rotary_W_kgm2,
                                    const std::vector<Eigen::Matrix3Xd>& phi_W,
                                    const std::vector<Vec3>& nodes_W_m);

/// The wing's inertial loads in a frame W turning at omega_W with angular acceleration alpha_W
/// about its origin (fixed): a_p = alpha x x_p + w x (w x x_p) + 2 w x Phi_p q' + Phi_p q''.
struct WingInertialLoads {
  Vec3 force_W_N = Vec3::Zero();         ///< -sum m_p a_p
  Vec3 moment_W_Nm = Vec3::Zero();       ///< -sum m_p x_p x a_p - J alpha, about the W origin
  double kinetic_energy_rate_W = 0.0;    ///< sum m_p a_p . v_p, v_p = w x x_p + Phi_p q'
  Vec3 rotary_moment_W_Nm = Vec3::Zero();  ///< J alpha (the nodes' rigid rotary inertia)
};

/// Scratch of wingInertialLoads: the generalised vectors [1, q], [0, q'], [0, q''], the product
/// c_x^T B and the modal mass times q''.
struct LumpedInertiaWorkspace {
  Eigen::VectorXd c_x, c_u, c_w, mass_qdd;
  Eigen::RowVectorXd cx_B;
  explicit LumpedInertiaWorkspace(int modes = 0) { resize(modes); }
  void resize(int modes) {
    c_x.setZero(modes + 1);
    c_u.setZero(modes + 1);
    c_w.setZero(modes + 1);
    mass_qdd.setZero(modes);
    cx_B.setZero(9 * (modes + 1));
  }
};

/// Allocation-free once `ws` is sized for the sums' mode count (it is resized otherwise).
WingInertialLoads wingInertialLoads(const LumpedInertiaSums& sums, const Eigen::VectorXd& q,
                                    const Eigen::VectorXd& qd, const Eigen::VectorXd& qdd,
                                    const Vec3& omega_W, const Vec3& alpha_W,
                                    LumpedInertiaWorkspace* ws);

}  // namespace orni::structure
