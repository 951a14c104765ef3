// ModalWing: the product of the structure module (docs/theory.md 3.2, 3.4-3.6).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/model/invalid_model_error.hpp"
#include "core/structure/dof_partition.hpp"
#include "core/structure/fe_assembly.hpp"
#include "core/structure/modal_solver.hpp"
#include "core/structure/modal_wing.hpp"
#include "tests/unit/structure/fe_test_meshes.hpp"

namespace orni::structure {
namespace {

// Spectra (tol 1e-10 on the Ritz values) and the dense shift-invert solver: measured 2e-12 on
// the eigenvalues; 1e-9 leaves room for other BLAS/compilers.
constexpr double kSolverAgreementTol = 1e-9;
// M-orthonormality of Spectra's vectors (docs/theory.md 3.3 measured 4e-15).
constexpr double kOrthonormalTol = 1e-10;

fe_test::MiniWing wing() { return fe_test::miniWing(6, 12, 0.04, 0.09); }

TEST(StructureFeModalWing, DefaultBuildIsMassNormalisedAndHeldAtTheJoints) {
  const fe_test::MiniWing mw = wing();
  ModalWingOptions o;
  o.selection.max_modes = 10;
  const ModalWing w = buildModalWing(mw.vehicle, mw.mesh, o);
  ASSERT_EQ(w.modeCount(), 10);
  for (int k = 0; k < 10; ++k) {
    EXPECT_GT(w.frequencies_hz(k), 0.0);
    if (k > 0) {
      EXPECT_GE(w.frequencies_hz(k), w.frequencies_hz(k - 1));
    }
    EXPECT_DOUBLE_EQ(w.damping_ratios(k), 0.015);
  }
  const Eigen::VectorXd omega = 2 * fe_test::kTestPi * w.frequencies_hz;
  EXPECT_LT((w.stiffnessDiagonal() - omega.cwiseAbs2()).norm(), 1e-9 * omega.squaredNorm());
  EXPECT_LT((w.dampingDiagonal() - 0.03 * omega).norm(), 1e-12 * omega.norm());

  const WingFeModel fe = assembleWingFe(mw.vehicle, mw.mesh);
  const Eigen::MatrixXd gm = w.mode_shapes.transpose() * (fe.mass * w.mode_shapes);
  EXPECT_LT((gm - Eigen::MatrixXd::Identity(10, 10)).cwiseAbs().maxCoeff(), kOrthonormalTol);
  for (int d : wingBoundaryDofs(mw.mesh)) EXPECT_EQ(w.mode_shapes.row(d).norm(), 0.0) << d;
  for (int d = 0; d < fe.dofCount(); ++d)
    if (!fe.active[static_cast<std::size_t>(d)]) {
      EXPECT_EQ(w.mode_shapes.row(d).norm(), 0.0) << d;
    }
  for (int p = 0; p < w.mesh.nodeCount(); ++p) {
    EXPECT_EQ(w.phi_W[static_cast<std::size_t>(p)], w.mode_shapes.middleRows<3>(6 * p));
    EXPECT_EQ(w.psi_W[static_cast<std::size_t>(p)], w.mode_shapes.middleRows<3>(6 * p + 3));
  }
  EXPECT_NEAR(w.nodal_mass_kg.sum() / w.wing_mass_kg, 1.0, 1e-12);
  EXPECT_NEAR((w.member_mass_kg + w.skin_mass_kg) / w.wing_mass_kg, 1.0, 1e-15);
  // Effective mass: fractions in [0, 1], cumulative non-decreasing.
  for (int k = 0; k < 10; ++k) {
    EXPECT_GE(w.effective_mass.flap_fraction(k), 0.0);
    EXPECT_LE(w.effective_mass.flap_cumulative(k), 1.0 + 1e-12);
    EXPECT_LE(w.effective_mass.heave_cumulative(k), 1.0 + 1e-12);
  }
  EXPECT_GT(w.effective_mass.flap_cumulative(9), 0.5);

  o.damping_schedule = ModalDampingSchedule::kAdamsDefault;
  const ModalWing adams = buildModalWing(mw.vehicle, mw.mesh, o);
  for (int k = 0; k < 10; ++k) {
    const double f = adams.frequencies_hz(k);
    EXPECT_DOUBLE_EQ(adams.damping_ratios(k), f < 100 ? 0.01 : f < 1000 ? 0.1 : 1.0) << f;
  }
}

TEST(StructureFeModalWing, SelectionByCutoffAndEffectiveMass) {
  const fe_test::MiniWing mw = wing();
  ModalWingOptions o;
  o.selection.max_modes = 12;
  const ModalWing all = buildModalWing(mw.vehicle, mw.mesh, o);
  ASSERT_EQ(all.modeCount(), 12);
  o.selection.cutoff_hz = 0.5 * (all.frequencies_hz(3) + all.frequencies_hz(4));
  const ModalWing cut = buildModalWing(mw.vehicle, mw.mesh, o);
  EXPECT_EQ(cut.modeCount(), 4);
  EXPECT_TRUE(cut.selection.cutoff_reached);
  EXPECT_LT((cut.frequencies_hz - all.frequencies_hz.head(4)).norm(),
            kSolverAgreementTol * all.frequencies_hz(3));

  // Effective-mass requirement: the smallest count reaching it for flap and heave.
  const double need = 0.5 * (all.effective_mass.flap_cumulative(5) +
                             all.effective_mass.flap_cumulative(6));
  o.selection.cutoff_hz = all.frequencies_hz(0) * 0.5;  // would keep none
  o.selection.min_effective_mass_fraction = need;
  const ModalWing em = buildModalWing(mw.vehicle, mw.mesh, o);
  int expected = 1;
  while (expected < 12 && (all.effective_mass.flap_cumulative(expected - 1) < need ||
                           all.effective_mass.heave_cumulative(expected - 1) < need))
    ++expected;
  EXPECT_GE(expected, 7);
  EXPECT_EQ(em.modeCount(), expected);
  EXPECT_EQ(em.selection.effective_mass_met,
            all.effective_mass.heave_cumulative(expected - 1) >= need &&
                all.effective_mass.flap_cumulative(expected - 1) >= need);
  EXPECT_FALSE(em.selection.BriefReport().empty());

  // A cut-off below the first mode with no effective-mass requirement keeps no mode: bad input,
  // reported as such (and never a wing with empty mode shapes).
  o.selection.min_effective_mass_fraction = 0.0;
  try {
    (void)buildModalWing(mw.vehicle, mw.mesh, o);
    ADD_FAILURE() << "a wing without a mode was built";
  } catch (const InvalidModelError& e) {
    EXPECT_NE(std::string(e.what()).find("wing.fe.cutoff_hz"), std::string::npos) << e.what();
  }
}

TEST(StructureFeModalWing, CraigBamptonWithFreeP3RotationBoundsTheDirectSolution) {
  const fe_test::MiniWing mw = wing();
  const int theta_z_p3 = globalDof(mw.mesh.p3_node, kThetaZ);
  ModalWingOptions o;
  o.selection.max_modes = 8;
  const ModalWing clamped = buildModalWing(mw.vehicle, mw.mesh, o);
  o.free_boundary_dofs = {theta_z_p3};
  const ModalWing cb = buildModalWing(mw.vehicle, mw.mesh, o);
  ASSERT_EQ(cb.modeCount(), 8);

  // Direct solution with theta_z at P3 left out of the constraints.
  const WingFeModel fe = assembleWingFe(mw.vehicle, mw.mesh);
  std::vector<int> bc = wingBoundaryDofs(mw.mesh);
  bc.erase(std::remove(bc.begin(), bc.end(), theta_z_p3), bc.end());
  const DofPartition part = makeDofPartition(fe.active, bc);
  const EigenSolution direct =
      lowestEigenpairs(extractBlock(fe.stiffness, part.interior, part.interior),
                       extractBlock(fe.mass, part.interior, part.interior), 8);
  ASSERT_TRUE(direct.success);
  for (int k = 0; k < 8; ++k) {
    const double f_direct = std::sqrt(direct.eigenvalues(k)) / (2 * fe_test::kTestPi);
    // CB (1 constraint mode + 8 interior modes) is a Ritz upper bound of the direct problem,
    EXPECT_GE(cb.frequencies_hz(k), f_direct * (1 - 1e-10)) << k;
    EXPECT_LT(cb.frequencies_hz(k), f_direct * 1.02) << k;
    // and releasing a constraint lowers every eigenvalue (interlacing).
    EXPECT_LE(f_direct, clamped.frequencies_hz(k) * (1 + 1e-10)) << k;
  }
  const Eigen::MatrixXd gm = cb.mode_shapes.transpose() * (fe.mass * cb.mode_shapes);
  EXPECT_LT((gm - Eigen::MatrixXd::Identity(8, 8)).cwiseAbs().maxCoeff(), kOrthonormalTol);
}

TEST(StructureFeModalWing, EigenSolverPathsAgree) {
  const fe_test::MiniWing mw = fe_test::miniWing(8, 14, 0.05, 0.1);
  const WingFeModel fe = assembleWingFe(mw.vehicle, mw.mesh);
  const DofPartition part = makeDofPartition(fe.active, wingBoundaryDofs(mw.mesh));
  const SparseMatrix k = extractBlock(fe.stiffness, part.interior, part.interior);
  const SparseMatrix m = extractBlock(fe.mass, part.interior, part.interior);
  EigenSolveOptions ldlt, lu, dense;
  ldlt.method = lu.method = EigenMethod::kSparseShiftInvert;
  lu.factorization = ShiftInvertFactorization::kSparseLu;
  dense.method = EigenMethod::kDense;
  const EigenSolution a = lowestEigenpairs(k, m, 12, ldlt);
  const EigenSolution b = lowestEigenpairs(k, m, 12, lu);
  const EigenSolution c = lowestEigenpairs(k, m, 12, dense);
  ASSERT_TRUE(a.success && b.success && c.success);
  EXPECT_LT(((a.eigenvalues - c.eigenvalues).array() / c.eigenvalues.array()).abs().maxCoeff(),
            kSolverAgreementTol);
  EXPECT_LT(((b.eigenvalues - c.eigenvalues).array() / c.eigenvalues.array()).abs().maxCoeff(),
            kSolverAgreementTol);
  const Eigen::MatrixXd gm = a.vectors.transpose() * (m * a.vectors);
  EXPECT_LT((gm - Eigen::MatrixXd::Identity(12, 12)).cwiseAbs().maxCoeff(), kOrthonormalTol);
}

TEST(StructureFeModalWing, InvalidInputThrows) {
  const fe_test::MiniWing mw = wing();
  ModalWingOptions o;
  o.damping_ratio = -0.1;
  EXPECT_THROW(buildModalWing(mw.vehicle, mw.mesh, o), std::invalid_argument);
  o = ModalWingOptions{};
  o.selection.max_modes = 0;
  EXPECT_THROW(buildModalWing(mw.vehicle, mw.mesh, o), std::invalid_argument);
  WingMesh no_p2 = mw.mesh;
  no_p2.p2_node = -1;
  EXPECT_THROW(buildModalWing(mw.vehicle, no_p2, ModalWingOptions{}), std::invalid_argument);
}

}  // namespace
}  // namespace orni::structure
