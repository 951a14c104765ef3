// The constrained flight test (paper Eq. 6-7, Fig. 9): coefficients and the zero moment point on
// synthetic loads with hand-computed answers, the singular points, strokes and cycle metrics.
#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <vector>

#include "core/dynamics/zero_moment_point.hpp"
#include "core/dynamics/flapping.hpp"
#include "tests/support/test_vehicles.hpp"

namespace orni {
namespace {

constexpr double kTol = 1e-12;

/// q = 61.25 Pa (rho 1.225, U 10 m/s), S = 0.04 m^2, c = 0.08 m: q S = 2.45 N, q S c = 0.196 N m.
CoefficientReference handReference(double theta_rad) {
  CoefficientReference r;
  r.dynamic_pressure_Pa = 0.5 * 1.225 * 10.0 * 10.0;
  r.wing_area_m2 = 0.04;
  r.mean_chord_m = 0.08;
  r.theta_mean_rad = theta_rad;
  return r;
}

LoadSample loads(double FV_N, double FH_N, double M_Nm) {
  LoadSample s;
  s.FV_N = FV_N;
  s.FH_N = FH_N;
  s.M_Nm = M_Nm;
  return s;
}

TEST(AnalysisZeroMomentPoint, CoefficientsOfASyntheticSample) {
  const CoefficientReference ref = handReference(0.0);
  // FV 0.98 N, FH -0.245 N, M 0.0098 N m over q S = 2.45 N and q S c = 0.196 N m.
  const LoadCoefficients c = loadCoefficients(loads(0.98, -0.245, 0.0098), ref);
  EXPECT_NEAR(c.CF_V, 0.4, kTol);
  EXPECT_NEAR(c.CF_H, -0.1, kTol);
  EXPECT_NEAR(c.CM_CG, 0.05, kTol);
}

TEST(AnalysisZeroMomentPoint, ReferenceFromTheModel) {
  const FlightCoreModel model(testing::rfwRig());
  const OperatingPoint point{6.0, 4.0, 20.0 * kDegToRad, 0.0};
  const CoefficientReference r = coefficientReference(model, point);
  EXPECT_NEAR(r.dynamic_pressure_Pa, 0.5 * 1.225 * 36.0, kTol);
  // Rectangular RFW: S = 2 * 0.27 * c0, c_MEAN = S / b = c0.
  EXPECT_NEAR(r.wing_area_m2, 0.54 * 0.54 / 5.58, 1e-12);
  EXPECT_NEAR(r.mean_chord_m, 0.54 / 5.58, 1e-12);
  EXPECT_EQ(r.wing_area_m2, model.wing_area_both_m2);
  EXPECT_EQ(r.mean_chord_m, model.mean_chord_m);
  EXPECT_EQ(r.theta_mean_rad, point.theta_rad);
}

TEST(AnalysisZeroMomentPoint, EpsilonByHand) {
  // theta 30 deg, C_F,V 0.4, C_F,H -0.1 ... forward positive, so -0.1 is a net drag:
  // denominator 0.4 cos 30 - (-0.1) sin 30 = 0.3464101615 + 0.05 = 0.3964101615.
  const double theta = 30.0 * kDegToRad;
  LoadCoefficients c;
  c.CF_V = 0.4;
  c.CF_H = -0.1;
  c.CM_CG = 0.05;
  EXPECT_NEAR(zmpDenominator(c, theta), 0.39641016151377546, kTol);
  const auto eps = zmpEpsilon(c, theta, 0.0);
  ASSERT_TRUE(eps.has_value());
  EXPECT_NEAR(*eps, -0.05 / 0.39641016151377546, kTol);  // -0.126130...: ZMP ahead of the CG
  // A thrust of the same size: 0.3464101615 - 0.05 = 0.2964101615.
  c.CF_H = 0.1;
  EXPECT_NEAR(*zmpEpsilon(c, theta, 0.0), -0.16868517511224485, kTol);
  // theta = 0: the ZMP is where the vertical force alone balances the moment.
  EXPECT_NEAR(*zmpEpsilon(c, 0.0, 0.0), -0.125, kTol);
}

TEST(AnalysisZeroMomentPoint, LoadsHaveNoMomentAboutTheZmp) {
  // Independent check by vectors: put the resultant (FH forward, FV up) at the point epsilon c
  // aft of the CG on the body axis pitched up by theta; its nose-up moment about the CG must equal
  // M_CG (the moment about the ZMP is then zero).
  const CoefficientReference ref = handReference(12.0 * kDegToRad);
  const double qS = ref.dynamic_pressure_Pa * ref.wing_area_m2;
  for (const LoadSample& s : {loads(1.1, 0.3, 0.02), loads(0.7, -0.4, -0.035),
                              loads(-0.9, 0.2, 0.01)}) {
    const LoadCoefficients c = loadCoefficients(s, ref);
    const auto eps = zmpEpsilon(c, ref.theta_mean_rad, 0.0);
    ASSERT_TRUE(eps.has_value());
    const double x_aft_m = *eps * ref.mean_chord_m;
    // Point of the ZMP relative to the CG: (forward, up) = -x_aft (cos theta, sin theta).
    const double r_fwd = -x_aft_m * std::cos(ref.theta_mean_rad);
    const double r_up = -x_aft_m * std::sin(ref.theta_mean_rad);
    const double moment_of_force_at_zmp = r_fwd * s.FV_N - r_up * s.FH_N;  // nose-up
    EXPECT_NEAR(moment_of_force_at_zmp, s.M_Nm, 1e-14) << "FV " << s.FV_N;
    EXPECT_NEAR(c.CF_V * qS, s.FV_N, 1e-14);
  }
}

TEST(AnalysisZeroMomentPoint, UndefinedWhereTheNormalForceVanishes) {
  LoadCoefficients c;
  c.CF_V = 0.0;
  c.CF_H = 0.3;
  c.CM_CG = 0.02;
  EXPECT_FALSE(zmpEpsilon(c, 0.0, 0.0).has_value());   // exactly zero: never inf or NaN
  c.CF_V = 0.01;
  EXPECT_FALSE(zmpEpsilon(c, 0.0, 0.05).has_value());  // below the threshold
  ASSERT_TRUE(zmpEpsilon(c, 0.0, 0.005).has_value());
  EXPECT_NEAR(*zmpEpsilon(c, 0.0, 0.005), -2.0, kTol);
  c.CF_V = std::nan("");
  EXPECT_FALSE(zmpEpsilon(c, 0.0, 0.0).has_value());
}

TEST(AnalysisZeroMomentPoint, StrokesFollowTheFlapAngle) {
  // delta_M = A sin(2 pi f t): up for phase in [0, 0.25) and [0.75, 1), down in [0.25, 0.75).
  const double A = 30.0 * kDegToRad, f = 12.0;
  const int n = 100;
  int down = 0;
  for (int i = 0; i < n; ++i) {
    const FlapState st = flapStateAt(A, f, i / (f * n));
    const Stroke s = strokeOf(st.delta_rad, st.delta_dot_radps, 1e-9 * A * 2 * kPi * f);
    const bool expect_down = i >= 25 && i < 75;
    EXPECT_EQ(s == Stroke::kDown, expect_down) << "sample " << i;
    down += s == Stroke::kDown;
  }
  EXPECT_EQ(down, 50);
  EXPECT_STREQ(toString(Stroke::kDown), "down");
  EXPECT_STREQ(toString(Stroke::kUp), "up");
}

/// One synthetic cycle of n samples: flap angle as flapping.hpp, loads from `make(phase, stroke)`.
template <class Make>
ConstrainedFlightTest syntheticCycle(int n, const CoefficientReference& ref, Make make,
                                     const ZmpOptions& options = {}) {
  const double A = 33.06 * kDegToRad, f = 12.0;
  std::vector<double> t, d, dd;
  std::vector<LoadSample> l;
  for (int i = 0; i < n; ++i) {
    const double ti = 5.0 / f + i / (f * n);  // cycle 6 (t0 = 5 T)
    const FlapState st = flapStateAt(A, f, ti);
    t.push_back(ti);
    d.push_back(st.delta_rad);
    dd.push_back(st.delta_dot_radps);
    l.push_back(make(static_cast<double>(i) / n, 4 * i >= n && 4 * i < 3 * n));  // downstroke
  }
  return analyseConstrainedFlightTest(t, d, dd, l, ref, options);
}

TEST(AnalysisZeroMomentPoint, StrokeMetricsOfPiecewiseConstantLoads) {
  // Downstroke: C_F,V 0.6, C_M 0.03 -> epsilon -0.05; upstroke: C_F,V 0.2, C_M -0.04 -> 0.2.
  const CoefficientReference ref = handReference(0.0);
  const double qS = ref.dynamic_pressure_Pa * ref.wing_area_m2, qSc = qS * ref.mean_chord_m;
  const ConstrainedFlightTest r = syntheticCycle(100, ref, [&](double, bool down) {
    return down ? loads(0.6 * qS, 0.0, 0.03 * qSc) : loads(0.2 * qS, 0.0, -0.04 * qSc);
  });
  ASSERT_EQ(r.samples.size(), 100u);
  EXPECT_EQ(r.downstroke.samples, 50);
  EXPECT_EQ(r.upstroke.samples, 50);
  EXPECT_NEAR(r.denominator_max_abs, 0.6, kTol);
  EXPECT_NEAR(r.singular_threshold, 0.06, kTol);
  EXPECT_EQ(r.cycle.defined_samples, 100);
  EXPECT_NEAR(*r.downstroke.weighted_mean, -0.05, kTol);
  EXPECT_NEAR(*r.downstroke.of_mean_loads, -0.05, kTol);
  EXPECT_NEAR(*r.downstroke.min, -0.05, kTol);
  EXPECT_NEAR(*r.downstroke.max, -0.05, kTol);
  EXPECT_NEAR(*r.upstroke.weighted_mean, 0.2, kTol);
  EXPECT_NEAR(*r.upstroke.of_mean_loads, 0.2, kTol);
  // Whole cycle: weighted (0.6 * -0.05 + 0.2 * 0.2) / 0.8 = 0.0125; mean loads
  // -(0.03 - 0.04) / 2 / ((0.6 + 0.2) / 2) = 0.0125 as well (C_M constant per stroke).
  EXPECT_NEAR(*r.cycle.weighted_mean, 0.0125, kTol);
  EXPECT_NEAR(*r.cycle.of_mean_loads, 0.0125, kTol);
  EXPECT_NEAR(*r.cycle.min, -0.05, kTol);
  EXPECT_NEAR(*r.cycle.max, 0.2, kTol);
  EXPECT_NEAR(r.CF_V.mean, 0.4, kTol);
  EXPECT_NEAR(r.CF_V.min, 0.2, kTol);
  EXPECT_NEAR(r.CF_V.max, 0.6, kTol);
  EXPECT_NEAR(r.CF_V.amplitude, 0.2, kTol);
  EXPECT_NEAR(r.CM_CG.mean, -0.005, kTol);
  EXPECT_NEAR(r.CF_H.amplitude, 0.0, kTol);
}

TEST(AnalysisZeroMomentPoint, SingularPointsOfASinusoidalNormalForce) {
  // C_F,V = 0.5 sin(2 pi phase) crosses zero at phase 0 and 0.5; C_M = 0.1: epsilon is undefined
  // where |sin| < singular_fraction, and never NaN or infinite.
  const CoefficientReference ref = handReference(0.0);
  const double qS = ref.dynamic_pressure_Pa * ref.wing_area_m2, qSc = qS * ref.mean_chord_m;
  ZmpOptions options;
  options.singular_fraction = 0.2;
  const ConstrainedFlightTest r = syntheticCycle(
      100, ref,
      [&](double phase, bool) {
        return loads(0.5 * std::sin(2 * kPi * phase) * qS, 0.0, 0.1 * qSc);
      },
      options);
  EXPECT_NEAR(r.denominator_max_abs, 0.5, kTol);
  EXPECT_NEAR(r.singular_threshold, 0.1, kTol);
  int undefined = 0;
  for (std::size_t i = 0; i < r.samples.size(); ++i) {
    const ZmpSample& s = r.samples[i];
    const bool singular = std::abs(std::sin(2 * kPi * i / 100.0)) < 0.2;
    EXPECT_EQ(s.epsilon.has_value(), !singular) << "sample " << i;
    if (s.epsilon) {
      EXPECT_TRUE(std::isfinite(*s.epsilon));
      EXPECT_NEAR(*s.epsilon, -0.1 / (0.5 * std::sin(2 * kPi * i / 100.0)), 1e-9);
      EXPECT_LE(std::abs(*s.epsilon), 0.1 / 0.1 + kTol);
    }
    undefined += !s.epsilon;
  }
  // |sin(2 pi i / 100)| < 0.2 for i in {0..3, 47..53, 97..99}: 14 samples.
  EXPECT_EQ(undefined, 14);
  EXPECT_EQ(r.cycle.defined_samples, 86);
  // Mean normal force 0 < threshold: the epsilon of the mean loads is undefined.
  EXPECT_FALSE(r.cycle.of_mean_loads.has_value());
  // Upstroke (phase < 0.25 or >= 0.75): weighted mean -sum C_M sign(D) / sum |D| over the defined
  // samples: 21 with D > 0 (i = 4..24), 22 with D < 0 (i = 75..96).
  double sum_abs = 0.0;
  for (int i : {4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 75,
                76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96})
    sum_abs += std::abs(0.5 * std::sin(2 * kPi * i / 100.0));
  EXPECT_EQ(r.upstroke.defined_samples, 43);
  ASSERT_TRUE(r.upstroke.weighted_mean.has_value());
  EXPECT_NEAR(*r.upstroke.weighted_mean, -0.1 * (21 - 22) / sum_abs, 1e-12);
}

TEST(AnalysisZeroMomentPoint, RejectsBadInput) {
  const CoefficientReference ref = handReference(0.0);
  const std::vector<double> one = {0.0};
  const std::vector<LoadSample> l = {loads(1, 0, 0)};
  EXPECT_THROW(analyseConstrainedFlightTest({}, {}, {}, {}, ref), std::invalid_argument);
  EXPECT_THROW(analyseConstrainedFlightTest(one, one, {}, l, ref), std::invalid_argument);
  CoefficientReference zero = ref;
  zero.mean_chord_m = 0.0;
  EXPECT_THROW(analyseConstrainedFlightTest(one, one, one, l, zero), std::invalid_argument);
  ZmpOptions bad;
  bad.singular_fraction = 1.0;
  std::string why;
  EXPECT_FALSE(bad.IsValid(&why));
  EXPECT_NE(why.find("singular_fraction"), std::string::npos);
  EXPECT_THROW(analyseConstrainedFlightTest(one, one, one, l, ref, bad), std::invalid_argument);
  // All loads zero: every epsilon undefined, metrics empty, nothing NaN.
  const ConstrainedFlightTest r =
      analyseConstrainedFlightTest(one, one, one, {loads(0, 0, 0)}, ref);
  EXPECT_FALSE(r.samples[0].epsilon.has_value());
  EXPECT_FALSE(r.cycle.weighted_mean.has_value());
  EXPECT_FALSE(r.cycle.of_mean_loads.has_value());
  EXPECT_FALSE(r.cycle.min.has_value());
}

// The test of a tethered history's last cycle: the last spc samples before the endpoint, the flap
// rate of the vehicle's flapping at the point's frequency; no test without one whole cycle.
TEST(AnalysisZeroMomentPoint, LastCycleOfATetheredHistory) {
  const FlightCoreModel model(testing::rfwRig());
  const OperatingPoint point{6.0, 4.0, 20.0 * kDegToRad, 0.0};
  const int spc = 8;
  const double T = 1.0 / point.freq_hz;
  TimeHistory h;
  for (int i = 0; i <= 2 * spc; ++i) {  // two cycles and the endpoint
    const double t = i * T / spc;
    h.t_s.push_back(t);
    h.delta_M_rad.push_back(flapStateAt(model.vehicle.flapping.amplitude_rad, point.freq_hz, t).delta_rad);
    h.loads.push_back(loads(1.0 + i, 0.1, 0.01 * i));  // FV tells which sample it is
  }
  const std::optional<ConstrainedFlightTest> r =
      lastCycleConstrainedFlightTest(model, point, h, spc);
  ASSERT_TRUE(r.has_value());
  ASSERT_EQ(r->samples.size(), static_cast<std::size_t>(spc));
  const CoefficientReference ref = coefficientReference(model, point);
  const double qS = ref.dynamic_pressure_Pa * ref.wing_area_m2;
  EXPECT_NEAR(r->CF_V.min, (1.0 + spc) / qS, kTol);          // sample spc starts the last cycle
  EXPECT_NEAR(r->CF_V.max, (1.0 + 2 * spc - 1) / qS, kTol);  // the endpoint is excluded
  EXPECT_EQ(r->reference.theta_mean_rad, point.theta_rad);

  TimeHistory short_one = h;  // less than one whole cycle and its endpoint
  short_one.t_s.resize(spc);
  short_one.delta_M_rad.resize(spc);
  short_one.loads.resize(spc);
  EXPECT_FALSE(lastCycleConstrainedFlightTest(model, point, short_one, spc).has_value());
  EXPECT_FALSE(lastCycleConstrainedFlightTest(model, point, h, 0).has_value());
  TimeHistory torn = h;  // not a whole number of cycles
  torn.t_s.pop_back();
  torn.delta_M_rad.pop_back();
  torn.loads.pop_back();
  EXPECT_FALSE(lastCycleConstrainedFlightTest(model, point, torn, spc).has_value());
}

}  // namespace
}  // namespace orni
