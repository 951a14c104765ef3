#include "studies/runner/plotting/trim_figures.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "core/model/frames.hpp"
#include "studies/runner/config/continuation_section.hpp"
#include "studies/runner/output/atomic_file.hpp"

namespace orni::studies {

// Residual norm per iteration (log scale) with every residual run, and the unknowns per iteration.
std::string trimConvergenceFigure(const Study& study, const TrimSummary& s, double tol) {
  int last = 0;
  for (const TrimEvaluationRecord& e : s.evaluation_log) last = std::max(last, e.iteration);
  // Stage 2 (free-flight refinement) moves the trim point after the last Eq. (4) iteration: shown
  // as open circles at x = last + 1 in the lower panel, so the figure ends at the reported point.
  const bool refined = s.refined_in_free_flight && s.converged;
  const double x2 = last + 1.0;
  std::ostringstream g;
  g << "set multiplot layout 2,1 title \"" << study.name << " trim (" << toString(s.status)
    << "), stage 1: paper Eq. (4) on tethered cycle means, max(|FV-W|, |FH|, |M|/c_mean) / W"
    << (refined ? "\\nstage 2: level settled free flight moves the trim point (open circles)"
                : "")
    << "\" noenhanced font ',13'\n";
  g << "set lmargin 12\nset rmargin 44\nset tmargin 4\n"
       "set key outside right top vertical Left reverse noenhanced\n";
  g << "set xrange [-0.2:" << last + 0.2 << "]\nset xlabel 'iteration'\nset xtics 1\n";
  g << "set logscale y\nset format y '10^{%L}'\nset ylabel 'scaled residual (-)'\n";
  double ymin = 0.1 * tol;
  for (const TrimIterationRecord& r : s.iteration_log)
    if (r.scaled_max > 0.0) ymin = std::min(ymin, 0.3 * r.scaled_max);
  g << "set yrange [" << ymin << ":*]\n";
  g << "plot 'trim_progress.csv' skip 2 using 1:8 with linespoints lw 2 pt 7 lc rgb '#c0392b' "
       "title 'accepted iterate', "
       "'trim_iterations.csv' skip 2 using ($3 == 0 && $4 == 1 ? $2 : 1/0):16 with points pt 6 "
       "ps 1.2 lc rgb '#2471a3' title 'residual runs (trial points)', "
    << tol << " with lines dt 2 lc rgb '#333333' title 'tolerance'\n";
  g << "unset logscale y\nset format y '%g'\nset yrange [*:*]\n";
  g << "set ylabel 'unknowns (deg, m/s, Hz)'\n";
  if (refined) {
    g << "set xrange [-0.2:" << x2 + 0.3 << "]\nset xtics add ('stage 2' " << x2 << ")\n";
    g << "set xlabel 'iteration (stage 1) / free-flight refinement (stage 2)'\n";
  }
  const char* kColours[3] = {"#9400d3", "#009e73", "#56b4e9"};  // gnuplot's first three
  g << "plot 'trim_progress.csv' skip 2 using 1:3 with linespoints lw 2 pt 7 lc rgb '"
    << kColours[0]
    << "' title 'theta mean (deg)', '' skip 2 using 1:4 with linespoints lw 2 pt 5 lc rgb '"
    << kColours[1]
    << "' title 'speed (m/s)', '' skip 2 using 1:5 with linespoints lw 2 pt 9 lc rgb '"
    << kColours[2]
    << "' title 'tail angle (deg)', '' skip 2 using 1:6 with linespoints lw 2 pt 11 "
       "lc rgb '#e69f00' title 'frequency (Hz)'";
  if (refined) {
    const double v[3] = {s.solution.theta_rad * kRadToDeg, s.solution.speed_mps,
                         s.solution.tail_angle_rad * kRadToDeg};
    const char* names[3] = {"theta", "U", "tail"};
    for (int k = 0; k < 3; ++k)
      g << ", '-' using 1:2 with points pt 6 ps 2.5 lw 2 lc rgb '" << kColours[k]
        << "' title 'stage 2: " << names[k] << " = " << formatFixed(v[k], 2) << "'";
    g << "\n";
    for (int k = 0; k < 3; ++k) g << x2 << "," << formatShortest(v[k]) << "\ne\n";
  }
  g << "\n";
  g << "unset multiplot\n";
  return g.str();
}

// The multipliers in the complex plane with the unit circle: the whole disc, and a zoom on the
// leading multiplier (near the circle on a weakly damped vehicle).
std::string floquetMultiplierFigure(const Study& study, const PeriodicTrimSummary& s) {
  const FloquetAnalysis& f = s.floquet;
  const FloquetMultiplier& lead = f.multipliers.front();
  std::ostringstream g;
  g << "set multiplot layout 1,2 title \"" << study.name << ": Floquet multipliers of the periodic "
    << "orbit at " << formatFixed(s.solution.freq_hz, 2) << " Hz, "
    << (f.stable ? "stable" : "UNSTABLE")
    << ", max |mu| = " << formatFixed(f.max_modulus, 5) << " (" << lead.label << ")\\n"
    << (f.complete ? "all " : "the leading ") << f.multipliers.size() << " of " << f.state_count
    << " multipliers; altitude and position (ignorable) excluded\" noenhanced font ',12'\n";
  g << "set size ratio -1\nset grid\nset key bottom left noenhanced\n";
  g << "set xlabel 'Re {/Symbol m}'\nset ylabel 'Im {/Symbol m}'\n";
  g << "set parametric\nset trange [0:2*pi]\nset samples 400\n";
  g << "set xrange [-1.2:1.2]\nset yrange [-1.2:1.2]\n";
  if (f.checked) {  // resolved filled, the others open (column 14 of floquet.csv: resolved)
    g << "plot cos(t), sin(t) with lines lw 2 lc rgb '#555555' title 'unit circle', "
         "'floquet.csv' skip 2 using 2:(strcol(14) eq '1' ? $3 : 1/0) with points pt 7 ps 1.3 "
         "lc rgb '#c0392b' title 'resolved', "
         "'' skip 2 using 2:(strcol(14) eq '1' ? 1/0 : $3) with points pt 6 ps 1.3 "
         "lc rgb '#c0392b' title 'not resolved'\n";
  } else {
    g << "plot cos(t), sin(t) with lines lw 2 lc rgb '#555555' title 'unit circle', "
         "'floquet.csv' skip 2 using 2:3 with points pt 7 ps 1.3 lc rgb '#c0392b' "
         "title 'multipliers'\n";
  }
  // Zoom: a square on the real axis holding the leading multiplier (and its conjugate) and the
  // circle's nearest point.
  const double half = std::max(0.02, 1.5 * std::max(std::abs(lead.mu.imag()),
                                                     std::abs(1.0 - lead.modulus)));
  const double cx = lead.mu.real() >= 0.0 ? std::max(lead.mu.real(), 1.0 - half)
                                          : std::min(lead.mu.real(), -1.0 + half);
  const double cy = 0.0;
  g << "set xrange [" << cx - half << ":" << cx + half << "]\nset yrange [" << cy - half << ":"
    << cy + half << "]\n";
  g << "set title 'zoom on the leading multiplier' noenhanced\n";
  g << "set label 1 '" << lead.label << "' at first " << lead.mu.real() << ", first "
    << std::abs(lead.mu.imag()) << " offset 1,1 noenhanced\n";
  g << "plot cos(t), sin(t) with lines lw 2 lc rgb '#555555' title 'unit circle', "
       "'floquet.csv' skip 2 using 2:3 with points pt 7 ps 1.5 lc rgb '#c0392b' "
       "title 'multipliers'\n";
  g << "unset multiplot\n";
  return g.str();
}

// theta, airspeed, W and altitude over one period of the orbit.
std::string periodicOrbitFigure(const Study& study, const PeriodicTrimSummary& s) {
  std::ostringstream g;
  g << "set multiplot layout 2,2 title \"" << study.name << ": periodic orbit at "
    << formatFixed(s.solution.freq_hz, 2) << " Hz (tail "
    << formatFixed(s.solution.tail_angle_rad * kRadToDeg, 3)
    << " deg), one flapping period from phase 0\" noenhanced font ',12'\n";
  g << "set grid\nset key off\nset xlabel 'phase t/T (-)'\nset xrange [0:1]\n";
  g << "set ylabel 'theta (deg)'\nplot 'periodic_orbit.csv' skip 2 using 2:4 with lines lw 2\n";
  g << "set ylabel 'airspeed (m/s)'\nplot 'periodic_orbit.csv' skip 2 using 2:8 with lines lw 2\n";
  g << "set ylabel 'W (m/s)'\nplot 'periodic_orbit.csv' skip 2 using 2:6 with lines lw 2\n";
  g << "set ylabel 'altitude gain h (m)'\nplot 'periodic_orbit.csv' skip 2 using 2:10 with lines "
       "lw 2\n";
  g << "unset multiplot\n";
  return g.str();
}

std::string continuationBranchFigure(const Study& study, PeriodicControl parameter,
                                     const std::string& parameter_unit, PeriodicControl control,
                                     const std::string& status) {
  const std::string x = std::string(continuationParameterName(parameter)) + " (" +
                        parameter_unit + ")";
  // Columns of continuation.csv: 2 parameter, 4 theta, 5 speed, 6 tail, 3 freq, 7 cg, 8 power,
  // 9 max |mu|, 10 stable, 19 event (text; events are rows whose point repeats the next one).
  const int control_col = control == PeriodicControl::kTailAngle   ? 6
                          : control == PeriodicControl::kFrequency ? 3
                                                                   : 7;
  const std::string control_label = control == PeriodicControl::kTailAngle ? "tail angle (deg)"
                                    : control == PeriodicControl::kFrequency
                                        ? "frequency (Hz)"
                                        : "CG shift (m)";
  std::ostringstream g;
  g << "set multiplot layout 2,2 title \"" << study.name << ": trimmed flight over "
    << continuationParameterName(parameter) << " (" << status
    << "); solid stable, dashed unstable, circles events\" noenhanced font ',12'\n";
  g << "set grid\nset key off\nset xlabel '" << x << "' noenhanced\n";
  auto panel = [&](int col, const std::string& ylabel) {
    g << "set ylabel '" << ylabel << "' noenhanced\n";
    g << "plot 'continuation.csv' skip 2 using 2:($10 == 1 ? $" << col
      << " : NaN) with lines lw 2 lc rgb '#1f77b4', "
      << "'' skip 2 using 2:($10 == 0 ? $" << col
      << " : NaN) with lines lw 2 dt 2 lc rgb '#d62728', "
      << "'' skip 2 using 2:(strcol(19) ne '' ? $" << col
      << " : NaN) with points pt 6 ps 2 lw 2 lc rgb 'black'\n";
  };
  panel(control_col, "control: " + control_label);
  panel(4, "cycle-mean theta (deg)");
  panel(5, "mean airspeed (m/s)");
  g << "set ylabel 'max |mu| (1 = stability limit)'\n";
  g << "plot 'continuation.csv' skip 2 using 2:9 with linespoints lw 2 pt 7 ps 0.6 lc rgb "
       "'#2ca02c', 1 with lines dt 3 lc rgb '#555555'\n";
  g << "unset multiplot\n";
  return g.str();
}

}  // namespace orni::studies
