#include "studies/runner/plotting/modes_figure.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>
#include <utility>

#include "core/structure/wing_mesh.hpp"

namespace orni::studies {

namespace {

/// Grid of the colour maps: stations along the span, points along the local chord.
constexpr int kFigureStations = 48;
constexpr int kFigureChordPoints = 14;

/// Values of a nodal field at point (x, y) of the wing plane: linear interpolation in the skin
/// triangle that contains it (the one with the largest smallest barycentric coordinate, so points
/// on the boundary or a hair outside use their nearest triangle).
class PlanformInterpolator {
 public:
  explicit PlanformInterpolator(const structure::WingMesh& mesh) : mesh_(mesh) {}

  /// Triangle index and barycentric weights of (x, y); index -1 when the mesh has no triangle.
  std::pair<int, Eigen::Vector3d> locate(double x, double y) const {
    int best = -1;
    double best_min = -std::numeric_limits<double>::infinity();
    Eigen::Vector3d best_l = Eigen::Vector3d::Zero();
    for (std::size_t t = 0; t < mesh_.triangles.size(); ++t) {
      const auto& tri = mesh_.triangles[t];
      const Eigen::Vector3d& a = mesh_.nodes_W_m[static_cast<std::size_t>(tri[0])];
      const Eigen::Vector3d& b = mesh_.nodes_W_m[static_cast<std::size_t>(tri[1])];
      const Eigen::Vector3d& c = mesh_.nodes_W_m[static_cast<std::size_t>(tri[2])];
      const double det = (b.x() - a.x()) * (c.y() - a.y()) - (c.x() - a.x()) * (b.y() - a.y());
      if (det == 0.0) continue;
      const double l1 = ((x - a.x()) * (c.y() - a.y()) - (c.x() - a.x()) * (y - a.y())) / det;
      const double l2 = ((b.x() - a.x()) * (y - a.y()) - (x - a.x()) * (b.y() - a.y())) / det;
      const double l0 = 1.0 - l1 - l2;
      const double m = std::min({l0, l1, l2});
      if (m > best_min) {
        best_min = m;
        best = static_cast<int>(t);
        best_l = Eigen::Vector3d(l0, l1, l2);
        if (m >= 0.0) break;  // inside
      }
    }
    // Outside every triangle: clamp to the nearest one's edge (no extrapolation).
    if (best_min < 0.0) {
      best_l = best_l.cwiseMax(0.0);
      best_l /= best_l.sum();
    }
    return {best, best_l};
  }

  double value(const std::pair<int, Eigen::Vector3d>& where, const std::vector<double>& f) const {
    if (where.first < 0) return 0.0;
    const auto& tri = mesh_.triangles[static_cast<std::size_t>(where.first)];
    return where.second(0) * f[static_cast<std::size_t>(tri[0])] +
           where.second(1) * f[static_cast<std::size_t>(tri[1])] +
           where.second(2) * f[static_cast<std::size_t>(tri[2])];
  }

