// CalculiX 2.20 input deck of the wing finite-element model (structure.md 6.1-6.2): the same mesh,
// members, materials and joints as assembleWingFe / wingBoundaryDofs, in quadratic CalculiX
// elements, for an independent check of the fixed-interface frequencies (`ccx -i JOB`).
//
// Units N-mm-t-s: coordinates in mm, E in MPa, density in t/mm^3, thickness and diameters in mm;
// frequencies come out in Hz. Node i of the mesh is CalculiX node i + 1; midside nodes follow.
//
// Element choice (structure.md 6.1; measured on the EFW, h = 5 mm, 2 threads, against our DKT/CST
// + Euler-Bernoulli model, first six modes): S6 skin + B32R rods: +0.7 ... +4.1 %, 8 s (default);
// each triangle split into three S8R quads + B32R: +0.7 ... +3.5 %, 77 s; B32 instead of B32R
// changes nothing. Linear elements do not work in ccx 2.20 (B31 refuses CIRC, S3 locks, S4 is
// wrong). Members are written with nu = 0 and the isotropic G (see calculix_deck.cpp): with the
// plain isotropic material the rigid beam-shell knots stiffen the rods by ~35 % and the EFW
// frequencies come out 4-12 % high.
#pragma once

#include <string>

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

struct CalculixDeckOptions {
  int mode_count = 12;  ///< eigenvalues of the *FREQUENCY step, [1, 10000]
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

/// The deck text. Throws std::invalid_argument for a mesh without P2, an unknown material, a
/// member index out of range, a node index out of range or a mode count outside [1, 10000].
/// P2 is clamped (DOF 1-6); P3 (when the mesh has one) has DOF 1-3 and the cross-axis rotation
/// fixed (structure.md 2.1), as wingBoundaryDofs does.
std::string calculixDeck(const WingStructure& wing_structure, const WingMesh& mesh,
                         const CalculixDeckOptions& options, CalculixDeckStats* stats = nullptr);

}  // namespace orni::structure
