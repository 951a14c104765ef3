// Station-sweep mesher of the flat right wing (docs/theory.md 2.5).
//
// Stations are lines y_W = const; every member crosses a station in one key point (or lies on it,
// for chordwise members), so members end up on mesh edges by construction. Between two stations
// the rails (leading edge, trailing edge, members active on both) split the strip into regions,
// each triangulated by a zipper. Everything is ordered by coordinates and indices only, so the
// result is deterministic.
//
// Choices beyond docs/theory.md 2.5:
// * Points (and stations) closer than snap = min(h / 1000, min(s, c0) / 10^4) merge into one, so a
//   member end written up to ~1e-6 m inside the trailing edge shares the edge node. The merged
//   node takes the coordinate of the highest-priority candidate (see the priorities below); the
//   others move by less than snap.
// * Between mandatory stations (root, tip, strip boundaries and mid-stations, member end y's) the
//   gaps are split into equal parts no longer than h / sqrt(1 + slope^2), instead of adding the
//   multiples of h: this keeps spacing <= h without the slivers that multiples of h would leave
//   next to the strip stations (e.g. 14 and 15 mm for h = 7 mm).
// * No quads and no smoothing: triangles only, nodes where the stations put them.
#include "core/structure/wing_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/model/invalid_model_error.hpp"
#include "core/model/wing_geometry.hpp"

