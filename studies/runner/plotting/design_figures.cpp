#include "studies/runner/plotting/design_figures.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "studies/runner/output/atomic_file.hpp"

namespace orni::studies {

namespace {

using orni::opt::DesignProblem;
using orni::opt::OptimizerSummary;

/// Column numbers (1-based) of history.csv for the figure.
struct HistoryColumns {
  int objective, feasible, failed, violation, best;
};

HistoryColumns historyColumns(const DesignProblem& p) {
  const int n = p.variableCount(), m = p.constraintCount(), k = p.valueCount();
  HistoryColumns c{};
  c.objective = 5 + n;
  c.feasible = c.objective + 1;
  c.failed = c.objective + 2;
  c.violation = c.objective + 3;
  c.best = c.violation + m + 2 + k + 1;
  return c;
}

}  // namespace

std::string optimizeConvergenceFigure(const Study& study, const DesignProblem& p,
                                      const OptimizerSummary& s) {
  const HistoryColumns c = historyColumns(p);
  const char* unit = orni::opt::objectiveUnit(p.options().objective);
  std::ostringstream g;
  g << "set multiplot layout 2,1 title \"" << study.name << " optimisation ("
    << orni::opt::toString(study.optimize().optimizer.algorithm) << ", "
    << s.starts.size() << " start(s)): objective "
    << orni::opt::toString(p.options().objective) << " per evaluation\" noenhanced font ',13'\n";
  g << "set lmargin 12\nset rmargin 30\nset tmargin 3\n"
       "set key outside right top vertical Left reverse noenhanced\n";
  g << "set xlabel 'evaluation (starts in order)'\nset xrange [-0.5:"
    << static_cast<double>(s.history.size()) - 0.5 << "]\n";
  g << "set ylabel 'objective (" << unit << ")'\n";
  g << "plot 'history.csv' skip 2 using 1:(($" << c.failed << " == 0 && $" << c.feasible
    << " == 0) ? $" << c.objective
    << " : 1/0) with points pt 6 ps 1.2 lc rgb '#c0392b' title 'infeasible', "
       "'' skip 2 using 1:($"
    << c.feasible << " == 1 ? $" << c.objective
    << " : 1/0) with points pt 7 ps 1.2 lc rgb '#1e8449' title 'feasible', "
       "'' skip 2 using 1:"
    << c.best << " with steps lw 2 lc rgb '#2471a3' title 'best feasible so far'\n";
  g << "set logscale y\nset format y '10^{%L}'\nset ylabel 'max constraint g (-)'\n";
  g << "set yrange [1e-4:*]\n";
  g << "plot 'history.csv' skip 2 using 1:(($" << c.failed << " == 0 && $" << c.feasible
    << " == 0) ? ($" << c.violation << " > 1e-4 ? $" << c.violation
    << " : 1e-4) : 1/0) with points pt 6 ps 1.2 lc rgb '#c0392b' title 'infeasible: violation', "
       "'' skip 2 using 1:($"
    << c.feasible
    << " == 1 ? 1e-4 : 1/0) with points pt 7 ps 1.2 lc rgb '#1e8449' title 'feasible (at 1e-4)', "
       "'' skip 2 using 1:($"
    << c.failed << " == 1 ? $" << c.violation
    << " : 1/0) with points pt 2 ps 1.2 lc rgb '#333333' title 'failed (penalty)'\n";
  g << "unset multiplot\n";
  return g.str();
}

/// Gnuplot script: one panel per plotted column with a value somewhere, the column against the
/// first axis, one line per combination of the other axes' values. Empty when nothing to plot.
std::string sweepFigure(const Study& study, const SweepGrid& grid,
                        const std::vector<SweepColumn>& columns,
                        const std::vector<SweepPointResult>& rows) {
  const SweepSettings& s = study.sweep();
  const std::size_t n_axes = s.axes.size();
  const std::size_t n_first = grid.sizes[0];
  const std::size_t n_series = rows.size() / n_first;  // combinations of the other axes
  auto rowOf = [&](std::size_t series, std::size_t i0) { return i0 * n_series + series; };

  struct Panel {
    std::size_t column;               // index into columns
    std::vector<std::size_t> series;  // series with a value
  };
  std::vector<Panel> panels;
  for (std::size_t c = 0; c < columns.size(); ++c) {
    if (!columns[c].plotted) continue;
    Panel p{c, {}};
    for (std::size_t se = 0; se < n_series; ++se)
      for (std::size_t i0 = 0; i0 < n_first; ++i0)
        if (!rows[rowOf(se, i0)].cells[c].empty()) {
          p.series.push_back(se);
          break;
        }
    if (!p.series.empty()) panels.push_back(std::move(p));
  }
  if (panels.empty()) return {};

  // Rows of one series are every n_series-th row of sweep.csv (the first axis is outermost), so
  // `every n_series::series` picks them in order; an empty cell is skipped by the line.
  const std::size_t cols = panels.size() <= 3 ? 1 : 2;
  const std::size_t rows_layout = (panels.size() + cols - 1) / cols;
  const bool legend = n_series > 1;
  const std::string& x_key = s.axes[0].key;
  std::ostringstream g;
  g << "set multiplot layout " << rows_layout << "," << cols << " margins 0.08,"
    << (legend ? "0.74" : "0.97") << ",0.07,0.92 spacing 0.09,0.1 title \"" << study.name << ": "
    << toString(s.run) << " sweep, " << rows.size() << " points\" noenhanced font ',13'\n";
  if (legend) {  // entries are the other axes' values; the legend's title names those axes
    std::string keys;
    for (std::size_t a = 1; a < n_axes; ++a)
      keys += (a > 1 ? ", " : "") + s.axes[a].key + " (" + keyUnit(s.axes[a].key) + ")";
    g << "set key at screen 0.76,0.92 left top Left reverse noenhanced box title '" << keys
      << "' noenhanced font ',10'\n";
  } else
    g << "unset key\n";
  g << "set xlabel '" << x_key << " (" << keyUnit(x_key) << ")' noenhanced\n";
  {  // tics at the swept values (few) or a handful (many), and a margin around them
    const std::vector<double>& xv = s.axes[0].values.values;
    const double lo = *std::min_element(xv.begin(), xv.end());
    const double hi = *std::max_element(xv.begin(), xv.end());
    const double pad = hi > lo ? 0.06 * (hi - lo) : std::max(0.05 * std::fabs(lo), 1e-9);
    g << "set xrange [" << formatShortest(lo - pad) << ":" << formatShortest(hi + pad) << "]\n";
    if (xv.size() <= 8) {
      g << "set xtics (";
      for (std::size_t i = 0; i < xv.size(); ++i)
        g << (i ? ", " : "") << formatShortest(xv[i]);
      g << ")\n";
    } else {
      g << "set xtics autofreq\n";
    }
  }
  for (std::size_t pi = 0; pi < panels.size(); ++pi) {
    const Panel& p = panels[pi];
    const SweepColumn& col = columns[p.column];
    const std::size_t csv_col = n_axes + 2 + p.column;  // 1-based: axes, status, results
    if (pi == 1) g << "unset key\n";                    // the legend once, beside the panels
    g << "set ylabel '" << col.name << " (" << col.unit << ")' noenhanced\n";
    g << "plot ";
    for (std::size_t k = 0; k < p.series.size(); ++k) {
      const std::size_t se = p.series[k];
      const std::vector<std::size_t> at = grid.axisIndices(rowOf(se, 0));
      std::string title;
      for (std::size_t a = 1; a < n_axes; ++a)
        title += (title.empty() ? "" : ", ") + formatShortest(s.axes[a].values.values[at[a]]);
      if (title.empty()) title = col.name;
      g << (k ? ", " : "") << "'sweep.csv' skip 2 every " << n_series << "::" << se
        << " using 1:" << csv_col << " with linespoints lw 2 pt 7 title '" << title << "'";
    }
    if (col.name == "norm_ratio_max")
      g << ", 1 with lines dt 2 lc rgb '#333333' title 'bound (bounded below 1)'";
    g << "\n";
  }
  g << "unset multiplot\n";
  return g.str();
}

}  // namespace orni::studies
