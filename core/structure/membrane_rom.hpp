// The skin's membrane stretching in the modal coordinates: an exact static condensation of the
// in-plane unknowns of the von Karman wing (von_karman.hpp, docs/theory.md 4.7).
//
// For a flat wing the linear stiffness does not couple the in-plane DOFs (u, v, theta_z) with the
// out-of-plane ones, and the modes kept by the dynamics bend the wing. Given the modal deflection
// Phi q, the membrane strain of every facet and member is eps = B d + eta(q), eta quadratic in q:
//   eta = sum_p Q_p h_p,   Q_p = q_i q_j over the pairs p = (i <= j).
// The membrane is stiff and light (its in-plane modes lie far above the flapping harmonics), so it
// follows q quasi-statically: d minimises the in-plane energy, K_mm d = -sum_p Q_p F_p, i.e.
// d = sum_p Q_p U_p with U_p = -K_mm^-1 F_p. What is left is a potential of q alone,
//   V_NL(q) = 1/2 Q^T C Q,   C_ps = sum_e w_e h_p^T D_e h_s + U_p^T F_s   (P x P, P = M(M+1)/2),
// quartic in q, exactly the in-plane-relaxed von Karman energy restricted to u_w = Phi q (with the
// members stretched by their out-of-plane slopes only, MemberStretch::kOutOfPlaneOnly: the full
// model's default also charges their in-plane rotation, which is not quadratic in the relaxation
// and is not here). Where it is valid (test_fe_membrane_efw.cpp): on a taut skin (100 N/m) the
// 24-mode model is within 1 % of the full nonlinear solution of the EFW and the members' in-plane
// rotation is worth nothing; on the slack skin the static problem has several wrinkled
// equilibria (the full model's differ by 5 % with the load path, this model's by a factor 2, and
// there the in-plane rotation is worth 36.2 -> 29.3 mm at the mid-span trailing edge), so the
// slack reduced wing is not validated. This is
// the enforced-displacement ROM of Muravyov & Rizzi (2003) with the membrane's "companion"
// displacements solved for once per pair instead of fitted (the relaxation Mignolet et al. 2013
// require, done exactly); it has no quadratic term because a flat wing's bending cannot stretch
// the membrane to first order. The modal force f = dV/dq and tangent derive from the one
// potential, so the model conserves energy. Cost per right-hand side: P^2 + 3P multiply-adds
// (12 modes: ~6300).
//
// Why this route and not implicit condensation (Hollkamp & Gordon 2008) or a prestressed
// linearisation: both need nonlinear static solves of the full model (ICE: hundreds for a cubic
// fit of 12 modes; prestress: one per trim iteration), this needs one in-plane factorisation and
// M(M+1)/2 back-substitutions (78 for 12 modes), and it is exact where they are fits (though a fit
// to the full model would also carry the members' in-plane rotation, which this cannot).
#pragma once

#include <vector>

#include <Eigen/Core>

#include "core/structure/dof_partition.hpp"
#include "core/structure/fe_assembly.hpp"
#include "core/structure/von_karman.hpp"

namespace orni::structure {

struct ModalMembraneStiffness {
  int mode_count = 0;
  std::vector<std::array<int, 2>> pairs;  ///< p -> (i, j), i <= j, row-major over i
  Eigen::MatrixXd pair_stiffness;         ///< C (P x P, symmetric), J per (m^2 kg)^2
  Eigen::MatrixXd relaxation;             ///< U (6n x P): in-plane displacement per Q_p (m per
                                          ///< (m sqrt(kg))^2); empty unless asked for

  bool empty() const { return mode_count == 0; }
  int pairCount() const { return static_cast<int>(pairs.size()); }

