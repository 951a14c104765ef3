// The full-order geometrically nonlinear wing in time: the finite-element model itself (every
// retained DOF, the von Karman terms of von_karman.hpp), integrated with the HHT-alpha method in
// the flapping frame W, which rotates about x_W through P2 (the tethered hinge, docs/theory.md
// 4.3). A reference for the reduced wing's basis (docs/theory.md 4.7, "A flapping reference"),
// not a production path: one sparse factorisation per Newton iteration.
//
// Equation of motion on the retained DOFs (interior and free boundary; the clamped ones at zero):
//   (M + A) u'' + C_n u' + K u + g(u) + K_a u + C_a u'
//       = F(t) - M [a_rigid(t) + (alpha^ + omega^ omega^) u + 2 omega^ u'],
// with K, M the assembled (prestressed) stiffness and the consistent mass, g = grad Pi_NL and
// H = hess Pi_NL (von_karman.hpp), A an optional added (apparent air) mass, K_a and C_a optional
// state-linear loads (a linearised aerodynamic correction), F the applied nodal loads in W,
// omega = phi' e_x and alpha = phi'' e_x the frame's rotation, a_rigid the acceleration of the
// undeformed wing's points (alpha x r + omega x (omega x r) on the translations, alpha on the
// rotations) and omega^ the cross product on the nodal translations.
// Damping C_n = beta (K + H(u_n)): stiffness-proportional on the tangent at the start of each
// step, the full-order form of the reduced wing's modal damping at its first mode and of its
// membrane (Kelvin-Voigt) damping (flexible_wing.hpp, membrane_damping_s): with beta = 2 zeta_1 /
// omega_1 the first mode has the ratio zeta_1 and a membrane-stiffened mode at omega the ratio
// zeta_1 omega / omega_1. Why the tangent at the step's start and not at u_{n+1}: the Newton matrix
// is then exact (the derivative of H(u) u' would need the third derivative of Pi_NL); without it
// Newton stalls on a slack skin (measured: a ramped 2 Pa lift on the EFW, step 24).
//
// HHT-alpha (alpha = -0.3 by default; 0 is Newmark's average acceleration, which conserves the
// energy of a linear undamped system exactly) with Newton's method on u_{n+1}, a backtracking line
// search on the residual, and the exact Newton matrix c_a (M + A) + (1 + alpha)(c_v C_n + K + H +
// K_a + c_v C_a + M (alpha^ + omega^ omega^ + 2 c_v omega^)), factored by LDL^T when it is
// symmetric (no frame motion, no K_a, C_a) and by LU otherwise.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/structure/dof_partition.hpp"
#include "core/structure/fe_types.hpp"
#include "core/structure/von_karman.hpp"
#include "core/structure/wing_mesh.hpp"

