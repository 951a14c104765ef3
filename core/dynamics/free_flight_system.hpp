// Right-hand side of free longitudinal flight (paper Eq. 1-2) with the wings as explicit bodies
// (docs/theory.md 4.2, Kane's method): generalised speeds u = (U, W, Q, q'), rigid (no modes) or
// flexible (linear modal wing, level L2 of docs/theory.md 4.5) wings on the prescribed hinge, the
// tail (paper Eq. 3, docs/theory.md 7) and gravity.
//
//   [M_fuselage + 2 (M_wing(t, q) + A_air)] u' = f_fuselage + 2 f_wing + f_tail
//
// M_wing is the wing's share of sum_p m_p V_p^T V_p from the inertia invariants (docs/theory.md
// 3.6, 4.3), A_air the apparent air mass of every strip along its mid-chord normal (6.4). The factor
// 2 is the mirrored left wing. For a massless wing without aerodynamics this is paper Eq. (1).
//
// State: [x_I, h, theta, U, W, Q, q (M), q' (M), MST-TD states (2 per strip), power integral].
// The immutable model (free_flight_model.hpp) may be shared; the workspace is the run's, sized
// once; the RHS does not allocate.
#pragma once

#include <array>
#include <memory>
#include <vector>

#include "core/dynamics/flexible_wing.hpp"
#include "core/dynamics/flight_core.hpp"
#include "core/dynamics/free_flight_model.hpp"
#include "core/dynamics/free_flight_result.hpp"
#include "core/dynamics/modal_implicit_split.hpp"
#include "core/dynamics/small_cholesky.hpp"
#include "core/dynamics/strip_kinematics.hpp"

namespace orni {

/// Per-run scratch of the right-hand side: sized once, reused by every evaluation (no heap
/// allocation in rhs).
struct FreeFlightWorkspace {
  FreeFlightWorkspace(const FreeFlightModel& model);
  FlightCoreData data;  ///< the kernel's strip batch (skin friction frozen per run)
  StripKinematics kin;
  int n_u = 3;          ///< generalised speeds (U, W, Q, q')
  Eigen::VectorXd q, qd, ud, f, scratch_modes;
  Eigen::VectorXd Gq_all, correction;  // K^_G q per load; u' correction (n_u)
  Eigen::VectorXd Pq_all, Cq_all, Cqd_all, Sq, Sqd;
  Eigen::MatrixXd A;  // generalised mass matrix (lower triangle)
  SmallCholesky chol;
  Eigen::VectorXd b_strip, k_twist;           // 0.5 (1 + f) m_a and f k per strip
  Eigen::VectorXd nuU, nuW, nuQ, nutQ;        // body partials of the apparent accelerations
  Eigen::VectorXd extra_force, extra_couple;  // apparent-mass force and couple of u' (ns)
  Eigen::VectorXd zero_ns, tmp_ns, packed;
  Eigen::VectorXd twist_mid_ud;  // [psi_twist; psi_mid] of the modal accelerations (2 ns)
  structure::ModalMembraneStiffness::Workspace membrane_ws;  // the nonlinear wing's membrane
};

/// What the last evaluation found, read by rhs (power) and sample (loads, energies).
struct FreeFlightEvaluation {
  Vec3 F_aero_W = Vec3::Zero(), M_aero_P2_W = Vec3::Zero();  ///< one wing, kernel loads
  double separated_fraction = 0.0;
  LoadSample tail;                     ///< tail and fuselage drag, B components
  Mat3 R_BW = Mat3::Identity();        ///< flap rotation
  Vec3 omega_W = Vec3::Zero(), alpha0_W = Vec3::Zero();  ///< W frame rate, accel. at u' = 0
  Vec3 a_O0_W = Vec3::Zero(), g_W = Vec3::Zero();        ///< P2 accel. at u' = 0, gravity
  Vec3 c_W = Vec3::Zero();             ///< one wing's first moment about P2 (deformed)
  Mat3 J_W = Mat3::Zero();             ///< one wing's inertia about P2 (deformed)
};

class FreeFlightSystem {
 public:
  static constexpr int kBody = 6;  // x_I, h, theta, U, W, Q

  /// A run of `model` (immutable, may be shared with other runs and threads). `reference_speed_mps`
  /// is the run's own flight speed (its operating point, never the vehicle file's): it freezes
  /// the skin friction until initialState sets the initial speed, and scales the power
  /// quadrature's absolute tolerance. Throws std::invalid_argument when it is not positive.
  FreeFlightSystem(std::shared_ptr<const FreeFlightModel> model, const ControlInput& control,
                   double reference_speed_mps);
  /// The same with a model of its own: `flex` null = rigid wing (mass properties of
  /// model.wing_mass). Throws as FreeFlightModel's constructor does.
  FreeFlightSystem(const FlightCoreModel& model, const FlexibleWingModel* flex,
                   const ControlInput& control, double reference_speed_mps);

