// Rigid-body nodal vectors (docs/theory.md 3.6).
#include "core/structure/rigid_body_vectors.hpp"

namespace orni::structure {

Eigen::MatrixXd rigidTranslationVectors(const std::vector<Vec3>& nodes_W_m) {
  const int n = static_cast<int>(nodes_W_m.size());
  Eigen::MatrixXd r = Eigen::MatrixXd::Zero(kDofsPerNode * n, 3);
  for (int p = 0; p < n; ++p)
    for (int k = 0; k < 3; ++k) r(globalDof(p, k), k) = 1.0;
  return r;
}

Eigen::VectorXd rigidRotationVector(const std::vector<Vec3>& nodes_W_m, const Vec3& point_W_m,
                                    const Vec3& axis_W) {
  const int n = static_cast<int>(nodes_W_m.size());
  const Vec3 e = axis_W.normalized();
  Eigen::VectorXd r(kDofsPerNode * n);
  for (int p = 0; p < n; ++p) {
    r.segment<3>(globalDof(p, kU)) = e.cross(nodes_W_m[static_cast<std::size_t>(p)] - point_W_m);
    r.segment<3>(globalDof(p, kThetaX)) = e;
  }
  return r;
}

Eigen::MatrixXd rigidRotationVectors(const std::vector<Vec3>& nodes_W_m, const Vec3& point_W_m) {
  Eigen::MatrixXd r(kDofsPerNode * static_cast<Eigen::Index>(nodes_W_m.size()), 3);
  for (int k = 0; k < 3; ++k) r.col(k) = rigidRotationVector(nodes_W_m, point_W_m, Vec3::Unit(k));
  return r;
}

}  // namespace orni::structure