namespace orni::structure {

struct WingTransientOptions {
  double damping_s = 0.0;          ///< beta of beta (K + H(u)) u' (s), >= 0
  /// HHT-alpha in [-1/3, 0]: 0 is Newmark's average acceleration (no numerical dissipation);
  /// -0.3 damps what the step does not resolve (spectral radius 0.54 at h omega -> infinity:
  /// the skin's rotations, whose consistent mass is 1e-18 kg m^2, and the in-plane modes) and
  /// keeps second order. The trapezoidal rule is not L-stable: with it an inconsistent start
  /// (a reduced wing's state) rings undamped at the Nyquist frequency in those DOFs.
  double hht_alpha = -0.3;
  int max_newton_iterations = 40;  ///< per step
  double force_tolerance = 1e-9;   ///< converged: |residual| <= tol * (load scale) ...
  double displacement_tolerance = 1e-11;  ///< ... or |Newton correction| <= tol * |u|
  double force_floor_n = 1e-12;  ///< ... or |residual| <= this (N): an unloaded state's round-off
  bool IsValid(std::string* why) const;
};

/// The applied loads of one step, at its end t_{n+1}.
struct WingTransientLoads {
  double omega_x_radps = 0.0;    ///< frame angular velocity about x_W
  double alpha_x_radps2 = 0.0;   ///< frame angular acceleration about x_W
  const Eigen::VectorXd* force = nullptr;      ///< nodal loads (6n, W); null = none
  const SparseMatrix* added_mass = nullptr;    ///< A (6n x 6n, symmetric); null = none
  /// Loads linear in the state, -K_a u - C_a u' (6n x 6n, need not be symmetric: a linearised
  /// aerodynamic correction); null = none. With either, the Newton matrix is factored by LU.
  const SparseMatrix* added_stiffness = nullptr;
  const SparseMatrix* added_damping = nullptr;
};

class WingTransient {
 public:
  /// K and M assembled (6n x 6n, full symmetric, K with any pretension), the terms of the same
  /// mesh, the support's partition, the undeformed node positions relative to the rotation axis'
  /// point P2 (W, m).
  WingTransient(SparseMatrix stiffness, SparseMatrix mass, const VonKarmanTerms& terms,
                const DofPartition& part, std::vector<Eigen::Vector3d> nodes_from_p2_W_m,
                const WingTransientOptions& options);

  /// Sets the state (6n each; the clamped and inactive DOFs are ignored), relaxes the in-plane DOFs
  /// (u, v, theta_z) to their static equilibrium with the out-of-plane ones held (a reduced wing's
  /// state has no membrane displacement: without it the skin would start stretched by its
  /// deflection), and sets the acceleration consistent with it under `loads` (one solve, M + A).
  /// With start_step_s > 0 the acceleration is that of an implicit step of this length,
  /// (M + A + beta_N h^2 K_T) a = -g, bounded where the mass is negligible (see the .cpp).
  void setState(const Eigen::VectorXd& u, const Eigen::VectorXd& v, const WingTransientLoads& loads,
                double start_step_s = 0.0);

  struct StepReport {
    bool converged = false;
    int newton_iterations = 0;
    double residual_ratio = 0.0;
    std::string message;
  };
  /// One HHT step of length h (s) to loads at its end. On failure the state is unchanged.
  StepReport step(double h_s, const WingTransientLoads& loads);

  /// The state (6n, zero on the clamped and inactive DOFs).
  Eigen::VectorXd displacement() const;
  Eigen::VectorXd velocity() const;
  /// Kinetic energy relative to W, 1/2 v^T M v, and strain energy 1/2 u^T K u + Pi_NL(u) (J).
  double kineticEnergy() const;
  double strainEnergy() const;

 private:
  void relaxInPlane(const WingTransientLoads& loads);
  Eigen::VectorXd restrictToFree(const Eigen::VectorXd& full) const;
  Eigen::VectorXd expand(const Eigen::VectorXd& free) const;
  // Frame inertia M [a_rigid + (alpha^ + omega^ omega^) u + 2 omega^ v] on the free DOFs.
  Eigen::VectorXd frameInertia(const WingTransientLoads& loads, const Eigen::VectorXd& u_full,
                               const Eigen::VectorXd& v_full) const;

  SparseMatrix k_ff_, m_ff_, m_full_;
  const VonKarmanTerms& terms_;
  std::vector<int> free_;
  int n_ = 0;
  std::vector<Eigen::Vector3d> nodes_;
  WingTransientOptions options_;
  // g(u, v, t) = K u + grad Pi_NL + beta (K + H) v + frame inertia - F on the free DOFs, and H.
  Eigen::VectorXd nonInertial(const WingTransientLoads& loads, const Eigen::VectorXd& u,
                              const Eigen::VectorXd& v, SparseMatrix* h_ff) const;
  Eigen::VectorXd u_, v_, a_, g_;  // free DOFs; g_ = g at the present state
  SparseMatrix c_ff_;  // damping matrix beta (K + H(u_n)) of the step from the present state
};

}  // namespace orni::structure
