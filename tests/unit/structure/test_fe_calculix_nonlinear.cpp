// Nonlinear statics against independent truths (docs/theory.md 2.7, 4.7): our von Karman
// solve (core/structure/von_karman.hpp) against CalculiX 2.20 with NLGEOM (a full large-rotation
// shell and beam solution) on the same mesh, S6 skin + B32R rods (calculix_deck.hpp). Needs `ccx`
// on PATH (Debian calculix-ccx); skipped without it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "core/structure/calculix_deck.hpp"
#include "core/structure/calculix_results.hpp"
#include "core/structure/corotational.hpp"
#include "core/structure/fe_assembly.hpp"
#include "core/structure/von_karman.hpp"
#include "core/structure/wing_mesh.hpp"
#include "tests/support/magpie_vehicle.hpp"
#include "tests/unit/structure/ccx_runner.hpp"
#include "tests/unit/structure/fe_test_disc.hpp"

namespace orni::structure {
namespace {

std::string fmt(const char* format, double a) {
  char buf[64];
  std::snprintf(buf, sizeof buf, format, a);
  return buf;
}

// w0/h of Timoshenko's approximation w0/h + 0.488 (w0/h)^3 = q a^4 / (64 D h), by Newton.
double timoshenkoRatio(double load_parameter) {
  double x = load_parameter;
  for (int i = 0; i < 100; ++i) x -= (x + 0.488 * x * x * x - load_parameter) / (1.0 + 1.464 * x * x);
  return x;
}

// ---------------------------------------------------------------------------------------------
// (a) Clamped circular plate (a = 50 mm, h = 1 mm, aluminium), immovable clamped rim, uniform
// pressure from the linear regime to w0/h ~ 12, a dead load in both codes (ours: q A / 3 on the
// corners of our linear facets; ccx: the consistent q A / 3 on the S6 midside nodes).
// Measured ours / ccx (2026-12-04): 14 rings 1.018 (linear) ... 1.009 (w0/h = 11); 20 rings
// 1.011 ... 1.005; 8 rings 1.047 ... 1.015: both codes converge towards each other. ccx's follower
// pressure (*DLOAD P) instead of the dead load: +0.9 % at w0/h = 11, the same below w0/h = 2. At
// w0/h = 11 both lie 1.7-2.6 % below Hencky's membrane (no bending) and 7-8 % below Timoshenko's
// one-term approximation, which overestimates w0 for w0/h >~ 2.

struct DiscCase {
  double radius_m = 0.05, thickness_m = 1e-3, youngs_pa = 70e9, nu = 0.3;
  int rings = 14;
  double rigidity() const { return youngs_pa * std::pow(thickness_m, 3) / (12.0 * (1.0 - nu * nu)); }
  // The pressure at which Timoshenko's approximation gives w0/h = ratio.
  double pressureFor(double ratio) const {
    return (ratio + 0.488 * ratio * ratio * ratio) * 64.0 * rigidity() * thickness_m /
           std::pow(radius_m, 4);
  }
};

TEST(StructureCalculixNonlinear, ClampedPlateCentreDeflectionMatchesCcxNlgeom) {
  if (!fe_test::ccxAvailable()) GTEST_SKIP() << fe_test::kNoCcxMessage;
  const DiscCase c;
  const VehicleModel vehicle = fe_test::skinVehicle(c.thickness_m, c.youngs_pa, c.nu, 2700.0);
  const WingMesh mesh = fe_test::discMesh(c.radius_m, c.rings);
  const std::vector<int> rim = fe_test::discRimNodes(mesh, c.radius_m);
  // Load levels: Timoshenko's w0/h = 0.1 (linear) ... 12 (a membrane).
  const std::vector<double> ratios = {0.1, 1.0, 2.0, 4.0, 7.0, 10.0, 12.0};
  const double q_max = c.pressureFor(ratios.back());

  CalculixDeckOptions deck;
  deck.frequency_step = false;
  deck.clamp_p2 = false;  // P2 is the centre node here
  deck.clamped_nodes = rim;
  deck.static_steps.print_nodes = {0};
  deck.static_steps.load.skin_pressure_pa = q_max;  // dead load, as ours
  // The steps themselves are the load ladder: one increment per step converges (4-6 Newton
  // iterations, ~25 s in all); ccx halves it by itself if not. The default 0.05 / 0.25 gives the
  // same w0 to 6 digits in 56 increments and 4 times the run time.
  deck.static_steps.initial_increment = 1.0;
  deck.static_steps.max_increment = 1.0;
  for (double r : ratios) deck.static_steps.load_factors.push_back(c.pressureFor(r) / q_max);
  const fe_test::CcxRun nl = fe_test::runCcx(calculixDeck(vehicle, mesh, deck), "disc_nl");
  // Linear ccx: one step (the answer is proportional to the load).
  CalculixDeckOptions lin_deck = deck;
  lin_deck.static_steps.nlgeom = false;
  lin_deck.static_steps.load_factors = {1.0};
  const fe_test::CcxRun lin = fe_test::runCcx(calculixDeck(vehicle, mesh, lin_deck), "disc_lin");
  ASSERT_FALSE(lin.tables.empty()) << lin.message;
  const CalculixDisplacementTable* lin_table = calculixTableAt(lin.tables, 1.0);
  ASSERT_NE(lin_table, nullptr) << lin.message;
  const double ccx_linear_per_pa = meshDisplacements(*lin_table, mesh.nodeCount())(2, 0) / q_max;

  // Ours.
  const WingFeModel fe = assembleWingFe(vehicle, mesh);
  std::vector<int> held;
  for (int n : rim)
    for (int k = 0; k < kDofsPerNode; ++k) held.push_back(globalDof(n, k));
  const DofPartition part = makeDofPartition(fe.active, held);
  const VonKarmanTerms terms(vehicle, mesh);
  const CoRotationalTerms corotational(vehicle, mesh, fe.stiffness);
  auto solve = [&](double q, bool nonlinear, const StaticNonlinearity& model) {
    NonlinearStaticOptions o;
    o.nonlinear = nonlinear;
    o.load_steps = 10;
    const NonlinearStaticResult r =
        solveNonlinearStatic(fe.stiffness, model, part, fe_test::pressureLoad(mesh, q), o);
    EXPECT_TRUE(r.converged) << r.message;
    return r.displacement(globalDof(0, kW));
  };
  auto ours = [&](double q, bool nonlinear) { return solve(q, nonlinear, terms); };
  const double ours_linear_per_pa = ours(q_max, false) / q_max;
  const double exact_linear_per_pa = std::pow(c.radius_m, 4) / (64.0 * c.rigidity());

  std::ostringstream table;
  table << "clamped plate a = 50 mm, h = 1 mm, " << c.rings << " rings, ccx S6 NLGEOM ("
        << fmt("%.1f", nl.seconds) << " s) and linear (" << fmt("%.1f", lin.seconds) << " s)\n"
        << "linear w0/q: ours " << ours_linear_per_pa << ", ccx " << ccx_linear_per_pa
        << ", Kirchhoff a^4/(64 D) " << exact_linear_per_pa << " m/Pa\n"
        << "  q (kPa)  Timoshenko w0/h  Hencky w0/h   ours w0/h   ccx w0/h   ours/ccx"
           "   co-rot w0/h  co-rot/ccx\n";
  fe_test::recordError("linear_ours_over_ccx", ours_linear_per_pa / ccx_linear_per_pa - 1.0);
  fe_test::recordError("ccx_seconds", nl.seconds + lin.seconds);
  for (std::size_t k = 0; k < ratios.size(); ++k) {
    const double q = c.pressureFor(ratios[k]);
    const CalculixDisplacementTable* t = calculixTableAt(nl.tables, static_cast<double>(k + 1));
    ASSERT_NE(t, nullptr) << "ccx did not finish static step " << k + 1 << "\n" << nl.message;
    const double w_ccx = meshDisplacements(*t, mesh.nodeCount())(2, 0);
    const double w_ours = ours(q, true);
    const double hencky =
        0.662 * c.radius_m * std::cbrt(q * c.radius_m / (c.youngs_pa * c.thickness_m));
    const double timoshenko = timoshenkoRatio(q * std::pow(c.radius_m, 4) /
                                              (64.0 * c.rigidity() * c.thickness_m));
    table << fmt("%9.1f", q * 1e-3) << fmt("%17.3f", timoshenko)
          << fmt("%13.3f", hencky / c.thickness_m) << fmt("%12.4f", w_ours / c.thickness_m)
          << fmt("%11.4f", w_ccx / c.thickness_m) << fmt("%11.4f", w_ours / w_ccx);
    // The co-rotational wing (corotational.hpp): the plate's slopes stay below ~0.3, where it
    // and von Karman agree; the same tolerance.
    const double w_cr = solve(q, true, corotational);
    table << fmt("%14.4f", w_cr / c.thickness_m) << fmt("%12.4f", w_cr / w_ccx) << "\n";
    fe_test::recordError(("corotational_over_ccx_wh_" + fmt("%g", ratios[k])).c_str(),
                         w_cr / w_ccx - 1.0);
    EXPECT_NEAR(w_cr / w_ccx, 1.0, 0.03) << "co-rotational, Timoshenko w0/h " << ratios[k];
    fe_test::recordError(("ours_over_ccx_wh_" + fmt("%g", ratios[k])).c_str(), w_ours / w_ccx - 1.0);
    // 3 %: the acceptance tolerance (two different discretisations of the same plate; measured
    // <= 1.9 %, the largest in the linear regime, where ccx's S6 is 1.7 % stiffer than Kirchhoff's
    // a^4 / (64 D) and ours 0.2 % softer).
    EXPECT_NEAR(w_ours / w_ccx, 1.0, 0.03) << "Timoshenko w0/h " << ratios[k];
  }
  std::printf("%s", table.str().c_str());
}

// ---------------------------------------------------------------------------------------------
// (b) The literal EFW (studies/vehicles/efw_magpie.toml, h = 5 mm) under a uniform 53 Pa lift
// pressure on the skin (about the rigid wing's mean lift per area at Table 3's trim point), along
// -z_W (z_W = x_W x y_W points down in the right wing's frame W, so lift is -z_W). Observed
// points: the tip (leading edge meets trailing edge at y_W = s) and the mid-span trailing edge
// (the trailing-edge sample node of strip 14 of 27, at y_W = s / 2).

struct EfwCase {
  VehicleModel vehicle = orni::testing::magpieVehicle();
  WingMesh mesh = buildWingMesh(vehicle, vehicle.wing.fe.element_size_m);
  WingSupport support = WingSupport::of(vehicle.wing.fe);
  int tip = -1, mid_te = -1;
  static constexpr double kPressurePa = -53.0;  // along +z_W: negative = lift
  EfwCase() {
    tip = 0;
    for (int n = 1; n < mesh.nodeCount(); ++n)
      if (mesh.nodes_W_m[static_cast<std::size_t>(n)].y() >
          mesh.nodes_W_m[static_cast<std::size_t>(tip)].y())
        tip = n;
    mid_te = mesh.strip_nodes[mesh.strip_nodes.size() / 2].trailing_edge;
  }
  CalculixDeckOptions deck(const std::vector<double>& factors, bool nlgeom) const {
    CalculixDeckOptions o = fe_test::staticDeckFor(support);
    o.static_steps.nlgeom = nlgeom;
    o.static_steps.load_factors = factors;
    o.static_steps.print_nodes = {tip, mid_te};
    o.static_steps.load.skin_pressure_pa = kPressurePa;
    return o;
  }
  NonlinearStaticResult ours(double factor, bool nonlinear) const {
    NonlinearStaticOptions o;
    o.nonlinear = nonlinear;
    o.max_newton_iterations = 300;
    // 1e-6: the residual of this model stagnates at ~1e-8 of the load in double precision (the
    // rods' axial stiffness E A ~ 8e5 N against skin loads of ~1e-4 N per node), above the
    // default 1e-8 at the first load steps.
    o.force_tolerance = 1e-6;
    return solveWingStatic(vehicle, mesh, support, factor * fe_test::pressureLoad(mesh, kPressurePa), o);
  }
};

TEST(StructureCalculixNonlinear, EfwLinearDeflectionUnderLiftPressureMatchesCcx) {
  if (!fe_test::ccxAvailable()) GTEST_SKIP() << fe_test::kNoCcxMessage;
  const EfwCase c;
  ASSERT_EQ(c.vehicle.wing.skin.pretension_N_per_m, 0.0);  // the deck has no pretension
  ASSERT_EQ(c.mesh.strip_nodes.size(), 27u);
  ASSERT_NEAR(c.mesh.nodes_W_m[static_cast<std::size_t>(c.mid_te)].y(), 0.135, 1e-9);
  const fe_test::CcxRun lin = fe_test::runCcx(calculixDeck(c.vehicle, c.mesh, c.deck({1.0}, false)), "efw_lin");
  const CalculixDisplacementTable* t = calculixTableAt(lin.tables, 1.0);
  ASSERT_NE(t, nullptr) << lin.message;
  const Eigen::Matrix3Xd u = meshDisplacements(*t, c.mesh.nodeCount());
  const NonlinearStaticResult r = c.ours(1.0, false);
  ASSERT_TRUE(r.converged) << r.message;
  const double ours_tip = r.displacement(globalDof(c.tip, kW));
  const double ours_te = r.displacement(globalDof(c.mid_te, kW));
  std::printf("EFW, 53 Pa lift, linear (ccx %.1f s): tip w ours %.3f mm, ccx %.3f mm; mid-span TE w "
              "ours %.3f mm, ccx %.3f mm\n",
              lin.seconds, 1e3 * ours_tip, 1e3 * u(2, c.tip), 1e3 * ours_te, 1e3 * u(2, c.mid_te));
  fe_test::recordError("linear_tip_ours_over_ccx", ours_tip / u(2, c.tip) - 1.0);
  fe_test::recordError("linear_mid_te_ours_over_ccx", ours_te / u(2, c.mid_te) - 1.0);
  fe_test::recordError("ccx_seconds", lin.seconds);
  // Lift moves the wing up (-z_W) in both codes; the linear answers are absurd (w / t ~ 4000 at
  // the trailing edge) but of the same linear model. Measured ours / ccx: tip 0.976, mid-span TE
  // 1.025; 5 %: the EFW's frequencies differ by up to 4 % between the two element families
  // (ccx_efw.sh).
  EXPECT_LT(ours_te, 0.0);
  EXPECT_NEAR(ours_tip / u(2, c.tip), 1.0, 0.05);
  EXPECT_NEAR(ours_te / u(2, c.mid_te), 1.0, 0.05);
}

// Our nonlinear solve of the EFW converges at every load level and stays far below the linear
// answer; the cross-check with ccx NLGEOM runs only with ORNI_CCX_SLOW=1: ccx needs ~10 s per
// Newton iteration of this 50 000-equation model on 2 cores and 7-11 iterations per 5 % load
// increment (measured: 35 % of the first 9 % load step in 10 minutes), far beyond a CI budget.
// What that partial run gave (2026-12-04, h = 5 mm, dead load): at 1.67 Pa (3.15 % of 53 Pa) ccx
// tip -0.920 mm, mid-span TE -2.528 mm, mid-span LE -0.143 mm; ours -0.901, -2.670, -0.139
// (ours / ccx 0.979, 1.056, 0.974); at 0.48 Pa 0.977, 1.014, 0.98: the trailing-edge gap grows
// with the load. On a 10 mm mesh at 2.22 Pa: ccx tip -1.167, mid-span TE -2.603 mm; ours -1.160,
// -3.337 (1.282 at the TE). Ours hardly depends on the mesh (TE at 2.22 Pa: -3.342 mm at 5 mm,
// -3.337 at 10 mm; at 1.67 Pa -2.670 / -2.648), ccx's S6 does: its TE at 5 mm, ~-3.0 mm at
// 2.22 Pa (interpolated in the load as w ~ q^0.6), is ~15 % deeper than at 10 mm (-2.603), so
// refining moves ccx towards ours: the gap looks like ccx's expanded wedges (t = 0.04 mm,
// h / t = 125) not yet converged on the free skin rather than an error of our von Karman model.
// The 10 mm mesh at 4.77 Pa (9 %, ccx 435 s): ccx tip -2.230, mid-span TE -4.341, mid-span LE
// -0.417 mm; ours -2.366, -6.308, -0.414 (1.061, 1.453, 0.992); ours at 5 mm: -2.207, -6.079.
TEST(StructureCalculixNonlinear, EfwNonlinearDeflectionUnderLiftPressure) {
  const EfwCase c;
  const bool with_ccx = std::getenv("ORNI_CCX_SLOW") != nullptr && fe_test::ccxAvailable();
  // Without ccx two levels (~30 s of CPU: 100-280 Newton iterations each from the flat wing).
  const std::vector<double> factors =
      with_ccx ? std::vector<double>{0.09, 0.25, 0.5, 1.0} : std::vector<double>{0.09, 1.0};
  fe_test::CcxRun nl;
  if (with_ccx) nl = fe_test::runCcx(calculixDeck(c.vehicle, c.mesh, c.deck(factors, true)), "efw_nl");
  for (std::size_t k = 0; k < factors.size(); ++k) {
    const NonlinearStaticResult lin = c.ours(factors[k], false);
    const NonlinearStaticResult r = c.ours(factors[k], true);
    ASSERT_TRUE(r.converged) << r.message;
    const double tip = r.displacement(globalDof(c.tip, kW)), te = r.displacement(globalDof(c.mid_te, kW));
    std::printf("EFW, %.1f Pa lift: tip w ours %.3f mm (linear %.3f), mid-span TE w ours %.3f mm "
                "(linear %.3f), %d Newton iterations\n",
                -factors[k] * EfwCase::kPressurePa, 1e3 * tip,
                1e3 * lin.displacement(globalDof(c.tip, kW)), 1e3 * te,
                1e3 * lin.displacement(globalDof(c.mid_te, kW)), r.newton_iterations);
    const std::string level = fmt("%.2f", factors[k]);
    fe_test::recordError(("ours_tip_mm_" + level).c_str(), 1e3 * tip);
    fe_test::recordError(("ours_mid_te_mm_" + level).c_str(), 1e3 * te);
    EXPECT_LT(te, 0.0);
    // The membrane carries the pressure: measured 0.39 (9 % load) ... 0.18 (full load) of the
    // linear trailing-edge deflection.
    EXPECT_LT(std::abs(te), 0.5 * std::abs(lin.displacement(globalDof(c.mid_te, kW))));
    if (!with_ccx) continue;
    const CalculixDisplacementTable* t = calculixTableAt(nl.tables, static_cast<double>(k + 1));
    ASSERT_NE(t, nullptr) << "ccx did not finish static step " << k + 1 << "\n" << nl.message;
    const Eigen::Matrix3Xd u = meshDisplacements(*t, c.mesh.nodeCount());
    std::printf("  ccx NLGEOM: tip w %.3f mm, mid-span TE w %.3f mm\n", 1e3 * u(2, c.tip),
                1e3 * u(2, c.mid_te));
    fe_test::recordError(("tip_ours_over_ccx_" + level).c_str(), tip / u(2, c.tip) - 1.0);
    fe_test::recordError(("mid_te_ours_over_ccx_" + level).c_str(), te / u(2, c.mid_te) - 1.0);
    // 5 %: the acceptance tolerance.
    EXPECT_NEAR(tip / u(2, c.tip), 1.0, 0.05);
    EXPECT_NEAR(te / u(2, c.mid_te), 1.0, 0.05);
  }
  if (!with_ccx)
    std::printf("(ccx NLGEOM comparison skipped: set ORNI_CCX_SLOW=1; it did not finish in 10 "
                "minutes, see the comment above)\n");
}

}  // namespace
}  // namespace orni::structure
