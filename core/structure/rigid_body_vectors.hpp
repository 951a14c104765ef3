// Rigid-body nodal vectors over 6 DOF per node (docs/theory.md 3.4, 3.6).
#pragma once

#include <vector>

#include "core/structure/fe_types.hpp"

namespace orni::structure {

/// R_t (6n x 3): column k is a unit translation along W axis k (translational slots only).
Eigen::MatrixXd rigidTranslationVectors(const std::vector<Vec3>& nodes_W_m);

/// R_r (6n x 3): column k is a unit rotation about W axis k through `point_W_m`:
/// translation e_k x (x_p - point), rotation e_k.
Eigen::MatrixXd rigidRotationVectors(const std::vector<Vec3>& nodes_W_m, const Vec3& point_W_m);

/// Unit rotation about `axis_W` (normalised here) through `point_W_m` (6n vector).
Eigen::VectorXd rigidRotationVector(const std::vector<Vec3>& nodes_W_m, const Vec3& point_W_m,
                                    const Vec3& axis_W);

}  // namespace orni::structure
