// CalculiX deck writer (docs/theory.md 2.7). See calculix_deck.hpp for units and element choices.
#include "core/structure/calculix_deck.hpp"

#include "core/structure/fe_assembly.hpp"

#include <array>
#include <cctype>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>
#include <utility>
#include <vector>

namespace orni::structure {
namespace {

constexpr double kMmPerM = 1e3;
constexpr double kMpaPerPa = 1e-6;
constexpr double kTpmm3PerKgpm3 = 1e-12;  // 1 kg/m^3 = 1e-12 t/mm^3
constexpr int kMaxModes = 10000;
constexpr std::size_t kMaxNameLength = 40;

/// Real number text CalculiX reads back to ~12 digits; always with a '.' or an exponent.
std::string real(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.12G", v);
  std::string s = buf;
  if (s.find_first_of(".E") == std::string::npos) s += ".";
  return s;
}

/// A CalculiX set / material name: letters, digits and '_', at most kMaxNameLength characters.
std::string setName(const std::string& prefix, std::size_t index, const std::string& name) {
  std::string s = prefix + std::to_string(index + 1) + "_";
  for (char c : name) {
    if (s.size() >= kMaxNameLength) break;
    const auto u = static_cast<unsigned char>(c);
    s += std::isalnum(u) ? static_cast<char>(std::toupper(u)) : '_';
  }
  return s;
}

/// Nodes of the deck: the mesh nodes (ids 1..n) plus generated nodes, each generated once per
/// key (edge midpoints and triangle centroids), in W coordinates (m).
class DeckNodes {
 public:
  explicit DeckNodes(const std::vector<Eigen::Vector3d>& mesh_nodes) : x_(mesh_nodes) {}

  /// 0-based id of the midpoint of the segment between nodes a and b (created on first use).
  int midpoint(int a, int b) {
    const std::pair<int, int> key = a < b ? std::make_pair(a, b) : std::make_pair(b, a);
    const auto it = midpoints_.find(key);
    if (it != midpoints_.end()) return it->second;
    const int id = add(0.5 * (x_[static_cast<std::size_t>(a)] + x_[static_cast<std::size_t>(b)]));
    midpoints_.emplace(key, id);
    return id;
  }

  int add(const Eigen::Vector3d& p) {
    x_.push_back(p);
    return static_cast<int>(x_.size()) - 1;
  }

  const std::vector<Eigen::Vector3d>& positions() const { return x_; }
  const std::map<std::pair<int, int>, int>& midpoints() const { return midpoints_; }

