// Geometric stiffness of the inertial loads (docs/theory.md 4.6): the unit load fields and their
// static solutions (equilibrium), the element matrices, the projected K^_G against the assembled
// one, symmetry, and which loads stress a flat wing.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/structure/dof_partition.hpp"
#include "core/structure/fe_assembly.hpp"
#include "core/structure/geometric_stiffness.hpp"
#include "core/structure/inertia_invariants.hpp"
#include "core/structure/modal_wing.hpp"
#include "core/structure/rigid_body_vectors.hpp"
#include "tests/unit/structure/fe_test_meshes.hpp"

namespace orni::structure {
namespace {

// Sums and products of the same numbers in another order, or a sparse solve of a well-scaled
// system (cond(K_ff) ~ 1e9 for the mini-wing: round-off 1e-16 x 1e9, relative): round-off.
constexpr double kRoundOffTol = 1e-9;
// Element identities in exact arithmetic, evaluated in double.
constexpr double kElementTol = 1e-12;

struct MiniWingFe {
  fe_test::MiniWing wing;
  WingFeModel fe;
  DofPartition part;
  Vec3 p2;
};

MiniWingFe miniWingSetup() {
  MiniWingFe s;
  s.wing = fe_test::miniWing(6, 10, 0.04, 0.08);
  s.fe = assembleWingFe(s.wing.vehicle, s.wing.mesh);
  s.part = makeDofPartition(s.fe.active, wingBoundaryDofs(s.wing.mesh));
  s.p2 = s.wing.mesh.nodes_W_m[static_cast<std::size_t>(s.wing.mesh.p2_node)];
  return s;
}

TEST(StructureGeometricStiffness, MembraneMatrixIsTheStringEnergyOfTheNormalSlope) {
  // A facet in a tilted plane: the normal displacement field w = g . (x - x0) along the facet's
  // normal n has strain energy 1/2 A g^T N g for the membrane forces N; a rigid normal
  // translation has none; the matrix is symmetric.
  const std::array<Vec3, 3> x = {Vec3(0.01, 0.02, 0.0), Vec3(0.03, 0.025, 0.004),
                                 Vec3(0.015, 0.05, 0.01)};
  const Vec3 forces(12.0, -3.0, 5.0);  // N_xx, N_yy, N_xy in the facet triad, N/m
  const Mat18 k = shellMembraneGeometricStiffness(x, forces);
  EXPECT_LT((k - k.transpose()).norm(), kElementTol * k.norm());
  const Mat3 triad = shellTriad(x);
  const Vec3 n = triad.row(2).transpose();
  Eigen::Matrix<double, 18, 1> translate = Eigen::Matrix<double, 18, 1>::Zero();
  for (int a = 0; a < 3; ++a) translate.segment<3>(6 * a) = n;
  EXPECT_LT((k * translate).norm(), kElementTol * k.norm());
  const Eigen::Vector2d g(0.7, -1.3);  // slope of w in the facet triad
  Eigen::Matrix<double, 18, 1> u = Eigen::Matrix<double, 18, 1>::Zero();
  for (int a = 0; a < 3; ++a) {
    const Vec3 d = x[static_cast<std::size_t>(a)] - x[0];
    const double w = g.x() * triad.row(0).dot(d) + g.y() * triad.row(1).dot(d);
    u.segment<3>(6 * a) = w * n;
  }
  Eigen::Matrix2d nm;
  nm << forces(0), forces(2), forces(2), forces(1);
  const double expected = triangleArea(x) * g.dot(nm * g);
  EXPECT_NEAR(u.dot(k * u), expected, kElementTol * std::abs(expected));
}

TEST(StructureGeometricStiffness, StaticSolutionsAreInEquilibrium) {
  // K u_i = F_i on the free DOFs, and the support reactions R = K u - F on the clamped DOFs
  // balance the applied load in force and moment about P2. The applied resultant is the rigid
  // part of the field: -(m a0 + A c0) for a(x) = a0 + A x.
  const MiniWingFe s = miniWingSetup();
  const UnitInertialLoadSolution sol =
      solveUnitInertialLoads(s.fe, s.part, s.wing.mesh.nodes_W_m, s.p2);
  const std::vector<Vec3>& nodes = s.wing.mesh.nodes_W_m;
  const Eigen::MatrixXd rt = rigidTranslationVectors(nodes);
  const Eigen::MatrixXd rr = rigidRotationVectors(nodes, s.p2);
  const Eigen::MatrixXd ku = s.fe.stiffness * sol.displacements;
  const double mass = s.fe.totalMass_kg();
  const Vec3 c0 =  // first moment about P2 with the same (consistent) mass
      invariantsOperatorForm(s.fe.mass, Eigen::MatrixXd::Zero(s.fe.dofCount(), 1), nodes, s.p2)
          .first_moment_W_kgm;
  ASSERT_TRUE(sol.flat);
  for (int i = 0; i < kInertialLoadCount; ++i) {
    const Eigen::VectorXd& f = sol.loads.col(i);
    const double scale = f.cwiseAbs().maxCoeff();
    if (!sol.solved[static_cast<std::size_t>(i)]) {
      // Out-of-plane load of the flat wing: no in-plane load component, so no membrane stress
      // (K and M do not couple the in-plane DOFs with the others); not solved.
      EXPECT_FALSE(isInPlaneLoad(static_cast<InertialLoad>(i)));
      for (int d = 0; d < s.fe.dofCount(); ++d) {
        const int slot = d % kDofsPerNode;
        if (slot == kU || slot == kV || slot == kThetaZ) {
          EXPECT_EQ(f(d), 0.0) << "load " << i;
        }
      }
      continue;
    }
    // Free DOFs: K u = F.
    double free_residual = 0.0;
    for (int d : s.part.interior) free_residual = std::max(free_residual, std::abs(ku(d, i) - f(d)));
    EXPECT_LT(free_residual, kRoundOffTol * scale) << "load " << i;
    // Reactions balance the load: R_t^T K u = 0 and R_r^T K u = 0 (K has the rigid null space),
    // i.e. sum of applied + reaction forces and moments vanish.
    const Vec3 force = rt.transpose() * ku.col(i);
    const Vec3 moment = rr.transpose() * ku.col(i);
    const double applied_force = (rt.transpose() * f).norm();
    EXPECT_LT(force.norm(), kRoundOffTol * std::max(applied_force, scale)) << "load " << i;
    EXPECT_LT(moment.norm(), kRoundOffTol * std::max(applied_force, scale) * 0.1) << "load " << i;
  }
  // Applied resultants against the rigid-body formula for three fields.
  const Vec3 f_ax = rt.transpose() * sol.loads.col(kLoadAccelX);
  EXPECT_LT((f_ax - Vec3(-mass, 0, 0)).norm(), kRoundOffTol * mass);
  const Vec3 f_wxx = rt.transpose() * sol.loads.col(kLoadSpinXX);  // -(e_x (e_x.c0) - c0)
  EXPECT_LT((f_wxx - Vec3(0.0, c0.y(), c0.z())).norm(), kRoundOffTol * c0.norm());
  const Vec3 f_az = rt.transpose() * sol.loads.col(kLoadAlphaZ);  // -(e_z x c0)
  EXPECT_LT((f_az + Vec3::UnitZ().cross(c0)).norm(), kRoundOffTol * c0.norm());
  EXPECT_GT(c0.y(), 0.0);  // the wing is outboard of P2: the check is not trivial
}

TEST(StructureGeometricStiffness, ProjectionEqualsTheAssembledMatrixAndIsSymmetric) {
  const MiniWingFe s = miniWingSetup();
  ModalWingOptions o;
  o.selection.max_modes = 8;
  const ModalWing w = buildModalWing(s.wing.vehicle, s.wing.mesh, o);
  const UnitInertialLoadSolution sol =
      solveUnitInertialLoads(s.fe, s.part, s.wing.mesh.nodes_W_m, s.p2);
  const ElementStresses st = recoverElementStresses(s.wing.vehicle, s.wing.mesh, sol.displacements);
  ASSERT_FALSE(w.geometric_stiffness.empty());
  double largest = 0.0;
  for (const Eigen::MatrixXd& k : w.geometric_stiffness.per_load)
    largest = std::max(largest, k.cwiseAbs().maxCoeff());
  for (int i = 0; i < kInertialLoadCount; ++i) {
    const SparseMatrix kg = assembleGeometricStiffness(s.wing.vehicle, s.wing.mesh, st, i);
    const SparseMatrix kgt = kg.transpose();
    EXPECT_LT((kg - kgt).norm(), kRoundOffTol * std::max(kg.norm(), 1e-300)) << "load " << i;
    const Eigen::MatrixXd assembled = w.mode_shapes.transpose() * (kg * w.mode_shapes);
    const Eigen::MatrixXd& projected = w.geometric_stiffness.per_load[static_cast<std::size_t>(i)];
    EXPECT_LT((projected - assembled).cwiseAbs().maxCoeff(), kRoundOffTol * largest)
        << "load " << i;
    EXPECT_LT((projected - projected.transpose()).cwiseAbs().maxCoeff(), kRoundOffTol * largest);
  }
}

TEST(StructureGeometricStiffness, OnlyInPlaneLoadsStressTheFlatWing) {
  // docs/theory.md 4.6: out-of-plane loads ((a - g)_z, alpha_x, alpha_y, w_x w_z, w_y w_z) bend the
  // flat wing without membrane stress, so their K^_G vanishes; the in-plane ones do not.
  const MiniWingFe s = miniWingSetup();
  ModalWingOptions o;
  o.selection.max_modes = 8;
  const ModalWing w = buildModalWing(s.wing.vehicle, s.wing.mesh, o);
  const ModalGeometricStiffness& kg = w.geometric_stiffness;
  double largest = 0.0;
  for (const Eigen::MatrixXd& k : kg.per_load) largest = std::max(largest, k.cwiseAbs().maxCoeff());
  for (InertialLoad i : {kLoadAccelZ, kLoadAlphaX, kLoadAlphaY, kLoadSpinXZ, kLoadSpinYZ})
    EXPECT_LT(kg[i].cwiseAbs().maxCoeff(), kRoundOffTol * largest) << "load " << i;
  for (InertialLoad i : {kLoadAccelX, kLoadAccelY, kLoadAlphaZ, kLoadSpinXX, kLoadSpinYY,
                         kLoadSpinZZ, kLoadSpinXY})
    EXPECT_GT(kg[i].cwiseAbs().maxCoeff(), 1e-6 * largest) << "load " << i;
  // Spin about the hinge axis stretches the span: it stiffens the first (bending) mode.
  EXPECT_GT(kg[kLoadSpinXX](0, 0), 0.0);
}

}  // namespace
}  // namespace orni::structure
