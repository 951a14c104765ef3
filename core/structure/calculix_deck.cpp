// CalculiX deck writer (structure.md 6.2). See calculix_deck.hpp for units and element choices.
#include "core/structure/calculix_deck.hpp"

#include "core/structure/fe_assembly.hpp"

#include <array>
#include <cctype>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <map>
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
  if (mesh.p2_node < 0 || mesh.p2_node >= n)
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

  std::ostringstream out;
  out << "*HEADING\n"
      << (options.heading.empty() ? "Ornithopter wing " + wing_structure.vehicle_name : options.heading) << "\n";
  out << "** Written by ornithopter (core/structure/calculix_deck.cpp), structure.md section 6.\n"
      << "** Units: N, mm, t, s (E in MPa, density in t/mm^3); frequencies in Hz.\n"
      << "** Frame W: x forward (leading edge at x = 0), y outboard, z = x cross y.\n"
      << "** Mesh node i is node i + 1; midside" << (split ? " and centroid" : "")
      << " nodes follow.\n"
      << "** " << n << " mesh nodes, " << mesh.triangles.size() << " triangles, "
      << mesh.beams.size() << " beam elements -> " << node_count << " nodes, "
      << skin.nodes.size() << " " << skin.type << ", " << beam_count << " " << beam_type << "\n"
      << "** Run: ccx -i JOB (job name without .inp); eigenfrequencies in JOB.dat.\n";

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

  out << "*NSET, NSET=P2\n" << mesh.p2_node + 1 << "\n";
  if (mesh.p3_node >= 0) out << "*NSET, NSET=P3\n" << mesh.p3_node + 1 << "\n";

  if (skin_mat != nullptr)
    out << "*MATERIAL, NAME=" << skin_material << "\n"
        << "*ELASTIC\n"
        << real(skin_mat->youngs_modulus_pa * kMpaPerPa) << ", " << real(skin_mat->poisson_ratio)
        << "\n"
        << "*DENSITY\n"
        << real(skin_mat->density_kgpm3 * kTpmm3PerKgpm3) << "\n"
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

  // Joints (structure.md 2.1): P2 clamped; P3 translations plus the rotations its joint holds
  // (the universal joint: about the cross axis n_u, z_W: DOF 6, y_W: DOF 5), the same DOFs as
  // wingBoundaryDofs; with a pinned root edge every node on y_W = 0, midside nodes included.
  if (options.root_edge_pinned) {
    out << "*NSET, NSET=ROOT\n";
    const auto& x = nodes.positions();
    for (int i = 0; i < node_count; ++i)
      if (x[static_cast<std::size_t>(i)].y() == 0.0) out << i + 1 << "\n";
  }
  out << "*BOUNDARY\n" << "P2, 1, 6\n";
  if (mesh.p3_node >= 0) {
    WingSupport support;
    support.p3_joint = options.p3_joint;
    support.p3_cross_axis = options.p3_cross_axis_normal ? UniversalJointCrossAxis::kZW
                                                         : UniversalJointCrossAxis::kYW;
    out << "P3, 1, 3\n";
    for (int d : p3HeldRotations(support)) out << "P3, " << d + 1 << ", " << d + 1 << "\n";
  }
  if (options.root_edge_pinned) out << "ROOT, 1, 3\n";
  out << "*STEP\n*FREQUENCY\n" << options.mode_count << "\n";
  if (options.node_file) out << "*NODE FILE\nU\n";
  out << "*END STEP\n";

  if (stats != nullptr) {
    stats->nodes = node_count;
    stats->skin_elements = static_cast<int>(skin.nodes.size());
    stats->beam_elements = beam_count;
  }
  return out.str();
}

}  // namespace orni::structure
