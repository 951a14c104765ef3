// FreeFlightModel: the part of the free-flight equations (free_flight_system.hpp) that a run
// does not change: the strips, one wing's inertia invariants about P2 (W components, docs/theory.md
// 3.6), their stacked modal products, the modal stiffness and damping, and the fuselage's own
// mass, pitch inertia and centre of gravity (the vehicle minus both wings, docs/theory.md 4.2).
// Built once per vehicle and wing, then immutable: one model may serve many runs and threads,
// each run keeping its own FreeFlightSystem (workspace, control, last results).
#pragma once

#include <array>
#include <vector>

#include "core/dynamics/flexible_wing.hpp"
#include "core/dynamics/flight_core.hpp"
#include "core/dynamics/strip_kinematics.hpp"

namespace orni {

struct FreeFlightModel {
  /// `flex` null = rigid wing (mass properties of core.wing_mass). Both must outlive the model.
  /// Throws InvalidModelError for an aerodynamic model the batch kernel does not support, or
  /// when the fuselage-only mass or pitch inertia (vehicle minus both wings) is not positive.
  FreeFlightModel(const FlightCoreModel& core, const FlexibleWingModel* flex);
  FreeFlightModel(const FreeFlightModel&) = delete;
  FreeFlightModel& operator=(const FreeFlightModel&) = delete;

  const FlightCoreModel& core;
  const FlexibleWingModel* flex;  ///< null: rigid wing
  int mode_count = 0;             ///< modes of one wing (0: rigid)
  int aero_state_count = 0;       ///< MST-TD states of one wing's strips

  std::vector<FlexibleStrip> strips;  ///< the rigid wing: strips with zero modes
  StackedStrips rigid_stacked;        ///< the rigid wing's stacked strips (flexible: flex->)
  const StackedStrips& stacked() const { return flex ? flex->stacked : rigid_stacked; }
  Eigen::VectorXd apparent_mass_kg;   ///< rho pi c^2 / 4 times the width, per strip

  // One wing's inertia invariants about P2, W components (docs/theory.md 3.6).
  double wing_mass_kg = 0.0;
  Vec3 wing_first_moment_W_kgm = Vec3::Zero();
  Mat3 wing_inertia_P2_W_kgm2 = Mat3::Zero();
  Eigen::Matrix3Xd L, H;                ///< translational and rotational participation
  std::array<Eigen::VectorXd, 9> S;     ///< S_kl, row-major k, l
  std::array<Eigen::MatrixXd, 3> C;     ///< C_x, C_y, C_z (skew parts of P)
  Eigen::MatrixXd modal_mass;           ///< generalised mass M_qq
  Eigen::VectorXd S_trace;              ///< sum_k S_kk
  Eigen::VectorXd modal_stiffness, modal_damping;  ///< diagonals
  // Stacked invariants: one product per evaluation instead of one per matrix. Pstack holds the
  // stiffness of the inertial loads per w_k w_l, softening and stiffening (docs/theory.md 3.6,
  // 4.6), Gstack the geometric stiffness of the acceleration loads that stress the wing.
  Eigen::MatrixXd Pstack, Cstack, Smat, Gstack;
  std::vector<structure::InertialLoad> linear_loads;  ///< acceleration loads with a K_G

  // The fuselage alone (docs/theory.md 4.2), B components.
  double fuselage_mass_kg = 0.0;
  double fuselage_pitch_inertia_kgm2 = 0.0;
  Vec3 p_P1P2_B_m = Vec3::Zero();      ///< hinge point P2 from P1
  Vec3 fuselage_cg_B_m = Vec3::Zero();  ///< the fuselage's CG from P1 (the vehicle's CG at P1)
};

}  // namespace orni
