// The condensed membrane (membrane_rom.hpp) on the literal EFW against the full nonlinear FE
// solution (von_karman.hpp) of the same wing under the same load: a uniform 53 Pa upward on the
// skin, about the rigid wing's mean lift per area at Table 3's point (2.3 N on 0.044 m^2), and a
// lift growing along the span. Acceptance: deflections within 5 %, section pitch within 0.3 deg;
// met on a taut skin, whose static equilibrium is unique; the slack skin has none to compare.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "core/structure/fe_assembly.hpp"
#include "core/structure/membrane_rom.hpp"
#include "core/structure/modal_wing.hpp"
#include "core/structure/skin_pretension.hpp"
#include "core/structure/static_shapes.hpp"
#include "core/structure/von_karman.hpp"
#include "core/structure/wing_mesh.hpp"
#include "fe_test_meshes.hpp"
#include "tests/support/magpie_vehicle.hpp"

namespace orni::structure {
namespace {

constexpr double kLiftPressure_Pa = 53.0;
constexpr double kDeflectionTol = 0.05;   // acceptance: 5 %


// The literal EFW, its modal wing (24 modes, as the nonlinear vehicle files ask for), the full
// nonlinear static solution and the reduced one under a load.
struct StaticCase {
  VehicleModel vehicle = testing::magpieVehicle();
  WingMesh mesh;
  ModalWingOptions options;
  ModalWing modal_wing;
  explicit StaticCase(double pretension_Npm, int modes = 24) {
    vehicle.wing.skin.pretension_N_per_m = pretension_Npm;
    mesh = buildWingMesh(vehicle, vehicle.wing.fe.element_size_m);
    options = modalWingOptionsOf(vehicle.wing.fe);
    options.nonlinear = true;
    options.selection.max_modes = modes;
    modal_wing = buildModalWing(vehicle, mesh, options);
  }
  NonlinearStaticResult full(const Eigen::VectorXd& load, int load_steps = 10) const {
    NonlinearStaticOptions o;
    o.load_steps = load_steps;
    return solveWingStatic(vehicle, mesh, options.support, load, o);
  }
  // The reduced static solution with `load_steps` equal load increments (false: no convergence).
  bool reduced(const Eigen::VectorXd& load, int load_steps, Eigen::VectorXd* u) const {
    Eigen::VectorXd q;
    if (!solveModalStatic(modal_wing.stiffnessDiagonal(), modal_wing.membrane,
                          modal_wing.mode_shapes.transpose() * load, &q, load_steps))
      return false;
    *u = modal_wing.mode_shapes * q;
    return true;
  }
  std::size_t tip() const { return mesh.strip_nodes.size() - 1; }
  std::size_t mid() const { return mesh.strip_nodes.size() / 2; }
};

// Where the slack skin's static solution is unique (small loads: the same answer with 10 or 40
// load increments), the reduced wing converges to the full one with the mode count, slowly: the
// membrane's deformation is not in the first linear modes. Measured (2026-12-06) at 1.67 Pa (3 % of
// 53 Pa), mid-span TE: full 2.670 mm; 12 / 24 / 48 / 96 / 160 modes 1.949 / 2.240 / 2.557 / 2.642
// / 2.658 mm (0.73 / 0.84 / 0.958 / 0.990 / 0.996; builds 0.2 / 0.5 / 2.2 / 20 / 130 s); tip LE
// full 0.866, 24 modes 0.871 mm. At 4.77 Pa (full 6.08-6.21 mm with 40 / 10 increments: the
// branches begin) 24 / 48 / 72 / 96 modes give 4.46 / 5.12 / 5.82 / 5.95 mm; at 15 Pa 96 modes jump
// to another branch (19.6 against 13.6-14.5 mm). CalculiX NLGEOM at 1.67 Pa (a partial run,
// test_fe_calculix_nonlinear.cpp): mid-span TE 2.528 mm, tip 0.920 mm; the full solution is within
// 6 % of it. So the 24 modes the nonlinear vehicle file uses are 16 % too stiff here, 48 meet the
// acceptance's 5 %; no pretension the frame can hold makes the skin taut (test_skin_pretension.cpp;
// the uniform 100 N/m under which 24 modes matched the full solution to 1 % before 2026-12-06 was
// not in equilibrium with the frame).
TEST(FeMembraneRomEfw, ReducedStaticConvergesInTheModesWhereTheSlackSolutionIsUnique) {
  const StaticCase c24(0.0, 24);
  constexpr double kSmallLift_Pa = 1.67;
  const Eigen::VectorXd load = uniformLiftLoad(c24.mesh, kSmallLift_Pa);
  const NonlinearStaticResult coarse = c24.full(load, 10), fine = c24.full(load, 40);
  ASSERT_TRUE(coarse.converged) << coarse.message;
  ASSERT_TRUE(fine.converged) << fine.message;
  const Section full_mid = sectionOf(c24.mesh, fine.displacement, c24.mid());
  const Section path_mid = sectionOf(c24.mesh, coarse.displacement, c24.mid());
  const Section full_tip = sectionOf(c24.mesh, fine.displacement, c24.tip());
  // Unique: the two load paths agree to 0.1 %.
  EXPECT_NEAR(path_mid.trail_up_m / full_mid.trail_up_m, 1.0, 1e-3);
  double previous = 0.0;
  for (const int modes : {12, 24, 48}) {
    const StaticCase c(0.0, modes);
    Eigen::VectorXd u_rom;
    ASSERT_TRUE(c.reduced(load, 10, &u_rom));
    const Section rom_mid = sectionOf(c.mesh, u_rom, c.mid());
    const Section rom_tip = sectionOf(c.mesh, u_rom, c.tip());
    const double ratio = rom_mid.trail_up_m / full_mid.trail_up_m;
    std::printf("EFW slack, %.2f Pa, %d modes: mid-span TE %.3f mm (full %.3f, 10 increments %.3f; "
                "ratio %.3f), tip LE %.3f mm (full %.3f)\n",
                kSmallLift_Pa, modes, 1e3 * rom_mid.trail_up_m, 1e3 * full_mid.trail_up_m,
                1e3 * path_mid.trail_up_m, ratio, 1e3 * rom_tip.lead_up_m, 1e3 * full_tip.lead_up_m);
    ::testing::Test::RecordProperty("rom_over_full_mid_te_" + std::to_string(modes) + "_modes",
                                    std::to_string(ratio));
    // From below, monotonically (a Ritz basis of a convex energy near the unique minimum).
    EXPECT_GT(ratio, previous) << modes << " modes";
    EXPECT_LT(ratio, 1.0 + 1e-3) << modes << " modes";
    EXPECT_NEAR(rom_tip.lead_up_m / full_tip.lead_up_m, 1.0, kDeflectionTol) << modes << " modes";
    previous = ratio;
  }
  // 48 modes: the acceptance's 5 % (measured 4.2 %); 24 modes do not (16 %).
  EXPECT_NEAR(previous, 1.0, kDeflectionTol);
}

// The slack skin (no pretension, the vehicle files' default) has no unique static equilibrium
// under this load: the compressed regions of a 0.04 mm skin wrinkle, and which wrinkled state a
// solution reaches depends on how the load is applied. Measured (2026-12-05) on the full model:
// 10 / 40 load increments give mid-span TE 29.25 / 30.86 mm, tip LE 17.28 / 18.33 mm, potentials
// -10.64 / -11.07 mJ (in von Karman's member ordering 36.19 / 34.02 mm, -11.89 / -11.49 mJ);
// a film shrunk onto the frame to 10 / 30 N/m leaves it at 31-34 mm (test_skin_pretension.cpp). The
// reduced wing's equilibria spread far more: mid-span TE 29.6 mm with 10 equal increments, 15.6 mm
// with 60 (the 10-increment path jumps to another branch). So a comparison at 5 % means nothing for
// the slack skin, and the reduced slack wing is not validated: its close mid-span agreement with 10
// increments was one branch matching another. Enrichment of the 24 modes with static shapes of the
// skin tensioned to 300, 3000 and 30000 N/m under lift, flap-inertia and pitching loads (Ritz
// vectors, tried 2026-12-05) did not remove the spread. Held here so the finding stays measured.
TEST(FeMembraneRomEfw, SlackSkinReducedStaticDependsOnTheLoadPath) {
  const StaticCase c(0.0);
  const Eigen::VectorXd load = uniformLiftLoad(c.mesh, kLiftPressure_Pa);
  Eigen::VectorXd coarse, fine;
  ASSERT_TRUE(c.reduced(load, 10, &coarse));
  ASSERT_TRUE(c.reduced(load, 60, &fine));
  const Section a = sectionOf(c.mesh, coarse, c.mid()), b = sectionOf(c.mesh, fine, c.mid());
  std::printf("EFW, slack skin, 53 Pa, 24 modes: mid-span TE up %.2f mm (10 increments), %.2f mm "
              "(60 increments)\n", 1e3 * a.trail_up_m, 1e3 * b.trail_up_m);
  ::testing::Test::RecordProperty("slack_rom_mid_te_mm_10_steps", std::to_string(1e3 * a.trail_up_m));
  ::testing::Test::RecordProperty("slack_rom_mid_te_mm_60_steps", std::to_string(1e3 * b.trail_up_m));
  // Two equilibria further apart than the acceptance tolerance (measured a ratio of 1.9).
  EXPECT_GT(a.trail_up_m / b.trail_up_m, 1.0 + 4.0 * kDeflectionTol);
}


// The condensation is exact for the model it condenses: with the members' stretch in von Karman's
// ordering (MemberStretch::kOutOfPlaneOnly, as the facets), the ROM's strain energy at its own
// static solution equals the full model's at the same state, the modal deflection plus the stored
// in-plane relaxation, and that relaxation is the full model's in-plane equilibrium (its in-plane
// residual vanishes). The default full model (members stretched by their in-plane rotation too)
// charges the same state more: that difference, not the condensation, is why the ROM is softer
// than the full solution (von_karman.hpp, MemberStretch).
TEST(FeMembraneRomEfw, CondensationIsExactForVonKarmansOrdering) {
  const VehicleModel v = testing::magpieVehicle();
  const WingMesh mesh = buildWingMesh(v, v.wing.fe.element_size_m);
  ModalWingOptions options = modalWingOptionsOf(v.wing.fe);
  options.nonlinear = true;
  options.keep_membrane_relaxation = true;
  const ModalWing mw = buildModalWing(v, mesh, options);
  const Eigen::VectorXd load = uniformLiftLoad(mesh, kLiftPressure_Pa);
  Eigen::VectorXd q;
  ASSERT_TRUE(solveModalStatic(mw.stiffnessDiagonal(), mw.membrane,
                               mw.mode_shapes.transpose() * load, &q, 10));
  const Eigen::VectorXd u = mw.mode_shapes * q + mw.membrane.membraneDisplacement(q);

  WingFeModel fe = assembleWingFe(v, mesh);
  addSkinPretension(v, mesh, options.support, &fe);
  const VonKarmanTerms von_karman(v, mesh, MemberStretch::kOutOfPlaneOnly);
  const VonKarmanTerms both_transverse(v, mesh);  // the default
  ModalMembraneStiffness::Workspace ws(mw.membrane);
  const double rom_J =
      0.5 * q.dot(mw.stiffnessDiagonal().cwiseProduct(q)) + mw.membrane.energy(q, &ws);
  const double linear_J = 0.5 * u.dot(fe.stiffness * u);
  const double full_J = linear_J + von_karman.energy(u);
  const double default_J = linear_J + both_transverse.energy(u);
  // In-plane residual of the full model at u over the retained in-plane DOFs, against the
  // in-plane force scale of the stretching (the nonlinear force's in-plane part alone).
  const Eigen::VectorXd nonlinear_force = von_karman.internalForce(u);
  const Eigen::VectorXd residual = fe.stiffness * u + nonlinear_force;
  const DofPartition part = makeDofPartition(fe.active, wingBoundaryDofs(mesh, options.support), {});
  double residual_sq = 0.0, scale_sq = 0.0;
  for (int d : part.retained()) {
    const int slot = d % kDofsPerNode;
    if (slot != kU && slot != kV && slot != kThetaZ) continue;
    residual_sq += residual(d) * residual(d);
    scale_sq += nonlinear_force(d) * nonlinear_force(d);
  }
  std::printf("EFW at %.0f Pa, %d modes: strain energy ROM %.6e J, full (von Karman ordering) "
              "%.6e J (ROM / full - 1 = %.1e), full (default members) %.6e J; in-plane residual %.2e "
              "of the stretching force\n",
              kLiftPressure_Pa, mw.modeCount(), rom_J, full_J, rom_J / full_J - 1.0, default_J,
              std::sqrt(residual_sq / scale_sq));
  ::testing::Test::RecordProperty("member_in_plane_rotation_J", std::to_string(default_J - full_J));
  // 1e-6: the energies are sums of terms 1e4-1e5 times larger that cancel (most of the bending's
  // quadratic strain relaxes in the plane), so round-off and the in-plane solve's accuracy set the
  // floor (measured 1.2e-9 relative).
  EXPECT_NEAR(rom_J / full_J, 1.0, 1e-6);
  EXPECT_LT(std::sqrt(residual_sq / scale_sq), 1e-6);
  // The members' in-plane rotation costs something at this state (measured 8.7e-4 J on a
  // strain energy of 5.5e-3 J).
  EXPECT_GT(default_J - full_J, 1e-3 * full_J);
}

// The tension-field film (tension_field.hpp) on the literal EFW under the Table-3 load. The elastic
// film's static answer is not unique (29.25 / 30.86 mm at mid-span with 10 / 40 increments,
// above): its compressed regions buckle on the mesh's scale. A film that wrinkles instead has one
// answer, and it is softer: the elastic plate's compression was holding the chord. Without a
// compression cap the answer depends on the residual stiffness kappa and does not converge as it
// falls (measured 2026-12-07, mid-span trailing edge / section pitch / tip leading edge at kappa
// 1e-1, 1e-2, 1e-3, 1e-4: 40.0 / 46.2 / 53.5 / 68.0 mm, -21.4 / -24.7 / -28.4 / -35.1 deg, 22.5 /
// 23.8 / 26.8 / 32.5 mm, each the same to 5 digits with 10, 20 and 40 increments; 849 / 1570 /
// 2715 Newton iterations at 1e-4). With the wrinkles' buckling load kept as a compression cap Nc
// (10-60 N/m on this skin) it converges: at Nc = 20 N/m 50.5 / 57.9 / 60.9 / 61.5 mm at kappa 1e-3
// / 1e-4 / 1e-5 / 1e-6, and over Nc = 10 / 20 / 40 / 60 N/m (kappa 1e-5) 68.5 / 60.9 / 53.2 / 47.7
// mm (orni_film_static; docs/theory.md 4.7, "A wrinkled film with a compression cap"). Checked
// here at Nc = 20 N/m, kappa 1e-5, the converged end (~50 s: 243 and 371 Newton iterations).
TEST(FeMembraneRomEfw, TensionFieldFilmHasOneStaticAnswerAtTheTable3LoadAndItIsSofter) {
  const StaticCase c(0.0, 12);
  const Eigen::VectorXd load = uniformLiftLoad(c.mesh, kLiftPressure_Pa);
  NonlinearStaticOptions o;
  o.skin_membrane = SkinMembrane::kTensionField;
  o.film.residual_stiffness = 1e-5;
  o.film.compression_cap_n_per_m = 20.0;
  o.max_newton_iterations = 400;  // the law's Hessian jumps between the film's states
  Section mid[2], tip[2];
  int k = 0;
  for (const int steps : {5, 10}) {
    o.load_steps = steps;
    const NonlinearStaticResult r = solveWingStatic(c.vehicle, c.mesh, c.options.support, load, o);
    ASSERT_TRUE(r.converged) << r.message;
    mid[k] = sectionOf(c.mesh, r.displacement, c.mid());
    tip[k] = sectionOf(c.mesh, r.displacement, c.tip());
    std::printf("EFW film (cap 20 N/m, kappa 1e-5), 53 Pa, %d increments: mid-span TE %.3f mm, "
                "pitch %.2f deg, tip LE %.3f mm (%d Newton iterations)\n", steps,
                1e3 * mid[k].trail_up_m, mid[k].pitch_deg, 1e3 * tip[k].lead_up_m, r.newton_iterations);
    ++k;
  }
  ::testing::Test::RecordProperty("tension_field_mid_te_mm", std::to_string(1e3 * mid[1].trail_up_m));
  // One answer: the two load paths agree to 1e-4 (measured: 5 digits, 60.942 mm).
  EXPECT_NEAR(mid[0].trail_up_m / mid[1].trail_up_m, 1.0, 1e-4);
  EXPECT_NEAR(tip[0].lead_up_m / tip[1].lead_up_m, 1.0, 1e-4);
  // Softer than either of the elastic film's answers (29.25 / 30.86 mm) by far more than their
  // spread (measured 1.97 times): the film sheds the compression beyond its wrinkles' buckling load.
  EXPECT_GT(mid[1].trail_up_m, 1.5 * 30.86e-3);
  // And stiffer than the film without a cap (68.0 mm at kappa 1e-4, above, and more as kappa
  // falls): the cap holds some of the chord.
  EXPECT_LT(mid[1].trail_up_m, 68.0e-3);
}

}  // namespace
}  // namespace orni::structure
