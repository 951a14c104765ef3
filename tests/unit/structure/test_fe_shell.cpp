// CST + DKT facet: patch tests on a distorted patch, rigid-body modes, and square-plate
// frequencies against Leissa (cantilever) and the exact simply supported values (docs/theory.md 2.8).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <Eigen/Geometry>
#include <Eigen/SparseCholesky>

#include "core/structure/dof_partition.hpp"
#include "core/structure/fe_assembly.hpp"
#include "core/structure/modal_solver.hpp"
#include "core/structure/shell_element.hpp"
#include "tests/unit/structure/fe_test_meshes.hpp"

namespace orni::structure {
namespace {

using fe_test::kTestPi;

// Patch tests: the exact field lies in the element space, so only round-off remains.
constexpr double kPatchTol = 1e-10;
// Element rigid-body check, relative to ||K|| ||r|| (task requirement).
constexpr double kRigidBodyTol = 1e-10;
// Cantilever plate vs Leissa: task requirement 2 %. Leissa's Ritz values are upper bounds about
// 0.2-0.7 % above the converged plate (h^2 extrapolation of this element: 3.471, 8.506, 21.28,
// 27.19, 30.95); 24 x 24 x 2 measures <= 0.6 % (consistent), <= 1.0 % (lumped).
constexpr double kCantileverPlateTol = 0.02;
// Simply supported plate vs exact: DKT converges as h^2, consistent translational mass from
// above (24 x 24 x 2: +0.78 % on mode 4), lumped from below (-0.36 %); 1 % bounds both.
constexpr double kSimplySupportedTol = 0.01;

// MacNeal-Harder distorted patch: 4 corners (0-3), 4 interior nodes (4-7), 10 triangles.
WingMesh distortedPatch(const Mat3& rotation) {
  WingMesh mesh;
  const double xy[8][2] = {{0, 0},       {0.24, 0},    {0.24, 0.12}, {0, 0.12},
                           {0.04, 0.02}, {0.18, 0.03}, {0.16, 0.08}, {0.08, 0.08}};
  for (const auto& p : xy) mesh.nodes_W_m.push_back(rotation * Vec3(p[0], p[1], 0.0));
  const int quads[5][4] = {{0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}, {4, 5, 6, 7}};
  for (const auto& q : quads) {
    mesh.triangles.push_back({q[0], q[1], q[2]});
    mesh.triangles.push_back({q[0], q[2], q[3]});
  }
  return mesh;
}

// Exact linear membrane field and quadratic (constant-curvature) plate field in the patch plane,
// as 6-DOF nodal values in W for the rotation Q of the patch.
struct PatchField {
  bool membrane = true;
  bool bending = true;
  Eigen::Matrix<double, 6, 1> at(const Vec3& x_local, const Mat3& q) const {
    const double x = x_local.x(), y = x_local.y();
    Vec3 u = Vec3::Zero(), th = Vec3::Zero();
    if (membrane) u += 1e-3 * Vec3(x + y / 2, y + x / 2, 0.0);
    if (bending) {
      u.z() += 1e-3 * (1 + x + y + x * x / 2 + x * y / 2 + y * y / 2) / 2;
      th.x() += 1e-3 * (1 + x / 2 + y) / 2;    // theta_x = dw/dy
      th.y() += -1e-3 * (1 + x + y / 2) / 2;   // theta_y = -dw/dx
    }
    Eigen::Matrix<double, 6, 1> out;
    out << q * u, q * th;
    return out;
  }
};

Eigen::VectorXd exactField(const WingMesh& mesh, const Mat3& q, const PatchField& f) {
  Eigen::VectorXd u(kDofsPerNode * mesh.nodeCount());
  for (int p = 0; p < mesh.nodeCount(); ++p) {
    Vec3 local;
    local.noalias() = q.transpose() * mesh.nodes_W_m[static_cast<std::size_t>(p)];
    u.segment<6>(kDofsPerNode * p) = f.at(local, q);
  }
  return u;
}

TEST(StructureFeShell, PatchTestFlatDistortedPatchSolvesExactly) {
  const WingMesh mesh = distortedPatch(Mat3::Identity());
  const VehicleModel v = fe_test::skinVehicle(0.01, 1e6, 0.25, 1.0);
  const WingFeModel fe = assembleWingFe(v, mesh);
  std::vector<int> corners;
  for (int p = 0; p < 4; ++p)
    for (int d = 0; d < kDofsPerNode; ++d) corners.push_back(globalDof(p, d));
  const DofPartition part = makeDofPartition(fe.active, {}, corners);
  const SparseMatrix k_ii = extractBlock(fe.stiffness, part.interior, part.interior);
  const SparseMatrix k_ib = extractBlock(fe.stiffness, part.interior, part.boundary_free);
  const Eigen::VectorXd exact = exactField(mesh, Mat3::Identity(), PatchField{});
  Eigen::VectorXd u_b(static_cast<Eigen::Index>(part.boundary_free.size()));
  for (std::size_t i = 0; i < part.boundary_free.size(); ++i)
    u_b(static_cast<Eigen::Index>(i)) = exact(part.boundary_free[i]);
  Eigen::SimplicialLDLT<SparseMatrix> ldlt(k_ii);
  ASSERT_EQ(ldlt.info(), Eigen::Success);
  const Eigen::VectorXd u_i = ldlt.solve(-(k_ib * u_b));
  double worst = 0.0;
  for (std::size_t i = 0; i < part.interior.size(); ++i) {
    const double err = std::abs(u_i(static_cast<Eigen::Index>(i)) - exact(part.interior[i]));
    worst = std::max(worst, err / exact.cwiseAbs().maxCoeff());
    EXPECT_LT(err, kPatchTol * exact.cwiseAbs().maxCoeff()) << "interior DOF " << part.interior[i];
  }
  fe_test::recordError("patch_interior_max_rel_error", worst);

  // Constant strain and curvature in every element (CST strain, DKT at 4 points).
  for (const auto& tri : mesh.triangles) {
    std::array<Eigen::Vector2d, 3> xy;
    Eigen::Matrix<double, 6, 1> um;
    Eigen::Matrix<double, 9, 1> ub;
    for (int a = 0; a < 3; ++a) {
      const int p = tri[static_cast<std::size_t>(a)];
      xy[static_cast<std::size_t>(a)] = mesh.nodes_W_m[static_cast<std::size_t>(p)].head<2>();
      um.segment<2>(2 * a) = exact.segment<2>(globalDof(p, kU));
      ub.segment<3>(3 * a) = exact.segment<3>(globalDof(p, kW));
    }
    const Vec3 strain = cstStrainMatrix(xy) * um;
    EXPECT_LT((strain - Vec3(1e-3, 1e-3, 1e-3)).norm(), kPatchTol * 1e-3);
    // kappa = (-w_xx, -w_yy, -2 w_xy) with beta_x = theta_y = -w_x, beta_y = -theta_x = -w_y.
    const Vec3 kappa_exact(-5e-4, -5e-4, -5e-4);
    for (const auto& pt : {std::array<double, 2>{0.5, 0.0}, std::array<double, 2>{0.5, 0.5},
                           std::array<double, 2>{0.0, 0.5}, std::array<double, 2>{1. / 3, 1. / 3}})
      EXPECT_LT((dktCurvatureMatrix(xy, pt[0], pt[1]) * ub - kappa_exact).norm(),
                kPatchTol * 5e-4);
  }
}

TEST(StructureFeShell, PatchTestRotatedPatchIsInEquilibrium) {
  // The same patch turned out of the wing plane: interior nodes carry no residual force for
  // the exact membrane and bending fields, separately.
  const Mat3 q = (Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized())).toRotationMatrix();
  const WingMesh mesh = distortedPatch(q);
  const VehicleModel v = fe_test::skinVehicle(0.05, 1e6, 0.25, 1.0);
  const WingFeModel fe = assembleWingFe(v, mesh);
  for (const PatchField f : {PatchField{true, false}, PatchField{false, true}}) {
    const Eigen::VectorXd u = exactField(mesh, q, f);
    const Eigen::VectorXd r = fe.stiffness * u;
    const double ratio =
        r.segment(4 * kDofsPerNode, 4 * kDofsPerNode).norm() / (fe.stiffness.norm() * u.norm());
    EXPECT_LT(ratio, 1e-12) << (f.membrane ? "membrane" : "bending");
    fe_test::recordError(f.membrane ? "rotated_patch_membrane_residual"
                                    : "rotated_patch_bending_residual",
                         ratio);
  }
}

TEST(StructureFeShell, RigidBodyMotionsGiveZeroForces) {
  const std::array<Vec3, 3> x = {Vec3(0.01, 0.02, -0.01), Vec3(0.05, 0.00, 0.02),
                                 Vec3(0.02, 0.06, 0.01)};
  ShellProperties p;
  p.thickness_m = 1e-3;
  p.youngs_modulus_pa = 100e9;
  p.poisson_ratio = 0.31;
  p.density_kgpm3 = 500.0;
  const Mat18 k = shellStiffness(x, p);
  EXPECT_LT((k - k.transpose()).norm(), 1e-14 * k.norm());
  double worst = 0.0;
  for (int axis = 0; axis < 3; ++axis) {
    Eigen::Matrix<double, 18, 1> t = Eigen::Matrix<double, 18, 1>::Zero(), r = t;
    const Vec3 e = Vec3::Unit(axis);
    for (int a = 0; a < 3; ++a) {
      t(6 * a + axis) = 1.0;
      r.segment<3>(6 * a) = e.cross(x[static_cast<std::size_t>(a)]);
      r.segment<3>(6 * a + 3) = e;
    }
    EXPECT_LT((k * t).norm(), kRigidBodyTol * k.norm() * t.norm()) << "translation " << axis;
    EXPECT_LT((k * r).norm(), kRigidBodyTol * k.norm() * r.norm()) << "rotation " << axis;
    worst = std::max({worst, (k * t).norm() / (k.norm() * t.norm()),
                      (k * r).norm() / (k.norm() * r.norm())});
  }
  fe_test::recordError("shell_rigid_body_max_residual", worst);
  // Consistent and lumped facet mass carry rho t A in each direction.
  const double mass = 500.0 * 1e-3 * triangleArea(x);
  for (const Mat18& m : {shellConsistentMass(x, p), shellLumpedMass(x, p)}) {
    Eigen::Matrix<double, 18, 3> rt = Eigen::Matrix<double, 18, 3>::Zero();
    for (int a = 0; a < 3; ++a)
      for (int k2 = 0; k2 < 3; ++k2) rt(6 * a + k2, k2) = 1.0;
    EXPECT_LT((rt.transpose() * m * rt - mass * Mat3::Identity()).norm(), 1e-14 * mass);
  }
}

// Frequency parameters lambda = omega a^2 sqrt(rho t / D) of a 1 m square steel plate.
std::vector<double> plateLambdas(int n, bool cantilever, MassLumping lumping, int count) {
  const double a = 1.0, t = 0.01, e = 200e9, nu = 0.3, rho = 7850.0;
  const WingMesh mesh = fe_test::plateGridMesh(a, a, n, n);
  const VehicleModel v = fe_test::skinVehicle(t, e, nu, rho);
  FeAssemblyOptions o;
  o.mass = lumping;
  const WingFeModel fe = assembleWingFe(v, mesh, o);
  std::vector<int> fixed;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const int p = fe_test::gridNode(i, j, n);
      if (cantilever) {
        if (i == 0)
          for (int d = 0; d < kDofsPerNode; ++d) fixed.push_back(globalDof(p, d));
      } else if (i == 0 || j == 0 || i == n || j == n) {
        for (int d : {kU, kV, kW}) fixed.push_back(globalDof(p, d));
      }
    }
  const DofPartition part = makeDofPartition(fe.active, fixed);
  EigenSolveOptions eo;
  eo.method = EigenMethod::kSparseShiftInvert;
  const EigenSolution sol =
      lowestEigenpairs(extractBlock(fe.stiffness, part.interior, part.interior),
                       extractBlock(fe.mass, part.interior, part.interior), count, eo);
  EXPECT_TRUE(sol.success) << sol.message;
  const double d = e * t * t * t / (12 * (1 - nu * nu));
  std::vector<double> out;
  for (int k = 0; k < count; ++k)
    out.push_back(std::sqrt(sol.eigenvalues(k)) * a * a * std::sqrt(rho * t / d));
  return out;
}

