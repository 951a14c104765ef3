// Skin pretension (docs/theory.md 4.7): the membrane stress a skin holds as built, and its
// geometric stiffness.
//
// A film is tensioned by shrinking (or pre-stretching) it onto the frame. What it then holds is not
// the nominal value everywhere: the stress must be in equilibrium with the frame, which yields, and
// with the free trailing edge, which carries no normal traction. So the pretension is computed as
// that equilibrium: an isotropic initial strain -s on every facet, s = N0 (1 - nu) / (E t), so that
// a fully held film would carry N_xx = N_yy = N0 (the key wing.skin.pretension_N_per_m, "the
// pretension of the film as laid"); the linear in-plane problem K d = f_s with the wing's own
// support (P2, P3, the root edge when pinned); then the skin's N = C (B_m d + s (1, 1, 0)) and the
// members' axial forces E A x'.du / L (compression where the film pulls the frame together). Both
// enter the geometric stiffness. (A uniform N0 on every facet, the model before 2026-12-06, is not
// in equilibrium with a free trailing edge and assumes a rigid frame: on Table 1's frame the film
// keeps 4 % of N0 chordwise and 20 % spanwise on average, and the wing buckles at 41 N/m, a local
// buckle of the skin at the trailing edge near the outer stiffener; tests/unit/structure/
// test_skin_pretension.cpp, where CalculiX checks the prestress field.)
#pragma once

#include <Eigen/Core>

#include "core/structure/fe_assembly.hpp"
#include "core/structure/fe_types.hpp"
#include "core/structure/geometric_stiffness.hpp"
#include "core/structure/wing_mesh.hpp"
#include "core/structure/wing_structure.hpp"

namespace orni::structure {

/// The isotropic shrink strain s (> 0 shrinks) that makes a fully held skin carry N0 (N/m):
/// s = N0 (1 - nu) / (E t).
double skinShrinkStrain(const WingStructure& wing_structure, double pretension_Npm);

/// The self-equilibrated prestress of a skin shrunk onto its frame (above).
struct SkinPrestress {
  Eigen::VectorXd displacement;  ///< 6n: the in-plane displacement the shrink causes (m, rad)
  ElementStresses stresses;      ///< one field: facet (N_xx, N_yy, N_xy) in the triad, member forces
};
SkinPrestress shrunkSkinPrestress(const WingStructure& wing_structure, const WingMesh& mesh,
                                  const WingSupport& support, double pretension_Npm);

/// The geometric stiffness of that prestress (6n x 6n); a zero matrix for N0 = 0.
SparseMatrix skinPretensionStiffness(const WingStructure& wing_structure, const WingMesh& mesh,
                                     const WingSupport& support, double pretension_Npm);

/// The physical check of a pretension: the largest N0' <= N0 for which K + K_G(N0') stays positive
/// definite on the retained DOFs (the film shrunk onto the frame does not buckle the wing), to 1e-12 of
/// N0 by bisection on Sylvester's inertia; N0 itself when the frame holds it.
double skinPretensionBucklingLimit(const WingStructure& wing_structure, const WingMesh& mesh,
                                   const WingSupport& support, double pretension_Npm);

/// K of the wing with the pretension of wing.skin added (every static and modal analysis of the
/// wing uses it). Throws InvalidModelError when the frame cannot hold the pretension (above),
/// naming the largest one it holds.
void addSkinPretension(const WingStructure& wing_structure, const WingMesh& mesh,
                       const WingSupport& support, WingFeModel* fe);

}  // namespace orni::structure
