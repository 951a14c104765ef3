// Wing planform, strips and rigid-wing mass properties against closed forms.
#include <gtest/gtest.h>

#include <cmath>

#include "core/model/frames.hpp"
#include "core/model/wing_geometry.hpp"
#include "core/model/wing_inertia.hpp"

namespace orni {
namespace {

// Quadrature of smooth integrands (Gauss on 400 panels in the angle variable): 1e-10 relative.
constexpr double kQuadratureTol = 1e-10;

WingModel ellipseWing() {
  WingModel w;
  w.planform = Planform::kQuarterEllipse;
  w.semispan_m = 0.27;
  w.root_chord_m = 0.104;
  w.strip_count = 27;
  return w;
}

TEST(ModelWingGeometry, QuarterEllipseAreaIsExact) {
  const WingModel w = ellipseWing();
  EXPECT_NEAR(halfWingArea(w), kPi * 0.27 * 0.104 / 4.0, 1e-15);
  double sum = 0.0;
  for (const Strip& s : makeStrips(w)) sum += s.chord_m * s.width_m;
  EXPECT_NEAR(sum, halfWingArea(w), 1e-14);  // area-preserving strip chords
}

TEST(ModelWingGeometry, StripsCoverTheSpanWithFiniteTipChord) {
  const auto strips = makeStrips(ellipseWing());
  ASSERT_EQ(strips.size(), 27u);
  EXPECT_DOUBLE_EQ(strips.front().y_inner_m, 0.0);
  EXPECT_NEAR(strips.back().y_outer_m, 0.27, 1e-15);
  EXPECT_GT(strips.back().chord_m, 0.0);  // no zero-chord strip at the tip (docs/theory.md 2.1)
  EXPECT_LT(strips.back().chord_m, strips.front().chord_m);
}

TEST(ModelWingGeometry, AspectRatioFromPlanformOrFile) {
  VehicleModel v;
  v.wing.planform = Planform::kRectangular;
  v.wing.semispan_m = 0.27;
  v.wing.root_chord_m = 0.54 / 5.58;
  EXPECT_NEAR(aerodynamicAspectRatio(v), 5.58, 1e-12);
  v.aero.aspect_ratio = 4.0;
  EXPECT_DOUBLE_EQ(aerodynamicAspectRatio(v), 4.0);
}

TEST(ModelWingInertia, RodMatchesClosedForm) {
  // Rod of length L along y from the origin: I_xx = I_zz = m L^2 / 3, I_yy = 0.
  const double m = 0.01, L = 0.3;
  const RigidBodyInertia r = rodInertia(Vec3::Zero(), Vec3(0, L, 0), m);
  EXPECT_NEAR(r.inertia_P2_W_kgm2(0, 0), m * L * L / 3.0, 1e-15);
  EXPECT_NEAR(r.inertia_P2_W_kgm2(2, 2), m * L * L / 3.0, 1e-15);
  EXPECT_NEAR(r.inertia_P2_W_kgm2(1, 1), 0.0, 1e-15);
  EXPECT_NEAR(r.centerOfMass_W_m().y(), L / 2.0, 1e-15);
}

TEST(ModelWingInertia, RectangularSkinMatchesPlateFormulas) {
  VehicleModel v;
  v.wing.planform = Planform::kRectangular;
  v.wing.semispan_m = 0.27;
  v.wing.root_chord_m = 0.1;
  v.wing.skin = WingSkin{"film", 1e-4};
  v.materials.push_back(Material{"film", 1e9, 0.3, 1000.0});
  const WingMassBreakdown mb = computeWingInertia(v);
  const double m = 1000.0 * 1e-4 * 0.27 * 0.1;
  EXPECT_NEAR(mb.skin_kg, m, m * kQuadratureTol);
  const Vec3 c = mb.total.centerOfMass_W_m();
  EXPECT_NEAR(c.x(), -0.05, 1e-12);
  EXPECT_NEAR(c.y(), 0.135, 1e-12);
  // Flapping (x) axis inertia of a plate from its edge: m s^2 / 3.
  EXPECT_NEAR(mb.total.inertia_P2_W_kgm2(0, 0), m * 0.27 * 0.27 / 3.0,
              m * 0.27 * 0.27 * kQuadratureTol);
  EXPECT_NEAR(mb.total.inertia_P2_W_kgm2(1, 1), m * 0.1 * 0.1 / 3.0, m * 0.01 * kQuadratureTol);
}

TEST(ModelWingInertia, QuarterEllipseSkinMassAndCentroid) {
  VehicleModel v;
  v.wing = ellipseWing();
  v.wing.skin = WingSkin{"SKIN", 4e-5};
  v.materials.push_back(Material{"SKIN", 100e9, 0.31, 500.0});
  const WingMassBreakdown mb = computeWingInertia(v);
  const double area = kPi * 0.27 * 0.104 / 4.0;
  EXPECT_NEAR(mb.skin_kg, 500.0 * 4e-5 * area, 500.0 * 4e-5 * area * kQuadratureTol);
  // Centroid of a quarter ellipse: (4 a / 3 pi, 4 b / 3 pi) from the corner.
  const Vec3 c = mb.total.centerOfMass_W_m();
  EXPECT_NEAR(c.y(), 4.0 * 0.27 / (3.0 * kPi), 1e-9);
  EXPECT_NEAR(c.x(), -4.0 * 0.104 / (3.0 * kPi), 1e-9);
}

}  // namespace
}  // namespace orni