namespace orni::structure {
namespace {

// Merge priorities (higher wins the coordinate when candidates closer than the snap tolerance
// merge). Stations: root/tip > member end > strip mid-station > strip boundary > spacing fill.
constexpr int kStationBoundary = 4;
constexpr int kStationMemberEnd = 3;
constexpr int kStationStripMid = 2;
constexpr int kStationStripBoundary = 1;
constexpr int kStationFill = 0;
// Key points on a station: member end points and P3 > leading/trailing edge > member crossing
// between its ends > quarter/three-quarter chord sample points. A member ending on the trailing
// edge (written a little inside it) thus moves the edge node onto the member, while a member that
// merely grazes an edge between its ends yields to the exact planform.
constexpr int kKeyMemberEnd = 4;
constexpr int kKeyEdge = 3;
constexpr int kKeyCrossing = 2;
constexpr int kKeySample = 1;

// Upper bound on the estimated node count: a guard against absurd element sizes.
constexpr double kMaxEstimatedNodes = 2.0e7;

// Key-point tags on a station.
constexpr int kTagLeadingEdge = 0;
constexpr int kTagTrailingEdge = 1;
constexpr int kTagP3 = 2;
constexpr int kTagQuarter = 3;
constexpr int kTagThreeQuarter = 4;
constexpr int kTagFirstMember = 5;  // member m: 5 + 2 m (crossing or start), 6 + 2 m (end)

struct Member {
  std::string name;
  double xa = 0.0, ya = 0.0, xb = 0.0, yb = 0.0;  // start a, end b (W frame, m)
  double length = 0.0;
  bool chordwise = false;  // lies on one station (|ya - yb| <= snap)
  int station_a = -1;      // station index of the start (chordwise: the station it lies on)
  int station_b = -1;      // station index of the end
  int stationLow() const { return std::min(station_a, station_b); }
  int stationHigh() const { return std::max(station_a, station_b); }
  // x_W of the member line at y (not for chordwise members); exact at the end points.
  double xAt(double y) const {
    if (y == ya) return xa;
    if (y == yb) return xb;
    const double t = std::clamp((y - ya) / (yb - ya), 0.0, 1.0);
    return xa + t * (xb - xa);
  }
};

struct StationCandidate {
  double y = 0.0;
  int priority = 0;
  int strip_mid = -1;  // strip index when this is a strip mid-station
};

struct KeyCandidate {
  double x = 0.0;
  int priority = 0;
  int tag = 0;
};

struct Station {
  double y = 0.0;
  int strip_mid = -1;           // strip whose mid-station this is, or -1
  std::vector<int> nodes;       // global node ids, ascending x_W (trailing edge first)
  std::vector<int> tag_local;   // local node index of every key-point tag, -1 if absent
};

std::string fmt(double v) {
  std::ostringstream os;
  os.precision(9);
  os << v;
  return os.str();
}

std::string point(double x, double y) { return "(" + fmt(x) + ", " + fmt(y) + ")"; }

void validateWing(const WingModel& wing, double h) {
  if (!(h > 0.0) || !std::isfinite(h))
    throw InvalidModelError("buildWingMesh: expected element size h > 0, got " + fmt(h));
  if (!(wing.semispan_m > 0.0) || !std::isfinite(wing.semispan_m))
    throw InvalidModelError("buildWingMesh: expected semispan > 0, got " +
                                fmt(wing.semispan_m));
  if (!(wing.root_chord_m > 0.0) || !std::isfinite(wing.root_chord_m))
    throw InvalidModelError("buildWingMesh: expected root chord > 0, got " +
                                fmt(wing.root_chord_m));
  if (wing.strip_count < 1)
    throw InvalidModelError("buildWingMesh: expected strip count >= 1, got " +
                                std::to_string(wing.strip_count));
  if (!(wing.p3_aft_of_le_m >= 0.0 && wing.p3_aft_of_le_m <= wing.root_chord_m))
    throw InvalidModelError("buildWingMesh: expected P3 aft of the leading edge in [0, " +
                                fmt(wing.root_chord_m) + "] m, got " +
                                fmt(wing.p3_aft_of_le_m));
}

bool insidePlanform(const WingModel& wing, double x, double y, double tol) {
  if (!std::isfinite(x) || !std::isfinite(y)) return false;
  if (y < -tol || y > wing.semispan_m + tol) return false;
  if (x > tol) return false;
  return x >= -chordAt(wing, std::clamp(y, 0.0, wing.semispan_m)) - tol;
}

std::vector<Member> collectMembers(const WingModel& wing, double snap) {
  std::vector<Member> members;
  members.reserve(wing.members.size());
  for (const WingMember& wm : wing.members) {
    Member m;
    m.name = wm.name;
    m.xa = wm.start_x_W_m;
    m.ya = wm.start_y_W_m;
    m.xb = wm.end_x_W_m;
    m.yb = wm.end_y_W_m;
    if (!insidePlanform(wing, m.xa, m.ya, snap) || !insidePlanform(wing, m.xb, m.yb, snap))
      throw InvalidModelError("buildWingMesh: member '" + m.name + "' from " +
                                  point(m.xa, m.ya) + " to " + point(m.xb, m.yb) +
                                  " m lies outside the planform (expected 0 <= y_W <= " +
                                  fmt(wing.semispan_m) + " and -c(y) <= x_W <= 0)");
    m.length = std::hypot(m.xb - m.xa, m.yb - m.ya);
    if (!(m.length > snap))
      throw InvalidModelError("buildWingMesh: member '" + m.name + "' has zero length (" +
                                  point(m.xa, m.ya) + " to " + point(m.xb, m.yb) + ")");
    m.chordwise = std::abs(m.yb - m.ya) <= snap;
    members.push_back(m);
  }
  return members;
}

double cross2(double ax, double ay, double bx, double by) { return ax * by - ay * bx; }

// Members may share end points, end on another member (T joint) or overlap collinearly; a
// crossing of two member interiors cannot be meshed with members on station crossings only.
void checkNoCrossings(const std::vector<Member>& members, double snap) {
  for (std::size_t i = 0; i < members.size(); ++i) {
    for (std::size_t j = i + 1; j < members.size(); ++j) {
      const Member& a = members[i];
      const Member& b = members[j];
      const double rx = a.xb - a.xa, ry = a.yb - a.ya;
      const double sx = b.xb - b.xa, sy = b.yb - b.ya;
      const double denom = cross2(rx, ry, sx, sy);
      if (std::abs(denom) <= 1e-12 * a.length * b.length) continue;  // parallel or collinear
      const double qx = b.xa - a.xa, qy = b.ya - a.ya;
      const double t = cross2(qx, qy, sx, sy) / denom;
      const double u = cross2(qx, qy, rx, ry) / denom;
      const double ta = snap / a.length, tb = snap / b.length;
      if (t > ta && t < 1.0 - ta && u > tb && u < 1.0 - tb)
        throw InvalidModelError("buildWingMesh: members '" + a.name + "' and '" + b.name +
                                    "' cross at " + point(a.xa + t * rx, a.ya + t * ry) +
                                    " m away from their end points");
    }
  }
}

// Strip boundaries, strip mid-stations, member end points, root and tip; candidates closer than
// `snap` merge into the one of highest priority.
std::vector<StationCandidate> mandatoryStations(const WingModel& wing,
                                                const std::vector<Member>& members,
                                                double snap) {
  const double s = wing.semispan_m;
  std::vector<StationCandidate> cand;
  cand.push_back({0.0, kStationBoundary, -1});
  cand.push_back({s, kStationBoundary, -1});
  const std::vector<Strip> strips = makeStrips(wing);
  for (std::size_t j = 0; j < strips.size(); ++j) {
    cand.push_back({strips[j].y_inner_m, kStationStripBoundary, -1});
    cand.push_back({strips[j].y_outer_m, kStationStripBoundary, -1});
    cand.push_back({strips[j].y_center_m, kStationStripMid, static_cast<int>(j)});
  }
  for (const Member& m : members) {
    cand.push_back({std::clamp(m.ya, 0.0, s), kStationMemberEnd, -1});
    cand.push_back({std::clamp(m.yb, 0.0, s), kStationMemberEnd, -1});
  }
  std::sort(cand.begin(), cand.end(), [](const StationCandidate& p, const StationCandidate& q) {
    if (p.y != q.y) return p.y < q.y;
    if (p.priority != q.priority) return p.priority > q.priority;
    return p.strip_mid < q.strip_mid;
  });
  std::vector<StationCandidate> out;
  std::size_t i = 0;
  while (i < cand.size()) {
    const double start = cand[i].y;
    StationCandidate best = cand[i];
    int strip_mid = -1;
    for (; i < cand.size() && cand[i].y - start <= snap; ++i) {
      if (cand[i].priority > best.priority) best = cand[i];
      if (cand[i].strip_mid >= 0) {
        if (strip_mid >= 0 && strip_mid != cand[i].strip_mid)
          throw InvalidModelError("buildWingMesh: strips too narrow for the element size");
        strip_mid = cand[i].strip_mid;
      }
    }
    best.strip_mid = strip_mid;
    out.push_back(best);
  }
  return out;
}

// Index of the station nearest to y (stations sorted ascending).
int nearestStation(const std::vector<StationCandidate>& st, double y) {
  const auto it = std::lower_bound(st.begin(), st.end(), y,
                                   [](const StationCandidate& c, double v) { return c.y < v; });
  int k = static_cast<int>(it - st.begin());
  if (k >= static_cast<int>(st.size())) return static_cast<int>(st.size()) - 1;
  if (k > 0 && std::abs(st[static_cast<std::size_t>(k - 1)].y - y) <=
                   std::abs(st[static_cast<std::size_t>(k)].y - y))
    --k;
  return k;
}

// Refinement (docs/theory.md 2.5 step 1): every gap between mandatory stations is split into equal
// parts no longer than h / sqrt(1 + slope^2), slope = |dx/dy| of the flattest member spanning it.
std::vector<StationCandidate> refineStations(const std::vector<StationCandidate>& mandatory,
                                             const std::vector<Member>& members, double h,
                                             double snap) {
  std::vector<StationCandidate> out;
  for (std::size_t i = 0; i + 1 < mandatory.size(); ++i) {
    const double y0 = mandatory[i].y, y1 = mandatory[i + 1].y;
    double slope = 0.0;
    for (const Member& m : members) {
      if (m.chordwise) continue;
      if (std::min(m.ya, m.yb) <= y0 + snap && std::max(m.ya, m.yb) >= y1 - snap)
        slope = std::max(slope, std::abs(m.xb - m.xa) / std::abs(m.yb - m.ya));
    }
    const double limit = h / std::sqrt(1.0 + slope * slope);
    const double gap = y1 - y0;
    const int n = std::max(1, static_cast<int>(std::ceil(gap / limit * (1.0 - 1e-12))));
    out.push_back(mandatory[i]);
    for (int k = 1; k < n; ++k) out.push_back({y0 + gap * k / n, kStationFill, -1});
  }
  out.push_back(mandatory.back());
  return out;
}

// Zipper triangulation of one region (docs/theory.md 2.5 step 3): lower chain lower[l0..l1] on the
// inner station, upper chain upper[u0..u1] on the outer station, both in ascending x_W. Each step
// advances the chain whose new diagonal is shorter; triangles come out counter-clockwise.
void zipper(const std::vector<Eigen::Vector3d>& p, const std::vector<int>& lower, int l0, int l1,
            const std::vector<int>& upper, int u0, int u1,
            std::vector<std::array<int, 3>>& triangles) {
  auto at = [](const std::vector<int>& v, int i) { return v[static_cast<std::size_t>(i)]; };
  auto dist2 = [&p](int a, int b) {
    return (p[static_cast<std::size_t>(a)] - p[static_cast<std::size_t>(b)]).squaredNorm();
  };
  int i = l0, k = u0;
  while (i < l1 || k < u1) {
    bool advance_lower = false;
    if (i == l1) {
      advance_lower = false;
    } else if (k == u1) {
      advance_lower = true;
    } else {
      advance_lower = dist2(at(lower, i + 1), at(upper, k)) <= dist2(at(lower, i), at(upper, k + 1));
    }
    if (advance_lower) {
      triangles.push_back({at(lower, i), at(lower, i + 1), at(upper, k)});
      ++i;
    } else {
      triangles.push_back({at(lower, i), at(upper, k + 1), at(upper, k)});
      ++k;
    }
  }
}

}  // namespace

WingMesh buildWingMesh(const WingStructure& wing_structure, double element_size_m) {
  const WingModel& wing = wing_structure.wing;
  const double h = element_size_m;
  validateWing(wing, h);
  const double s = wing.semispan_m;
  const double c0 = wing.root_chord_m;
  // Points closer than this merge (e.g. a member end written a little inside the trailing edge).
  const double snap = std::min(1e-3 * h, 1e-4 * std::min(s, c0));

  std::vector<Member> members = collectMembers(wing, snap);
  checkNoCrossings(members, snap);

  {
    double member_length = 0.0;
    for (const Member& m : members) member_length += m.length;
    const double stations = s / h + 2.0 * wing.strip_count + 2.0 + member_length / h;
    const double per_station = c0 / h + 6.0 + 2.0 * static_cast<double>(members.size());
    if (stations * per_station > kMaxEstimatedNodes)
      throw InvalidModelError("buildWingMesh: element size " + fmt(h) +
                                  " m is too small for this wing (about " +
                                  fmt(stations * per_station) + " nodes)");
  }

  // 1. Stations.
  const std::vector<StationCandidate> mandatory = mandatoryStations(wing, members, snap);
  const std::vector<StationCandidate> st_cand = refineStations(mandatory, members, h, snap);
  const int n_st = static_cast<int>(st_cand.size());
  for (Member& m : members) {
    if (m.chordwise) {
      m.station_a = m.station_b = nearestStation(st_cand, std::clamp(0.5 * (m.ya + m.yb), 0.0, s));
    } else {
      m.station_a = nearestStation(st_cand, std::clamp(m.ya, 0.0, s));
      m.station_b = nearestStation(st_cand, std::clamp(m.yb, 0.0, s));
    }
  }
  const int n_tags = kTagFirstMember + 2 * static_cast<int>(members.size());

  // 2. Key points and nodes of every station.
  WingMesh mesh;
  std::vector<Station> stations(static_cast<std::size_t>(n_st));
  std::vector<KeyCandidate> keys;
  std::vector<double> key_x;
  std::vector<std::vector<int>> key_tags;
  for (int k = 0; k < n_st; ++k) {
    Station& st = stations[static_cast<std::size_t>(k)];
    st.y = st_cand[static_cast<std::size_t>(k)].y;
    st.strip_mid = st_cand[static_cast<std::size_t>(k)].strip_mid;
    st.tag_local.assign(static_cast<std::size_t>(n_tags), -1);
    const double c = chordAt(wing, st.y);

    keys.clear();
    keys.push_back({0.0, kKeyEdge, kTagLeadingEdge});
    keys.push_back({-c, kKeyEdge, kTagTrailingEdge});
    if (k == 0) keys.push_back({-wing.p3_aft_of_le_m, kKeyMemberEnd, kTagP3});
    if (st.strip_mid >= 0) {
      keys.push_back({-0.25 * c, kKeySample, kTagQuarter});
      keys.push_back({-0.75 * c, kKeySample, kTagThreeQuarter});
    }
    for (std::size_t mi = 0; mi < members.size(); ++mi) {
      const Member& m = members[mi];
      const int tag = kTagFirstMember + 2 * static_cast<int>(mi);
      if (m.chordwise) {
        if (m.station_a != k) continue;
        keys.push_back({m.xa, kKeyMemberEnd, tag});
        keys.push_back({m.xb, kKeyMemberEnd, tag + 1});
      } else if (m.stationLow() <= k && k <= m.stationHigh()) {
        const bool at_end = k == m.station_a || k == m.station_b;
        keys.push_back({m.xAt(st.y), at_end ? kKeyMemberEnd : kKeyCrossing, tag});
      }
    }
    std::sort(keys.begin(), keys.end(), [](const KeyCandidate& p, const KeyCandidate& q) {
      if (p.x != q.x) return p.x < q.x;
      if (p.priority != q.priority) return p.priority > q.priority;
      return p.tag < q.tag;
    });
    // Merge coincident key points.
    key_x.clear();
    key_tags.clear();
    for (std::size_t i = 0; i < keys.size();) {
      const double start = keys[i].x;
      KeyCandidate best = keys[i];
      std::vector<int> tags;
      for (; i < keys.size() && keys[i].x - start <= snap; ++i) {
        if (keys[i].priority > best.priority) best = keys[i];
        tags.push_back(keys[i].tag);
      }
      key_x.push_back(best.x);
      key_tags.push_back(tags);
    }
    auto hasTag = [](const std::vector<int>& tags, int tag) {
      return std::find(tags.begin(), tags.end(), tag) != tags.end();
    };
    if (!hasTag(key_tags.front(), kTagTrailingEdge) || !hasTag(key_tags.back(), kTagLeadingEdge))
      throw InvalidModelError("buildWingMesh: a member leaves the planform at station y_W = " +
                                  fmt(st.y) + " m");
    // Fill the gaps with round(len / h) equal segments (at least one).
    for (std::size_t i = 0; i < key_x.size(); ++i) {
      if (i > 0) {
        const double xa = key_x[i - 1], len = key_x[i] - xa;
        const long n = std::max(1L, std::lround(len / h));
        for (long q = 1; q < n; ++q) {
          st.nodes.push_back(mesh.nodeCount());
          mesh.nodes_W_m.emplace_back(xa + len * static_cast<double>(q) / static_cast<double>(n),
                                      st.y, 0.0);
        }
      }
      for (int tag : key_tags[i])
        st.tag_local[static_cast<std::size_t>(tag)] = static_cast<int>(st.nodes.size());
      st.nodes.push_back(mesh.nodeCount());
      mesh.nodes_W_m.emplace_back(key_x[i], st.y, 0.0);
    }
  }
  auto localOf = [&stations](int k, int tag) {
    return stations[static_cast<std::size_t>(k)].tag_local[static_cast<std::size_t>(tag)];
  };
  auto nodeOf = [&stations, &localOf](int k, int tag) {
    return stations[static_cast<std::size_t>(k)].nodes[static_cast<std::size_t>(localOf(k, tag))];
  };

  // 3. Regions between rails, zipper-triangulated.
  struct Rail {
    int lower = 0, upper = 0;
    bool operator<(const Rail& o) const {
      return lower != o.lower ? lower < o.lower : upper < o.upper;
    }
    bool operator==(const Rail& o) const { return lower == o.lower && upper == o.upper; }
  };
  std::vector<Rail> rails;
  for (int k = 0; k + 1 < n_st; ++k) {
    rails.clear();
    rails.push_back({localOf(k, kTagLeadingEdge), localOf(k + 1, kTagLeadingEdge)});
    rails.push_back({localOf(k, kTagTrailingEdge), localOf(k + 1, kTagTrailingEdge)});
    for (std::size_t mi = 0; mi < members.size(); ++mi) {
      const Member& m = members[mi];
      if (m.chordwise || m.stationLow() > k || m.stationHigh() < k + 1) continue;
      const int tag = kTagFirstMember + 2 * static_cast<int>(mi);
      rails.push_back({localOf(k, tag), localOf(k + 1, tag)});
    }
    std::sort(rails.begin(), rails.end());
    rails.erase(std::unique(rails.begin(), rails.end()), rails.end());
    const Station& lo = stations[static_cast<std::size_t>(k)];
    const Station& up = stations[static_cast<std::size_t>(k + 1)];
    for (std::size_t r = 0; r + 1 < rails.size(); ++r) {
      const Rail& a = rails[r];
      const Rail& b = rails[r + 1];
      if (b.upper < a.upper)
        throw InvalidModelError("buildWingMesh: members cross between y_W = " + fmt(lo.y) +
                                    " and " + fmt(up.y) + " m");
      zipper(mesh.nodes_W_m, lo.nodes, a.lower, b.lower, up.nodes, a.upper, b.upper,
             mesh.triangles);
    }
  }

  // 4. Beams along every member, from its start to its end.
  for (std::size_t mi = 0; mi < members.size(); ++mi) {
    const Member& m = members[mi];
    const int tag = kTagFirstMember + 2 * static_cast<int>(mi);
    if (m.chordwise) {
      const Station& st = stations[static_cast<std::size_t>(m.station_a)];
      const int a = localOf(m.station_a, tag), b = localOf(m.station_a, tag + 1);
      const int step = b > a ? 1 : -1;
      for (int i = a; i != b; i += step)
        mesh.beams.push_back({{st.nodes[static_cast<std::size_t>(i)],
                               st.nodes[static_cast<std::size_t>(i + step)]},
                              static_cast<int>(mi)});
    } else {
      const int step = m.station_b > m.station_a ? 1 : -1;
      for (int k = m.station_a; k != m.station_b; k += step)
        mesh.beams.push_back({{nodeOf(k, tag), nodeOf(k + step, tag)}, static_cast<int>(mi)});
    }
  }

  // 5. Joints and aerodynamic sample nodes.
  mesh.p2_node = nodeOf(0, kTagLeadingEdge);
  mesh.p3_node = nodeOf(0, kTagP3);
  mesh.strip_nodes.assign(static_cast<std::size_t>(wing.strip_count), StripSampleNodes{});
  for (int k = 0; k < n_st; ++k) {
    const Station& st = stations[static_cast<std::size_t>(k)];
    if (st.strip_mid < 0) continue;
    StripSampleNodes& sn = mesh.strip_nodes[static_cast<std::size_t>(st.strip_mid)];
    sn.y_W_m = st.y;
    sn.leading_edge = nodeOf(k, kTagLeadingEdge);
    sn.quarter_chord = nodeOf(k, kTagQuarter);
    sn.three_quarter_chord = nodeOf(k, kTagThreeQuarter);
    sn.trailing_edge = nodeOf(k, kTagTrailingEdge);
  }
  return mesh;
}

}  // namespace orni::structure
