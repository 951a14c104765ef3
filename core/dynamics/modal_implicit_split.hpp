// Implicit-explicit split of the flexible wing's equations (docs/theory.md 9.2). The stiff part of
// the modal equations is their linear structural part: with A0 = M_qq + A(f = 1), the generalised
// mass plus the attached-flow apparent air mass of one wing (docs/theory.md 6.4), and K, D the
// modal stiffness and damping,
//   L y:  q' = q-dot,   q-dot' = -A0^{-1} (K q + D q-dot),
// integrated by the ESDIRK half of an additive Runge-Kutta pair; the explicit part is the full
// right-hand side minus L y (aerodynamics, the separation-dependent apparent mass, frame inertia
// with the time-varying spin softening and geometric stiffening of docs/theory.md 4.6, body
// coupling).
//
// The nonlinear wing (docs/theory.md 4.7) keeps its membrane force in the implicit part, exactly:
//   q-dot' = -A0^{-1} (K q + D q-dot + f_NL(q, q-dot)),
// f_NL with the membrane's strain-rate damping (FlexibleWingModel::membrane_damping_s), and its
// stage equations are solved by Newton's method. Why: the stretched skin is the stiffest part of
// the motion (tangent frequencies up to ~5 kHz at 1 g on the slack magpie, against 460 Hz for
// the linear wing's 24th mode) and f_NL is cubic, so its stiffness changes over the stroke and
// within a step. Measured on the slack magpie, 24 modes, 10 tethered cycles: a fixed 1-g
// linearisation in L took 68k right-hand sides, re-linearising L after every step 36k; the
// Newton stages with A0 re-taken from the system's modal mass after every step 6.8k (28.5k with
// the fixed A0: the mismatch (M(t)^{-1} - A0^{-1}) f_NL, from the separation-dependent apparent
// mass, is stiff in the explicit part). After every accepted step (OdeIntegrator's update hook)
// the system passes its effective modal mass at the new state, and the Newton matrix takes the
// membrane's tangent there; Newton's method re-linearises about its iterate when it stops
// contracting (a hardening spring whose stage stiffness exceeds twice the matrix's). With the
// dense C the tangent comes from the pair Hessian S (ModalMembraneStiffness::newtonParts: two
// passes over P x P instead of about four, and the force at the linearised state with it), less
// the antisymmetric part of the damping force's change with q; measured on the slack magpie, 24
// modes, 10 tethered cycles: the same Newton iterations within 1 % as with the exact tangent
// (27.7k against 27.3k), 4.7k linearisations each.
//
// The linear wing's stage equations (I - gamma L) x = b reduce to one M x M SPD solve:
//   (A0 + gamma D + gamma^2 K) x_qd = A0 b_qd - gamma K b_q,   x_q = b_q + gamma x_qd,
// every other state x = b. The Cholesky factor is kept for the last gamma (one per step: gamma
// is h times the common diagonal of the ESDIRK table). No allocation after construction.
#pragma once

#include <vector>

