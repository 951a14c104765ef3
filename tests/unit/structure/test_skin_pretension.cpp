// The skin pretension as the equilibrium of a film shrunk onto its frame
// (core/structure/skin_pretension.hpp, docs/theory.md 4.7): exact limits of the in-plane problem
// (a free film shrinks without stress; a rigid frame holds the nominal pretension) and the
// finding on the literal EFW (the frame holds little of it and buckles at about 41 N/m).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "core/model/invalid_model_error.hpp"
#include "core/structure/calculix_deck.hpp"
#include "core/structure/calculix_results.hpp"
#include "core/structure/fe_assembly.hpp"
#include "core/structure/modal_wing.hpp"
#include "core/structure/skin_pretension.hpp"
#include "core/structure/von_karman.hpp"
#include "core/structure/wing_mesh.hpp"
#include "ccx_runner.hpp"
#include "fe_test_meshes.hpp"
#include "tests/support/magpie_vehicle.hpp"

namespace orni::structure {
namespace {

constexpr double kPretension_Npm = 20.0;

// A 40 x 60 mm film of the EFW's skin (0.04 mm, 100 GPa, nu 0.31).
VehicleModel filmVehicle() { return fe_test::skinVehicle(4e-5, 100e9, 0.31, 500.0); }

// The shrunk film on the literal EFW against CalculiX (the deck of calculix_deck.hpp: S6 skin with
// a thermal expansion of 1 cooled by s, B32R rods without one, the vehicle's support; a linear
// static step): the in-plane displacement field over every mesh node. Measured (2026-12-06) at 30
// N/m: RMS difference 0.9 % of the RMS displacement, tip 1.803 / 1.833 um along -x_W. 3 %: CST
// facets against quadratic S6 on the same mesh (the EFW's linear static deflections differ by up
// to 2.5 %, test_fe_calculix_nonlinear.cpp). The prestress field is what enters the geometric
// stiffness, so this checks the pretension model independently. (The stability limit is not
// asserted against CalculiX: its linear buckling step takes no thermal load. Its first frequency
// after an NLGEOM shrink, 24.2 / 19.0 / 14.5 Hz at 0 / 30 / 40 N/m against our 23.9 / 17.7 / 7.8
// Hz on the 5 mm mesh, agrees at 30 N/m; at 40 N/m, near our limit of 41 N/m (a local buckle of the
// skin at the trailing edge), CalculiX converges towards ours as the mesh is refined: 14.5 / 12.0 /
// 10.8 Hz at h = 5 / 3.5 / 2.5 mm, ours 7.8 / 7.2 / 7.3 Hz (second frequency 26.3 / 23.4 / 22.3
// against 20.5 / 20.5 / 20.6 Hz): its 3D-expanded 0.04 mm shells are too stiff in bending on a
// coarse mesh, as in its static deflections (test_fe_calculix_nonlinear.cpp). Recorded here.)
TEST(SkinPretension, ShrunkFilmOnTheEfwMatchesCalculix) {
  if (!fe_test::ccxAvailable()) GTEST_SKIP() << fe_test::kNoCcxMessage;
  const VehicleModel v = testing::magpieVehicle();
  const WingMesh mesh = buildWingMesh(v, v.wing.fe.element_size_m);
  const WingSupport support = WingSupport::of(v.wing.fe);
  constexpr double kHeld_Npm = 30.0;
  const SkinPrestress p = shrunkSkinPrestress(v, mesh, support, kHeld_Npm);
  CalculixDeckOptions o = fe_test::staticDeckFor(support);
  o.static_steps.nlgeom = false;
  o.static_steps.load_factors = {1.0};
  o.static_steps.skin_shrink_strain = skinShrinkStrain(v, kHeld_Npm);
  const fe_test::CcxRun run = fe_test::runCcx(calculixDeck(v, mesh, o), "efw_shrink");
  const CalculixDisplacementTable* t = calculixTableAt(run.tables, 1.0);
  ASSERT_NE(t, nullptr) << run.message;
  const Eigen::Matrix3Xd u = meshDisplacements(*t, mesh.nodeCount());
  double diff_sq = 0.0, ccx_sq = 0.0;
  for (int n = 0; n < mesh.nodeCount(); ++n) {
    const Eigen::Vector2d ours = p.displacement.segment<2>(globalDof(n, kU));
    const Eigen::Vector2d theirs = u.col(n).head<2>();
    diff_sq += (ours - theirs).squaredNorm();
    ccx_sq += theirs.squaredNorm();
  }
  const double rms = std::sqrt(diff_sq / ccx_sq);
  std::printf("EFW film shrunk to %.0f N/m: in-plane displacement, RMS difference ours / ccx %.4f "
              "(ccx %.1f s)\n", kHeld_Npm, rms, run.seconds);
  fe_test::recordError("shrink_rms_ours_vs_ccx", rms);
  EXPECT_LT(rms, 0.03);
}

// A film held only at one corner (P2, all six DOFs) shrinks freely: no stress anywhere, and the
// displacement is the uniform contraction u = -s (x - x_P2) (constant strain, which the CST
// facets represent exactly). s = N0 (1 - nu) / (E t).
TEST(SkinPretension, FreeFilmShrinksWithoutStress) {
  VehicleModel v = filmVehicle();
  WingMesh mesh = fe_test::plateGridMesh(0.04, 0.06, 8, 12, -0.04, 0.0);
  mesh.p2_node = fe_test::gridNode(8, 0, 8);
  const SkinPrestress p = shrunkSkinPrestress(v, mesh, WingSupport{}, kPretension_Npm);
  const double s = skinShrinkStrain(v, kPretension_Npm);
  EXPECT_NEAR(s, kPretension_Npm * 0.69 / (100e9 * 4e-5), 1e-18);
  // 1e-9 of N0 and of the largest displacement: round-off of a linear solve.
  EXPECT_LT(p.stresses.skin_membrane_force_Npm.cwiseAbs().maxCoeff(), 1e-9 * kPretension_Npm);
  // A skin-only mesh has no drilling DOF at P2 (nothing but a beam activates it), so the film may
  // also turn rigidly in its plane about P2: that null motion (no strain) is removed by least
  // squares before the comparison.
  const Vec3 x_p2 = mesh.nodes_W_m[static_cast<std::size_t>(mesh.p2_node)];
  double num = 0.0, den = 0.0;
  for (int n = 0; n < mesh.nodeCount(); ++n) {
    const Vec3 r = mesh.nodes_W_m[static_cast<std::size_t>(n)] - x_p2;
    const Vec3 rest = p.displacement.segment<3>(globalDof(n, kU)) + s * r;
    num += Vec3::UnitZ().cross(r).dot(rest);
    den += Vec3::UnitZ().cross(r).squaredNorm();
  }
  const double turn_rad = num / den;
  double largest = 0.0, error = 0.0;
  for (int n = 0; n < mesh.nodeCount(); ++n) {
    const Vec3 r = mesh.nodes_W_m[static_cast<std::size_t>(n)] - x_p2;
    const Vec3 expected = -s * r + turn_rad * Vec3::UnitZ().cross(r);
    largest = std::max(largest, (s * r).norm());
    error = std::max(error, (p.displacement.segment<3>(globalDof(n, kU)) - expected).norm());
  }
  std::printf("free film: largest shrink %.3e m, largest error %.3e m (rigid turn %.2e rad)\n",
              largest, error, turn_rad);
  EXPECT_LT(error, 1e-9 * largest);
}

// A film on a frame on all four edges that is far stiffer than the film (rods of 4 mm, E a
// million times the skin's) is held: every facet carries N_xx = N_yy = N0, N_xy = 0, and the
// frame's compression balances the film's pull (each side carries about N0 times half the other
// side's length). 1e-3: the frame yields by ~(E t L) / (E_frame A) ~ 1e-5 of the shrink.
TEST(SkinPretension, RigidFrameHoldsTheNominalPretension) {
  VehicleModel v = filmVehicle();
  v.materials.push_back(fe_test::makeMaterial("FRAME", 1e17, 0.3, 1000.0));
  v.wing.members.push_back(fe_test::makeMember("FRAME", "FRAME", 4e-3));
  const int nx = 8, ny = 12;
  WingMesh mesh = fe_test::plateGridMesh(0.04, 0.06, nx, ny, -0.04, 0.0);
  for (int i = 0; i < nx; ++i) {
    mesh.beams.push_back({{fe_test::gridNode(i, 0, nx), fe_test::gridNode(i + 1, 0, nx)}, 0});
    mesh.beams.push_back({{fe_test::gridNode(i, ny, nx), fe_test::gridNode(i + 1, ny, nx)}, 0});
  }
  for (int j = 0; j < ny; ++j) {
    mesh.beams.push_back({{fe_test::gridNode(0, j, nx), fe_test::gridNode(0, j + 1, nx)}, 0});
    mesh.beams.push_back({{fe_test::gridNode(nx, j, nx), fe_test::gridNode(nx, j + 1, nx)}, 0});
  }
  mesh.p2_node = fe_test::gridNode(nx, 0, nx);
  const SkinPrestress p = shrunkSkinPrestress(v, mesh, WingSupport{}, kPretension_Npm);
  const Eigen::MatrixXd& n = p.stresses.skin_membrane_force_Npm;
  double worst = 0.0;
  for (Eigen::Index f = 0; f < n.rows() / 3; ++f) {
    // The facet triads differ, but an isotropic N0 is the same in every one.
    worst = std::max({worst, std::abs(n(3 * f, 0) / kPretension_Npm - 1.0),
                      std::abs(n(3 * f + 1, 0) / kPretension_Npm - 1.0),
                      std::abs(n(3 * f + 2, 0) / kPretension_Npm)});
  }
  std::printf("film on a rigid frame: largest |N / N0 - 1| %.2e\n", worst);
  EXPECT_LT(worst, 1e-3);
  EXPECT_LT(p.stresses.beam_axial_force_N.maxCoeff(), 0.0);  // every frame element compressed
}

// The literal EFW (Table 1's rods, a free trailing edge): the film keeps a small and uneven part
// of N0, and the wing buckles when the film is shrunk to about 41 N/m (mesh-converged: 41.13 /
// 41.22 / 40.97 N/m at h = 7 / 5 / 3.5 mm; the mode is a local buckle of the skin at the trailing
// edge around the outer stiffener's end, y_W = 0.20-0.22 m, where the shrunk film is compressed
// along the edge).
// Measured (2026-12-06, 5 mm mesh, the vehicle's support): area means N_chordwise 0.036 N0,
// N_spanwise 0.197 N0; the aft fifth of the chord carries almost nothing either way (spanwise
// -0.11 .. +0.06 N0), the leading-edge fifth 0.3-0.54 N0 spanwise; buckling at 41.2 N/m. At 30
// N/m the first fixed-interface frequency falls from 23.9 Hz (slack) to 17.7 Hz, at 40 N/m to 7.8
// Hz: the compressed frame softens the wing more than the film stiffens it.
TEST(SkinPretension, TheEfwFrameHoldsLittleOfAShrunkFilmAndBucklesNear41NPerM) {
  VehicleModel v = testing::magpieVehicle();
  const WingMesh mesh = buildWingMesh(v, v.wing.fe.element_size_m);
  const WingSupport support = WingSupport::of(v.wing.fe);
  const SkinPrestress p = shrunkSkinPrestress(v, mesh, support, 1.0);
  const VonKarmanTerms terms(v, mesh);
  double area = 0.0, chordwise = 0.0, spanwise = 0.0;
  for (std::size_t k = 0; k < terms.facets().size(); ++k) {
    const VonKarmanTerms::Facet& e = terms.facets()[k];
    const Eigen::Vector3d n = p.stresses.skin_membrane_force_Npm.middleRows<3>(3 * static_cast<Eigen::Index>(k));
    Eigen::Matrix2d local;
    local << n(0), n(2), n(2), n(1);
    const Eigen::Matrix2d t = e.triad.topLeftCorner<2, 2>();  // rows e1, e2 in (x_W, y_W)
    const Eigen::Matrix2d in_w = t.transpose() * local * t;
    area += e.area_m2;
    chordwise += e.area_m2 * in_w(0, 0);
    spanwise += e.area_m2 * in_w(1, 1);
  }
  const double limit = skinPretensionBucklingLimit(v, mesh, support, 100.0);
  std::printf("EFW, a film shrunk to N0: area means chordwise %.3f N0, spanwise %.3f N0; the wing "
              "buckles at %.2f N/m\n",
              chordwise / area, spanwise / area, limit);
  EXPECT_LT(chordwise / area, 0.1);
  EXPECT_LT(spanwise / area, 0.3);
  // 38-44: the measured 41.2 N/m with room beyond the mesh spread (0.25 N/m).
  EXPECT_GT(limit, 38.0);
  EXPECT_LT(limit, 44.0);
  EXPECT_EQ(skinPretensionBucklingLimit(v, mesh, support, 30.0), 30.0);

  v.wing.skin.pretension_N_per_m = 45.0;
  try {
    (void)buildModalWing(v, mesh, modalWingOptionsOf(v.wing.fe));
    ADD_FAILURE() << "a pretension that buckles the wing was accepted";
  } catch (const InvalidModelError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("wing.skin.pretension_N_per_m"), std::string::npos) << what;
    EXPECT_NE(what.find("buckles the wing"), std::string::npos) << what;
  }
}

}  // namespace
}  // namespace orni::structure
