// Implicit-explicit split of the flexible wing's equations (structure.md 5.2). The stiff part of
// the modal equations is their linear structural part: with A0 = M_qq + A(f = 1), the generalised
// mass plus the attached-flow apparent air mass of one wing (structure.md 4.4), and K, D the modal
// stiffness and damping,
//   L y:  q' = q-dot,   q-dot' = -A0^{-1} (K q + D q-dot),
// integrated by the ESDIRK half of an additive Runge-Kutta pair; the explicit part is the full
// right-hand side minus L y (aerodynamics, the separation-dependent apparent mass, frame inertia
// with the time-varying spin softening and geometric stiffening of structure.md 3.7, body
// coupling). The nonlinear wing (structure.md 3.8) adds its membrane's tangent at the 1-g static
// shape to K (FlexibleWingModel::membrane_reference_stiffness): the stretched skin is the stiffest
// part of its motion, and the explicit part keeps only f_NL(q) minus that linearisation. Measured on the calibrated magpie (12 modes to 332 Hz): the full Jacobian has
// eigenvalues up to |lambda| = 2025 rad/s on the imaginary axis; the explicit remainder's are
// real, below 1000 1/s, and hardly depend on the reference separation fraction of A0.
//
// The stage equations (I - gamma L) x = b reduce to one M x M SPD solve:
//   (A0 + gamma D + gamma^2 K) x_qd = A0 b_qd - gamma K b_q,   x_q = b_q + gamma x_qd,
// every other state x = b. The Cholesky factor is kept for the last gamma (one per step: gamma
// is h times the common diagonal of the ESDIRK table). No allocation after construction.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "core/dynamics/flexible_wing.hpp"
#include "core/dynamics/small_cholesky.hpp"
#include "core/integrate/integration_method.hpp"
#include "core/integrate/integrator_options.hpp"

namespace orni {

class ModalImplicitSplit {
 public:
  /// q at y[q_offset .. q_offset + M), q-dot right after it; `state_count` values in y.
  ModalImplicitSplit(const FlexibleWingModel& flex, int q_offset, int state_count);

  /// ydot = L y (zero outside the modal rows).
  void apply(const double* y, double* ydot);
  /// ydot -= L y: turns a full right-hand side into the explicit part.
  void removeFrom(const double* y, double* ydot);
  /// x = (I - gamma L)^{-1} b.
  void solve(double gamma, const double* b, double* x);

 private:
  // w = A0^{-1} (K q + D q-dot) = [A0^{-1} K, A0^{-1} D] (q; q-dot)
  void stiffAcceleration(const double* y);

  int mode_count_, off_, n_;
  Eigen::MatrixXd A0_;   // symmetric, full
  Eigen::MatrixXd GH_;   // [A0^{-1} K, A0^{-1} D], M x 2M
  Eigen::MatrixXd K_;    // modal stiffness diag(omega^2) + the membrane's reference tangent
  Eigen::VectorXd D_;
  double gamma_ = -1.0;  // gamma of S_chol_
  Eigen::MatrixXd S_;
  SmallCholesky S_chol_;
  Eigen::VectorXd w_, r_;
};

/// Absolute tolerances of the mass-normalised modal coordinates (m sqrt(kg); typical size 1e-4)
/// and their rates at relative tolerance rel_tol, structure.md 5.2: 1e-3 rel_tol for q and
/// 1e-1 rel_tol for q-dot (1e-9 and 1e-7 at rel_tol 1e-6), written to (*atol)[offset ...
/// offset + 2M). The cycle means of the magpie agree with a rel_tol 1e-7 reference to 5e-5 of
/// their values at the default rel_tol 1e-4 (tests/unit/dynamics/test_modal_imex.cpp).
void modalAbsoluteTolerances(double rel_tol, int mode_count, int offset, std::vector<double>* atol);

/// The IMEX callbacks of a System with rhs(t, y, ydot), stateCount(), a ModalImplicitSplit&
/// split() and the full right-hand side as System::rhsCallback: explicit part = rhs - L y,
/// implicit part and solve from the split; and the flexible wing's two integrations of them.
template <class System>
struct ModalImex {
  static int explicitRhs(double t, const double* y, double* ydot, void* self) {
    auto* s = static_cast<System*>(self);
    s->rhs(t, y, ydot);
    s->split().removeFrom(y, ydot);
    return 0;
  }
  static int implicitRhs(double, const double* y, double* ydot, void* self) {
    static_cast<System*>(self)->split().apply(y, ydot);
    return 0;
  }
  static int solve(double gamma, const double* b, double* x, void* self) {
    static_cast<System*>(self)->split().solve(gamma, b, x);
    return 0;
  }
  static LinearImplicitPart part() { return LinearImplicitPart{&implicitRhs, &solve}; }

  /// The right-hand side an OdeIntegrator integrates explicitly: the explicit part with the modal
  /// stiffness `implicit`, else the full right-hand side.
  static RhsFunction rhs(bool implicit) { return implicit ? &explicitRhs : &System::rhsCallback; }
  /// Its method: with the modal stiffness implicit, the additive pair ARK4(3)7L[2]SA; else all
  /// explicit, where the steps are stability-limited (the highest mode) and the explicit table of
  /// ARK4(3)6L[2]SA needs fewer evaluations than Dormand-Prince.
  static IntegrationMethod method(bool implicit) {
    return implicit ? IntegrationMethod::implicitExplicit(part(), ImexMethod::kArk437)
                    : IntegrationMethod::explicitRungeKutta(ErkMethod::kArk436);
  }
};

}  // namespace orni
