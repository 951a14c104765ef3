// Station-sweep wing mesher (docs/theory.md 2.5) on the two vehicle layouts of studies/vehicles:
// areas, element quality, members on mesh edges, sample nodes, conformity, determinism.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "core/model/wing_geometry.hpp"
#include "core/structure/wing_mesh.hpp"

namespace orni::structure {
namespace {

constexpr double kPiValue = 3.14159265358979323846;
constexpr double kExactTol = 1e-12;        // geometric identities, relative or in metres
constexpr double kNodeSeparation = 1e-9;   // minimum distance between two nodes, m
constexpr double kMinAngleDeg = 1.0;       // no triangle may be flatter than this
constexpr double kEllipseAreaTol = 1e-3;   // inscribed polygon vs ellipse at h = 5 mm
constexpr double kOnBoundaryTol = 1e-6;    // member ends are written within 1e-6 m of the TE

WingMember member(const std::string& name, const std::string& material, double d, double x0,
                  double y0, double x1, double y1) {
  WingMember m;
  m.name = name;
  m.material = material;
  m.diameter_m = d;
  m.start_x_W_m = x0;
  m.start_y_W_m = y0;
  m.end_x_W_m = x1;
  m.end_y_W_m = y1;
  return m;
}

// studies/vehicles/efw_magpie.toml (wing part).
VehicleModel efwMagpie() {
  VehicleModel v;
  v.name = "efw_magpie";
  WingModel& w = v.wing;
  w.planform = Planform::kQuarterEllipse;
  w.semispan_m = 0.27;
  w.root_chord_m = 0.104;
  w.strip_count = 27;
  w.structure = StructureLevel::kFlexible;
  w.p3_aft_of_le_m = 0.052;
  w.skin = WingSkin{"SKIN", 4e-5};
  w.members = {
      member("LE1", "LE1", 0.002, 0.0, 0.0, 0.0, 0.135),
      member("LE2", "LE2", 0.001, 0.0, 0.135, 0.0, 0.27),
      member("DIAG1", "CFRP_ROD", 4e-4, -0.052, 0.0, 0.0, 0.0945),
      member("DIAG2", "CFRP_ROD", 4e-4, -0.052, 0.0, 0.0, 0.1755),
      member("STIF1", "CFRP_ROD", 4e-4, -0.052, 0.0, -0.1018987, 0.054),
      member("STIF2", "CFRP_ROD", 4e-4, -0.052, 0.0, -0.0953175, 0.108),
      member("STIF3", "CFRP_ROD", 4e-4, -0.052, 0.0, -0.0832, 0.162),
      member("STIF4", "CFRP_ROD", 4e-4, -0.052, 0.0, -0.0624, 0.216),
  };
  v.materials = {Material{"LE1", 250e9, 0.31, 1800.0}, Material{"LE2", 100e9, 0.31, 1800.0},
                 Material{"CFRP_ROD", 175e9, 0.31, 500.0}, Material{"SKIN", 100e9, 0.31, 500.0}};
  return v;
}

// studies/vehicles/rfw_tunnel.toml (wing part; p3_aft_of_le_m defaults to half the root chord).
VehicleModel rfwTunnel() {
  VehicleModel v;
  v.name = "rfw_tunnel";
  WingModel& w = v.wing;
  w.planform = Planform::kRectangular;
  w.semispan_m = 0.27;
  w.root_chord_m = 0.0967742;
  w.strip_count = 27;
  w.structure = StructureLevel::kFlexible;
  w.p3_aft_of_le_m = 0.5 * w.root_chord_m;
  w.skin = WingSkin{"RIPSTOP", 4e-5};
  const double c = w.root_chord_m;
  w.members = {
      member("LE_SPAR", "CFRP", 0.003, 0.0, 0.0, 0.0, 0.27),
      member("BATTEN1", "CFRP", 0.001, 0.0, 0.0, -c, 0.0),
      member("BATTEN2", "CFRP", 0.001, 0.0, 0.09, -c, 0.09),
      member("BATTEN3", "CFRP", 0.001, 0.0, 0.18, -c, 0.18),
      member("BATTEN4", "CFRP", 0.001, 0.0, 0.27, -c, 0.27),
  };
  v.materials = {Material{"CFRP", 135e9, 0.3, 1600.0}, Material{"RIPSTOP", 2e9, 0.35, 1000.0}};
  return v;
}

struct Case {
  const char* name;
  VehicleModel vehicle;
  double h;
};

std::vector<Case> allCases() {
  return {{"EFW h=5mm", efwMagpie(), 0.005},
          {"EFW h=10mm", efwMagpie(), 0.010},
          {"RFW h=5mm", rfwTunnel(), 0.005},
          {"RFW h=10mm", rfwTunnel(), 0.010}};
}

double x(const WingMesh& m, int n) { return m.nodes_W_m[static_cast<std::size_t>(n)].x(); }
double y(const WingMesh& m, int n) { return m.nodes_W_m[static_cast<std::size_t>(n)].y(); }

double signedArea(const WingMesh& m, const std::array<int, 3>& t) {
  const double ax = x(m, t[1]) - x(m, t[0]), ay = y(m, t[1]) - y(m, t[0]);
  const double bx = x(m, t[2]) - x(m, t[0]), by = y(m, t[2]) - y(m, t[0]);
  return 0.5 * (ax * by - ay * bx);
}

double minAngleDeg(const WingMesh& m, const std::array<int, 3>& t) {
  double smallest = 180.0;
  for (int i = 0; i < 3; ++i) {
    const Eigen::Vector3d& p = m.nodes_W_m[static_cast<std::size_t>(t[static_cast<std::size_t>(i)])];
    const Eigen::Vector3d& a =
        m.nodes_W_m[static_cast<std::size_t>(t[static_cast<std::size_t>((i + 1) % 3)])];
    const Eigen::Vector3d& b =
        m.nodes_W_m[static_cast<std::size_t>(t[static_cast<std::size_t>((i + 2) % 3)])];
    const Eigen::Vector3d u = a - p, v = b - p;
    const double crs = std::abs(u.x() * v.y() - u.y() * v.x());
    const double ang = std::atan2(crs, u.dot(v)) * 180.0 / kPiValue;
    smallest = std::min(smallest, ang);
  }
  return smallest;
}

double totalArea(const WingMesh& m) {
  double a = 0.0;
  for (const auto& t : m.triangles) a += signedArea(m, t);
  return a;
}

std::pair<int, int> undirected(int a, int b) { return {std::min(a, b), std::max(a, b)}; }

// Undirected edge -> number of triangles using it.
std::map<std::pair<int, int>, int> edgeUse(const WingMesh& m) {
  std::map<std::pair<int, int>, int> use;
  for (const auto& t : m.triangles)
    for (int i = 0; i < 3; ++i)
      ++use[undirected(t[static_cast<std::size_t>(i)], t[static_cast<std::size_t>((i + 1) % 3)])];
  return use;
}

bool onTrailingEdge(const WingModel& w, double px, double py) {
  return std::abs(px + chordAt(w, py)) <= kOnBoundaryTol;
}

// Trailing-edge boundary nodes sorted by y: the vertices of the inscribed polygon.
std::vector<std::pair<double, double>> trailingEdgeVertices(const WingMesh& m, const WingModel& w) {
  std::vector<int> boundary_nodes;
  for (const auto& [edge, count] : edgeUse(m)) {
    if (count != 1) continue;
    boundary_nodes.push_back(edge.first);
    boundary_nodes.push_back(edge.second);
  }
  std::sort(boundary_nodes.begin(), boundary_nodes.end());
  boundary_nodes.erase(std::unique(boundary_nodes.begin(), boundary_nodes.end()),
                       boundary_nodes.end());
  std::vector<std::pair<double, double>> te;  // (y, x)
  for (int n : boundary_nodes)
    if (onTrailingEdge(w, x(m, n), y(m, n))) te.emplace_back(y(m, n), x(m, n));
  std::sort(te.begin(), te.end());
  return te;
}

double polylineLength(const std::vector<std::pair<double, double>>& pts) {
  double len = 0.0;
  for (std::size_t i = 0; i + 1 < pts.size(); ++i)
    len += std::hypot(pts[i + 1].first - pts[i].first, pts[i + 1].second - pts[i].second);
  return len;
}

// Area under the trailing-edge polyline: the exact area of the inscribed polygon.
double polygonArea(const std::vector<std::pair<double, double>>& te) {
  double a = 0.0;
  for (std::size_t i = 0; i + 1 < te.size(); ++i)
    a += 0.5 * (-te[i].second - te[i + 1].second) * (te[i + 1].first - te[i].first);
  return a;
}

double distanceToLine(const WingMember& mb, const Eigen::Vector3d& p) {
  const double dx = mb.end_x_W_m - mb.start_x_W_m, dy = mb.end_y_W_m - mb.start_y_W_m;
  const double len = std::hypot(dx, dy);
  return std::abs(dx * (p.y() - mb.start_y_W_m) - dy * (p.x() - mb.start_x_W_m)) / len;
}

TEST(StructureMeshArea, TotalAreaMatchesPlanformOrInscribedPolygon) {
  for (const Case& c : allCases()) {
    SCOPED_TRACE(c.name);
    const WingMesh m = buildWingMesh(c.vehicle, c.h);
    const WingModel& w = c.vehicle.wing;
    const double area = totalArea(m);
    const double exact = halfWingArea(w);
    if (w.planform == Planform::kRectangular) {
      EXPECT_NEAR(area, exact, kExactTol * exact);
      std::printf("[ mesh     ] %-10s area %.12e m^2, planform %.12e, rel err %.2e\n", c.name,
                  area, exact, (area - exact) / exact);
    } else {
      const double poly = polygonArea(trailingEdgeVertices(m, w));
      EXPECT_NEAR(area, poly, kExactTol * poly);
      const double deficit = (exact - poly) / exact;
      EXPECT_GT(deficit, -1e-9);  // inscribed: never more than the ellipse (TE ends written in)
      std::printf("[ mesh     ] %-10s area %.12e m^2, inscribed polygon %.12e, ellipse %.12e, "
                  "rel deficit %.3e\n",
                  c.name, area, poly, exact, deficit);
    }
  }
}

TEST(StructureMeshArea, EllipseDeficitSmallAndDecreasingWithH) {
  const VehicleModel v = efwMagpie();
  const double exact = halfWingArea(v.wing);
  std::vector<double> deficits;
  for (double h : {0.010, 0.005, 0.0025}) {
    const double a = totalArea(buildWingMesh(v, h));
    deficits.push_back((exact - a) / exact);
    std::printf("[ mesh     ] EFW h=%.4f m: relative area deficit %.4e\n", h, deficits.back());
  }
  EXPECT_LT(deficits[1], kEllipseAreaTol);
  EXPECT_LE(deficits[1], deficits[0]);
  EXPECT_LE(deficits[2], deficits[1]);
  EXPECT_GT(deficits[2], 0.0);
}

TEST(StructureMeshQuality, PositiveAreaAndMinimumAngle) {
  for (const Case& c : allCases()) {
    SCOPED_TRACE(c.name);
    const WingMesh m = buildWingMesh(c.vehicle, c.h);
    double min_angle = 180.0, min_area = 1.0;
    int below10 = 0;
    for (const auto& t : m.triangles) {
      const double a = signedArea(m, t);
      EXPECT_GT(a, 0.0);
      min_area = std::min(min_area, a);
      const double ang = minAngleDeg(m, t);
      min_angle = std::min(min_angle, ang);
      if (ang < 10.0) ++below10;
    }
    EXPECT_GT(min_angle, kMinAngleDeg);
    std::printf("[ mesh     ] %-10s nodes %d, triangles %zu, beams %zu, elements %zu; min angle "
                "%.2f deg, %d triangles below 10 deg, min area %.3e m^2\n",
                c.name, m.nodeCount(), m.triangles.size(), m.beams.size(),
                m.triangles.size() + m.beams.size(), min_angle, below10, min_area);
  }
}

TEST(StructureMeshMembers, BeamsLieOnMembersAndOnTriangleEdges) {
  for (const Case& c : allCases()) {
    SCOPED_TRACE(c.name);
    const WingMesh m = buildWingMesh(c.vehicle, c.h);
    const auto use = edgeUse(m);
    const auto& members = c.vehicle.wing.members;
    double worst = 0.0;
    for (const BeamElement& b : m.beams) {
      ASSERT_GE(b.member, 0);
      ASSERT_LT(b.member, static_cast<int>(members.size()));
      const WingMember& mb = members[static_cast<std::size_t>(b.member)];
      for (int n : b.nodes)
        worst = std::max(worst, distanceToLine(mb, m.nodes_W_m[static_cast<std::size_t>(n)]));
      EXPECT_NE(b.nodes[0], b.nodes[1]);
      EXPECT_TRUE(use.count(undirected(b.nodes[0], b.nodes[1])) == 1)
          << "beam of " << mb.name << " is not a triangle edge";
    }
    EXPECT_LT(worst, kExactTol);
  }
}

TEST(StructureMeshMembers, ChainsCoverEveryMemberFromStartToEnd) {
  for (const Case& c : allCases()) {
    SCOPED_TRACE(c.name);
    const WingMesh m = buildWingMesh(c.vehicle, c.h);
    const auto& members = c.vehicle.wing.members;
    for (std::size_t mi = 0; mi < members.size(); ++mi) {
      const WingMember& mb = members[mi];
      SCOPED_TRACE(mb.name);
      std::vector<BeamElement> chain;
      for (const BeamElement& b : m.beams)
        if (b.member == static_cast<int>(mi)) chain.push_back(b);
      ASSERT_FALSE(chain.empty());
      const double len = std::hypot(mb.end_x_W_m - mb.start_x_W_m, mb.end_y_W_m - mb.start_y_W_m);
      double sum = 0.0;
      for (std::size_t i = 0; i < chain.size(); ++i) {
        const auto& b = chain[i];
        sum += (m.nodes_W_m[static_cast<std::size_t>(b.nodes[1])] -
                m.nodes_W_m[static_cast<std::size_t>(b.nodes[0])])
                   .norm();
        if (i > 0) {
          EXPECT_EQ(chain[i - 1].nodes[1], b.nodes[0]);  // connected chain
        }
      }
      EXPECT_NEAR(sum, len, kExactTol * len);
      const int first = chain.front().nodes[0], last = chain.back().nodes[1];
      EXPECT_NEAR(x(m, first), mb.start_x_W_m, kExactTol);
      EXPECT_NEAR(y(m, first), mb.start_y_W_m, kExactTol);
      EXPECT_NEAR(x(m, last), mb.end_x_W_m, kExactTol);
      EXPECT_NEAR(y(m, last), mb.end_y_W_m, kExactTol);
      // Spanwise-running members: stations are refined so that elements stay within h.
      if (mb.start_y_W_m != mb.end_y_W_m) {
        for (const auto& b : chain) {
          EXPECT_LE((m.nodes_W_m[static_cast<std::size_t>(b.nodes[1])] -
                     m.nodes_W_m[static_cast<std::size_t>(b.nodes[0])])
                        .norm(),
                    c.h * (1.0 + 1e-9));
        }
      }
    }
  }
}

TEST(StructureMeshSamples, StripNodesAndJointsAreExact) {
  for (const Case& c : allCases()) {
    SCOPED_TRACE(c.name);
    const WingMesh m = buildWingMesh(c.vehicle, c.h);
    const WingModel& w = c.vehicle.wing;
    const std::vector<Strip> strips = makeStrips(w);
    ASSERT_EQ(m.strip_nodes.size(), strips.size());
    for (std::size_t j = 0; j < strips.size(); ++j) {
      const StripSampleNodes& sn = m.strip_nodes[j];
      const double yc = strips[j].y_center_m, ch = chordAt(w, yc);
      EXPECT_NEAR(sn.y_W_m, yc, kExactTol);
      const std::array<std::pair<int, double>, 4> expected = {
          {{sn.leading_edge, 0.0},
           {sn.quarter_chord, -0.25 * ch},
           {sn.three_quarter_chord, -0.75 * ch},
           {sn.trailing_edge, -ch}}};
      for (const auto& [node, xe] : expected) {
        ASSERT_GE(node, 0);
        ASSERT_LT(node, m.nodeCount());
        EXPECT_NEAR(x(m, node), xe, kExactTol);
        EXPECT_NEAR(y(m, node), yc, kExactTol);
      }
    }
    ASSERT_GE(m.p2_node, 0);
    ASSERT_GE(m.p3_node, 0);
    EXPECT_EQ(m.nodes_W_m[static_cast<std::size_t>(m.p2_node)], Eigen::Vector3d::Zero());
    EXPECT_EQ(m.nodes_W_m[static_cast<std::size_t>(m.p3_node)],
              Eigen::Vector3d(-w.p3_aft_of_le_m, 0.0, 0.0));
  }
}

TEST(StructureMeshNodes, NoDuplicateNodesAllUsedFlat) {
  for (const Case& c : allCases()) {
    SCOPED_TRACE(c.name);
    const WingMesh m = buildWingMesh(c.vehicle, c.h);
    // Sweep in y: only pairs closer than the separation in y need the full distance.
    std::vector<int> order(static_cast<std::size_t>(m.nodeCount()));
    for (int i = 0; i < m.nodeCount(); ++i) order[static_cast<std::size_t>(i)] = i;
    std::sort(order.begin(), order.end(), [&m](int a, int b) { return y(m, a) < y(m, b); });
    double min_dist = 1.0;
    for (std::size_t i = 0; i < order.size(); ++i)
      for (std::size_t j = i + 1; j < order.size() && y(m, order[j]) - y(m, order[i]) < min_dist;
           ++j)
        min_dist = std::min(min_dist, (m.nodes_W_m[static_cast<std::size_t>(order[i])] -
                                       m.nodes_W_m[static_cast<std::size_t>(order[j])])
                                          .norm());
    EXPECT_GT(min_dist, kNodeSeparation);
    std::vector<int> used(static_cast<std::size_t>(m.nodeCount()), 0);
    for (const auto& t : m.triangles)
      for (int n : t) {
        ASSERT_GE(n, 0);
        ASSERT_LT(n, m.nodeCount());
        used[static_cast<std::size_t>(n)] = 1;
      }
    EXPECT_EQ(std::count(used.begin(), used.end(), 0), 0);
    for (const auto& p : m.nodes_W_m) EXPECT_EQ(p.z(), 0.0);
    std::printf("[ mesh     ] %-10s min node distance %.3e m\n", c.name, min_dist);
  }
}

TEST(StructureMeshTopology, ConformingWithPlanformBoundary) {
  for (const Case& c : allCases()) {
    SCOPED_TRACE(c.name);
    const WingMesh m = buildWingMesh(c.vehicle, c.h);
    const WingModel& w = c.vehicle.wing;
    const double s = w.semispan_m, c0 = w.root_chord_m;
    const auto use = edgeUse(m);
    // Consistent orientation: every directed edge occurs at most once.
    std::map<std::pair<int, int>, int> directed;
    for (const auto& t : m.triangles)
      for (int i = 0; i < 3; ++i)
        ++directed[{t[static_cast<std::size_t>(i)], t[static_cast<std::size_t>((i + 1) % 3)]}];
    for (const auto& [e, count] : directed) EXPECT_EQ(count, 1);
    double boundary_length = 0.0;
    int boundary_edges = 0;
    for (const auto& [e, count] : use) {
      ASSERT_TRUE(count == 1 || count == 2) << "edge " << e.first << "-" << e.second;
      if (count == 2) continue;
      ++boundary_edges;
      const double xa = x(m, e.first), ya = y(m, e.first), xb = x(m, e.second), yb = y(m, e.second);
      const bool root = ya == 0.0 && yb == 0.0;
      const bool le = xa == 0.0 && xb == 0.0;
      const bool tip = w.planform == Planform::kRectangular && ya == s && yb == s;
      const bool te = onTrailingEdge(w, xa, ya) && onTrailingEdge(w, xb, yb);
      EXPECT_TRUE(root || le || tip || te)
          << "boundary edge (" << xa << ", " << ya << ")-(" << xb << ", " << yb
          << ") is not on the planform boundary";
      boundary_length += std::hypot(xb - xa, yb - ya);
    }
    // A disc: V - E + F = 1.
    EXPECT_EQ(m.nodeCount() - static_cast<int>(use.size()) + static_cast<int>(m.triangles.size()),
              1);
    double perimeter = 0.0;
    if (w.planform == Planform::kRectangular) {
      perimeter = 2.0 * (s + c0);
    } else {
      const auto te = trailingEdgeVertices(m, w);
      ASSERT_GE(te.size(), 2u);
      EXPECT_EQ(te.front(), std::make_pair(0.0, -c0));
      EXPECT_EQ(te.back(), std::make_pair(s, 0.0));
      perimeter = s + c0 + polylineLength(te);
    }
    EXPECT_NEAR(boundary_length, perimeter, kExactTol * perimeter);
    std::printf("[ mesh     ] %-10s %d boundary edges, boundary length %.12f m\n", c.name,
                boundary_edges, boundary_length);
  }
}

TEST(StructureMeshCount, EfwAt7mmNearPaperElementCount) {
  const WingMesh m = buildWingMesh(efwMagpie(), 0.007);
  const std::size_t elements = m.triangles.size() + m.beams.size();
  std::printf("[ mesh     ] EFW h=7mm: %d nodes, %zu triangles, %zu beams, %zu elements "
              "(paper: 1857)\n",
              m.nodeCount(), m.triangles.size(), m.beams.size(), elements);
  EXPECT_GT(elements, 1857u / 3u);
  EXPECT_LT(elements, 1857u * 3u);
}

TEST(StructureMeshDeterminism, TwoBuildsAreIdentical) {
  for (const Case& c : allCases()) {
    SCOPED_TRACE(c.name);
    const WingMesh a = buildWingMesh(c.vehicle, c.h);
    const WingMesh b = buildWingMesh(c.vehicle, c.h);
    EXPECT_EQ(a.nodes_W_m, b.nodes_W_m);
    EXPECT_EQ(a.triangles, b.triangles);
    ASSERT_EQ(a.beams.size(), b.beams.size());
    for (std::size_t i = 0; i < a.beams.size(); ++i) {
      EXPECT_EQ(a.beams[i].nodes, b.beams[i].nodes);
      EXPECT_EQ(a.beams[i].member, b.beams[i].member);
    }
    ASSERT_EQ(a.strip_nodes.size(), b.strip_nodes.size());
    for (std::size_t j = 0; j < a.strip_nodes.size(); ++j) {
      EXPECT_EQ(a.strip_nodes[j].quarter_chord, b.strip_nodes[j].quarter_chord);
      EXPECT_EQ(a.strip_nodes[j].three_quarter_chord, b.strip_nodes[j].three_quarter_chord);
    }
    EXPECT_EQ(a.p2_node, b.p2_node);
    EXPECT_EQ(a.p3_node, b.p3_node);
  }
}

TEST(StructureMeshLayouts, BareWingAndInteriorMemberEnd) {
  // No members at all: P3 must still be a node.
  VehicleModel bare = efwMagpie();
  bare.wing.members.clear();
  const WingMesh mb = buildWingMesh(bare, 0.005);
  EXPECT_TRUE(mb.beams.empty());
  EXPECT_EQ(mb.nodes_W_m[static_cast<std::size_t>(mb.p3_node)],
            Eigen::Vector3d(-0.052, 0.0, 0.0));
  // A member ending inside the skin, a T joint on a batten and a trailing-edge spar.
  VehicleModel rfw = rfwTunnel();
  const double c = rfw.wing.root_chord_m;
  rfw.wing.members.push_back(member("STUB", "CFRP", 1e-3, -0.02, 0.09, -0.05, 0.13));
  rfw.wing.members.push_back(member("TE_SPAR", "CFRP", 1e-3, -c, 0.0, -c, 0.27));
  const WingMesh m = buildWingMesh(rfw, 0.005);
  EXPECT_NEAR(totalArea(m), 0.27 * c, kExactTol * 0.27 * c);
  const auto use = edgeUse(m);
  for (const BeamElement& b : m.beams)
    EXPECT_EQ(use.count(undirected(b.nodes[0], b.nodes[1])), 1u);
  for (const auto& t : m.triangles) EXPECT_GT(signedArea(m, t), 0.0);
}

TEST(StructureMeshErrors, RejectsBadInput) {
  const VehicleModel efw = efwMagpie();
  EXPECT_THROW(buildWingMesh(efw, 0.0), std::invalid_argument);
  EXPECT_THROW(buildWingMesh(efw, -0.005), std::invalid_argument);
  EXPECT_THROW(buildWingMesh(efw, std::nan("")), std::invalid_argument);

  VehicleModel crossing = efw;  // a diagonal from the root TE to the LE crosses every stiffener
  crossing.wing.members.push_back(member("X", "CFRP_ROD", 4e-4, -0.104, 0.0, 0.0, 0.2));
  try {
    buildWingMesh(crossing, 0.005);
    ADD_FAILURE() << "crossing members accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("cross"), std::string::npos) << e.what();
  }

  VehicleModel outside = efw;  // beyond the elliptic trailing edge
  outside.wing.members.push_back(member("OUT", "CFRP_ROD", 4e-4, -0.052, 0.0, -0.1, 0.2));
  try {
    buildWingMesh(outside, 0.005);
    ADD_FAILURE() << "member outside the planform accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("outside"), std::string::npos) << e.what();
  }
  VehicleModel ahead = efw;  // ahead of the leading edge
  ahead.wing.members.push_back(member("AHEAD", "CFRP_ROD", 4e-4, 0.01, 0.05, -0.05, 0.05));
  EXPECT_THROW(buildWingMesh(ahead, 0.005), std::invalid_argument);
}

}  // namespace
}  // namespace orni::structure
