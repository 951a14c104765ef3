// Right-hand side of free longitudinal flight (paper Eq. 1-2) with the wings as explicit bodies
// (structure.md 3.2, Kane's method): generalised speeds u = (U, W, Q, q'), rigid (no modes) or
// flexible (linear modal wing, level L2 of structure.md 3.6) wings on the prescribed hinge, the
// tail (paper Eq. 3, aero-mst.md 10) and gravity.
//
//   [M_fuselage + 2 (M_wing(t, q) + A_air)] u' = f_fuselage + 2 f_wing + f_tail
//
// M_wing is the wing's share of sum_p m_p V_p^T V_p from the inertia invariants (structure.md
// 3.3-3.4), A_air the apparent air mass of every strip along its mid-chord normal (4.4). The factor
// 2 is the mirrored left wing. For a massless wing without aerodynamics this is paper Eq. (1).
//
// State: [x_I, h, theta, U, W, Q, q (M), q' (M), MST-TD states (2 per strip), power integral].
// Workspace sized once; the RHS does not allocate.
#pragma once

#include <array>
#include <memory>
#include <vector>

#include "core/dynamics/flexible_wing.hpp"
#include "core/dynamics/flight_core.hpp"
#include "core/dynamics/modal_implicit_split.hpp"
#include "core/dynamics/small_cholesky.hpp"
#include "core/dynamics/strip_kinematics.hpp"

namespace orni {

/// Longitudinal body state (B components; h altitude up).
struct BodyState {
  double x_I_m = 0, h_m = 0, theta_rad = 0, U_mps = 0, W_mps = 0, Q_radps = 0;
};

/// Everything the free-flight RHS computes at one instant (for histories and tests).
struct FreeFlightSample {
  double Udot_mps2 = 0, Wdot_mps2 = 0, Qdot_radps2 = 0;
  LoadSample loads;   ///< aerodynamic loads of wings (incl. apparent mass) and tail about P1 in
                      ///< the flight-path frame; the inertial fields hold the wings' inertial
                      ///< reaction on the fuselage
  double kinetic_energy_J = 0;    ///< fuselage + both wings (rigid part + modal)
  double potential_energy_J = 0;  ///< gravity (m g h of the whole vehicle, wing CG offsets
                                  ///< included) + strain energy of both wings
};

class FreeFlightSystem {
 public:
  static constexpr int kBody = 6;  // x_I, h, theta, U, W, Q

  /// `flex` null = rigid wing (mass properties of model.wing_mass). `reference_speed_mps` is the
  /// run's own flight speed (its operating point, never the vehicle file's): it freezes the skin
  /// friction until initialState sets the initial speed, and scales the power quadrature's
  /// absolute tolerance. Throws std::invalid_argument when it is not positive, or when the
  /// fuselage-only mass or pitch inertia (vehicle minus both wings) is not positive.
  FreeFlightSystem(const FlightCoreModel& model, const FlexibleWingModel* flex,
                   const ControlInput& control, double reference_speed_mps);

  int modeCount() const { return mode_count_; }
  int stateCount() const { return kBody + 2 * mode_count_ + n_aero_ + 1; }
  int aeroOffset() const { return kBody + 2 * mode_count_; }
  int powerOffset() const { return kBody + 2 * mode_count_ + n_aero_; }

  /// Body at `body` (x_I, h, theta, U, W, Q), wing undeformed at rest, quasi-steady aero states.
  /// Also freezes the skin-friction coefficients at the initial speed (setFrictionSpeed).
  void initialState(double t_s, const BodyState& body, double* y);
  /// M11 skin friction per strip at this flight speed (frozen during a run).
  void setFrictionSpeed(double speed_mps);
  void absoluteTolerances(double rel_tol, double lag_abs_tol, double separation_abs_tol,
                          std::vector<double>* atol) const;
  void rhs(double t_s, const double* y, double* ydot);
  /// Accelerations and loads at (t, y); the energies too when `with_energy` (one more evaluation).
  void sample(double t_s, const double* y, FreeFlightSample* out, bool with_energy = true);

  static int rhsCallback(double t, const double* y, double* ydot, void* self) {
    static_cast<FreeFlightSystem*>(self)->rhs(t, y, ydot);
    return 0;
  }
  /// The linear modal part for implicit integration (flexible wing only: hasModes()).
  bool hasModes() const { return mode_count_ > 0; }
  ModalImplicitSplit& split() { return *split_; }

