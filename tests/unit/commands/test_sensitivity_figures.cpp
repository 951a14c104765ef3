// The figures of a sensitivity study (plotting/sensitivity_figures.hpp) on a hand-made ranking:
// the tornado draws an element only for what has a point (gnuplot 5.4 fails on a plot element
// without a valid point and crashes on such a `with labels` beside others), labels each parameter
// with its range and says which end has no value; tornado.csv has one row per prediction and
// parameter in rank order.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "studies/runner/plotting/sensitivity_figures.hpp"

namespace orni::studies {
namespace {

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

Study twoParameters() {
  Study s;
  s.name = "demo";
  s.kind = StudyKind::kSensitivity;
  s.settings.emplace<SensitivitySettings>().parameters = {
      {"body.pitch_inertia_kgm2", 4e-5, 3.2e-4, 3e-4},
      {"aero.suction_efficiency", 0.5, 1.0, std::numeric_limits<double>::quiet_NaN()}};
  return s;
}

/// theta: parameter 1 moves it both ways (swing 2), parameter 0 has no value at high.
std::vector<PredictionRanking> ranking() {
  PredictionRanking p;
  p.column = 0;  // theta_mean_deg
  p.base = 9.0;
  SensitivityEffect a;
  a.parameter = 1;
  a.low_value = 8.0;
  a.high_value = 10.0;
  a.delta_low = -1.0;
  a.delta_high = 1.0;
  a.swing = 2.0;
  a.swing_share = 1.0;
  SensitivityEffect b;
  b.parameter = 0;
  b.low_value = 9.5;
  b.delta_low = 0.5;
  p.ranked = {a, b};
  return {p};
}

TEST(CommandsSensitivityFigures, LabelsAndOnlyElementsWithPoints) {
  EXPECT_EQ(parameterLabel(twoParameters().sensitivity().parameters[0]),
            "body.pitch_inertia_kgm2: 4e-05 .. 0.00032 kg m^2 (base 3e-04)");
  EXPECT_EQ(parameterLabel(twoParameters().sensitivity().parameters[1]),
            "aero.suction_efficiency: 0.5 .. 1");
  EXPECT_EQ(tornadoStem(ranking()[0]), "tornado_theta_mean_deg");

  const std::string g = tornadoFigure(twoParameters(), ranking(), 0);
  SCOPED_TRACE(g);
  // Rank 1 (top, y = 2) is the suction efficiency; rank 2 says its high end has no value, with a
  // line break gnuplot reads in a double-quoted string (one backslash).
  EXPECT_NE(g.find("\"aero.suction_efficiency: 0.5 .. 1\" 2"), std::string::npos);
  EXPECT_NE(g.find("(base 3e-04)\\nno value at high: see sensitivity.csv\" 1"), std::string::npos);
  EXPECT_EQ(g.find("\\\\"), std::string::npos);
  // Bars for both ends; value labels: negative and positive low deltas, a positive high delta,
  // none for negative high deltas (there is none).
  EXPECT_EQ(count(g, "with boxxyerror"), 2u);
  EXPECT_EQ(count(g, "with labels right"), 1u);
  EXPECT_EQ(count(g, "with labels left"), 2u);
  EXPECT_NE(g.find("every ::0::1 "), std::string::npos);  // the rows of prediction 0

  // Nothing to draw without deltas.
  std::vector<PredictionRanking> empty = ranking();
  for (SensitivityEffect& e : empty[0].ranked) e.delta_low = e.delta_high = std::nullopt;
  EXPECT_TRUE(tornadoFigure(twoParameters(), empty, 0).empty());
  for (SensitivityEffect& e : empty[0].ranked) e.swing_share = std::nullopt;
  EXPECT_TRUE(overviewFigure(twoParameters(), empty).empty());
  EXPECT_FALSE(overviewFigure(twoParameters(), ranking()).empty());
}

TEST(CommandsSensitivityFigures, TornadoTableRowsInRankOrder) {
  const std::string csv = tornadoTable(twoParameters(), ranking()).toString();
  EXPECT_EQ(csv,
            "prediction,prediction_unit,prediction_index,rank,parameter,parameter_index,label,base,"
            "low_value,high_value,delta_low,delta_high,swing,swing_share\n"
            "-,-,-,-,-,-,-,prediction_unit,prediction_unit,prediction_unit,prediction_unit,"
            "prediction_unit,prediction_unit,-\n"
            "theta_mean_deg,deg,1,1,aero.suction_efficiency,2,aero.suction_efficiency: 0.5 .. 1,9,"
            "8,10,-1,1,2,1\n"
            "theta_mean_deg,deg,1,2,body.pitch_inertia_kgm2,1,body.pitch_inertia_kgm2: 4e-05 .. "
            "0.00032 kg m^2 (base 3e-04),9,9.5,,0.5,,,\n");
}

}  // namespace
}  // namespace orni::studies
