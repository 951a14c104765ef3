// Assembly: total mass, consistent vs lumped first moment, DOF activity mask, boundary sets.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "core/structure/beam_element.hpp"
#include "core/structure/dof_partition.hpp"
#include "core/structure/fe_assembly.hpp"
#include "core/structure/inertia_invariants.hpp"
#include "core/structure/rigid_body_vectors.hpp"
#include "tests/unit/structure/fe_test_meshes.hpp"

namespace orni::structure {
namespace {

// Sums of a few thousand positive terms: round-off only (task requirement 1e-12).
constexpr double kMassTol = 1e-12;

double analyticMass(const fe_test::MiniWing& w) {
  double m = 0.0;
  for (const BeamElement& b : w.mesh.beams) {
    const WingMember& member = w.vehicle.wing.members[static_cast<std::size_t>(b.member)];
    const Material* mat = w.vehicle.findMaterial(member.material);
    const double len = (w.mesh.nodes_W_m[static_cast<std::size_t>(b.nodes[1])] -
                        w.mesh.nodes_W_m[static_cast<std::size_t>(b.nodes[0])])
                           .norm();
    m += mat->density_kgpm3 * solidRodSection(member.diameter_m).area_m2 * len;
  }
  // The mini-wing skin is a c x s rectangle.
  const double c = 0.04, s = 0.08;
  m += 500.0 * 4e-5 * c * s;
  return m;
}

TEST(StructureFeMass, TotalMassIsMembersPlusSkin) {
  const fe_test::MiniWing w = fe_test::miniWing(6, 10, 0.04, 0.08);
  const double expected = analyticMass(w);
  for (MassLumping lumping : {MassLumping::kConsistent, MassLumping::kLumped}) {
    FeAssemblyOptions o;
    o.mass = lumping;
    const WingFeModel fe = assembleWingFe(w.vehicle, w.mesh, o);
    const Eigen::MatrixXd rt = rigidTranslationVectors(w.mesh.nodes_W_m);
    const Mat3 g = rt.transpose() * (fe.mass * rt);
    EXPECT_LT((g - expected * Mat3::Identity()).norm(), kMassTol * expected);
    fe_test::recordError(lumping == MassLumping::kLumped ? "total_mass_rel_error_lumped"
                                                         : "total_mass_rel_error_consistent",
                         (g - expected * Mat3::Identity()).norm() / expected);
    EXPECT_NEAR(fe.totalMass_kg() / expected, 1.0, kMassTol);
    // Both triangles are stored and equal.
    EXPECT_LT((fe.stiffness - SparseMatrix(fe.stiffness.transpose())).norm(),
              1e-14 * fe.stiffness.norm());
    EXPECT_LT((fe.mass - SparseMatrix(fe.mass.transpose())).norm(), 1e-14 * fe.mass.norm());
  }
  const LumpedNodalMass lumped = lumpedNodalMass(w.vehicle, w.mesh);
  EXPECT_NEAR(lumped.mass_kg.sum() / expected, 1.0, kMassTol);
}

TEST(StructureFeMass, ConsistentAndLumpedAgreeOnMassAndFirstMoment) {
  const fe_test::MiniWing w = fe_test::miniWing(6, 10, 0.04, 0.08);
  const WingFeModel fe = assembleWingFe(w.vehicle, w.mesh);  // consistent
  const Eigen::MatrixXd no_modes = Eigen::MatrixXd::Zero(fe.dofCount(), 0);
  const Vec3 p2 = w.mesh.nodes_W_m[static_cast<std::size_t>(w.mesh.p2_node)];
  const InertiaInvariants op = invariantsOperatorForm(fe.mass, no_modes, w.mesh.nodes_W_m, p2);
  const LumpedNodalMass lumped = lumpedNodalMass(w.vehicle, w.mesh);
  const InertiaInvariants sums =
      invariantsNodalSums(lumped.mass_kg, {}, no_modes, w.mesh.nodes_W_m, p2);
  EXPECT_NEAR(op.mass_kg / sums.mass_kg, 1.0, kMassTol);
  EXPECT_LT((op.first_moment_W_kgm - sums.first_moment_W_kgm).norm(),
            kMassTol * sums.first_moment_W_kgm.norm());
  fe_test::recordError("first_moment_rel_diff",
                       (op.first_moment_W_kgm - sums.first_moment_W_kgm).norm() /
                           sums.first_moment_W_kgm.norm());
}

TEST(StructureFeAssembly, DrillingDofInactiveOnlyAtSkinOnlyNodes) {
  const fe_test::MiniWing w = fe_test::miniWing(4, 8);
  const std::vector<bool> active = dofActivityMask(w.mesh);
  std::vector<bool> on_beam(static_cast<std::size_t>(w.mesh.nodeCount()), false);
  for (const BeamElement& b : w.mesh.beams)
    for (int n : b.nodes) on_beam[static_cast<std::size_t>(n)] = true;
  for (int p = 0; p < w.mesh.nodeCount(); ++p)
    for (int d = 0; d < kDofsPerNode; ++d)
      EXPECT_EQ(active[static_cast<std::size_t>(globalDof(p, d))],
                d != kThetaZ || on_beam[static_cast<std::size_t>(p)])
          << "node " << p << " dof " << d;
  // The drilling DOF of a skin-only node has neither stiffness nor coupling.
  const WingFeModel fe = assembleWingFe(w.vehicle, w.mesh);
  const int skin_only = fe_test::gridNode(1, 3, 4);
  ASSERT_FALSE(on_beam[static_cast<std::size_t>(skin_only)]);
  EXPECT_EQ(fe.stiffness.col(globalDof(skin_only, kThetaZ)).norm(), 0.0);
}

TEST(StructureFeAssembly, BoundaryDofsOfP2AndP3) {
  const fe_test::MiniWing w = fe_test::miniWing(4, 8);
  const int p2 = w.mesh.p2_node, p3 = w.mesh.p3_node;
  std::vector<int> expected;
  for (int d = 0; d < kDofsPerNode; ++d) expected.push_back(globalDof(p2, d));
  for (int d : {kU, kV, kW, kThetaZ}) expected.push_back(globalDof(p3, d));
  std::sort(expected.begin(), expected.end());
  EXPECT_EQ(wingBoundaryDofs(w.mesh), expected);
  const std::vector<int> alt = wingBoundaryDofs(w.mesh, WingSupport{P3Joint::kUniversal, UniversalJointCrossAxis::kYW, false});
  EXPECT_NE(std::find(alt.begin(), alt.end(), globalDof(p3, kThetaY)), alt.end());
  EXPECT_EQ(std::find(alt.begin(), alt.end(), globalDof(p3, kThetaZ)), alt.end());

  const WingFeModel fe = assembleWingFe(w.vehicle, w.mesh);
  const DofPartition part = makeDofPartition(fe.active, wingBoundaryDofs(w.mesh));
  EXPECT_EQ(part.clamped, expected);
  EXPECT_TRUE(part.boundary_free.empty());
  const int active_count =
      static_cast<int>(std::count(fe.active.begin(), fe.active.end(), true));
  EXPECT_EQ(static_cast<int>(part.interior.size()), active_count - 10);
}

TEST(StructureFeAssembly, MissingMaterialThrows) {
  fe_test::MiniWing w = fe_test::miniWing(4, 8);
  w.vehicle.wing.members[1].material = "NOPE";
  EXPECT_THROW(assembleWingFe(w.vehicle, w.mesh), std::invalid_argument);
  w = fe_test::miniWing(4, 8);
  w.mesh.beams.push_back({{0, 1}, 7});
  EXPECT_THROW(assembleWingFe(w.vehicle, w.mesh), std::invalid_argument);
}

}  // namespace
}  // namespace orni::structure
