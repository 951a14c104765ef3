#include "studies/runner/plotting/aeromap_figures.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <sstream>
#include <vector>

#include "studies/runner/output/atomic_file.hpp"
#include "studies/runner/plotting/gnuplot.hpp"

namespace orni::studies {

namespace {

/// Most panels (frequencies), speed lines and tail dash types drawn; larger axes are thinned
/// evenly (first and last kept) and the title says so.
constexpr std::size_t kMaxPanels = 12;
constexpr std::size_t kMaxSpeeds = 8;
constexpr std::size_t kMaxTails = 4;

/// At most `limit` indices of 0..n-1, evenly spread, first and last included.
std::vector<std::size_t> thinned(std::size_t n, std::size_t limit) {
  std::vector<std::size_t> idx;
  if (n <= limit) {
    for (std::size_t i = 0; i < n; ++i) idx.push_back(i);
    return idx;
  }
  for (std::size_t k = 0; k < limit; ++k) idx.push_back(k * (n - 1) / (limit - 1));
  return idx;
}

std::string shownNote(const char* what, std::size_t shown, std::size_t n) {
  if (shown == n) return "";
  std::ostringstream s;
  s << ", " << shown << " of " << n << " " << what << " shown";
  return s.str();
}

}  // namespace

std::string aeromapFigureScript(const Study& study, int column, const std::string& what,
                                const std::string& ylabel) {
  const AeromapSettings& a = study.aeromap();
  const std::size_t ns = a.speed_mps.values.size(), nf = a.freq_hz.values.size(),
                    nt = a.theta_deg.values.size(), na = a.tail_angle_deg.values.size();
  const std::vector<std::size_t> freqs = thinned(nf, kMaxPanels);
  const std::vector<std::size_t> speeds = thinned(ns, kMaxSpeeds);
  const std::vector<std::size_t> tails = thinned(na, kMaxTails);
  const std::size_t panels = freqs.size();
  std::size_t cols = 1;
  while (cols * cols < panels) ++cols;
  const std::size_t rows = (panels + cols - 1) / cols;

  std::ostringstream g;
  g << "set multiplot layout " << rows << "," << cols << " title \"" << study.name << ": " << what
    << " over pitch, speed and frequency (cf. paper Fig. 5)" << shownNote("frequencies",
                                                                          panels, nf)
    << shownNote("speeds", speeds.size(), ns) << shownNote("tail angles", tails.size(), na)
    << "\" noenhanced font ',13'\n";
  // One y range for every panel, so that the panels compare (the frequency effect of Fig. 5);
  // a column of one value (one point, or equal values) gets a range around it, not an empty one.
  g << "stats 'aeromap.csv' skip 2 using " << column << " nooutput\n"
    << "pad = 0.05 * (STATS_max - STATS_min)\n"
    << "if (pad == 0) pad = (STATS_max == 0 ? 1 : 0.05 * abs(STATS_max))\n"
    << "set yrange [STATS_min - pad : STATS_max + pad]\n";
  // One pitch value: a range of +-1 deg around it (gnuplot would warn of an empty x range).
  const double theta_lo = *std::min_element(a.theta_deg.values.begin(), a.theta_deg.values.end());
  const double theta_hi = *std::max_element(a.theta_deg.values.begin(), a.theta_deg.values.end());
  if (theta_hi == theta_lo)
    g << "set xrange [" << formatShortest(theta_lo - 1.0) << ":" << formatShortest(theta_hi + 1.0)
      << "]\n";
  g << "set xlabel '{/Symbol q}_{mean} (deg)'\n";
  g << "set ylabel '" << ylabel << "'\n";
  g << "set key top left font ',9' spacing 0.9\n";
  for (std::size_t p = 0; p < panels; ++p) {
    const std::size_t jf = freqs[p];
    g << "set title 'f = " << formatShortest(a.freq_hz.values[jf]) << " Hz";
    if (na == 1)
      g << ", {/Symbol d}_T = " << formatShortest(a.tail_angle_deg.values[0]) << " deg";
    g << "'\n";
    if (p == 1) g << "unset key\n";
    g << "plot ";
    bool first = true;
    for (std::size_t ks = 0; ks < speeds.size(); ++ks) {
      for (std::size_t kt = 0; kt < tails.size(); ++kt) {
        const std::size_t js = speeds[ks], ja = tails[kt];
        // Rows of (speed js, frequency jf, tail ja) over theta: every na-th row from the first.
        const std::size_t base = (js * nf + jf) * nt * na;
        const std::size_t start = base + ja, end = base + (nt - 1) * na + ja;
        if (!first) g << ", \\\n     ";
        first = false;
        g << "'aeromap.csv' skip 2 every " << na << "::" << start << "::" << end << " using "
          << AeromapCsvColumns::kTheta << ":" << column << " with linespoints lt " << ks + 1
          << " dt " << kt + 1 << " lw 2 pt 7 ps 0.7 title 'U = "
          << formatShortest(a.speed_mps.values[js]) << " m/s";
        if (na > 1)
          g << ", {/Symbol d}_T = " << formatShortest(a.tail_angle_deg.values[ja]) << " deg";
        g << "'";
      }
    }
    g << "\n";
  }
  g << "unset multiplot\n";
  return g.str();
}

void drawAeromapFigures(const std::filesystem::path& dir, const Study& study) {
  using C = AeromapCsvColumns;
  drawFigure(dir, "aeromap_FV",
             aeromapFigureScript(study, C::kFV, "mean vertical force FV", "mean F_V (N)"));
  drawFigure(dir, "aeromap_FH",
             aeromapFigureScript(study, C::kFH, "mean horizontal force FH (thrust)",
                                 "mean F_H (N)"));
  drawFigure(dir, "aeromap_M",
             aeromapFigureScript(study, C::kM, "mean pitching moment M about the CG",
                                 "mean M (N m)"));
  drawFigure(dir, "aeromap_power",
             aeromapFigureScript(study, C::kPower, "mean hinge power", "mean hinge power P (W)"));
}

}  // namespace orni::studies