  int modeCount() const { return mode_count_; }
  int stateCount() const { return kBody + 2 * mode_count_ + n_aero_ + 1; }
  int aeroOffset() const { return kBody + 2 * mode_count_; }
  int powerOffset() const { return kBody + 2 * mode_count_ + n_aero_; }
  const FreeFlightModel& model() const { return *model_; }

  /// Body at `body` (x_I, h, theta, U, W, Q), wing undeformed at rest, quasi-steady aero states.
  /// Also freezes the skin-friction coefficients at the initial speed (setFrictionSpeed).
  void initialState(double t_s, const BodyState& body, double* y);
  /// M11 skin friction per strip at this flight speed (frozen during a run).
  void setFrictionSpeed(double speed_mps);
  void absoluteTolerances(double rel_tol, double lag_abs_tol, double separation_abs_tol,
                          std::vector<double>* atol) const;
  void rhs(double t_s, const double* y, double* ydot);
  /// Accelerations and loads at (t, y); the energies too when `with_energy` (one more evaluation).
  /// `ydot` (may be null): dy/dt at (t, y) from the integrator's dense output; with a flexible
  /// wing the body's and the modes' accelerations u' (the sample's U', W', Q' and the apparent-mass
  /// loads of u') are then taken from it instead of solved at the interpolated state, where the
  /// nonlinear wing's stiff membrane force turns the interpolant's small error into a large one
  /// (docs/theory.md 9.4). The circulatory loads are evaluated at (t, y) either way.
  void sample(double t_s, const double* y, FreeFlightSample* out, bool with_energy = true,
              const double* ydot = nullptr);

  static int rhsCallback(double t, const double* y, double* ydot, void* self) {
    static_cast<FreeFlightSystem*>(self)->rhs(t, y, ydot);
    return 0;
  }
  /// The linear modal part for implicit integration (flexible wing only: hasModes()).
  bool hasModes() const { return mode_count_ > 0; }
  ModalImplicitSplit& split() { return *split_; }
  bool nonlinearWing() const { return model_->flex != nullptr && model_->flex->nonlinear(); }
  /// Where rhs() evaluated the membrane force (nonlinear wing; null otherwise).
  const structure::ModalMembraneStiffness::Workspace* membraneWorkspace() const {
    return nonlinearWing() ? &ws_.membrane_ws : nullptr;
  }
  /// After an accepted step: the nonlinear wing's split re-linearised about y, with one wing's
  /// effective modal mass at y (the Schur complement of the body rows; no-op for the linear wing).
  void updateSplit(double t_s, const double* y);

  double fuselageMass_kg() const { return model_->fuselage_mass_kg; }
  double fuselagePitchInertia_kgm2() const { return model_->fuselage_pitch_inertia_kgm2; }

  /// Switches for the tests (paper Eq. 1 reduction, energy conservation).
  struct Switches {
    bool aerodynamics = true;  ///< wing strips (and their apparent mass)
    bool tail = true;
    bool damping = true;       ///< modal damping
  };
  void setSwitches(const Switches& s) { switches_ = s; }

 private:
  // The terms of one evaluation that its steps share: body state, flap, frame axes.
  struct Frame;
  // The generalised accelerations u' at (t, y) into ws_.ud (and the kernel's aerodynamic state
  // derivatives when `aero_derivatives` is not null), in named steps: forces f and mass matrix A
  // of [M_fuselage + 2 (M_wing + A_air)] u' = f, then the solve.
  void evaluate(double t_s, const double* y, double* aero_derivatives);
  Frame frameAt(double t_s, const double* y);
  void addWingAerodynamics(const Frame& fr, const double* y, double* aero_derivatives);
  void addWingInertiaAndGravity(const Frame& fr);
  void addWingMassMatrix(const Frame& fr);
  void addModalRows();
  void addFuselage(const Frame& fr);
  void addTailAndBodyDrag(const Frame& fr);
  void solveAccelerations(const Frame& fr);
  void apparentAccelerations();

  std::shared_ptr<const FreeFlightModel> model_;
  ControlInput control_;
  Switches switches_;
  int mode_count_ = 0;
  int n_aero_ = 0;
  double reference_speed_mps_ = 0.0;  ///< the run's flight speed (constructor)
  FreeFlightWorkspace ws_;
  FreeFlightEvaluation last_;
  std::unique_ptr<ModalImplicitSplit> split_;  // flexible wing only
  Eigen::MatrixXd modal_mass_, coupling_;      // updateSplit's scratch (M x M, M x 3)
};

}  // namespace orni
