// Right-hand side of the tethered simulation with the flexible wing (docs/theory.md 4, 6, 9): state
// [q (M), q' (M), MST-TD states (2 per strip), 5 quadratures]. Workspace sized once; the RHS does
// not allocate.
#pragma once

#include "core/dynamics/flexible_wing.hpp"
#include "core/dynamics/flight_core.hpp"
#include "core/dynamics/modal_implicit_split.hpp"
#include "core/dynamics/small_cholesky.hpp"
#include "core/dynamics/strip_kinematics.hpp"

namespace orni {

class FlexibleTetheredSystem {
 public:
  FlexibleTetheredSystem(const FlightCoreModel& model, const FlexibleWingModel& flex,
                         const BodyMotion& body, const ControlInput& control);

  int stateCount() const { return 2 * mode_count_ + n_aero_ + kQuadratureChannels; }
  int aeroOffset() const { return 2 * mode_count_; }
  int quadratureOffset() const { return 2 * mode_count_ + n_aero_; }
  /// Undeformed wing at rest relative to the frame, quasi-steady aero states, zero integrals.
  void initialState(double t_s, double* y) const;
  /// Absolute tolerances per state for a relative tolerance rel_tol.
  void absoluteTolerances(double rel_tol, double lag_abs_tol, double separation_abs_tol,
                          std::vector<double>* atol) const;
  /// dy/dt; the quadrature rows receive FV, FH, M (aerodynamic + tail: the inertial loads of a
  /// periodic orbit average to zero) and the aerodynamic and hinge power (aero + modal damping).
  void rhs(double t_s, const double* y, double* ydot);
  /// Full loads at (t, y) for the histories: aerodynamic plus inertial (nodal sums over the FE
  /// mesh with lumped masses), tip deflection and twist.
  void sample(double t_s, const double* y, LoadSample* out);
  /// The same loads at a sampled instant from the state y and its derivative ydot as the
  /// integrator's dense output gives them there (OdeIntegrator::derivative), without the strip
  /// aerodynamics: the wing's aerodynamic loads and powers are the quadrature rows of ydot (less
  /// the tail, which the tethered body holds constant), q'' its modal rows; the inertial loads,
  /// the separated area (from the separation states), the tip's deflection and twist are
  /// evaluated from them as in sample(). About a third of sample()'s cost; the aerodynamic loads
  /// are then the interpolant's, as accurate as the sampled state (docs/theory.md 9.4). Returns
  /// false (out untouched) without the separation lag, whose fraction is not a state.
  bool sampleFromDerivative(double t_s, const double* y, const double* ydot, LoadSample* out);

  static int rhsCallback(double t, const double* y, double* ydot, void* self) {
    static_cast<FlexibleTetheredSystem*>(self)->rhs(t, y, ydot);
    return 0;
  }
  /// The linear modal part for implicit integration (modal_implicit_split.hpp).
  ModalImplicitSplit& split() { return split_; }
  bool nonlinearWing() const { return flex_.nonlinear(); }
  /// Where rhs() evaluated the membrane force (nonlinear wing; null for the linear one).
  const structure::ModalMembraneStiffness::Workspace* membraneWorkspace() const {
    return flex_.nonlinear() ? &membrane_ws_ : nullptr;
  }
  /// The strip loads of the last evaluation (rhs() or sample()) as the kernel gave them, without
  /// the apparent-mass force of q'' (the left-hand side's A(f)): force (3 x ns, W, one wing), the
  /// moment about e_s (ns, nose-up) and the separation fraction f (ns) of A(f).
  void lastStripLoads(Eigen::Matrix3Xd* force_W_N, Eigen::VectorXd* moment_Nm,
                      Eigen::VectorXd* separation_f) const;
  /// After an accepted step: the nonlinear wing's split re-linearised about y, with the modal
  /// mass at y (no-op for the linear wing).
  void updateSplit(double t_s, const double* y);

 private:
  struct AeroResult {
    Vec3 F_W = Vec3::Zero();      // both wings not yet applied: one (right) wing, W components
    Vec3 M_P2_W = Vec3::Zero();   // about P2
    double power_aero_W = 0.0;
    double separated_fraction = 0.0;
  };
  // Strip kinematics, kernel, generalised forces; solves for q''. Fills qdd_ and the loads.
  void evaluate(double t_s, const double* y, double* aero_derivatives, AeroResult* aero);
  void fuselageLoads(const AeroResult& aero, const Vec3& F_inertial_W, const Vec3& M_inertial_P2_W,
                     double hinge_power_one_wing_W, LoadSample* out) const;
  // The parts both kinds of sample share, at q_, qd_, omega_W_: the rate of the strain energy
  // (elastic and, with w_x^2 K_G, geometric) of one wing, and the tip's deflection and twist.
  double strainEnergyRate();
  void setTip(LoadSample* out) const;

  const FlightCoreModel& model_;
  const FlexibleWingModel& flex_;
  BodyMotion body_;
  ControlInput control_;
  int mode_count_ = 0;
  int n_aero_ = 0;
  FlightCoreData data_;
  // Per-evaluation workspace.
  Mat3 R_BW_ = Mat3::Identity();
  Vec3 omega_W_ = Vec3::Zero(), alpha_W_ = Vec3::Zero();
  Eigen::VectorXd q_, qd_, qdd_, Q_, rhs_vec_, frame_inertia_;
  Eigen::VectorXd membrane_force_;  // f_NL(q) of the nonlinear wing (zero for the linear one)
  structure::ModalMembraneStiffness::Workspace membrane_ws_;
  structure::LumpedInertiaWorkspace inertia_ws_;  // sample()'s inertial loads
  double membrane_power_W_ = 0.0;  // its power on q' (per wing): dissipation + dV_NL/dt
  Eigen::VectorXd mass_base_packed_;  // M_qq + the f-independent apparent mass, packed lower
  SmallCholesky chol_;
  StripKinematics kin_;
  Eigen::VectorXd packed_, extra_force_, extra_couple_, twist_mid_qdd_;
  ModalImplicitSplit split_;
  Eigen::MatrixXd modal_mass_;  // M_qq + A(f) at the last accepted step (nonlinear wing)
};

}  // namespace orni
