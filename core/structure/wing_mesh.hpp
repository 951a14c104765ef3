// Finite-element mesh of the flat right wing in the W frame (docs/theory.md 2.1, 2.5): shell
// triangles for the skin, beam elements along the members (always on element edges), and the
// aerodynamic sample points of every strip on mesh nodes (docs/theory.md 6.1).
#pragma once

#include <array>
#include <vector>

#include <Eigen/Core>

#include "core/structure/wing_structure.hpp"

namespace orni::structure {

/// A beam element between two mesh nodes along member `member` (index into wing.members).
struct BeamElement {
  std::array<int, 2> nodes{};
  int member = -1;
};

/// Mesh nodes of one aerodynamic strip, all on its mid-station y (docs/theory.md 6.1).
struct StripSampleNodes {
  double y_W_m = 0.0;
  int leading_edge = -1;          ///< L_j, on the leading edge
  int quarter_chord = -1;         ///< Q_j, x_W = -c/4
  int three_quarter_chord = -1;   ///< T_j, x_W = -3c/4
  int trailing_edge = -1;         ///< E_j
};

struct WingMesh {
  std::vector<Eigen::Vector3d> nodes_W_m;        ///< node positions, z_W = 0 (flat wing)
  std::vector<std::array<int, 3>> triangles;     ///< skin facets, counter-clockwise in (x_W, y_W)
  std::vector<BeamElement> beams;                ///< member elements (on triangle edges)
  std::vector<StripSampleNodes> strip_nodes;     ///< one per aerodynamic strip, root to tip
  int p2_node = -1;                              ///< hinge P2: root leading edge (origin of W)
  int p3_node = -1;                              ///< universal joint P3 on the root chord

  int nodeCount() const { return static_cast<int>(nodes_W_m.size()); }
};

/// Station-sweep mesher (docs/theory.md 2.5). `element_size_m` is the target edge length h (> 0).
/// Throws std::invalid_argument on a geometry it cannot mesh (e.g. crossing members).
WingMesh buildWingMesh(const WingStructure& wing_structure, double element_size_m);

}  // namespace orni::structure