 private:
  const structure::WingMesh& mesh_;
};

}  // namespace

/// The z_W column of mode k over all nodes, signed so that its largest |w| is positive
/// (mode shapes are defined up to sign; this makes the output deterministic).
std::vector<double> modeShapeW(const structure::ModalWing& wing, int k) {
  const int n = wing.mesh.nodeCount();
  std::vector<double> w(static_cast<std::size_t>(n));
  double peak = 0.0;
  for (int p = 0; p < n; ++p) {
    const double v = wing.mode_shapes(structure::globalDof(p, structure::kW), k);
    w[static_cast<std::size_t>(p)] = v;
    if (std::abs(v) > std::abs(peak)) peak = v;
  }
  if (peak < 0.0)
    for (double& v : w) v = -v;
  return w;
}

/// gnuplot data for the colour maps (a pm3d grid: one scan per span station, separated by blank
/// lines): columns y_W (mm), x_W (mm), then w / max|w| of the first `modes` modes, interpolated
/// from the mesh onto kFigureStations x kFigureChordPoints points that follow the planform. A
/// coarse grid keeps modes.svg small (the full mesh would be ~10 MB of SVG).
std::string modesFigureData(const structure::ModalWing& wing, const WingModel& planform,
                            int modes) {
  std::vector<std::vector<double>> w;
  for (int k = 0; k < modes; ++k) {
    std::vector<double> v = modeShapeW(wing, k);
    double peak = 0.0;
    for (double a : v) peak = std::max(peak, std::abs(a));
    if (peak > 0.0)
      for (double& a : v) a /= peak;
    w.push_back(std::move(v));
  }
  const PlanformInterpolator interp(wing.mesh);
  std::string out =
      "# Figure data of modes.gp: mode shapes on a planform grid (one scan per span station).\n"
      "# columns: y_W (mm), x_W (mm), w/max|w| of modes 1..N (sign: largest |w| positive)\n";
  char buf[64];
  for (int j = 0; j <= kFigureStations; ++j) {
    const double y = planform.semispan_m * j / kFigureStations;
    const double c = chordAt(planform, y);
    for (int i = 0; i <= kFigureChordPoints; ++i) {
      const double x = -c * i / kFigureChordPoints;
      const auto where = interp.locate(x, y);
      std::snprintf(buf, sizeof buf, "%.5g,%.5g", 1e3 * y, 1e3 * x);
      out += buf;
      for (const std::vector<double>& v : w) {
        std::snprintf(buf, sizeof buf, ",%.4f", interp.value(where, v));
        out += buf;
      }
      out += '\n';
    }
    out += '\n';
  }
  return out;
}

std::string modesFigure(const Study& study, const structure::ModalWing& wing, int modes) {
  const WingModel& w = study.vehicle.wing;
  std::ostringstream g;
  g << "set multiplot layout 3,2 title \"" << study.name << ": fixed-interface modes (P2 clamped, "
    << "P3 universal joint), colour = w_z / max|w_z| over the planform (z_W down)\" noenhanced "
    << "font ',12'\n";
  g << "set pm3d map corners2color mean\n"
       "set size ratio -1\n"
       "set palette defined (-1 '#2166ac', 0 '#f7f7f7', 1 '#b2182b')\n"
       "set cbrange [-1:1]\nset cbtics 0.5\nunset key\nunset grid\n"
       "set xlabel 'y_W (mm)' offset 0,0.5\nset ylabel 'x_W (mm)'\n";
  g << "set xrange [0:" << 1e3 * w.semispan_m << "]\nset yrange [" << -1e3 * w.root_chord_m
    << ":0]\n";
  // At most ~4 chordwise tics (the axis is short at equal scale).
  double step = 1.0;
  for (double s : {1.0, 2.0, 5.0, 10.0, 20.0, 25.0, 50.0, 100.0, 200.0, 500.0, 1000.0}) {
    step = s;
    if (1e3 * w.root_chord_m / s <= 4.0) break;
  }
  g << "set ytics " << step << "\n";
  // Members as black lines on top of the colour map.
  int id = 1;
  for (const WingMember& m : w.members)
    g << "set arrow " << id++ << " from " << 1e3 * m.start_y_W_m << "," << 1e3 * m.start_x_W_m
      << ",0 to " << 1e3 * m.end_y_W_m << "," << 1e3 * m.end_x_W_m
      << ",0 nohead front lw 1.2 lc rgb '#222222'\n";
  for (int k = 0; k < modes; ++k) {
    char title[96];
    std::snprintf(title, sizeof title, "mode %d: f = %.1f Hz", k + 1, wing.frequencies_hz(k));
    g << "set title '" << title << "' font ',12'\n"
      << "splot 'modes_figure.dat' using 1:2:" << k + 3 << " with pm3d\n";
  }
  g << "unset multiplot\n";
  return g.str();
}

}  // namespace orni::studies
