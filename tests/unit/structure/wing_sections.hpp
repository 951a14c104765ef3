// A strip's section of a wing deflection, for the static checks of the membrane wing
// (test_fe_membrane_efw.cpp, test_fe_static_shapes.cpp).
#pragma once

#include <cmath>
#include <cstddef>

#include <Eigen/Core>

#include "core/structure/fe_types.hpp"
#include "core/structure/wing_mesh.hpp"
#include "fe_test_meshes.hpp"

namespace orni::structure::fe_test {

struct Section {
  double lead_up_m, trail_up_m, pitch_deg;
};

// Upward deflections of a strip's leading- and trailing-edge nodes and its nose-up pitch change
// (the trailing edge rising relative to the leading edge pitches the section nose-down).
inline Section sectionOf(const WingMesh& mesh, const Eigen::VectorXd& u, std::size_t strip) {
  const StripSampleNodes& s = mesh.strip_nodes[strip];
  const double lead = -u(globalDof(s.leading_edge, kW));
  const double trail = -u(globalDof(s.trailing_edge, kW));
  const double chord = (mesh.nodes_W_m[static_cast<std::size_t>(s.leading_edge)] -
                        mesh.nodes_W_m[static_cast<std::size_t>(s.trailing_edge)]).norm();
  return {lead, trail, -std::atan2(trail - lead, chord) * 180.0 / kTestPi};
}

}  // namespace orni::structure::fe_test