 private:
  std::vector<Eigen::Vector3d> x_;
  std::map<std::pair<int, int>, int> midpoints_;
};

struct ElementBlock {
  std::string type;
  std::string elset;
  std::vector<std::vector<int>> nodes;  // 0-based deck node ids, CalculiX order
};

void writeElements(std::ostream& out, const ElementBlock& block, int& next_id) {
  if (block.nodes.empty()) return;
  out << "*ELEMENT, TYPE=" << block.type << ", ELSET=" << block.elset << "\n";
  for (const std::vector<int>& e : block.nodes) {
    out << next_id++;
    for (int n : e) out << ", " << n + 1;
    out << "\n";
  }
}

/// Consistent nodal forces (N) of a uniform pressure p (MPa) along the element normal (right-hand
/// rule of its node order) on a quadratic shell element of the deck (S6 or S8R, node positions in
/// mm): f_i = p * integral of N_i n dA over the undeformed element.
std::vector<Eigen::Vector3d> pressureForces(const std::vector<Eigen::Vector3d>& x_mm,
                                            const std::vector<int>& element, double p_mpa) {
  auto at = [&](std::size_t k) { return x_mm[static_cast<std::size_t>(element[k])]; };
  std::vector<Eigen::Vector3d> f(element.size(), Eigen::Vector3d::Zero());
  if (element.size() == 6) {
    // Straight-edged quadratic triangle: integral of N_i dA = 0 at the corners, A / 3 at the
    // midside nodes; n dA integrates to (x2 - x1) x (x3 - x1) / 2.
    const Eigen::Vector3d n_area = 0.5 * (at(1) - at(0)).cross(at(2) - at(0));
    for (std::size_t k = 3; k < 6; ++k) f[k] = p_mpa * n_area / 3.0;
    return f;
  }
  // 8-node serendipity quad, 3 x 3 Gauss points.
  static const double kXi[8] = {-1, 1, 1, -1, 0, 1, 0, -1};
  static const double kEta[8] = {-1, -1, 1, 1, -1, 0, 1, 0};
  const double g = std::sqrt(0.6);
  const double pts[3] = {-g, 0.0, g}, wts[3] = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) {
      const double xi = pts[a], eta = pts[b];
      double n[8], dxi[8], deta[8];
      for (int k = 0; k < 8; ++k) {
        const double xk = kXi[k], ek = kEta[k];
        if (k < 4) {
          n[k] = 0.25 * (1 + xi * xk) * (1 + eta * ek) * (xi * xk + eta * ek - 1);
          dxi[k] = 0.25 * xk * (1 + eta * ek) * (2 * xi * xk + eta * ek);
          deta[k] = 0.25 * ek * (1 + xi * xk) * (xi * xk + 2 * eta * ek);
        } else if (xk == 0.0) {
          n[k] = 0.5 * (1 - xi * xi) * (1 + eta * ek);
          dxi[k] = -xi * (1 + eta * ek);
          deta[k] = 0.5 * (1 - xi * xi) * ek;
        } else {
          n[k] = 0.5 * (1 + xi * xk) * (1 - eta * eta);
          dxi[k] = 0.5 * xk * (1 - eta * eta);
          deta[k] = -eta * (1 + xi * xk);
        }
      }
      Eigen::Vector3d x_xi = Eigen::Vector3d::Zero(), x_eta = Eigen::Vector3d::Zero();
      for (std::size_t k = 0; k < 8; ++k) {
        x_xi += dxi[k] * at(k);
        x_eta += deta[k] * at(k);
      }
      const Eigen::Vector3d n_da = wts[a] * wts[b] * x_xi.cross(x_eta);
      for (std::size_t k = 0; k < 8; ++k) f[k] += p_mpa * n[k] * n_da;
    }
  return f;
}

const Material& requireMaterial(const WingStructure& wing_structure, const std::string& name,
                                const std::string& user) {
  const Material* m = wing_structure.findMaterial(name);
  if (m == nullptr)
    throw std::invalid_argument("calculixDeck: unknown material '" + name + "' of " + user);
  return *m;
}

}  // namespace

