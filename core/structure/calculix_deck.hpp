// CalculiX 2.20 input deck of the wing finite-element model (structure.md 6.1-6.2): the same mesh,
// members, materials and joints as assembleWingFe / wingBoundaryDofs, in quadratic CalculiX
// elements, for an independent check of the fixed-interface frequencies (`ccx -i JOB`).
//
// Units N-mm-t-s: coordinates in mm, E in MPa, density in t/mm^3, thickness and diameters in mm;
// frequencies come out in Hz. Node i of the mesh is CalculiX node i + 1; midside nodes follow.
//
// Element choice (structure.md 6.1, measured on the EFW against our DKT/CST + Euler-Bernoulli
// model, see calculix_deck.cpp): every skin triangle is split into three quadrilaterals (corner,
// edge midpoints, centroid) as S8R; members are B32R with SECTION=CIRC. S6 triangles are the
// alternative. Linear elements do not work in ccx 2.20 (B31 refuses CIRC, S3 locks, S4 is wrong).
#pragma once

#include <string>

#include "core/model/vehicle_model.hpp"
#include "core/structure/wing_mesh.hpp"

namespace orni::structure {

enum class CalculixSkinElement {
  kS8RSplit,  ///< each triangle -> 3 S8R quads (corner, edge midpoints, centroid): default
  kS6,        ///< each triangle -> one S6 (quadratic triangle): a few % stiffer
};

enum class CalculixBeamElement {
  kB32R,  ///< quadratic beam, reduced integration: default
  kB32,   ///< quadratic beam, full integration
};

struct CalculixDeckOptions {
  int mode_count = 12;  ///< eigenvalues of the *FREQUENCY step, [1, 10000]
  bool p3_cross_axis_normal = true;  ///< P3 rotation fixed about z_W (true, DOF 6) or y_W (DOF 5)
  CalculixSkinElement skin = CalculixSkinElement::kS8RSplit;
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
std::string calculixDeck(const VehicleModel& vehicle, const WingMesh& mesh,
                         const CalculixDeckOptions& options, CalculixDeckStats* stats = nullptr);

}  // namespace orni::structure
