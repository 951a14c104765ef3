#include "studies/runner/commands/constrained_flight_output.hpp"

#include <cmath>
#include <limits>
#include <optional>
#include <sstream>

#include "core/dynamics/flapping.hpp"
#include "core/model/frames.hpp"
#include "studies/runner/output/atomic_file.hpp"

namespace orni::studies {

namespace {

std::string cell(double v) { return std::isfinite(v) ? formatShortest(v) : std::string(); }

template <typename Getter>
std::vector<std::string> cells(const ConstrainedFlightTest& test, Getter get) {
  std::vector<std::string> c;
  c.reserve(test.samples.size());
  for (const ZmpSample& s : test.samples) c.push_back(get(s));
  return c;
}

/// NaN (written as null by JsonObject) for an undefined value.
double orNull(const std::optional<double>& v) {
  return v ? *v : std::numeric_limits<double>::quiet_NaN();
}

JsonObject statsJson(const ChannelStats& s) {
  return JsonObject()
      .set("mean", s.mean)
      .set("min", s.min)
      .set("max", s.max)
      .set("amplitude", s.amplitude);
}

JsonObject epsilonJson(const EpsilonMetrics& m) {
  return JsonObject()
      .set("samples", m.samples)
      .set("defined_samples", m.defined_samples)
      .set("weighted_mean", orNull(m.weighted_mean))
      .set("of_mean_loads", orNull(m.of_mean_loads))
      .set("min", orNull(m.min))
      .set("max", orNull(m.max));
}

/// A tic step of 1, 2 or 5 times a power of ten giving about four intervals over `span`.
double ticStep(double span) {
  if (!(span > 0.0) || !std::isfinite(span)) return 1.0;
  const double raw = span / 4.0;
  const double decade = std::pow(10.0, std::floor(std::log10(raw)));
  for (const double m : {1.0, 2.0, 5.0})
    if (m * decade >= raw) return m * decade;
  return 10.0 * decade;
}

}  // namespace

std::optional<ConstrainedFlightTest> lastCycleConstrainedFlightTest(
    const Study& study, const FlightCoreModel& model, const TimeHistory& history,
    int samples_per_cycle) {
  const std::size_t spc = static_cast<std::size_t>(samples_per_cycle);
  const std::size_t size = history.loads.size();
  if (spc == 0 || size < spc + 1 || (size - 1) % spc != 0) return std::nullopt;
  const std::size_t start = size - 1 - spc;
  std::vector<double> t(history.t_s.begin() + static_cast<std::ptrdiff_t>(start),
                        history.t_s.end() - 1);
  std::vector<double> delta(history.delta_M_rad.begin() + static_cast<std::ptrdiff_t>(start),
                            history.delta_M_rad.end() - 1);
  std::vector<LoadSample> loads(history.loads.begin() + static_cast<std::ptrdiff_t>(start),
                                history.loads.end() - 1);
  std::vector<double> delta_dot;
  delta_dot.reserve(t.size());
  for (const double ti : t)
    delta_dot.push_back(
        flapStateAt(model.vehicle.flapping.amplitude_rad, study.point.freq_hz, ti).delta_dot_radps);
  return analyseConstrainedFlightTest(t, delta, delta_dot, loads,
                                      coefficientReference(model, study.point));
}

CsvTable zmpTable(const ConstrainedFlightTest& test) {
  CsvTable t("zmp.csv");
  t.addTextColumn("t", cells(test, [](const ZmpSample& s) { return cell(s.t_s); }));
  t.addTextColumn("delta_M",
                  cells(test, [](const ZmpSample& s) { return cell(s.delta_rad * kRadToDeg); }));
  t.addTextColumn("stroke",
                  cells(test, [](const ZmpSample& s) { return std::string(toString(s.stroke)); }));
  t.addTextColumn("CF_V",
                  cells(test, [](const ZmpSample& s) { return cell(s.coefficients.CF_V); }));
  t.addTextColumn("CF_H",
                  cells(test, [](const ZmpSample& s) { return cell(s.coefficients.CF_H); }));
  t.addTextColumn("CM_CG",
                  cells(test, [](const ZmpSample& s) { return cell(s.coefficients.CM_CG); }));
  t.addTextColumn("epsilon", cells(test, [](const ZmpSample& s) {
                    return s.epsilon ? cell(*s.epsilon) : std::string();
                  }));
  t.addTextColumn("CF_normal", cells(test, [](const ZmpSample& s) { return cell(s.denominator); }));
  return t;
}

JsonObject zmpSummary(const ConstrainedFlightTest& test) {
  const CoefficientReference& r = test.reference;
  return JsonObject()
      .set("cycle_samples", static_cast<int>(test.samples.size()))
      .set("reference", JsonObject()
                            .set("dynamic_pressure_Pa", r.dynamic_pressure_Pa)
                            .set("wing_area_m2", r.wing_area_m2)
                            .set("mean_chord_m", r.mean_chord_m)
                            .set("theta_mean_deg", r.theta_mean_rad * kRadToDeg))
      .set("CF_V", statsJson(test.CF_V))
      .set("CF_H", statsJson(test.CF_H))
      .set("CM_CG", statsJson(test.CM_CG))
      .set("epsilon",
           JsonObject()
               .set("definition",
                    "(x_ZMP - x_CG)/c_mean = -CM_CG/(CF_V cos theta - CF_H sin theta), "
                    "> 0: ZMP aft of the CG")
               .set("singular_fraction", test.options.singular_fraction)
               .set("CF_normal_max_abs", test.denominator_max_abs)
               .set("singular_threshold", test.singular_threshold)
               .set("cycle", epsilonJson(test.cycle))
               .set("upstroke", epsilonJson(test.upstroke))
               .set("downstroke", epsilonJson(test.downstroke)));
}

std::string zmpFigureScript(const Study& study, const ConstrainedFlightTest& test, int cycle) {
  using C = ZmpCsvColumns;
  const double T = 1.0 / study.point.freq_hz;
  const double t0 = test.samples.front().t_s;
  const char* kUpColour = "#2471a3";
  const char* kDownColour = "#c0392b";
  std::ostringstream g;
  g << "set multiplot title \"" << study.name
    << " - constrained flight test (tethered): theta = " << study.point.theta_rad * kRadToDeg
    << " deg, f = " << study.point.freq_hz << " Hz, U = " << study.point.speed_mps
    << " m/s";
  if (study.vehicle.tail.present)
    g << ", tail = " << study.point.tail_angle_rad * kRadToDeg << " deg";
  else
    g << ", no tail (rig)";
  g << ", cycle " << cycle
    << "\" noenhanced font ',13'\n";
  g << "set lmargin 13\nset rmargin 12\nset tmargin 0.5\nset bmargin 0.5\n";
  // (a) coefficients against time over the cycle, downstroke shaded.
  g << "set xrange [" << t0 << ":" << t0 + T << "]\n";
  g << "set object 1 rect from " << t0 + 0.25 * T << ", graph 0 to " << t0 + 0.75 * T
    << ", graph 1 behind fc rgb '#e8e8f0' fs solid noborder\n";
  g << "set format x ''\nset size 1,0.18\n";
  g << "set origin 0,0.75\nset ylabel 'C_{F,V} (-)'\nset y2label '{/Symbol d}_M (deg)'\n"
       "set y2tics 20\nset ytics " << ticStep(test.CF_V.max - test.CF_V.min) << " nomirror\n"
       "set key top right box opaque font ',10'\n"
       "plot 'zmp.csv' skip 2 using "
    << C::kT << ":" << C::kCFV
    << " with lines lw 2 lc rgb '#333333' title 'C_{F,V}', '' skip 2 using " << C::kT << ":"
    << C::kDelta
    << " axes x1y2 with lines dt 2 lw 1 lc rgb '#888888' title '{/Symbol d}_M (right axis)'\n";
  g << "unset y2tics\nunset y2label\nset key off\n";
  g << "set origin 0,0.57\nset ytics " << ticStep(test.CF_H.max - test.CF_H.min)
    << " mirror\nset ylabel 'C_{F,H} (-)'\nplot 'zmp.csv' skip 2 using " << C::kT
    << ":" << C::kCFH << " with lines lw 2 lc rgb '#333333'\n";
  g << "set origin 0,0.36\nset size 1,0.21\nset bmargin 3\nset format x '%g'\nset ytics "
    << ticStep(test.CM_CG.max - test.CM_CG.min) << "\n"
       "set xlabel 'time (s); shaded: downstroke' offset 0,0.5\n"
       "set ylabel 'C_{M,CG} (-)'\nplot 'zmp.csv' skip 2 using "
    << C::kT << ":" << C::kCM << " with lines lw 2 lc rgb '#333333'\n";
  // (b) epsilon against delta_M (paper Fig. 9b).
  g << "unset object 1\nset size 1,0.36\nset origin 0,0\nset tmargin 1\nset bmargin 6.5\n"
       "set ytics autofreq\n";
  const double a_deg = study.vehicle.flapping.amplitude_rad * kRadToDeg;
  const double x_lim = 10.0 * std::ceil(a_deg / 10.0 + 1e-9);
  g << "set xrange [" << -x_lim << ":" << x_lim << "]\n"
       "set xlabel '{/Symbol d}_M (deg)' offset 0,0.3\n"
       "set ylabel '{/Symbol e} = (x_{ZMP} - x_{CG}) / c_{MEAN} (-)'\n"
       "set key outside below center horizontal maxrows 2 box font ',10'\n";
  g << "set label 1 'ZMP aft of the CG' at graph 0.01, graph 0.93 left font ',9'\n"
       "set label 2 'ZMP ahead of the CG' at graph 0.01, graph 0.06 left font ',9'\n";
  // Undefined epsilon (empty cells) and the other stroke become 1/0, which breaks the lines (a
  // plain $N would make gnuplot skip the row as missing and draw across the gap).
  g << "set label 3 'gaps: no ZMP where |C_{F,normal}| < " << 100.0 * test.options.singular_fraction
    << " % of its maximum' at graph 0.99, graph 0.06 right font ',9'\n";
  g << "plot 0 with lines lc rgb '#555555' lw 1 title 'static moment equilibrium', "
       "'zmp.csv' skip 2 using "
    << C::kDelta << ":(strcol(" << C::kStroke << ") eq 'up' && strcol(" << C::kEpsilon
    << ") ne '' ? real(strcol(" << C::kEpsilon << ")) : 1/0) with linespoints pt 7 ps 0.5 lw 1.5 "
       "lc rgb '" << kUpColour
    << "' title 'upstroke', '' skip 2 using " << C::kDelta << ":(strcol(" << C::kStroke
    << ") eq 'down' && strcol(" << C::kEpsilon << ") ne '' ? real(strcol(" << C::kEpsilon
    << ")) : 1/0) with linespoints pt 7 ps 0.5 lw 1.5 lc rgb '"
    << kDownColour << "' title 'downstroke'";
  if (test.upstroke.weighted_mean)
    g << ", " << *test.upstroke.weighted_mean << " with lines dt 2 lw 1.5 lc rgb '" << kUpColour
      << "' title 'upstroke mean (|C_{F,normal}|-weighted)'";
  if (test.downstroke.weighted_mean)
    g << ", " << *test.downstroke.weighted_mean << " with lines dt 2 lw 1.5 lc rgb '"
      << kDownColour << "' title 'downstroke mean (|C_{F,normal}|-weighted)'";
  g << "\nunset label 1\nunset label 2\nunset label 3\nunset multiplot\n";
  return g.str();
}

}  // namespace orni::studies