TEST(StructureFeShell, CantileverSquarePlateMatchesLeissa) {
  const double leissa[5] = {3.492, 8.525, 21.43, 27.33, 31.11};
  for (MassLumping lumping : {MassLumping::kConsistent, MassLumping::kLumped}) {
    const std::vector<double> lambda = plateLambdas(24, true, lumping, 5);
    double worst = 0.0;
    for (int k = 0; k < 5; ++k) {
      worst = std::max(worst, std::abs(lambda[static_cast<std::size_t>(k)] / leissa[k] - 1));
      EXPECT_NEAR(lambda[static_cast<std::size_t>(k)] / leissa[k], 1.0, kCantileverPlateTol)
          << "mode " << k + 1 << (lumping == MassLumping::kLumped ? " lumped" : " consistent");
    }
    fe_test::recordError(
        lumping == MassLumping::kLumped ? "cfff_lumped_max_err" : "cfff_consistent_max_err", worst);
  }
}

TEST(StructureFeShell, SimplySupportedSquarePlateMatchesExact) {
  const double exact[4] = {2 * kTestPi * kTestPi, 5 * kTestPi * kTestPi, 5 * kTestPi * kTestPi,
                           8 * kTestPi * kTestPi};
  for (MassLumping lumping : {MassLumping::kConsistent, MassLumping::kLumped}) {
    const std::vector<double> lambda = plateLambdas(24, false, lumping, 4);
    double worst = 0.0;
    for (int k = 0; k < 4; ++k) {
      worst = std::max(worst, std::abs(lambda[static_cast<std::size_t>(k)] / exact[k] - 1));
      EXPECT_NEAR(lambda[static_cast<std::size_t>(k)] / exact[k], 1.0, kSimplySupportedTol)
          << "mode " << k + 1 << (lumping == MassLumping::kLumped ? " lumped" : " consistent");
    }
    fe_test::recordError(
        lumping == MassLumping::kLumped ? "ssss_lumped_max_err" : "ssss_consistent_max_err", worst);
  }
}

}  // namespace
}  // namespace orni::structure