#include <Eigen/Core>
#include <Eigen/LU>

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
  /// ydot -= L y: turns a full right-hand side into the explicit part. `evaluated`: the
  /// workspace in which that right-hand side evaluated the membrane force (nonlinear wing), whose
  /// stress is reused when it was at this y (the same bits, one pass over C fewer).
  void removeFrom(const double* y, double* ydot,
                  const structure::ModalMembraneStiffness::Workspace* evaluated = nullptr);
  /// x = (I - gamma L)^{-1} b; for the nonlinear wing x - gamma f_I(x) = b by Newton's method.
  /// Returns 0, or 1 when Newton's method did not converge (the step is retried smaller).
  int solve(double gamma, const double* b, double* x);
  /// Re-linearise the nonlinear wing's membrane about the state y (no-op for the linear wing),
  /// and take `modal_mass` (M x M, symmetric; the system's effective modal mass at y) as A0.
  void update(const double* y, const Eigen::MatrixXd* modal_mass);
  long newtonIterations() const { return newton_iterations_; }
  long linearisations() const { return linearisations_; }
  /// Membrane force evaluations of its own (passes over C); those taken from an evaluation at the
  /// same state (the right-hand side's, a linearisation's) are not counted.
  long forcePasses() const { return force_passes_; }

 private:
  // w = A0^{-1} (K q + D q-dot) = [A0^{-1} K, A0^{-1} D] (q; q-dot)
  void stiffAcceleration(const double* y,
                         const structure::ModalMembraneStiffness::Workspace* evaluated = nullptr);
  // g = K q + D q' + f_NL(q, q') of the linear modes and the membrane, into g_ (f_NL from the
  // stress in `evaluated` when it was at this state).
  void restoring(const Eigen::Ref<const Eigen::VectorXd>& q,
                 const Eigen::Ref<const Eigen::VectorXd>& qd,
                 const structure::ModalMembraneStiffness::Workspace* evaluated = nullptr);
  void factor(double gamma);
  void solveStageMatrix();  // r_ = S^{-1} r_
  // K, D of the Newton matrix: the linear modes plus the membrane's tangent at q.
  void linearise(const Eigen::Ref<const Eigen::VectorXd>& q,
                 const Eigen::Ref<const Eigen::VectorXd>& qd);
  static constexpr int kMaxNewtonIterations = 12;
  // Re-linearise when a correction is above this fraction of the last one. Measured on the slack
  // magpie (24 modes, 10 tethered cycles): 0.25 took 837 steps, 0.5 1102, 0.8 2110 (failed
  // stages make the steps shorter); each re-linearisation costs ~8 Newton iterations.
  // Tried 2026-12-06 and withdrawn: Broyden updates of S^{-1} between linearisations (ratio 0.5)
  // took these 10 cycles from 0.62 to 0.48 s with the cycle means moved by 2e-4, but moved the
  // calibrated vehicle (efw_magpie_table3) onto another orbit: released at Table 3's point
  // (fig6_8_free_flight_table3) it starts at theta -11.5 deg, Q 754 deg/s (without the updates:
  // 10.3 deg, 82 deg/s on an Intel machine, 9.4 deg, -57 deg/s on an AMD one) and is judged
  // unbounded (bounded on both machines without). Also measured: a Newton tolerance of 1e-5
  // saves 7 %, ARKODE's predictors 1-3 cost 20-80 % more right-hand sides. With the cheaper
  // Newton matrix of newtonParts (two passes over P x P where tangentParts took about eight
  // passes' time), measured again: 0.1 takes 20.7k iterations and 7.1k linearisations, 0.25 23.0k
  // and 4.6k, 0.5 34.3k and 2.6k (with more failed steps); 0.25 stays the least work.
  static constexpr double kRelineariseRatio = 0.25;
  // Newton's iteration ends when the error left in the iterate, estimated from the last
  // correction and the contraction rate, is below 1e-6 of the stage data (plus a floor of the
  // modal scales, 1e-6 m sqrt(kg) and 1e-4 m sqrt(kg)/s): two orders below the integrator's error
  // weights, whose absolute parts are 1e-3 and 1e-1 rel_tol (1e-7 and 1e-5 at the default rel_tol
  // 1e-4). Until 2026-12-06 the last correction itself had to be below it (one more iteration
  // in most stages: 27.7k against 23.1k on the slack magpie's 10 cycles). Measured there: a
  // tolerance of 1e-5 takes 19.1k; not taken, to stay two orders below the error weights (the
  // cycle means move by about 1e-3 of their values with any change of the iteration on this
  // slack skin, this one included).
  static constexpr double kNewtonTolerance = 1e-6;
  static constexpr double kModalScale_msqrtkg = 1e-6;
  static constexpr double kModalRateScale = 1e-4;

  int mode_count_, off_, n_;
  const structure::ModalMembraneStiffness* membrane_;  // null for the linear wing
  double membrane_beta_s_;
  Eigen::MatrixXd A0_;   // symmetric, full
  Eigen::MatrixXd A0_inv_;
  Eigen::MatrixXd GH_;   // [A0^{-1} K, A0^{-1} D], M x 2M
  Eigen::VectorXd K_diag_, D_diag_;  // the linear modes: omega^2, 2 zeta omega
  Eigen::MatrixXd K_;    // diag(omega^2) + d f_NL / dq at the last linearisation
  Eigen::MatrixXd D_;    // diag(2 zeta omega) + d f_NL / dq' = beta J^T C J
  Eigen::MatrixXd gauss_newton_, rest_;  // the membrane's Jacobian (membrane_rom.hpp)
  structure::ModalMembraneStiffness::TangentWorkspace tangent_ws_;
  structure::ModalMembraneStiffness::Workspace membrane_ws_;
  SmallCholesky mass_chol_;
  Eigen::VectorXd q_, qd_, g_, rq_;
  long newton_iterations_ = 0, linearisations_ = 0, force_passes_ = 0;
  double gamma_ = -1.0;  // gamma of S_chol_
  Eigen::MatrixXd S_;
  SmallCholesky S_chol_;
  Eigen::PartialPivLU<Eigen::MatrixXd> lu_;  // S of the nonlinear wing
  Eigen::VectorXd w_, r_;
};

