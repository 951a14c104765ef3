// Inertia invariants (docs/theory.md 3.6): operator form vs nodal sums, and the identities between
// the primitives.
#include <gtest/gtest.h>

#include <cmath>

#include "core/structure/fe_assembly.hpp"
#include "core/structure/inertia_invariants.hpp"
#include "core/structure/modal_wing.hpp"
#include "tests/unit/structure/fe_test_meshes.hpp"

namespace orni::structure {
namespace {

// Two summation orders of the same products: round-off.
constexpr double kRoundOffTol = 1e-12;

struct Fixture {
  fe_test::MiniWing wing;
  ModalWing modal;
};

Fixture lumpedWing() {
  Fixture f;
  f.wing = fe_test::miniWing(6, 10, 0.04, 0.08);
  ModalWingOptions o;
  o.mass = MassLumping::kLumped;
  o.selection.max_modes = 8;
  f.modal = buildModalWing(f.wing.vehicle, f.wing.mesh, o);
  return f;
}

double relDiff(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
  const double scale = std::max(a.cwiseAbs().maxCoeff(), b.cwiseAbs().maxCoeff());
  return scale > 0.0 ? (a - b).cwiseAbs().maxCoeff() / scale : 0.0;
}

TEST(StructureFeInvariants, OperatorFormWithLumpedMassEqualsNodalSums) {
  const Fixture f = lumpedWing();
  const ModalWing& w = f.modal;
  const Vec3 p2 = w.mesh.nodes_W_m[static_cast<std::size_t>(w.mesh.p2_node)];
  const InertiaInvariants sums = invariantsNodalSums(w.nodal_mass_kg, w.nodal_rotary_W_kgm2,
                                                     w.mode_shapes, w.mesh.nodes_W_m, p2);
  const InertiaInvariants& op = w.invariants;
  EXPECT_NEAR(op.mass_kg / sums.mass_kg, 1.0, kRoundOffTol);
  EXPECT_LT(relDiff(op.first_moment_W_kgm, sums.first_moment_W_kgm), kRoundOffTol);
  EXPECT_LT(relDiff(op.inertia_P2_W_kgm2, sums.inertia_P2_W_kgm2), kRoundOffTol);
  EXPECT_LT(relDiff(op.translational_participation, sums.translational_participation),
            kRoundOffTol);
  EXPECT_LT(relDiff(op.rotational_participation, sums.rotational_participation), kRoundOffTol);
  EXPECT_LT(relDiff(op.generalized_mass, sums.generalized_mass), kRoundOffTol);
  for (int k = 0; k < 3; ++k)
    for (int l = 0; l < 3; ++l) {
      EXPECT_LT(relDiff(op.P(k, l), sums.P(k, l)), kRoundOffTol) << k << l;
      EXPECT_LT(relDiff(op.S(k, l), sums.S(k, l)), kRoundOffTol) << k << l;
    }
}

TEST(StructureFeInvariants, ConsistentOperatorFormMatchesNodalSumsOnMassAndFirstMoment) {
  const fe_test::MiniWing wing = fe_test::miniWing(6, 10, 0.04, 0.08);
  ModalWingOptions o;
  o.selection.max_modes = 8;
  const ModalWing w = buildModalWing(wing.vehicle, wing.mesh, o);  // consistent
  const Vec3 p2 = w.mesh.nodes_W_m[static_cast<std::size_t>(w.mesh.p2_node)];
  const InertiaInvariants sums =
      invariantsNodalSums(w.nodal_mass_kg, {}, w.mode_shapes, w.mesh.nodes_W_m, p2);
  EXPECT_NEAR(w.invariants.mass_kg / sums.mass_kg, 1.0, kRoundOffTol);
  EXPECT_NEAR(w.invariants.mass_kg / w.wing_mass_kg, 1.0, kRoundOffTol);
  EXPECT_LT(relDiff(w.invariants.first_moment_W_kgm, sums.first_moment_W_kgm), kRoundOffTol);
}

TEST(StructureFeInvariants, PrimitiveIdentities) {
  for (MassLumping lumping : {MassLumping::kConsistent, MassLumping::kLumped}) {
    const fe_test::MiniWing wing = fe_test::miniWing(6, 10, 0.04, 0.08);
    ModalWingOptions o;
    o.mass = lumping;
    o.selection.max_modes = 8;
    const ModalWing w = buildModalWing(wing.vehicle, wing.mesh, o);
    const InertiaInvariants& inv = w.invariants;
    const int m = inv.modeCount();
    const Eigen::MatrixXd eye = Eigen::MatrixXd::Identity(m, m);
    EXPECT_LT((inv.generalized_mass - eye).cwiseAbs().maxCoeff(), kRoundOffTol);
    for (int k = 0; k < 3; ++k)
      for (int l = 0; l < 3; ++l)
        EXPECT_LT((inv.P(l, k) - inv.P(k, l).transpose()).cwiseAbs().maxCoeff(), kRoundOffTol);
    // Sum_k P_kk is the translational part of Phi^T M Phi; the rest is the rotational (beam
    // rotary / Hermite coupling and shell rotary) part: together exactly M_qq = I.
    Eigen::MatrixXd rot = Eigen::MatrixXd::Zero(m, m);
    {
      const fe_test::MiniWing& mw = wing;
      FeAssemblyOptions fo;
      fo.mass = lumping;
      const WingFeModel fe = assembleWingFe(mw.vehicle, mw.mesh, fo);
      Eigen::MatrixXd rot_rows = w.mode_shapes;
      for (int d = 0; d < fe.dofCount(); ++d)
        if (d % kDofsPerNode < 3) rot_rows.row(d).setZero();
      const Eigen::MatrixXd a = w.mode_shapes.transpose() * (fe.mass * rot_rows);
      rot = 0.5 * (a + a.transpose());
    }
    const Eigen::MatrixXd sum_pkk = inv.P(0, 0) + inv.P(1, 1) + inv.P(2, 2);
    EXPECT_LT((sum_pkk + rot - eye).cwiseAbs().maxCoeff(), kRoundOffTol);
    fe_test::recordError(lumping == MassLumping::kLumped ? "sum_pkk_minus_I_lumped"
                                                         : "sum_pkk_minus_I_consistent",
                         (sum_pkk - eye).cwiseAbs().maxCoeff());
    // C_k = P_32 - P_23 (cyclic) is skew-symmetric (docs/theory.md 3.6).
    for (int k = 0; k < 3; ++k) {
      const int a = (k + 1) % 3, b = (k + 2) % 3;
      const Eigen::MatrixXd c = inv.P(b, a) - inv.P(a, b);
      EXPECT_LT((c + c.transpose()).cwiseAbs().maxCoeff(), kRoundOffTol);
    }
  }
}

TEST(StructureFeInvariants, HFromSWithoutRotaryInertiaAndExactPlateInertia) {
  // Nodal sums without rotary inertia: row k of H = sum_ab eps_kab S_ba^T.
  const Fixture f = lumpedWing();
  const ModalWing& w = f.modal;
  const Vec3 p2 = w.mesh.nodes_W_m[static_cast<std::size_t>(w.mesh.p2_node)];
  const InertiaInvariants sums =
      invariantsNodalSums(w.nodal_mass_kg, {}, w.mode_shapes, w.mesh.nodes_W_m, p2);
  for (int k = 0; k < 3; ++k) {
    const int a = (k + 1) % 3, b = (k + 2) % 3;
    const Eigen::VectorXd h = sums.S(b, a) - sums.S(a, b);
    EXPECT_LT(relDiff(sums.rotational_participation.row(k).transpose(), h), kRoundOffTol);
  }

  // Consistent J0 of a bare a x b plate about a corner is exact (linear triangles represent a
  // rigid rotation exactly), plus the rotary inertia rho t^3/12 A on every rotation axis.
  const double a = 0.05, b = 0.08, t = 1e-3, rho = 500.0;
  WingMesh plate = fe_test::plateGridMesh(a, b, 5, 7);
  plate.p2_node = 0;
  const VehicleModel v = fe_test::skinVehicle(t, 1e9, 0.3, rho);
  const WingFeModel fe = assembleWingFe(v, plate);
  const InertiaInvariants inv = invariantsOperatorForm(
      fe.mass, Eigen::MatrixXd::Zero(fe.dofCount(), 0), plate.nodes_W_m, Vec3::Zero());
  const double m = rho * t * a * b, rotary = rho * t * t * t / 12 * a * b;
  Mat3 j;
  j << m * b * b / 3, -m * a * b / 4, 0, -m * a * b / 4, m * a * a / 3, 0, 0, 0,
      m * (a * a + b * b) / 3;
  j += rotary * Mat3::Identity();
  EXPECT_LT(relDiff(inv.inertia_P2_W_kgm2, j), kRoundOffTol);
  EXPECT_LT(relDiff(inv.first_moment_W_kgm, Vec3(m * a / 2, m * b / 2, 0)), kRoundOffTol);
}

}  // namespace
}  // namespace orni::structure
