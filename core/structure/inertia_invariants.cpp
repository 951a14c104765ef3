// Inertia invariants (docs/theory.md 3.6).
#include "core/structure/inertia_invariants.hpp"

#include <stdexcept>

#include "core/structure/rigid_body_vectors.hpp"

namespace orni::structure {
namespace {

using SlotMap = Eigen::Map<const Eigen::MatrixXd, 0, Eigen::Stride<Eigen::Dynamic, Eigen::Dynamic>>;

// Rows 6p + slot (p = 0 .. n-1) of a column-major 6n x M matrix, without a copy.
SlotMap slotRows(const Eigen::MatrixXd& a, int slot) {
  const Eigen::Index n = a.rows() / kDofsPerNode;
  // No shapes (M = 0 columns): data() is null and null + slot undefined behaviour; the map is empty.
  const double* first = a.size() > 0 ? a.data() + slot : a.data();
  return SlotMap(first, n, a.cols(),
                 Eigen::Stride<Eigen::Dynamic, Eigen::Dynamic>(a.rows(), kDofsPerNode));
}

void checkSizes(const Eigen::MatrixXd& shapes, const std::vector<Vec3>& nodes) {
  if (shapes.rows() != kDofsPerNode * static_cast<Eigen::Index>(nodes.size()))
    throw std::invalid_argument("inertia invariants: shapes must have 6 rows per node");
}

Eigen::MatrixXd relativeCoordinates(const std::vector<Vec3>& nodes, const Vec3& origin) {
  Eigen::MatrixXd x(static_cast<Eigen::Index>(nodes.size()), 3);
  for (std::size_t p = 0; p < nodes.size(); ++p)
    x.row(static_cast<Eigen::Index>(p)) = (nodes[p] - origin).transpose();
  return x;
}

}  // namespace

InertiaInvariants invariantsOperatorForm(const SparseMatrix& mass, const Eigen::MatrixXd& shapes,
                                         const std::vector<Vec3>& nodes_W_m,
                                         const Vec3& origin_W_m) {
  checkSizes(shapes, nodes_W_m);
  if (mass.rows() != shapes.rows())
    throw std::invalid_argument("inertia invariants: M and shapes sizes differ");
  const Eigen::MatrixXd x = relativeCoordinates(nodes_W_m, origin_W_m);
  const Eigen::MatrixXd r_t = rigidTranslationVectors(nodes_W_m);
  const Eigen::MatrixXd r_r = rigidRotationVectors(nodes_W_m, origin_W_m);
  const Eigen::MatrixXd m_rt = mass * r_t;
  const Eigen::MatrixXd m_rr = mass * r_r;
  const Eigen::MatrixXd m_phi = mass * shapes;

  InertiaInvariants inv;
  inv.mass_kg = (r_t.transpose() * m_rt).trace() / 3.0;
  for (int l = 0; l < 3; ++l)
    inv.first_moment_W_kgm(l) = slotRows(m_rt, l).col(l).dot(x.col(l));
  const Mat3 j0 = r_r.transpose() * m_rr;
  inv.inertia_P2_W_kgm2 = 0.5 * (j0 + j0.transpose());
  inv.translational_participation = m_rt.transpose() * shapes;
  inv.rotational_participation = m_rr.transpose() * shapes;
  const Eigen::MatrixXd gm = shapes.transpose() * m_phi;
  inv.generalized_mass = 0.5 * (gm + gm.transpose());

  // A_kl = Phi^T M B_kl Phi (docs/theory.md 3.6); P_kl = (A_kl + A_lk^T) / 2 so that
  // P_lk = P_kl^T holds also for the consistent beam mass (equal to A_kl for a lumped M).
  std::array<Eigen::MatrixXd, 9> a;
  for (int k = 0; k < 3; ++k)
    for (int l = 0; l < 3; ++l) {
      a[static_cast<std::size_t>(3 * k + l)] =
          slotRows(m_phi, k).transpose() * slotRows(shapes, l);
      inv.s[static_cast<std::size_t>(3 * k + l)] = slotRows(m_phi, k).transpose() * x.col(l);
    }
  for (int k = 0; k < 3; ++k)
    for (int l = 0; l < 3; ++l)
      inv.p[static_cast<std::size_t>(3 * k + l)] =
          0.5 * (a[static_cast<std::size_t>(3 * k + l)] +
                 a[static_cast<std::size_t>(3 * l + k)].transpose());
  return inv;
}

InertiaInvariants invariantsNodalSums(const Eigen::VectorXd& nodal_mass_kg,
                                      const std::vector<Mat3>& nodal_rotary_W_kgm2,
                                      const Eigen::MatrixXd& shapes,
                                      const std::vector<Vec3>& nodes_W_m, const Vec3& origin_W_m) {
  checkSizes(shapes, nodes_W_m);
  const Eigen::Index n = static_cast<Eigen::Index>(nodes_W_m.size());
  const bool rotary = !nodal_rotary_W_kgm2.empty();
  if (nodal_mass_kg.size() != n ||
      (rotary && nodal_rotary_W_kgm2.size() != static_cast<std::size_t>(n)))
    throw std::invalid_argument("inertia invariants: one nodal mass per node expected");
  const Eigen::Index modes = shapes.cols();

  InertiaInvariants inv;
  inv.translational_participation = Eigen::Matrix3Xd::Zero(3, modes);
  inv.rotational_participation = Eigen::Matrix3Xd::Zero(3, modes);
  inv.generalized_mass = Eigen::MatrixXd::Zero(modes, modes);
  for (auto& pk : inv.p) pk = Eigen::MatrixXd::Zero(modes, modes);
  for (auto& sk : inv.s) sk = Eigen::VectorXd::Zero(modes);

  for (Eigen::Index p = 0; p < n; ++p) {
    const double m = nodal_mass_kg(p);
    const Vec3 x = nodes_W_m[static_cast<std::size_t>(p)] - origin_W_m;
    inv.mass_kg += m;
    inv.first_moment_W_kgm += m * x;
    inv.inertia_P2_W_kgm2 += m * (x.squaredNorm() * Mat3::Identity() - x * x.transpose());
    if (rotary) inv.inertia_P2_W_kgm2 += nodal_rotary_W_kgm2[static_cast<std::size_t>(p)];
    // No modes: the rigid-body sums only (a row block of a 0-column matrix would offset its null
    // data pointer, undefined behaviour).
    if (modes == 0) continue;
    const auto phi = shapes.middleRows<3>(kDofsPerNode * p);
    const auto psi = shapes.middleRows<3>(kDofsPerNode * p + 3);
    inv.translational_participation += m * phi;
    Mat3 skew_x;
    skew_x << 0, -x.z(), x.y(), x.z(), 0, -x.x(), -x.y(), x.x(), 0;
    inv.rotational_participation += m * skew_x * phi;
    inv.generalized_mass += m * phi.transpose() * phi;
    for (int k = 0; k < 3; ++k)
      for (int l = 0; l < 3; ++l) {
        inv.p[static_cast<std::size_t>(3 * k + l)] += m * phi.row(k).transpose() * phi.row(l);
        inv.s[static_cast<std::size_t>(3 * k + l)] += (m * x(l)) * phi.row(k).transpose();
      }
    if (rotary) {
      const Mat3& jp = nodal_rotary_W_kgm2[static_cast<std::size_t>(p)];
      inv.rotational_participation += jp * psi;
      inv.generalized_mass += psi.transpose() * jp * psi;
    }
  }
  return inv;
}

}  // namespace orni::structure
