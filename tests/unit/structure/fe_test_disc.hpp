// The clamped circular plate of the geometric-nonlinearity tests: a triangulated disc and the
// lumped load of a uniform pressure (the same helpers as test_fe_von_karman.cpp's, shared here for
// the cross-code checks against CalculiX).
#pragma once

#include <array>
#include <cmath>
#include <vector>

#include <Eigen/Core>

#include "core/structure/fe_assembly.hpp"
#include "core/structure/fe_types.hpp"
#include "core/structure/shell_element.hpp"
#include "core/structure/wing_mesh.hpp"
#include "tests/unit/structure/fe_test_meshes.hpp"

namespace orni::structure::fe_test {

/// Disc of radius a in the (x_W, y_W) plane: a centre node (node 0, also P2) and `rings` rings of
/// 6k nodes, neighbouring rings joined by merging their nodes by angle (counter-clockwise
/// triangles). No P3, no members.
inline WingMesh discMesh(double radius_m, int rings) {
  WingMesh mesh;
  mesh.nodes_W_m.emplace_back(0.0, 0.0, 0.0);
  std::vector<std::vector<int>> ring_nodes(static_cast<std::size_t>(rings) + 1);
  ring_nodes[0] = {0};
  for (int k = 1; k <= rings; ++k) {
    const int count = 6 * k;
    for (int i = 0; i < count; ++i) {
      const double angle = 2.0 * kTestPi * i / count;
      const double r = radius_m * k / rings;
      ring_nodes[static_cast<std::size_t>(k)].push_back(mesh.nodeCount());
      mesh.nodes_W_m.emplace_back(r * std::cos(angle), r * std::sin(angle), 0.0);
    }
  }
  for (int i = 0; i < 6; ++i) mesh.triangles.push_back({0, 1 + i, 1 + (i + 1) % 6});
  for (int k = 2; k <= rings; ++k) {
    const std::vector<int>& in = ring_nodes[static_cast<std::size_t>(k) - 1];
    const std::vector<int>& out = ring_nodes[static_cast<std::size_t>(k)];
    const int n_in = static_cast<int>(in.size()), n_out = static_cast<int>(out.size());
    int i = 0, j = 0;
    while (i < n_in || j < n_out) {
      const double next_in = i < n_in ? static_cast<double>(i + 1) / n_in : 2.0;
      const double next_out = j < n_out ? static_cast<double>(j + 1) / n_out : 2.0;
      if (next_out <= next_in) {
        mesh.triangles.push_back({in[static_cast<std::size_t>(i % n_in)],
                                  out[static_cast<std::size_t>(j)],
                                  out[static_cast<std::size_t>((j + 1) % n_out)]});
        ++j;
      } else {
        mesh.triangles.push_back({in[static_cast<std::size_t>(i)],
                                  out[static_cast<std::size_t>(j % n_out)],
                                  in[static_cast<std::size_t>((i + 1) % n_in)]});
        ++i;
      }
    }
  }
  mesh.p2_node = 0;
  return mesh;
}

/// Lumped load of a uniform pressure q along +z_W on linear triangles: q A / 3 per corner node
/// (the consistent load of our facets' linear w interpolation), 6 DOF per node.
inline Eigen::VectorXd pressureLoad(const WingMesh& mesh, double pressure_pa) {
  Eigen::VectorXd f = Eigen::VectorXd::Zero(kDofsPerNode * mesh.nodeCount());
  for (const std::array<int, 3>& tri : mesh.triangles) {
    const std::array<Vec3, 3> x = {mesh.nodes_W_m[static_cast<std::size_t>(tri[0])],
                                   mesh.nodes_W_m[static_cast<std::size_t>(tri[1])],
                                   mesh.nodes_W_m[static_cast<std::size_t>(tri[2])]};
    const double share = pressure_pa * triangleArea(x) / 3.0;
    for (int n : tri) f(globalDof(n, kW)) += share;
  }
  return f;
}

/// The nodes on the rim of a disc mesh (|x| = a).
inline std::vector<int> discRimNodes(const WingMesh& mesh, double radius_m) {
  std::vector<int> rim;
  for (int n = 0; n < mesh.nodeCount(); ++n)
    if (mesh.nodes_W_m[static_cast<std::size_t>(n)].norm() > radius_m * (1.0 - 1e-9)) rim.push_back(n);
  return rim;
}

}  // namespace orni::structure::fe_test