  /// Scratch of one evaluation (P entries each); no allocation after construction.
  struct Workspace {
    Eigen::VectorXd products, z, rates;
    explicit Workspace(int pair_count = 0)
        : products(pair_count), z(pair_count), rates(pair_count) {}
  };
  /// Scratch of the tangent (P x M and M x M); no allocation after construction.
  struct TangentWorkspace {
    Eigen::VectorXd products, z;
    Eigen::MatrixXd c_jac, c_jac_rate;  ///< C J(q), beta C J(q') (P x M)
    explicit TangentWorkspace(int pair_count = 0, int mode_count = 0)
        : products(pair_count),
          z(pair_count),
          c_jac(pair_count, mode_count),
          c_jac_rate(pair_count, mode_count) {}
  };
  /// Power of the membrane force on the modal rates q' (per wing).
  struct Rates {
    double strain_energy_rate_W = 0.0;  ///< dV_NL/dt = Q'^T C Q
    double dissipation_W = 0.0;         ///< beta Q'^T C Q' >= 0 (the strain-rate damping)
  };

  /// V_NL(q) (J with mass-normalised modes: q in m sqrt(kg)).
  double energy(const Eigen::VectorXd& q, Workspace* ws) const;
  /// f += scale dV_NL/dq (the membrane's restoring force on the modes). No allocation.
  void addForce(const Eigen::VectorXd& q, Workspace* ws, Eigen::VectorXd* f,
                double scale = 1.0) const;
  /// The membrane force with Kelvin-Voigt damping of the membrane strains (strain-rate stress
  /// beta D eps'): f += scale J^T C (Q + beta Q'), J = dQ/dq, Q' = J q'. The in-plane field
  /// follows q quasi-statically, so eps' is linear in Q' and the dissipation is beta Q'^T C Q'
  /// (the condensed strain energy of the strain rate, times beta): never negative. Returns the
  /// force's power on q' (unscaled), dV_NL/dt + dissipation. One pass over C; no allocation.
  double addForce(const Eigen::VectorXd& q, const Eigen::VectorXd& q_dot, double beta_s,
                  Workspace* ws, Eigen::VectorXd* f, double scale = 1.0) const;
  /// The two parts of that power separately (two passes over C; for histories and checks).
  Rates rates(const Eigen::VectorXd& q, const Eigen::VectorXd& q_dot, double beta_s,
              Workspace* ws) const;
  /// d^2 V_NL / dq^2 (M x M): the membrane's tangent stiffness at q.
  Eigen::MatrixXd tangent(const Eigen::VectorXd& q) const;
  /// The Jacobian of the damped force in two parts, without allocation: `gauss_newton` = J^T C J
  /// (positive semi-definite; times beta it is d f / dq'), and `rest` = d f / dq - J^T C J =
  /// sum_p z_p d2Q_p/dq2 with z = C (Q + beta Q') (the membrane stress part, indefinite in
  /// general) + beta J^T C J(q') (the damping force's change with q; not symmetric). At q' = 0 or
  /// beta = 0 the two sum to tangent(q). M x M each, overwritten.
  void tangentParts(const Eigen::VectorXd& q, const Eigen::VectorXd& q_dot, double beta_s,
                    TangentWorkspace* ws, Eigen::MatrixXd* gauss_newton,
                    Eigen::MatrixXd* rest) const;
  /// The in-plane displacement that goes with q (6n); needs `relaxation`.
  Eigen::VectorXd membraneDisplacement(const Eigen::VectorXd& q) const;
};

/// Builds the condensed membrane stiffness of the modes `shapes` (6n x M). `stiffness` is the
/// assembled K, `part` the fixed-interface partition; the wing must be flat (every node in the
/// plane of P2): std::invalid_argument otherwise. `keep_relaxation` stores U.
ModalMembraneStiffness modalMembraneStiffness(const VonKarmanTerms& terms,
                                              const SparseMatrix& stiffness,
                                              const DofPartition& part,
                                              const std::vector<Vec3>& nodes_W_m,
                                              const Eigen::MatrixXd& shapes,
                                              bool keep_relaxation = false);

/// The reduced static problem K q + f_NL(q) = F_modal (diagonal modal stiffness K, mass-normalised
/// modes), by Newton's method with load increments. Returns false if it did not converge.
bool solveModalStatic(const Eigen::VectorXd& stiffness_diagonal,
                      const ModalMembraneStiffness& membrane, const Eigen::VectorXd& modal_load,
                      Eigen::VectorXd* q, int load_steps = 8);

}  // namespace orni::structure