  double fuselageMass_kg() const { return m_f_; }
  double fuselagePitchInertia_kgm2() const { return I_f_; }

  /// Switches for the tests (paper Eq. 1 reduction, energy conservation).
  struct Switches {
    bool aerodynamics = true;  ///< wing strips (and their apparent mass)
    bool tail = true;
    bool damping = true;       ///< modal damping
  };
  void setSwitches(const Switches& s) { switches_ = s; }

 private:
  // Strip kinematics, kernel, mass matrix and forcing at (t, y); solves for u'.
  void evaluate(double t_s, const double* y, double* aero_derivatives);

  const FlightCoreModel& model_;
  const FlexibleWingModel* flex_;
  ControlInput control_;
  Switches switches_;
  int mode_count_ = 0;
  double reference_speed_mps_ = 0.0;  ///< the run's flight speed (constructor)
  int n_aero_ = 0;
  FlightCoreData data_;
  std::vector<FlexibleStrip> strips_;        // rigid wing: strips with zero modes
  StackedStrips rigid_stacked_;              // the rigid wing's (flexible: flex_->stacked)
  StripKinematics kin_;
  Eigen::VectorXd apparent_mass_kg_;
  // Wing inertia invariants about P2 (W), one wing.
  double m_w_ = 0.0;
  Vec3 c0_ = Vec3::Zero();
  Mat3 J0_ = Mat3::Zero();
  Eigen::Matrix3Xd L_, H_;
  std::array<Eigen::VectorXd, 9> S_;
  Eigen::MatrixXd C_[3];   // C_x, C_y, C_z (skew)
  Eigen::MatrixXd M_qq_;
  Eigen::VectorXd S_trace_;  // sum_k S_kk
  Eigen::VectorXd stiffness_, damping_;
  double m_f_ = 0.0, I_f_ = 0.0;
  Vec3 r2_B_ = Vec3::Zero();
  Vec3 r_f_B_ = Vec3::Zero();  // fuselage CG from P1 (vehicle CG at P1 at zero flap)

  // Workspace (evaluate).
  int n_u_ = 3;
  Eigen::VectorXd q_, qd_, ud_, f_, scratch_modes_;
  Eigen::MatrixXd Pstack_, Cstack_, Smat_;  // stacked invariants (constructor)
  std::vector<structure::InertialLoad> linear_loads_;  // acceleration loads with a K_G
  Eigen::MatrixXd Gstack_;                              // their K^_G, stacked
  Eigen::VectorXd Gq_all_, correction_;  // K^_G q per load; u' correction (n_u)
  Eigen::VectorXd Pq_all_, Cq_all_, Cqd_all_, Sq_{9}, Sqd_{9};
  Eigen::MatrixXd A_;
  SmallCholesky chol_;
  Eigen::VectorXd b_strip_, k_twist_;           // 0.5 (1 + f) m_a and f k per strip
  Eigen::VectorXd nuU_, nuW_, nuQ_, nutQ_;      // body partials of the apparent accelerations
  Eigen::VectorXd extra_force_, extra_couple_;  // apparent-mass force and couple of u' (ns)
  Eigen::VectorXd zero_ns_, tmp_ns_, packed_;
  Eigen::VectorXd twist_mid_ud_;  // [psi_twist; psi_mid] of the modal accelerations (2 ns)
  void apparentAccelerations();
  // Results of the last evaluate.
  Vec3 F_aero_W_ = Vec3::Zero(), M_aero_P2_W_ = Vec3::Zero();  // one wing, kernel loads
  double power_aero_one_wing_W_ = 0.0, separated_fraction_ = 0.0;
  LoadSample tail_;
  Mat3 R_BW_ = Mat3::Identity();
  Vec3 omega_W_ = Vec3::Zero(), alpha0_W_ = Vec3::Zero(), a_O0_W_ = Vec3::Zero();
  Vec3 g_W_ = Vec3::Zero(), c_W_ = Vec3::Zero();
  Mat3 J_W_ = Mat3::Zero();
  std::unique_ptr<ModalImplicitSplit> split_;  // flexible wing only
};

}  // namespace orni
