// Mode selection (docs/theory.md 3.4): frequency cut-off and/or count, and the effective-mass
// criterion for rigid flapping (rotation about the hinge axis x_W through P2) and heave
// (translation along z_W).
#pragma once

#include <string>
#include <vector>

#include "core/structure/fe_types.hpp"

namespace orni::structure {

/// Effective masses L_kj^2 of modes k for the rigid vectors R_j, as fractions of R_j^T M R_j.
struct EffectiveMassTable {
  double flap_reference_kgm2 = 0.0;  ///< R_flap^T M R_flap: inertia about the hinge axis
  double heave_reference_kg = 0.0;   ///< R_z^T M R_z: mass
  Eigen::VectorXd flap_fraction;     ///< per mode
  Eigen::VectorXd heave_fraction;    ///< per mode
  Eigen::VectorXd flap_cumulative;   ///< running sum of flap_fraction
  Eigen::VectorXd heave_cumulative;  ///< running sum of heave_fraction
};

/// `shapes` (6n x m) must be M-orthonormal. The hinge axis passes through `hinge_point_W_m`.
EffectiveMassTable effectiveMassTable(const SparseMatrix& mass, const Eigen::MatrixXd& shapes,
                                      const std::vector<Vec3>& nodes_W_m,
                                      const Vec3& hinge_point_W_m,
                                      const Vec3& hinge_axis_W = Vec3::UnitX());

struct ModeSelectionOptions {
  int max_modes = 12;       ///< modes computed and upper bound on the count, >= 1
  double cutoff_hz = 0.0;   ///< > 0: keep only modes with f <= cutoff_hz; 0: no cut-off
  /// In (0, 1): add modes (within max_modes) until both flap and heave cumulative effective mass
  /// reach this fraction (docs/theory.md 3.4 asks for 0.95); 0: no requirement.
  double min_effective_mass_fraction = 0.0;

  bool IsValid(std::string* why) const;
};

struct ModeSelection {
  int count = 0;                   ///< number of leading modes kept
  bool cutoff_reached = true;      ///< false if every computed mode lies below cutoff_hz
  bool effective_mass_met = true;  ///< both cumulative fractions >= min_effective_mass_fraction
  double flap_fraction = 0.0;      ///< cumulative flap effective mass of the kept modes
  double heave_fraction = 0.0;     ///< cumulative heave effective mass of the kept modes

  std::string BriefReport() const;
};

/// Selects the leading modes among the computed ones (ascending frequencies).
ModeSelection selectModes(const Eigen::VectorXd& frequencies_hz, const EffectiveMassTable& table,
                          const ModeSelectionOptions& options);

}  // namespace orni::structure
