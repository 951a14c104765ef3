// Craig-Bampton self-checks (docs/theory.md 3.1) on a small mini-wing (dense reference solves).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include <Eigen/Eigenvalues>

#include "core/structure/craig_bampton.hpp"
#include "core/structure/dof_partition.hpp"
#include "core/structure/fe_assembly.hpp"
#include "core/structure/rigid_body_vectors.hpp"
#include "tests/unit/structure/fe_test_meshes.hpp"

namespace orni::structure {
namespace {

// Same subspace, different algebra (dense eigen-solvers on matrices with cond ~ 1e10):
// eigenvalues relative to the largest one compared.
constexpr double kFullBasisTol = 1e-9;
// Rayleigh-Ritz upper bounds can only be violated by round-off (relative to the largest
// eigenvalue, as for kFullBasisTol).
constexpr double kUpperBoundSlack = 1e-9;
// Task requirement for the orthonormalised modes.
constexpr double kOrthonormalTol = 1e-10;
// Rigid-body mass captured by the six rigid modes: round-off.
constexpr double kRigidMassTol = 1e-10;

struct Model {
  fe_test::MiniWing wing;
  WingFeModel fe;
};

Model smallWing() {
  Model m;
  m.wing = fe_test::miniWing(4, 6, 0.04, 0.06);
  m.fe = assembleWingFe(m.wing.vehicle, m.wing.mesh);
  return m;
}

std::vector<int> nodeDofs(int node) {
  std::vector<int> d;
  for (int k = 0; k < kDofsPerNode; ++k) d.push_back(globalDof(node, k));
  return d;
}

// Lowest eigenvalues of the retained (b_f + i) model, dense.
Eigen::VectorXd fullEigenvalues(const WingFeModel& fe, const DofPartition& part) {
  std::vector<int> r = part.retained();
  std::sort(r.begin(), r.end());
  const Eigen::MatrixXd k = Eigen::MatrixXd(extractBlock(fe.stiffness, r, r));
  const Eigen::MatrixXd m = Eigen::MatrixXd(extractBlock(fe.mass, r, r));
  return Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd>(k, m).eigenvalues();
}

// P2 clamped (b_c), P3's six DOF left free (b_f).
DofPartition p3FreePartition(const Model& m) {
  return makeDofPartition(m.fe.active, nodeDofs(m.wing.mesh.p2_node),
                          nodeDofs(m.wing.mesh.p3_node));
}

TEST(StructureFeCraigBampton, FullInteriorBasisReproducesTheFullModel) {
  const Model m = smallWing();
  const DofPartition part = p3FreePartition(m);
  const Eigen::VectorXd full = fullEigenvalues(m.fe, part);
  const CraigBamptonModel cb = craigBampton(m.fe.stiffness, m.fe.mass, part);  // m = all
  ASSERT_EQ(cb.size(), full.size());
  const Eigen::VectorXd reduced =
      Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd>(cb.stiffness, cb.mass)
          .eigenvalues();
  const double err = (reduced - full).cwiseAbs().maxCoeff() / full.maxCoeff();
  EXPECT_LT(err, kFullBasisTol);
  fe_test::recordError("full_basis_max_rel_error", err);
}

TEST(StructureFeCraigBampton, TruncatedBasesConvergeFromAboveMonotonically) {
  const Model m = smallWing();
  const DofPartition part = p3FreePartition(m);
  const Eigen::VectorXd full = fullEigenvalues(m.fe, part);
  constexpr int kChecked = 6;
  const double slack = kUpperBoundSlack * full.maxCoeff();
  Eigen::VectorXd previous = Eigen::VectorXd::Constant(kChecked, HUGE_VAL);
  for (int modes : {1, 2, 4, 8, 16, 32}) {
    CraigBamptonOptions o;
    o.max_modes = modes;
    const CraigBamptonModel cb = craigBampton(m.fe.stiffness, m.fe.mass, part, o);
    const Eigen::VectorXd reduced =
        Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd>(cb.stiffness, cb.mass)
            .eigenvalues()
            .head(kChecked);
    for (int k = 0; k < kChecked; ++k) {
      EXPECT_GE(reduced(k), full(k) - slack) << "m = " << modes << ", k = " << k;
      EXPECT_LE(reduced(k), previous(k) + slack)
          << "m = " << modes << ", k = " << k;
    }
    previous = reduced;
  }
  EXPECT_LT(((previous - full.head(kChecked)).array() / full.head(kChecked).array()).maxCoeff(),
            1e-3);
}

TEST(StructureFeCraigBampton, OrthonormalisedModesAreMassAndStiffnessOrthogonal) {
  const Model m = smallWing();
  CraigBamptonOptions o;
  o.max_modes = 10;
  const CraigBamptonModel cb = craigBampton(m.fe.stiffness, m.fe.mass, p3FreePartition(m), o);
  const OrthonormalModes on = orthonormalise(cb);
  EXPECT_EQ(on.rigid_count, 0);  // b_c = P2 holds the body
  const Eigen::MatrixXd& phi = on.shapes;
  const Eigen::MatrixXd gm = phi.transpose() * (m.fe.mass * phi);
  const Eigen::MatrixXd gk = phi.transpose() * (m.fe.stiffness * phi);
  const double m_err = (gm - Eigen::MatrixXd::Identity(gm.rows(), gm.cols())).cwiseAbs().maxCoeff();
  EXPECT_LT(m_err, kOrthonormalTol);
  const double lambda_max = on.eigenvalues.maxCoeff();
  Eigen::MatrixXd off = gk;
  off.diagonal().setZero();
  EXPECT_LT(off.cwiseAbs().maxCoeff() / lambda_max, kOrthonormalTol);
  fe_test::recordError("phiT_M_phi_minus_I", m_err);
  fe_test::recordError("phiT_K_phi_offdiag_rel", off.cwiseAbs().maxCoeff() / lambda_max);
  EXPECT_LT((gk.diagonal() - on.eigenvalues).cwiseAbs().maxCoeff() / lambda_max,
            kOrthonormalTol);
}

TEST(StructureFeCraigBampton, FreeComponentHasSixRigidModesCarryingTheRigidMass) {
  const Model m = smallWing();
  // No clamped DOF; P2 and P3 (both on members, 12 active DOF) form b_f.
  std::vector<int> bf = nodeDofs(m.wing.mesh.p2_node);
  for (int d : nodeDofs(m.wing.mesh.p3_node)) bf.push_back(d);
  const DofPartition part = makeDofPartition(m.fe.active, {}, bf);
  ASSERT_EQ(part.boundary_free.size(), 12u);
  CraigBamptonOptions o;
  o.max_modes = 8;
  const CraigBamptonModel cb = craigBampton(m.fe.stiffness, m.fe.mass, part, o);
  const OrthonormalModes on = orthonormalise(cb);
  EXPECT_EQ(on.rigid_count, 6);
  for (int k = 0; k < 6; ++k) EXPECT_TRUE(on.rigid[static_cast<std::size_t>(k)]);
  EXPECT_GT(on.eigenvalues(6), 0.0);

  // Rigid vectors on the active DOFs (the retained space) about P2.
  const Vec3 p2 = m.wing.mesh.nodes_W_m[static_cast<std::size_t>(m.wing.mesh.p2_node)];
  Eigen::MatrixXd r(m.fe.dofCount(), 6);
  r << rigidTranslationVectors(m.wing.mesh.nodes_W_m),
      rigidRotationVectors(m.wing.mesh.nodes_W_m, p2);
  for (int d = 0; d < m.fe.dofCount(); ++d)
    if (!m.fe.active[static_cast<std::size_t>(d)]) r.row(d).setZero();
  const Eigen::MatrixXd mr = m.fe.mass * r;
  const Eigen::MatrixXd g = r.transpose() * mr;  // [m I, m skew(c)^T; ., J0]
  const Eigen::MatrixXd phi_r = on.shapes.leftCols(6);
  const Eigen::MatrixXd l = phi_r.transpose() * mr;  // participation of the rigid modes
  EXPECT_LT((l.transpose() * l - g).norm(), kRigidMassTol * g.norm());
  fe_test::recordError("rigid_mass_rel_error", (l.transpose() * l - g).norm() / g.norm());
  fe_test::recordError("seventh_over_max_eigenvalue",
                       on.eigenvalues(6) / on.eigenvalues.maxCoeff());
  EXPECT_LT((g.topLeftCorner<3, 3>() - m.fe.totalMass_kg() * Mat3::Identity()).norm(),
            1e-12 * m.fe.totalMass_kg());
}

TEST(StructureFeCraigBampton, DefaultPathBasisIsTheFixedInterfaceModes) {
  const Model m = smallWing();
  const DofPartition part = makeDofPartition(m.fe.active, wingBoundaryDofs(m.wing.mesh));
  CraigBamptonOptions o;
  o.max_modes = 8;
  const CraigBamptonModel cb = craigBampton(m.fe.stiffness, m.fe.mass, part, o);
  EXPECT_EQ(cb.size(), 8);
  EXPECT_LT((cb.mass - Eigen::MatrixXd::Identity(8, 8)).cwiseAbs().maxCoeff(), 1e-12);
  const OrthonormalModes on = orthonormalise(cb);
  EXPECT_LT((on.eigenvalues - cb.interior_eigenvalues).cwiseAbs().maxCoeff(),
            1e-12 * cb.interior_eigenvalues.maxCoeff());
  // N is a signed identity: the orthonormalised modes are the fixed-interface modes.
  EXPECT_LT((on.coefficients.cwiseAbs() - Eigen::MatrixXd::Identity(8, 8)).cwiseAbs().maxCoeff(),
            1e-8);
}

}  // namespace
}  // namespace orni::structure