std::string calculixDeck(const WingStructure& wing_structure, const WingMesh& mesh,
                         const CalculixDeckOptions& options, CalculixDeckStats* stats) {
  const int n = mesh.nodeCount();
  if (options.clamp_p2 && (mesh.p2_node < 0 || mesh.p2_node >= n))
    throw std::invalid_argument("calculixDeck: the mesh has no valid P2 node");
  if (mesh.p3_node >= n) throw std::invalid_argument("calculixDeck: P3 node out of range");
  if (options.mode_count < 1 || options.mode_count > kMaxModes)
    throw std::invalid_argument("calculixDeck: mode_count must be in [1, 10000], got " +
                                std::to_string(options.mode_count));
  auto checkNode = [n](int id) {
    if (id < 0 || id >= n)
      throw std::invalid_argument("calculixDeck: element node " + std::to_string(id) +
                                  " out of range [0, " + std::to_string(n) + ")");
  };
  const CalculixStaticOptions& st = options.static_steps;
  const bool has_static = !st.load_factors.empty();
  const bool shrink = has_static && st.skin_shrink_strain != 0.0;
  if (!options.frequency_step && !has_static)
    throw std::invalid_argument("calculixDeck: no step (neither the frequency step nor a static one)");
  if (has_static) {
    for (double f : st.load_factors)
      if (!std::isfinite(f))
        throw std::invalid_argument("calculixDeck: a static load factor is not finite");
    if (!std::isfinite(st.skin_shrink_strain))
      throw std::invalid_argument("calculixDeck: the skin shrink strain is not finite");
    if (!(st.min_increment > 0.0 && st.min_increment <= st.initial_increment &&
          st.initial_increment <= st.max_increment && st.max_increment <= 1.0) ||
        st.max_increments < 1)
      throw std::invalid_argument(
          "calculixDeck: static increments need 0 < min <= initial <= max <= 1 and a count >= 1");
    const Eigen::Index dofs = static_cast<Eigen::Index>(kDofsPerNode) * n;
    if (st.load.nodal_load.size() != 0 && st.load.nodal_load.size() != dofs)
      throw std::invalid_argument("calculixDeck: the nodal load has " +
                                  std::to_string(st.load.nodal_load.size()) + " entries, not " +
                                  std::to_string(dofs));
    if (!std::isfinite(st.load.skin_pressure_pa) || !st.load.nodal_load.allFinite())
      throw std::invalid_argument("calculixDeck: the static load is not finite");
    for (int id : st.print_nodes)
      if (id < 0 || id >= n)
        throw std::invalid_argument("calculixDeck: print node " + std::to_string(id) +
                                    " out of range");
  }
  for (int id : options.clamped_nodes)
    if (id < 0 || id >= n)
      throw std::invalid_argument("calculixDeck: clamped node " + std::to_string(id) +
                                  " out of range");

  DeckNodes nodes(mesh.nodes_W_m);
  const bool split = options.skin == CalculixSkinElement::kS8RSplit;

  // Skin: S8R quads (4 corners counter-clockwise, then midsides 1-2, 2-3, 3-4, 4-1) or S6
  // (3 corners, then midsides 1-2, 2-3, 3-1). Triangles are counter-clockwise in (x_W, y_W), so
  // every element normal is +z_W.
  ElementBlock skin{split ? "S8R" : "S6", "SKIN", {}};
  for (const std::array<int, 3>& t : mesh.triangles) {
    for (int id : t) checkNode(id);
    if (split) {
      const std::array<int, 3> mid = {nodes.midpoint(t[0], t[1]), nodes.midpoint(t[1], t[2]),
                                      nodes.midpoint(t[2], t[0])};
      const auto& x = nodes.positions();
      const int centre = nodes.add((x[static_cast<std::size_t>(t[0])] +
                                    x[static_cast<std::size_t>(t[1])] +
                                    x[static_cast<std::size_t>(t[2])]) /
                                   3.0);
      for (int i = 0; i < 3; ++i) {
        const std::array<int, 4> q = {t[static_cast<std::size_t>(i)],
                                      mid[static_cast<std::size_t>(i)], centre,
                                      mid[static_cast<std::size_t>((i + 2) % 3)]};
        std::vector<int> e(q.begin(), q.end());
        for (int k = 0; k < 4; ++k)
          e.push_back(nodes.midpoint(q[static_cast<std::size_t>(k)],
                                     q[static_cast<std::size_t>((k + 1) % 4)]));
        skin.nodes.push_back(std::move(e));
      }
    } else {
      skin.nodes.push_back({t[0], t[1], t[2], nodes.midpoint(t[0], t[1]),
                            nodes.midpoint(t[1], t[2]), nodes.midpoint(t[2], t[0])});
    }
  }

  // Members: one ELSET per member, quadratic beams (end, middle, end). With split skin quads the
  // mesh edge is halved, so each beam element becomes two that share the quads' midside nodes.
  const std::string beam_type = options.beam == CalculixBeamElement::kB32R ? "B32R" : "B32";
  std::vector<ElementBlock> members;
  for (std::size_t k = 0; k < wing_structure.wing.members.size(); ++k)
    members.push_back({beam_type, setName("B", k, wing_structure.wing.members[k].name), {}});
  for (const BeamElement& b : mesh.beams) {
    checkNode(b.nodes[0]);
    checkNode(b.nodes[1]);
    if (b.member < 0 || b.member >= static_cast<int>(members.size()))
      throw std::invalid_argument("calculixDeck: beam element of member " +
                                  std::to_string(b.member) + ", which does not exist");
    std::vector<std::vector<int>>& out = members[static_cast<std::size_t>(b.member)].nodes;
    const int a = b.nodes[0], c = b.nodes[1];
    if (split) {
      const int m = nodes.midpoint(a, c);
      out.push_back({a, nodes.midpoint(a, m), m});
      out.push_back({m, nodes.midpoint(m, c), c});
    } else {
      out.push_back({a, nodes.midpoint(a, c), c});
    }
  }

  // Materials: the skin's isotropic; one per member with its own orientation (see below).
  std::string skin_material;
  const Material* skin_mat = nullptr;
  if (!skin.nodes.empty()) {
    skin_mat = &requireMaterial(wing_structure, wing_structure.wing.skin.material, "the skin");
    skin_material = setName("S", static_cast<std::size_t>(skin_mat - wing_structure.materials.data()),
                            skin_mat->name);
    if (!(wing_structure.wing.skin.thickness_m > 0.0))
      throw std::invalid_argument("calculixDeck: the skin thickness must be > 0");
  }
  for (std::size_t k = 0; k < members.size(); ++k) {
    if (members[k].nodes.empty()) continue;
    const WingMember& m = wing_structure.wing.members[k];
    requireMaterial(wing_structure, m.material, "member '" + m.name + "'");
    if (!(m.diameter_m > 0.0))
      throw std::invalid_argument("calculixDeck: member '" + m.name + "' needs a diameter > 0");
  }

  int beam_count = 0;
  for (const ElementBlock& b : members) beam_count += static_cast<int>(b.nodes.size());
  const int node_count = static_cast<int>(nodes.positions().size());

  // Clamped nodes: the given mesh nodes and, repeatedly, the midpoint nodes between two clamped
  // nodes (the midside nodes of a clamped edge; with split quads also those of its halves).
  std::set<int> clamped(options.clamped_nodes.begin(), options.clamped_nodes.end());
  for (bool grew = !clamped.empty(); grew;) {
    grew = false;
    for (const auto& [ends, id] : nodes.midpoints())
      if (clamped.count(ends.first) != 0 && clamped.count(ends.second) != 0 &&
          clamped.insert(id).second)
        grew = true;
  }

  // Static load per deck node (N, N mm) at load factor 1: the dead pressure's consistent forces
  // and the nodal load of the mesh nodes (m -> mm for the moments).
  std::map<int, std::array<double, 6>> node_loads;
  if (has_static) {
    const double p_mpa = st.load.skin_pressure_pa * kMpaPerPa;
    if (p_mpa != 0.0 && !st.load.follower_pressure) {
      std::vector<Eigen::Vector3d> x_mm;
      for (const Eigen::Vector3d& p : nodes.positions()) x_mm.push_back(kMmPerM * p);
      for (const std::vector<int>& e : skin.nodes) {
        const std::vector<Eigen::Vector3d> f = pressureForces(x_mm, e, p_mpa);
        for (std::size_t k = 0; k < e.size(); ++k)
          for (int d = 0; d < 3; ++d) node_loads[e[k]][static_cast<std::size_t>(d)] += f[k](d);
      }
    }
    if (st.load.nodal_load.size() != 0)
      for (int i = 0; i < n; ++i)
        for (int d = 0; d < kDofsPerNode; ++d) {
          const double v = st.load.nodal_load(globalDof(i, d));
          if (v != 0.0) node_loads[i][static_cast<std::size_t>(d)] += d < 3 ? v : kMmPerM * v;
        }
  }

  std::ostringstream out;
  out << "*HEADING\n"
      << (options.heading.empty() ? "Ornithopter wing " + wing_structure.vehicle_name : options.heading) << "\n";
  out << "** Written by ornithopter (core/structure/calculix_deck.cpp), docs/theory.md section 2.7.\n"
      << "** Units: N, mm, t, s (E in MPa, density in t/mm^3); frequencies in Hz.\n"
      << "** Frame W: x forward (leading edge at x = 0), y outboard, z = x cross y.\n"
      << "** Mesh node i is node i + 1; midside" << (split ? " and centroid" : "")
      << " nodes follow.\n"
      << "** " << n << " mesh nodes, " << mesh.triangles.size() << " triangles, "
      << mesh.beams.size() << " beam elements -> " << node_count << " nodes, "
      << skin.nodes.size() << " " << skin.type << ", " << beam_count << " " << beam_type << "\n"
      << "** Run: ccx -i JOB (job name without .inp); "
      << (has_static ? (options.frequency_step ? "eigenfrequencies and displacements"
                                               : "displacements")
                     : "eigenfrequencies")
      << " in JOB.dat.\n";

  out << "*NODE, NSET=NALL\n";
  {
    const auto& x = nodes.positions();
    for (int i = 0; i < node_count; ++i) {
      const Eigen::Vector3d p = kMmPerM * x[static_cast<std::size_t>(i)];
      out << i + 1 << ", " << real(p.x()) << ", " << real(p.y()) << ", " << real(p.z()) << "\n";
    }
  }
  int next_id = 1;
  writeElements(out, skin, next_id);
  for (const ElementBlock& b : members) writeElements(out, b, next_id);

  if (options.clamp_p2) out << "*NSET, NSET=P2\n" << mesh.p2_node + 1 << "\n";
  if (mesh.p3_node >= 0) out << "*NSET, NSET=P3\n" << mesh.p3_node + 1 << "\n";
  if (!clamped.empty()) {
    out << "*NSET, NSET=CLAMPED\n";
    for (int id : clamped) out << id + 1 << "\n";
  }
  if (has_static) {
    out << "*NSET, NSET=NPRINT\n";
    if (st.print_nodes.empty())
      for (int i = 0; i < n; ++i) out << i + 1 << "\n";
    else
      for (int id : std::set<int>(st.print_nodes.begin(), st.print_nodes.end()))
        out << id + 1 << "\n";
  }

  if (skin_mat != nullptr)
    out << "*MATERIAL, NAME=" << skin_material << "\n"
        << "*ELASTIC\n"
        << real(skin_mat->youngs_modulus_pa * kMpaPerPa) << ", " << real(skin_mat->poisson_ratio)
        << "\n"
        << "*DENSITY\n"
        << real(skin_mat->density_kgpm3 * kTpmm3PerKgpm3) << "\n"
        << (shrink ? "*EXPANSION\n1.\n" : "")
        << "*SHELL SECTION, ELSET=SKIN, MATERIAL=" << skin_material << "\n"
        << real(wing_structure.wing.skin.thickness_m * kMmPerM) << "\n";

  // Members. CalculiX joins beams and shells that share a node by a rigid "knot", which also
  // freezes the cross-section of the expanded rod and so locks its Poisson contraction: the rod
  // becomes ~35 % stiffer in bending (LE1 rod + EFW skin, tip load: 0.247 mm instead of the
  // 0.334 mm of beam theory, independent of the skin thickness). Beam theory has no Poisson
  // coupling, so each member gets nu = 0 with the isotropic shear modulus G = E / (2 (1 + nu))
  // (engineering constants in the member's axes: 1 along the rod, 3 = z_W), which keeps E I and
  // G J of the rod exactly.
  for (std::size_t k = 0; k < members.size(); ++k) {
    if (members[k].nodes.empty()) continue;
    const WingMember& m = wing_structure.wing.members[k];
    const Material& mat = requireMaterial(wing_structure, m.material, "member '" + m.name + "'");
    const std::string name = members[k].elset;  // B<k>_<NAME>, also used for material/orientation
    const double e = mat.youngs_modulus_pa * kMpaPerPa;
    const double g = e / (2.0 * (1.0 + mat.poisson_ratio));
    // Member axis from its first element in the mesh (members are straight).
    const std::vector<int>& first = members[k].nodes.front();
    Eigen::Vector3d t = nodes.positions()[static_cast<std::size_t>(first.back())] -
                        nodes.positions()[static_cast<std::size_t>(first.front())];
    t.z() = 0.0;
    if (!(t.norm() > 0.0))
      throw std::invalid_argument("calculixDeck: member '" + m.name +
                                  "' has an element of zero length in the wing plane");
    t.normalize();
    out << "*ORIENTATION, NAME=O" << name << ", SYSTEM=RECTANGULAR\n"
        << real(t.x()) << ", " << real(t.y()) << ", 0., " << real(0.0 - t.y()) << ", "
        << real(t.x()) << ", 0.\n"
        << "*MATERIAL, NAME=M" << name << "\n"
        << "*ELASTIC, TYPE=ENGINEERING CONSTANTS\n"
        << real(e) << ", " << real(e) << ", " << real(e) << ", 0., 0., 0., " << real(g) << ", "
        << real(g) << "\n"
        << real(g) << "\n"
        << "*DENSITY\n"
        << real(mat.density_kgpm3 * kTpmm3PerKgpm3) << "\n";
    const double d_mm = wing_structure.wing.memberDiameter(m) * kMmPerM;
    // Solid circular rod: both "thicknesses" are the diameter; local 1-direction = the wing
    // normal z_W (never parallel to an in-plane member), the same on every element of a member.
    out << "*BEAM SECTION, ELSET=" << name << ", MATERIAL=M" << name << ", SECTION=CIRC, "
        << "ORIENTATION=O" << name << "\n"
        << real(d_mm) << ", " << real(d_mm) << "\n"
        << "0., 0., 1.\n";
  }

  // Joints (docs/theory.md 2.6): P2 clamped; P3 translations plus the rotations its joint holds
  // (the universal joint: about the cross axis n_u, z_W: DOF 6, y_W: DOF 5), the same DOFs as
  // wingBoundaryDofs; with a pinned root edge every node on y_W = 0, midside nodes included.
  if (options.root_edge_pinned) {
    out << "*NSET, NSET=ROOT\n";
    const auto& x = nodes.positions();
    for (int i = 0; i < node_count; ++i)
      if (x[static_cast<std::size_t>(i)].y() == 0.0) out << i + 1 << "\n";
  }
  out << "*BOUNDARY\n";
  if (options.clamp_p2) out << "P2, 1, 6\n";
  if (mesh.p3_node >= 0) {
    WingSupport support;
    support.p3_joint = options.p3_joint;
    support.p3_cross_axis = options.p3_cross_axis_normal ? UniversalJointCrossAxis::kZW
                                                         : UniversalJointCrossAxis::kYW;
    out << "P3, 1, 3\n";
    for (int d : p3HeldRotations(support)) out << "P3, " << d + 1 << ", " << d + 1 << "\n";
  }
  if (options.root_edge_pinned) out << "ROOT, 1, 3\n";
  if (!clamped.empty()) out << "CLAMPED, 1, 6\n";
  if (shrink) out << "*INITIAL CONDITIONS, TYPE=TEMPERATURE\nNALL, 0.\n";
  if (options.frequency_step) {
    out << "*STEP\n*FREQUENCY\n" << options.mode_count << "\n";
    if (options.node_file) out << "*NODE FILE\nU\n";
    out << "*END STEP\n";
  }
  // Static steps: each ends at its factor times the load; the loads ramp within a step from the
  // previous step's values (ccx's default for *STATIC), and every card below replaces the
  // previous step's value of the same node and DOF (OP=MOD).
  const double p_mpa = st.load.skin_pressure_pa * kMpaPerPa;
  for (std::size_t k = 0; k < st.load_factors.size(); ++k) {
    const double factor = st.load_factors[k];
    out << "** Static step " << k + 1 << ": load factor " << real(factor) << ", ends at time "
        << k + 1 << "\n";
    out << (st.nlgeom ? "*STEP, NLGEOM, INC=" : "*STEP, INC=") << st.max_increments << "\n"
        << st.controls << "*STATIC\n"
        << real(st.initial_increment) << ", 1., " << real(st.min_increment) << ", "
        << real(st.max_increment) << "\n";
    if (p_mpa != 0.0 && st.load.follower_pressure && !skin.nodes.empty())
      out << "*DLOAD\nSKIN, P, " << real(factor * p_mpa) << "\n";
    if (!node_loads.empty()) {
      out << "*CLOAD\n";
      for (const auto& [id, f] : node_loads)
        for (std::size_t d = 0; d < 6; ++d)
          if (f[d] != 0.0) out << id + 1 << ", " << d + 1 << ", " << real(factor * f[d]) << "\n";
    }
    if (shrink) out << "*TEMPERATURE\nNALL, " << real(-st.skin_shrink_strain) << "\n";
    out << "*NODE PRINT, NSET=NPRINT\nU\n";
    if (st.node_file) out << "*NODE FILE\nU\n";
    out << "*END STEP\n";
  }

  if (stats != nullptr) {
    stats->nodes = node_count;
    stats->skin_elements = static_cast<int>(skin.nodes.size());
    stats->beam_elements = beam_count;
  }
  return out.str();
}

}  // namespace orni::structure
