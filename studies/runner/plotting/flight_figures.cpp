#include "studies/runner/plotting/flight_figures.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/model/frames.hpp"
#include "studies/runner/plotting/figure_rows.hpp"

namespace orni::studies {

namespace {

std::string freeFlightTitle(const Study& study) {
  std::ostringstream s;
  s << study.name << " (free flight): U0 = " << study.point.speed_mps
    << " m/s, f = " << study.point.freq_hz << " Hz, theta0 = "
    << study.point.theta_rad * kRadToDeg << " deg, tail = "
    << study.point.tail_angle_rad * kRadToDeg << " deg";
  return s.str();
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

// Paper Fig. 7 layout: delta_M, theta and h against time (left) and their spectra (right).
std::string freeFlightFigure(const Study& study, bool with_spectra, const std::string& skip) {
  std::ostringstream g;
  g << "set multiplot layout 3," << (with_spectra ? 2 : 1) << " columnsfirst title \""
    << freeFlightTitle(study) << "\" noenhanced font ',12'\n";
  g << "set key off\nset grid\nset xlabel 'time (s)'\n";
  g << "set ylabel '{/Symbol d}_M (deg)'\nplot 'histories.csv' " << skip
    << " using 1:2 with lines lc rgb '#333333'\n";
  g << "set ylabel '{/Symbol q} (deg)'\nplot 'histories.csv' " << skip
    << " using 1:5 with lines lc rgb '#c0392b'\n";
  g << "set ylabel 'h (m)'\nplot 'histories.csv' " << skip
    << " using 1:4 with lines lc rgb '#2471a3'\n";
  if (with_spectra) {
    g << "set xlabel 'f (Hz)'\n";
    g << "set ylabel '|{/Symbol d}_M(f)| (deg)'\nplot 'spectra.csv' skip 2 using 1:2 with "
         "impulses lw 2 lc rgb '#333333'\n";
    g << "set ylabel '|{/Symbol q}(f)| (deg)'\nplot 'spectra.csv' skip 2 using 1:3 with impulses "
         "lw 2 lc rgb '#c0392b'\n";
    g << "set logscale y\nset yrange [1e-5:1]\nset format y '10^{%L}'\nset ylabel '|h(f)| "
         "(m)'\nplot 'spectra.csv' "
         "skip 2 using 1:($4 > 0 ? $4 : 1/0) with impulses lw 2 lc rgb '#2471a3'\n";
  }
  g << "unset multiplot\n";
  return g.str();
}

// Paper Fig. 6: the last flapping cycle, delta_M and theta, downstroke shaded.
std::string freeFlightCycleFigure(const Study& study, int cycles, const std::string& skip) {
  const double T = 1.0 / study.point.freq_hz;
  std::ostringstream g;
  g << "set multiplot layout 2,1 title \"" << freeFlightTitle(study) << ", cycle " << cycles
    << " (shaded: downstroke)\" noenhanced font ',12'\n";
  g << "set key off\nset grid\nset xrange [" << (cycles - 1) * T << ":" << cycles * T << "]\n";
  g << "set object 1 rect from " << (cycles - 0.75) * T << ", graph 0 to " << (cycles - 0.25) * T
    << ", graph 1 behind fc rgb '#e8e8f0' fs solid noborder\n";
  g << "set ylabel '{/Symbol d}_M (deg)'\nplot 'histories.csv' " << skip
    << " using 1:2 with lines lw 2 lc rgb '#333333'\n";
  g << "set xlabel 'time (s)'\nset ylabel '{/Symbol q} (deg)'\nplot 'histories.csv' " << skip
    << " using 1:5 with lines lw 2 lc rgb '#c0392b'\n";
  g << "unset multiplot\n";
  return g.str();
}

// Paper Fig. 8: pitch phase portrait (theta, Q) after the transient.
std::string freeFlightPhaseFigure(const Study& study, double t_from, const std::string& skip) {
  std::ostringstream g;
  g << "set title \"" << freeFlightTitle(study) << "\" noenhanced font ',12'\n";
  g << "set key off\nset grid\nset xlabel '{/Symbol q} (deg)'\nset ylabel 'Q (deg/s)'\n";
  g << "plot 'histories.csv' " << skip << " using ($1 >= " << t_from
    << " ? $5 : 1/0):8 with lines lc rgb '#8e44ad'\n";
  return g.str();
}

// Figure in the layout of paper Fig. 2: delta_M, FV, FH and M against time over the last (at most
// three) cycles, i.e. the periodic steady state, with the downstrokes shaded.
// A long history is read from the first shown row on (figure_rows.hpp).
std::string tetheredLoadsFigure(const Study& study, const SimulationSummary& s, std::size_t rows) {
  const double T = 1.0 / study.point.freq_hz;
  const int shown = std::min(3, s.cycles_run);
  const int first = s.cycles_run - shown;
  const std::size_t spc = static_cast<std::size_t>(study.simulate().options.samples_per_cycle);
  const std::size_t every = static_cast<std::size_t>(study.simulate().history_every);
  const std::string skip =
      "skip 2" + figureEvery(rows, historyRowOf(static_cast<std::size_t>(first) * spc, every),
                             historyRowsPerCycle(spc, every));
  std::ostringstream g;
  g << "set multiplot layout 4,1 title \"" << study.name << " (tethered): U = "
    << study.point.speed_mps << " m/s, f = " << study.point.freq_hz
    << " Hz, theta = " << study.point.theta_rad * kRadToDeg << " deg, cycles " << first + 1
    << "-" << s.cycles_run << " of " << s.cycles_run
    << " (shaded: downstroke)\" noenhanced font ',13'\n";
  g << "set lmargin 12\nset rmargin 22\nset key outside right top vertical Left reverse\n";
  g << "set xrange [" << first * T << ":" << s.cycles_run * T << "]\n";
  for (int k = first; k < s.cycles_run; ++k)
    g << "set object " << k + 1 << " rect from " << (k + 0.25) * T << ", graph 0 to "
      << (k + 0.75) * T << ", graph 1 behind fc rgb '#e8e8f0' fs solid noborder\n";
  g << "set format x ''\n";
  // One curve: 'histories.csv' (or '' for the file of the curve before) with its rows.
  auto curve = [&](const char* file, int column, const char* style) {
    g << file << " " << skip << " using 1:" << column << " with lines " << style;
  };
  g << "set ylabel '{/Symbol d}_M (deg)'\nplot ";
  curve("'histories.csv'", 2, "lw 2 lc rgb '#333333' title 'flap angle'\n");
  const char* total = "lw 2 lc rgb '#c0392b' title 'total', ";
  const char* aero = "dt 2 lw 1.5 lc rgb '#2471a3' title 'wing aero', ";
  const char* inertia = "dt 3 lw 1.5 lc rgb '#27ae60' title 'wing inertia'\n";
  const struct {
    const char* label;
    int total, aero, inertia;
  } panels[] = {{"F_V (N)", 3, 8, 11}, {"F_H (N)", 4, 9, 12}, {"M_{CG} (N m)", 5, 10, 13}};
  for (const auto& p : panels) {
    if (p.total == 5) g << "set format x '%g'\nset xlabel 'time (s)'\n";
    g << "set ylabel '" << p.label << "'\nplot ";
    curve("'histories.csv'", p.total, total);
    curve("''", p.aero, aero);
    curve("''", p.inertia, inertia);
  }
  g << "unset multiplot\n";
  return g.str();
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
