// CalculiX 2.20 input deck of the wing finite-element model (docs/theory.md 2.7): the same mesh,
// members, materials and joints as assembleWingFe / wingBoundaryDofs, in quadratic CalculiX
// elements, for an independent check of the fixed-interface frequencies (`ccx -i JOB`) and, with
// static steps (geometrically nonlinear with NLGEOM, or linear), of static deflections under a
// skin pressure or nodal forces (docs/theory.md 4.7; the displacement reader is calculix_results.hpp).
//
// Units N-mm-t-s: coordinates in mm, E in MPa, density in t/mm^3, thickness and diameters in mm;
// frequencies come out in Hz. Node i of the mesh is CalculiX node i + 1; midside nodes follow.
//
// Element choice (docs/theory.md 2.7; measured on the EFW, h = 5 mm, 2 threads, against our DKT/CST
// + Euler-Bernoulli model, first six modes): S6 skin + B32R rods: +0.7 ... +4.1 %, 8 s (default);
// each triangle split into three S8R quads + B32R: +0.7 ... +3.5 %, 77 s; B32 instead of B32R
// changes nothing. Linear elements do not work in ccx 2.20 (B31 refuses CIRC, S3 locks, S4 is
// wrong). Members are written with nu = 0 and the isotropic G (see calculix_deck.cpp): with the
// plain isotropic material the rigid beam-shell knots stiffen the rods by ~35 % and the EFW
// frequencies come out 4-12 % high.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/structure/wing_structure.hpp"
#include "core/structure/wing_mesh.hpp"

namespace orni::structure {

enum class CalculixSkinElement {
  kS6,        ///< each triangle -> one S6 (quadratic triangle): default, fast
  kS8RSplit,  ///< each triangle -> 3 S8R quads (corner, edge midpoints, centroid): ~10x slower
};

enum class CalculixBeamElement {
  kB32R,  ///< quadratic beam, reduced integration: default
  kB32,   ///< quadratic beam, full integration
};

/// The load of the static steps, in SI units on our model (the deck converts to N-mm).
struct CalculixStaticLoad {
  /// Uniform pressure on every skin element (Pa), positive along +z_W, the facets' normal
  /// (counter-clockwise triangles in (x_W, y_W)). CalculiX's shell pressure P acts along the
  /// element normal of its node order (checked with ccx 2.20: a counter-clockwise S6 plate under
  /// P > 0 moves along +z), so the deck writes P = +pressure.
  double skin_pressure_pa = 0.0;
  /// true: *DLOAD P, which CalculiX applies to the deformed surface with NLGEOM (a follower load);
  /// false: the consistent nodal forces of the pressure on the undeformed quadratic elements
  /// (S6: q A / 3 on each midside node, nothing on the corners) as *CLOAD along z_W, a dead load
  /// as in solveNonlinearStatic.
  bool follower_pressure = false;
  /// Nodal forces of our model, 6 per mesh node (N along x_W, y_W, z_W, then moments in N m), or
  /// empty: *CLOAD on the mesh nodes (moments in N mm). A moment on a shell or beam node makes
  /// CalculiX join that node's expanded nodes rigidly (a knot).
  Eigen::VectorXd nodal_load;
};

/// Static steps (docs/theory.md 4.7): one *STEP per load factor, each ending at factor x load (the
/// load ramps linearly from the previous step's), time period 1 each, so step k ends at total
/// time k (k = 1, 2, ...). With NLGEOM every step starts from the previous step's deformed state:
/// ascending factors give a load sweep in one run.
struct CalculixStaticOptions {
  std::vector<double> load_factors;  ///< one static step per factor; empty = no static step
  bool nlgeom = true;                ///< *STEP, NLGEOM (large displacements); false: linear
  /// *STATIC increments as fractions of a step (a strongly nonlinear membrane needs small ones
  /// at first, then ccx grows them as the Newton iterations converge quickly).
  double initial_increment = 0.05;
  double min_increment = 1e-5;
  double max_increment = 0.25;
  int max_increments = 1000;  ///< *STEP, INC=
  /// Extra keyword cards written into every static step before *STATIC, verbatim (e.g.
  /// "*CONTROLS, PARAMETERS=TIME INCREMENTATION\n..."), each ending with a newline.
  std::string controls;
  /// Mesh nodes (0-based) whose displacements *NODE PRINT writes to JOB.dat (NSET=NPRINT);
  /// empty = every mesh node (midside nodes are never printed).
  std::vector<int> print_nodes;
  bool node_file = false;  ///< also *NODE FILE U (JOB.frd, for cgx)
  CalculixStaticLoad load;
  /// The skin's isotropic shrink strain s (skinShrinkStrain, skin_pretension.hpp), or 0: the
  /// skin material gets *EXPANSION 1, every node starts at temperature 0 and is at -s in every
  /// static step (the first ramps it in), so CalculiX finds the shrunk film's prestress as we do.
  double skin_shrink_strain = 0.0;
};

struct CalculixDeckOptions {
  int mode_count = 12;  ///< eigenvalues of the *FREQUENCY step, [1, 10000]
  bool frequency_step = true;  ///< the *FREQUENCY step (before any static step)
  CalculixStaticOptions static_steps;  ///< static steps after it (none by default)
  /// P2 clamped (DOF 1-6). false for a test mesh held otherwise (e.g. a plate whose P2 is the
  /// centre node); the mesh then needs no P2.
  bool clamp_p2 = true;
  /// Further mesh nodes (0-based) with all six DOFs held (a clamped edge, NSET=CLAMPED). The
  /// midside nodes of every element edge whose two ends are clamped are clamped too, so that the
  /// whole edge is held as in our model.
  std::vector<int> clamped_nodes;
  bool p3_cross_axis_normal = true;  ///< P3 rotation fixed about z_W (true, DOF 6) or y_W (DOF 5)
  P3Joint p3_joint = P3Joint::kUniversal;  ///< the rotations held at P3 (WingSupport)
  bool root_edge_pinned = false;  ///< every root-chord node (midside nodes too) held in translation
  CalculixSkinElement skin = CalculixSkinElement::kS6;
  CalculixBeamElement beam = CalculixBeamElement::kB32R;
  bool node_file = true;  ///< *NODE FILE U: mode shapes in JOB.frd (for cgx)
  std::string heading;    ///< *HEADING text; empty = "Ornithopter wing <vehicle name>"
};

/// Counts of what calculixDeck wrote (for reports and tests).
struct CalculixDeckStats {
  int nodes = 0;           ///< all nodes, corners + midside (+ centroids)
  int skin_elements = 0;   ///< S8R or S6
  int beam_elements = 0;   ///< B32R / B32
};

/// The deck text. Throws std::invalid_argument for a mesh without P2 (when clamp_p2), an unknown
/// material, a member index out of range, a node index out of range, a mode count outside
/// [1, 10000], a deck without any step, a nodal load of the wrong size or bad increments.
/// P2 is clamped (DOF 1-6); P3 (when the mesh has one) has DOF 1-3 and the cross-axis rotation
/// fixed (docs/theory.md 2.6), as wingBoundaryDofs does.
std::string calculixDeck(const WingStructure& wing_structure, const WingMesh& mesh,
                         const CalculixDeckOptions& options, CalculixDeckStats* stats = nullptr);

}  // namespace orni::structure
