// Nonlinear static shapes as Ritz vectors of the nonlinear (membrane) wing (docs/theory.md 4.7).
//
// The condensed membrane (membrane_rom.hpp) is exact for the deflections the basis can hold, but a
// slack 0.04 mm skin under lift takes shapes the first linear modes do not hold: its panels bulge
// between the members as membranes do, not as the plate modes bend. Measured on the literal EFW
// under a uniform lift (2026-12-07, docs/theory.md 4.7): with the 24 linear modes the reduced
// wing's mid-span trailing edge reaches 0.84 / 0.73 of the full nonlinear solution at 1.67 / 4.77
// Pa, with 48 modes 0.96 / 0.84, with 24 modes and the shapes at 0.5 and 3 Pa 0.993 / 0.980
// (test_fe_static_shapes.cpp); the full solution's own out-of-plane shape added to the 24 modes
// makes it exact (1.0001), so the condensation is right and the basis is what is missing.
//
// The route: the full nonlinear static solution (von_karman.hpp) under a few uniform lift pressures
// chosen by the user, its out-of-plane part (w, theta_x, theta_y; the in-plane part is the
// membrane's, which the condensation recovers), added to the kept modes and the whole set
// replaced by its Rayleigh-Ritz vectors (mass-normalised, stiffness-diagonal, ascending), so that
// everything downstream sees an ordinary modal basis. This is the nonlinear analogue of adding
// static correction (load-dependent Ritz) vectors to a modal basis; it is a choice of basis, not a
// fit: the reduced model stays the exact condensation on the enlarged basis, and it stays one
// potential (energy conserved).
#pragma once

#include <vector>

#include <Eigen/Core>

#include "core/structure/dof_partition.hpp"
#include "core/structure/fe_types.hpp"
#include "core/structure/von_karman.hpp"
#include "core/structure/wing_mesh.hpp"

namespace orni::structure {

/// Consistent nodal loads (6n) of a uniform pressure on the skin acting upward, along -z_W (lift;
/// z_W points down), Pa: a third of each facet's force on each of its nodes.
Eigen::VectorXd uniformLiftLoad(const WingMesh& mesh, double pressure_pa);

/// A strip's section of a wing deflection u (6n): the upward (-z_W) deflections of the strip's
/// leading- and trailing-edge sample nodes (m) and the section's nose-up pitch change (deg; the
/// trailing edge rising relative to the leading edge pitches it nose-down).
struct Section {
  double lead_up_m, trail_up_m, pitch_deg;
};
Section sectionOf(const WingMesh& mesh, const Eigen::VectorXd& u, std::size_t strip);

/// The out-of-plane part of a displacement field of the flat wing (w, theta_x, theta_y; u, v and
/// theta_z zeroed).
Eigen::VectorXd outOfPlanePart(const Eigen::VectorXd& displacement);

/// A basis replaced by its Rayleigh-Ritz vectors: the span of [shapes, extra] (6n columns each)
/// with every direction whose mass norm is below `dependence_tol` of the largest dropped (the
/// extra columns are scaled to unit mass norm first), then K- and M-orthogonalised. shapes are
/// mass-normalised (Phi^T M Phi = I), omega2 ascending.
struct RitzBasis {
  Eigen::MatrixXd shapes;
  Eigen::VectorXd omega2;
  int dropped = 0;  ///< directions already in the span
};
RitzBasis rayleighRitzBasis(const SparseMatrix& stiffness, const SparseMatrix& mass,
                            const Eigen::MatrixXd& shapes, const Eigen::MatrixXd& extra,
                            double dependence_tol = 1e-8);

/// The out-of-plane parts of the full nonlinear static solutions under uniform lift pressures
/// (6n x pressures.size()). `stiffness` the assembled (possibly prestressed) K, `part` the wing's
/// support. Throws InvalidModelError naming the pressure when a solution does not converge.
Eigen::MatrixXd nonlinearStaticShapes(const SparseMatrix& stiffness, const VonKarmanTerms& terms,
                                      const DofPartition& part, const WingMesh& mesh,
                                      const std::vector<double>& pressures_pa);

}  // namespace orni::structure
