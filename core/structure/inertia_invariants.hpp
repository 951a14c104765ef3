// Inertia invariants of the modal wing about P2 in W components (docs/theory.md 3.6): the
// consistent-mass operator form and the nodal-sum form (test oracle).
#pragma once

#include <array>
#include <vector>

#include "core/structure/fe_types.hpp"

namespace orni::structure {

struct InertiaInvariants {
  double mass_kg = 0.0;                           ///< m_w (I1)
  Vec3 first_moment_W_kgm = Vec3::Zero();         ///< c0 = sum m x (I2), x from P2
  Mat3 inertia_P2_W_kgm2 = Mat3::Zero();          ///< J0 about P2, incl. rotary inertia (I7)
  Eigen::Matrix3Xd translational_participation;   ///< L (3 x M) (I3)
  Eigen::Matrix3Xd rotational_participation;      ///< H (3 x M), incl. rotary inertia (I4)
  std::array<Eigen::MatrixXd, 9> p;               ///< P_kl = p[3k + l] (M x M), P_lk = P_kl^T
  std::array<Eigen::VectorXd, 9> s;               ///< S_kl = s[3k + l] (M)
  Eigen::MatrixXd generalized_mass;               ///< Phi^T M Phi (= I for mass-normalised modes)

  const Eigen::MatrixXd& P(int k, int l) const { return p[static_cast<std::size_t>(3 * k + l)]; }
  const Eigen::VectorXd& S(int k, int l) const { return s[static_cast<std::size_t>(3 * k + l)]; }
  int modeCount() const { return static_cast<int>(generalized_mass.rows()); }
};

/// Operator form with any (consistent or lumped) M: L = (Phi^T M R_t)^T, H = (Phi^T M R_r)^T,
/// S_kl = Phi^T M V_kl, P_kl = Phi^T M B_kl Phi, m and c0 from R_t^T M R_t and R_t^T M V,
/// J0 = R_r^T M R_r. `shapes` is 6n x M over all nodes; positions are taken relative to
/// `origin_W_m` (P2).
InertiaInvariants invariantsOperatorForm(const SparseMatrix& mass, const Eigen::MatrixXd& shapes,
                                         const std::vector<Vec3>& nodes_W_m,
                                         const Vec3& origin_W_m);

/// Nodal-sum form with point masses m_p and optional rotary blocks J_p (3 x 3, W; empty vector =
/// none): the sums of the docs/theory.md 3.6 table.
InertiaInvariants invariantsNodalSums(const Eigen::VectorXd& nodal_mass_kg,
                                      const std::vector<Mat3>& nodal_rotary_W_kgm2,
                                      const Eigen::MatrixXd& shapes,
                                      const std::vector<Vec3>& nodes_W_m, const Vec3& origin_W_m);

}  // namespace orni::structure
