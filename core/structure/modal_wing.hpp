// ModalWing: the reduced flexible wing the dynamics consumes (docs/theory.md 3.2, 3.4-3.6).
// Built once by buildModalWing and then only read (docs/design.md 7.1; share it as
// std::shared_ptr<const ModalWing>).
#pragma once

#include <string>
#include <vector>

#include "core/structure/wing_structure.hpp"
#include "core/structure/fe_assembly.hpp"
#include "core/structure/geometric_stiffness.hpp"
#include "core/structure/inertia_invariants.hpp"
#include "core/structure/lumped_inertia_sums.hpp"
#include "core/structure/membrane_rom.hpp"
#include "core/structure/modal_solver.hpp"
#include "core/structure/mode_selection.hpp"
#include "core/structure/wing_mesh.hpp"

namespace orni::structure {

/// Modal damping schedule (docs/theory.md 3.5).
enum class ModalDampingSchedule {
  kConstant,      ///< damping_ratio for every mode (physics default)
  kAdamsDefault,  ///< ADAMS CRATIO default: 1 % below 100 Hz, 10 % to 1 kHz, 100 % above
};

/// Bounds of ModalWingOptions::static_shape_pressures_pa (and of wing.fe.static_shapes_pa).
inline constexpr int kMaxStaticShapes = kMaxStaticShapesOfAWing;
inline constexpr double kMaxStaticShapePressure_Pa = 1000.0;

struct ModalWingOptions {
  MassLumping mass = MassLumping::kConsistent;  ///< M used for modes and invariants
  WingSupport support;  ///< P3 joint and root edge (docs/theory.md 2.6)
  /// Boundary DOFs (global ids 6 node + dof) left free (b_f) and reduced by Craig-Bampton with
  /// orthonormalisation; empty = the default fixed-interface basis (docs/theory.md 3.2).
  std::vector<int> free_boundary_dofs;
  ModeSelectionOptions selection;   ///< count / cut-off / effective mass (docs/theory.md 3.4)
  double damping_ratio = 0.015;     ///< zeta of every elastic mode, [0, 1) (docs/theory.md 3.5)
  ModalDampingSchedule damping_schedule = ModalDampingSchedule::kConstant;
  EigenSolveOptions eigen;
  /// Compute the modal geometric stiffness of the unit inertial loads (docs/theory.md 4.6).
  bool geometric_stiffness = true;
  /// Condense the skin's membrane stretching into the modes (docs/theory.md 4.7,
  /// membrane_rom.hpp): the geometrically nonlinear wing.
  bool nonlinear = false;
  /// Keep the in-plane relaxation shapes of the condensation (tests, deflection output).
  bool keep_membrane_relaxation = false;
  /// MembraneCondensationOptions::rank_tolerance (0: truncated only at C's numerical rank).
  double membrane_rank_tolerance = 1e-10;
  /// Uniform lift pressures (Pa, each in (0, kMaxStaticShapePressure_Pa]) whose full nonlinear
  /// static solutions' out-of-plane shapes join the kept modes, the whole replaced by its
  /// Rayleigh-Ritz vectors (static_shapes.hpp, docs/theory.md 4.7). Nonlinear wing and the
  /// fixed-interface basis only; at most kMaxStaticShapes. Empty: the modes alone.
  std::vector<double> static_shape_pressures_pa;

  bool IsValid(std::string* why) const;
};

/// The options a vehicle's wing.fe settings ask for (support, mode count, cut-off, damping; the
/// rest at their defaults): one mapping, so `modes` analyses the wing a simulation flies.
ModalWingOptions modalWingOptionsOf(const WingFeSettings& fe);

struct ModalWing {
  WingMesh mesh;                          ///< the FE mesh (nodes, strips, P2, P3)
  Eigen::VectorXd frequencies_hz;         ///< f_k, ascending (M)
  Eigen::VectorXd damping_ratios;         ///< zeta_k (M)
  Eigen::MatrixXd mode_shapes;            ///< 6n x M, mass-normalised, zero at constrained DOFs
  std::vector<Eigen::Matrix3Xd> phi_W;    ///< per node: translational shapes Phi_p (3 x M), m
  std::vector<Eigen::Matrix3Xd> psi_W;    ///< per node: rotational shapes Psi_p (3 x M), rad
  Eigen::VectorXd nodal_mass_kg;          ///< lumped translational mass per node
  std::vector<Mat3> nodal_rotary_W_kgm2;  ///< lumped rotary block per node
  InertiaInvariants invariants;           ///< operator form with the chosen M, about P2
  LumpedInertiaSums lumped_sums;          ///< nodal sums of the lumped mesh (histories' loads)
  ModalGeometricStiffness geometric_stiffness;  ///< K^_G per unit inertial load (docs/theory.md
                                                ///< 4.6); empty if not asked for
  /// Of the M vectors, how many the nonlinear static shapes added (ModalWingOptions::
  /// static_shape_pressures_pa): the basis is then the Rayleigh-Ritz vectors of the modes and
  /// the shapes, and frequencies_hz their Ritz frequencies; 0 = the fixed-interface modes.
  int static_shape_count = 0;
  ModalMembraneStiffness membrane;        ///< the condensed membrane (docs/theory.md 4.7); empty
                                          ///< for the linear wing
  double wing_mass_kg = 0.0;              ///< members + skin
  double member_mass_kg = 0.0;
  double skin_mass_kg = 0.0;
  EffectiveMassTable effective_mass;      ///< over the kept modes
  ModeSelection selection;

  int modeCount() const { return static_cast<int>(frequencies_hz.size()); }
  /// Modal stiffness omega_k^2 and damping 2 zeta_k omega_k (docs/theory.md 3.5).
  Eigen::VectorXd stiffnessDiagonal() const;
  Eigen::VectorXd dampingDiagonal() const;
};

/// FE assembly, fixed-interface (or Craig-Bampton) modes, selection, invariants. The mesh must
/// have p2_node set. Throws std::invalid_argument for bad input and std::runtime_error when the
/// eigen-solution fails.
ModalWing buildModalWing(const WingStructure& wing_structure, const WingMesh& mesh,
                         const ModalWingOptions& options = {});

}  // namespace orni::structure