/// Absolute tolerances of the mass-normalised modal coordinates (m sqrt(kg); typical size 1e-4)
/// and their rates at relative tolerance rel_tol, docs/theory.md 9.2: 1e-3 rel_tol for q and
/// 1e-1 rel_tol for q-dot (1e-9 and 1e-7 at rel_tol 1e-6), written to (*atol)[offset ...
/// offset + 2M). The cycle means of the magpie agree with a rel_tol 1e-7 reference to 5e-5 of
/// their values at the default rel_tol 1e-4 (tests/unit/dynamics/test_modal_imex.cpp).
void modalAbsoluteTolerances(double rel_tol, int mode_count, int offset, std::vector<double>* atol);

/// The IMEX callbacks of a System with rhs(t, y, ydot), stateCount(), a ModalImplicitSplit&
/// split(), membraneWorkspace() (where rhs evaluated the membrane force, or null) and the full
/// right-hand side as System::rhsCallback: explicit part = rhs - L y,
/// implicit part and solve from the split; and the flexible wing's two integrations of them.
template <class System>
struct ModalImex {
  static int explicitRhs(double t, const double* y, double* ydot, void* self) {
    auto* s = static_cast<System*>(self);
    s->rhs(t, y, ydot);
    s->split().removeFrom(y, ydot, s->membraneWorkspace());
    return 0;
  }
  static int implicitRhs(double, const double* y, double* ydot, void* self) {
    static_cast<System*>(self)->split().apply(y, ydot);
    return 0;
  }
  static int solve(double gamma, const double* b, double* x, void* self) {
    return static_cast<System*>(self)->split().solve(gamma, b, x);
  }
  static int update(double t, const double* y, void* self) {
    static_cast<System*>(self)->updateSplit(t, y);
    return 0;
  }
  /// `relinearise`: the nonlinear wing's split follows the state (System::updateSplit after every
  /// accepted step); the linear wing's L is constant and needs no update.
  static LinearImplicitPart part(bool relinearise) {
    return LinearImplicitPart{&implicitRhs, &solve, relinearise ? &update : nullptr};
  }

  /// The right-hand side an OdeIntegrator integrates explicitly: the explicit part with the modal
  /// stiffness `implicit`, else the full right-hand side.
  static RhsFunction rhs(bool implicit) { return implicit ? &explicitRhs : &System::rhsCallback; }
  /// Its method: with the modal stiffness implicit, the additive pair ARK4(3)7L[2]SA; else all
  /// explicit, where the steps are stability-limited (the highest mode) and the explicit table of
  /// ARK4(3)6L[2]SA needs fewer evaluations than Dormand-Prince.
  static IntegrationMethod method(bool implicit, bool relinearise) {
    return implicit ? IntegrationMethod::implicitExplicit(part(relinearise), ImexMethod::kArk437)
                    : IntegrationMethod::explicitRungeKutta(ErkMethod::kArk436);
  }
};

}  // namespace orni
