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
// potential, so the model conserves energy. Cost per right-hand side: P^2 + 3P multiply-adds with
// the dense C, 2 R P + 3P with C = G^T G truncated to R strain directions (modalMembraneStiffness).
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
  /// The condensed stiffness C (P x P, symmetric, J per (m^2 kg)^2), kept in one of two forms
  /// (modalMembraneStiffness, "storage"): `pair_stiffness` = C itself, or `strain_factor` = G
  /// (R x P) with C = G^T G kept to its R significant strain directions; the other is empty.
  Eigen::MatrixXd pair_stiffness;
  Eigen::MatrixXd strain_factor;
  Eigen::MatrixXd relaxation;             ///< U (6n x P): in-plane displacement per Q_p (m per
                                          ///< (m sqrt(kg))^2); empty unless asked for
  /// S (P x P), with the dense C only: the Hessian of V_NL in the pair products,
  /// d2V/dq_a dq_b = sum_s S_(ab),s Q_s (V_NL is quartic, so its Hessian is quadratic in q and
  /// S is unique). One pass over S gives the tangent that tangentParts builds from about four
  /// passes over C (newtonParts).
  Eigen::MatrixXd hessian_pairs;

  bool empty() const { return mode_count == 0; }
  int pairCount() const { return static_cast<int>(pairs.size()); }
  bool factored() const { return strain_factor.size() > 0; }
  /// R of the factor, or P for the dense C.
  int rank() const { return factored() ? static_cast<int>(strain_factor.rows()) : pairCount(); }
  /// C (P x P) in either form: for checks; the evaluations do not form it.
  Eigen::MatrixXd pairStiffness() const {
    return factored() ? Eigen::MatrixXd(strain_factor.transpose() * strain_factor)
                      : pair_stiffness;
  }

  /// Scratch of one evaluation; no allocation after construction. After the damped addForce it
  /// also holds what that evaluation was of (q, q', beta) and its stress z = C (Q + beta Q'), so
  /// that another caller at the same state can reuse z (addForceEvaluatedIn).
  struct Workspace {
    Eigen::VectorXd products, z, rates, strain, strain_rate;  // P, P, P, R, R
    Eigen::VectorXd evaluated_q, evaluated_q_dot;              // M, M
    double evaluated_beta_s = 0.0;
    bool holds_evaluation = false;  ///< z is the damped force's stress at the three above
    Workspace() = default;
    explicit Workspace(const ModalMembraneStiffness& m)
        : products(m.pairCount()),
          z(m.pairCount()),
          rates(m.pairCount()),
          strain(m.rank()),
          strain_rate(m.rank()),
          evaluated_q(m.mode_count),
          evaluated_q_dot(m.mode_count) {}
  };
  /// Scratch of the tangent; no allocation after construction.
  struct TangentWorkspace {
    Eigen::VectorXd products, z, strain;  // P, P, R
    Eigen::MatrixXd jac, jac_rate;  ///< X J(q), beta X J(q') with X = C (P x M) or G (R x M)
    /// newtonParts: [Q, Q'], C [Q, Q'] and S [Q, Q'] (P x 2 each)
    Eigen::MatrixXd products_and_rates, pair_stress, pair_hessian;
    TangentWorkspace() = default;
    explicit TangentWorkspace(const ModalMembraneStiffness& m)
        : products(m.pairCount()),
          z(m.pairCount()),
          strain(m.rank()),
          jac(m.rank(), m.mode_count),
          jac_rate(m.rank(), m.mode_count),
          products_and_rates(m.pairCount(), 2),
          pair_stress(m.pairCount(), 2),
          pair_hessian(m.pairCount(), 2) {}
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
  /// force's power on q' (unscaled), dV_NL/dt + dissipation. One pass over C (P^2 multiply-adds)
  /// or two over G (2 R P); no allocation.
  double addForce(const Eigen::VectorXd& q, const Eigen::VectorXd& q_dot, double beta_s,
                  Workspace* ws, Eigen::VectorXd* f, double scale = 1.0) const;
  /// The same force from the stress an earlier damped addForce left in `evaluated`, if that was
  /// at exactly this (q, q', beta): f += scale J^T z in P multiply-adds, the same bits as
  /// addForce. Returns false (f untouched) when `evaluated` holds another state. The implicit
  /// integrator's explicit part asks for the membrane force twice at one state (the right-hand
  /// side, then the implicit part removed from it): the second is this.
  bool addForceEvaluatedIn(const Workspace& evaluated, const Eigen::VectorXd& q,
                           const Eigen::VectorXd& q_dot, double beta_s, Eigen::VectorXd* f,
                           double scale = 1.0) const;
  /// The two parts of that power separately (for histories and checks).
  Rates rates(const Eigen::VectorXd& q, const Eigen::VectorXd& q_dot, double beta_s,
              Workspace* ws) const;
  /// The Newton matrix of the damped force from S (needs hessian_pairs, i.e. the dense C): two
  /// passes, over S and C with [Q, Q'], instead of tangentParts' four over C. `damping` =
  /// d f / dq' = beta J^T C J exactly (= beta (H(q) - sum_p z0_p d2Q_p/dq2), H the Hessian of
  /// V_NL, z0 = C Q); `stiffness` = d f / dq less the antisymmetric part of the damping force's
  /// change with q, beta (J^T C J(q') - J(q')^T C J)/2: exact where q' = 0 or beta = 0, and
  /// symmetric (H(q) + beta/2 (S Q' + sum_p (C Q')_p d2Q_p/dq2), by polarisation of H). What
  /// is left out changes how fast Newton's method contracts, not what it converges to. M x M
  /// each, overwritten.
  /// `evaluation` (optional) receives the damped force's stress at this state, z = C Q + beta
  /// C Q', as a damped addForce would leave it, for addForceEvaluatedIn: the force at the state
  /// of a linearisation then costs no further pass over C.
  void newtonParts(const Eigen::VectorXd& q, const Eigen::VectorXd& q_dot, double beta_s,
                   TangentWorkspace* ws, Eigen::MatrixXd* stiffness, Eigen::MatrixXd* damping,
                   Workspace* evaluation = nullptr) const;
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

/// How modalMembraneStiffness keeps C (see there).
enum class MembraneStorage {
  kCheaper,  ///< the factor G if 2 R < P (an evaluation costs 2 R P against P^2), else C
  kDense,    ///< C (untruncated)
  kFactor,   ///< G (the dense C if C = 0: a factor of no rows)
};
struct MembraneCondensationOptions {
  MembraneStorage storage = MembraneStorage::kCheaper;
  bool keep_relaxation = false;  ///< store U (tests, deflection output)
  /// Amplitude scale a_i of each mode (M; m sqrt(kg)), e.g. 1 / omega_i^2, the static response to
  /// a unit modal force: the truncation measures the pairs' energy at Q_p = a_i a_j. Empty: no
  /// truncation (R = the numerical rank of C).
  Eigen::VectorXd mode_amplitude;
  /// Relative size of the last strain direction kept: the pivoted Cholesky factorisation of the
  /// scaled C stops when its largest remaining diagonal falls below this times the largest
  /// diagonal of C (the energy of one scaled pair left out, relative to the stiffest pair's).
  double rank_tolerance = 1e-10;
  /// Threads for the column blocks of the in-plane solve and of the products that form C (0 = the
  /// machine's cores, at most 4). Every column is the same arithmetic on any thread, so C has the
  /// same bits for any count (test_fe_von_karman.cpp).
  int threads = 0;
};

/// Builds the condensed membrane stiffness of the modes `shapes` (6n x M). `stiffness` is the
/// assembled K, `part` the fixed-interface partition; the wing must be flat (every node in the
/// plane of P2): std::invalid_argument otherwise.
///
/// C may be kept as a factor G with C ~ G^T G, from a diagonally pivoted Cholesky factorisation
/// of A C A (A = diag(a_i a_j), options.mode_amplitude) stopped at options.rank_tolerance: an
/// evaluation then costs 2 R P instead of P^2. The truncated C is positive semi-definite and every
/// force and tangent derives from its one potential, so the truncated wing still conserves
/// energy; the left-out part is positive semi-definite too (a Schur complement), so truncation
/// never stiffens the energy, and the left-out part's largest scaled diagonal is at most the
/// tolerance times the largest of A C A. Measured on the magpie at Table 3's point (efw_magpie_table3, 10 tethered cycles,
/// 1/omega^2 amplitudes): 48 modes, R = 684 (numerical rank) / 353 / 172 at tolerance 0 / 1e-10 /
/// 1e-8: mean FV 1.30748 / 1.30749 / 1.275 N, 33 / 17.6 / 4.7 s; so 1e-10 (the default) and not
/// 1e-8. 24 modes: R = 220 of P = 300 at 1e-10, and the dense C is cheaper (kCheaper keeps it).
ModalMembraneStiffness modalMembraneStiffness(const VonKarmanTerms& terms,
                                              const SparseMatrix& stiffness,
                                              const DofPartition& part,
                                              const std::vector<Vec3>& nodes_W_m,
                                              const Eigen::MatrixXd& shapes,
                                              const MembraneCondensationOptions& options = {});

/// The reduced static problem K q + f_NL(q) = F_modal (diagonal modal stiffness K, mass-normalised
/// modes), by Newton's method with load increments. Returns false if it did not converge.
bool solveModalStatic(const Eigen::VectorXd& stiffness_diagonal,
                      const ModalMembraneStiffness& membrane, const Eigen::VectorXd& modal_load,
                      Eigen::VectorXd* q, int load_steps = 8);

}  // namespace orni::structure
