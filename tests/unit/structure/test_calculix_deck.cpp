// CalculiX deck writer (docs/theory.md 2.7): parse the deck text of a small mesh back and check
// node and element counts, shared midside nodes, units (mm, MPa, t/mm^3) and the joints.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "core/structure/calculix_deck.hpp"
#include "core/structure/calculix_results.hpp"
#include "tests/unit/structure/fe_test_meshes.hpp"

namespace orni::structure {
namespace {

/// One keyword card of a deck: its keyword line ("*ELEMENT, TYPE=S6, ELSET=SKIN") and data lines
/// (comment lines "**" dropped).
struct Card {
  std::string keyword;
  std::vector<std::string> lines;
};

std::vector<Card> parseDeck(const std::string& text) {
  std::vector<Card> cards;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("**", 0) == 0) continue;
    if (!line.empty() && line[0] == '*') {
      cards.push_back({line, {}});
    } else {
      if (cards.empty()) throw std::runtime_error("data before the first keyword: " + line);
      cards.back().lines.push_back(line);
    }
  }
  return cards;
}

std::vector<double> numbers(const std::string& line) {
  std::vector<double> v;
  std::string cell;
  std::istringstream in(line);
  while (std::getline(in, cell, ',')) v.push_back(std::stod(cell));
  return v;
}

std::vector<const Card*> cardsStartingWith(const std::vector<Card>& cards,
                                           const std::string& prefix) {
  std::vector<const Card*> out;
  for (const Card& c : cards)
    if (c.keyword.rfind(prefix, 0) == 0) out.push_back(&c);
  return out;
}

/// Unique undirected edges of the triangles.
std::size_t edgeCount(const WingMesh& mesh) {
  std::set<std::pair<int, int>> edges;
  for (const auto& t : mesh.triangles)
    for (int i = 0; i < 3; ++i) {
      const int a = t[static_cast<std::size_t>(i)], b = t[static_cast<std::size_t>((i + 1) % 3)];
      edges.insert({std::min(a, b), std::max(a, b)});
    }
  return edges.size();
}

struct ParsedDeck {
  std::vector<Card> cards;
  std::map<int, Eigen::Vector3d> nodes_mm;
  std::map<std::string, std::vector<std::vector<int>>> elsets;  // "TYPE/ELSET" -> node lists
};

ParsedDeck parse(const std::string& text) {
  ParsedDeck d;
  d.cards = parseDeck(text);
  for (const Card* c : cardsStartingWith(d.cards, "*NODE,")) {
    for (const std::string& l : c->lines) {
      const std::vector<double> v = numbers(l);
      EXPECT_EQ(v.size(), 4u) << l;
      d.nodes_mm[static_cast<int>(v[0])] = Eigen::Vector3d(v[1], v[2], v[3]);
    }
  }
  for (const Card* c : cardsStartingWith(d.cards, "*ELEMENT")) {
    const std::size_t t = c->keyword.find("TYPE="), s = c->keyword.find("ELSET=");
    const std::string type = c->keyword.substr(t + 5, c->keyword.find(',', t) - t - 5);
    const std::string key = type + "/" + c->keyword.substr(s + 6);
    for (const std::string& l : c->lines) {
      const std::vector<double> v = numbers(l);
      std::vector<int> ids;
      for (std::size_t i = 1; i < v.size(); ++i) ids.push_back(static_cast<int>(v[i]));
      d.elsets[key].push_back(ids);
    }
  }
  return d;
}

TEST(StructureCalculixDeck, MiniWingS6CountsUnitsAndJoints) {
  const fe_test::MiniWing w = fe_test::miniWing(4, 8, 0.04, 0.08);
  CalculixDeckOptions o;
  o.skin = CalculixSkinElement::kS6;
  o.mode_count = 7;
  CalculixDeckStats stats;
  const std::string text = calculixDeck(w.vehicle, w.mesh, o, &stats);
  const ParsedDeck d = parse(text);

  // Nodes: mesh nodes + one midside node per edge (every beam lies on a triangle edge).
  const std::size_t n = static_cast<std::size_t>(w.mesh.nodeCount());
  ASSERT_EQ(edgeCount(w.mesh), 108u);
  EXPECT_EQ(d.nodes_mm.size(), n + 108u);
  EXPECT_EQ(stats.nodes, static_cast<int>(d.nodes_mm.size()));
  // Units: mm. Mesh node i is deck node i + 1.
  for (std::size_t i = 0; i < n; ++i)
    EXPECT_LT((d.nodes_mm.at(static_cast<int>(i) + 1) - 1e3 * w.mesh.nodes_W_m[i]).norm(), 1e-9);

  ASSERT_EQ(d.elsets.count("S6/SKIN"), 1u);
  const auto& skin = d.elsets.at("S6/SKIN");
  EXPECT_EQ(skin.size(), w.mesh.triangles.size());
  std::set<int> skin_nodes;
  for (const std::vector<int>& e : skin) {
    ASSERT_EQ(e.size(), 6u);
    skin_nodes.insert(e.begin(), e.end());
    // Midsides at the edge midpoints; normal +z_W (counter-clockwise corners).
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector3d mid =
          0.5 * (d.nodes_mm.at(e[static_cast<std::size_t>(k)]) +
                 d.nodes_mm.at(e[static_cast<std::size_t>((k + 1) % 3)]));
      EXPECT_LT((d.nodes_mm.at(e[static_cast<std::size_t>(k + 3)]) - mid).norm(), 1e-9);
    }
    const Eigen::Vector3d a = d.nodes_mm.at(e[0]), b = d.nodes_mm.at(e[1]), c = d.nodes_mm.at(e[2]);
    EXPECT_GT((b - a).cross(c - a).z(), 0.0);
  }
  EXPECT_EQ(skin_nodes.size(), d.nodes_mm.size());

  // Beams: one ELSET per member, B32R (end, middle, end) sharing the skin's midside nodes.
  ASSERT_EQ(d.elsets.count("B32R/B1_LE1"), 1u);
  ASSERT_EQ(d.elsets.count("B32R/B2_STIF"), 1u);
  EXPECT_EQ(d.elsets.at("B32R/B1_LE1").size(), 8u);
  EXPECT_EQ(d.elsets.at("B32R/B2_STIF").size(), 2u);
  for (const auto& name : {"B32R/B1_LE1", "B32R/B2_STIF"})
    for (const std::vector<int>& e : d.elsets.at(name)) {
      ASSERT_EQ(e.size(), 3u);
      EXPECT_EQ(skin_nodes.count(e[1]), 1u);
      EXPECT_LT((d.nodes_mm.at(e[1]) - 0.5 * (d.nodes_mm.at(e[0]) + d.nodes_mm.at(e[2]))).norm(),
                1e-9);
    }
  EXPECT_EQ(stats.skin_elements, 64);
  EXPECT_EQ(stats.beam_elements, 10);

  // Materials in MPa and t/mm^3, sections in mm. The skin is isotropic; each member has nu = 0,
  // G = E / (2 (1 + nu)) in its own axes (1 along the rod), against the knots' Poisson locking.
  EXPECT_NE(text.find("*MATERIAL, NAME=S3_SKIN\n*ELASTIC\n100000., 0.31\n*DENSITY\n5E-10\n"
                      "*SHELL SECTION, ELSET=SKIN, MATERIAL=S3_SKIN\n0.04\n"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("*ORIENTATION, NAME=OB1_LE1, SYSTEM=RECTANGULAR\n0., 1., 0., -1., 0., 0.\n"
                      "*MATERIAL, NAME=MB1_LE1\n*ELASTIC, TYPE=ENGINEERING CONSTANTS\n"
                      "250000., 250000., 250000., 0., 0., 0., 95419.8473282, 95419.8473282\n"
                      "95419.8473282\n*DENSITY\n1.8E-09\n"
                      "*BEAM SECTION, ELSET=B1_LE1, MATERIAL=MB1_LE1, SECTION=CIRC, "
                      "ORIENTATION=OB1_LE1\n2., 2.\n0., 0., 1.\n"),
            std::string::npos)
      << text;
  // The stiffener runs along the grid diagonal (dx, dy) = (10, 10) mm.
  EXPECT_NE(text.find("*ORIENTATION, NAME=OB2_STIF, SYSTEM=RECTANGULAR\n0.707106781187, "
                      "0.707106781187, 0., -0.707106781187, 0.707106781187, 0.\n"),
            std::string::npos);
  EXPECT_NE(text.find("*BEAM SECTION, ELSET=B2_STIF, MATERIAL=MB2_STIF, SECTION=CIRC, "
                      "ORIENTATION=OB2_STIF\n0.4, 0.4\n"),
            std::string::npos);
  EXPECT_EQ(cardsStartingWith(d.cards, "*MATERIAL").size(), 3u);  // skin + one per member

  // Joints: P2 clamped, P3 translations + rotation about z_W; the frequency step.
  const auto nsets = cardsStartingWith(d.cards, "*NSET");
  ASSERT_EQ(nsets.size(), 2u);
  EXPECT_EQ(nsets[0]->keyword, "*NSET, NSET=P2");
  EXPECT_EQ(nsets[0]->lines, std::vector<std::string>{std::to_string(w.mesh.p2_node + 1)});
  EXPECT_EQ(nsets[1]->keyword, "*NSET, NSET=P3");
  EXPECT_EQ(nsets[1]->lines, std::vector<std::string>{std::to_string(w.mesh.p3_node + 1)});
  const auto boundary = cardsStartingWith(d.cards, "*BOUNDARY");
  ASSERT_EQ(boundary.size(), 1u);
  EXPECT_EQ(boundary[0]->lines, (std::vector<std::string>{"P2, 1, 6", "P3, 1, 3", "P3, 6, 6"}));
  const auto freq = cardsStartingWith(d.cards, "*FREQUENCY");
  ASSERT_EQ(freq.size(), 1u);
  EXPECT_EQ(freq[0]->lines, std::vector<std::string>{"7"});
  EXPECT_EQ(cardsStartingWith(d.cards, "*STEP").size(), 1u);
  EXPECT_EQ(d.cards.back().keyword, "*END STEP");
}

TEST(StructureCalculixDeck, MiniWingSplitQuadsShareNodesWithBeams) {
  const fe_test::MiniWing w = fe_test::miniWing(4, 8, 0.04, 0.08);
  CalculixDeckOptions o;
  o.skin = CalculixSkinElement::kS8RSplit;
  o.p3_cross_axis_normal = false;
  const std::string text = calculixDeck(w.vehicle, w.mesh, o);
  const ParsedDeck d = parse(text);

  // Nodes: corners + edge midpoints + centroids + midpoints of the 2 halves of every edge and of
  // the 3 centroid spokes of every triangle.
  const std::size_t n = static_cast<std::size_t>(w.mesh.nodeCount());
  const std::size_t edges = edgeCount(w.mesh), tris = w.mesh.triangles.size();
  EXPECT_EQ(d.nodes_mm.size(), n + edges + tris + 2 * edges + 3 * tris);

  ASSERT_EQ(d.elsets.count("S8R/SKIN"), 1u);
  const auto& skin = d.elsets.at("S8R/SKIN");
  EXPECT_EQ(skin.size(), 3 * tris);
  std::set<int> skin_nodes;
  double area_mm2 = 0.0;
  for (const std::vector<int>& e : skin) {
    ASSERT_EQ(e.size(), 8u);
    skin_nodes.insert(e.begin(), e.end());
    for (int k = 0; k < 4; ++k) {
      const Eigen::Vector3d a = d.nodes_mm.at(e[static_cast<std::size_t>(k)]);
      const Eigen::Vector3d b = d.nodes_mm.at(e[static_cast<std::size_t>((k + 1) % 4)]);
      EXPECT_LT((d.nodes_mm.at(e[static_cast<std::size_t>(k + 4)]) - 0.5 * (a + b)).norm(), 1e-9);
      area_mm2 += 0.5 * a.cross(b).z();  // shoelace: counter-clockwise quads add up positively
    }
  }
  EXPECT_NEAR(area_mm2, 40.0 * 80.0, 1e-6);
  EXPECT_EQ(skin_nodes.size(), d.nodes_mm.size());

  // Each mesh beam element becomes two B32R on the halves of its edge.
  EXPECT_EQ(d.elsets.at("B32R/B1_LE1").size(), 16u);
  EXPECT_EQ(d.elsets.at("B32R/B2_STIF").size(), 4u);
  for (const auto& name : {"B32R/B1_LE1", "B32R/B2_STIF"})
    for (const std::vector<int>& e : d.elsets.at(name))
      for (int id : e) EXPECT_EQ(skin_nodes.count(id), 1u) << name << " node " << id;

  const auto boundary = cardsStartingWith(d.cards, "*BOUNDARY");
  ASSERT_EQ(boundary.size(), 1u);
  EXPECT_EQ(boundary[0]->lines, (std::vector<std::string>{"P2, 1, 6", "P3, 1, 3", "P3, 5, 5"}));
  EXPECT_EQ(cardsStartingWith(d.cards, "*FREQUENCY")[0]->lines,
            std::vector<std::string>{"12"});
}

TEST(StructureCalculixDeck, RejectsBadInput) {
  fe_test::MiniWing w = fe_test::miniWing(4, 8, 0.04, 0.08);
  CalculixDeckOptions o;
  o.mode_count = 0;
  EXPECT_THROW(calculixDeck(w.vehicle, w.mesh, o), std::invalid_argument);
  o.mode_count = 12;
  WingMesh no_p2 = w.mesh;
  no_p2.p2_node = -1;
  EXPECT_THROW(calculixDeck(w.vehicle, no_p2, o), std::invalid_argument);
  WingMesh bad_member = w.mesh;
  bad_member.beams.front().member = 5;
  EXPECT_THROW(calculixDeck(w.vehicle, bad_member, o), std::invalid_argument);
  w.vehicle.wing.skin.material = "NOPE";
  EXPECT_THROW(calculixDeck(w.vehicle, w.mesh, o), std::invalid_argument);
}

// Static steps (docs/theory.md 4.7): the load ladder, the dead pressure's consistent forces on the
// S6 midside nodes, nodal forces in N and N mm, clamped nodes with their edges' midside nodes,
// no P2 clamp, the printed node set.
TEST(StructureCalculixDeck, StaticStepsLoadsAndClampedNodes) {
  fe_test::MiniWing w = fe_test::miniWing(4, 8, 0.04, 0.08);
  const int n = w.mesh.nodeCount();
  CalculixDeckOptions o;
  o.frequency_step = false;
  o.clamp_p2 = false;
  o.clamped_nodes = {fe_test::gridNode(0, 0, 4), fe_test::gridNode(1, 0, 4)};  // one edge
  o.static_steps.load_factors = {0.5, 1.0};
  o.static_steps.load.skin_pressure_pa = 1000.0;  // 1e-3 MPa
  o.static_steps.load.nodal_load = Eigen::VectorXd::Zero(kDofsPerNode * n);
  o.static_steps.load.nodal_load(globalDof(3, kV)) = 2.0;          // N
  o.static_steps.load.nodal_load(globalDof(3, kThetaX)) = 0.25;    // N m -> 250 N mm
  o.static_steps.print_nodes = {3, 0};
  const std::string text = calculixDeck(w.vehicle, w.mesh, o);
  const ParsedDeck d = parse(text);

  EXPECT_TRUE(cardsStartingWith(d.cards, "*FREQUENCY").empty());
  const auto steps = cardsStartingWith(d.cards, "*STEP");
  ASSERT_EQ(steps.size(), 2u);
  EXPECT_EQ(steps[0]->keyword, "*STEP, NLGEOM, INC=1000");
  const auto statics = cardsStartingWith(d.cards, "*STATIC");
  ASSERT_EQ(statics.size(), 2u);
  EXPECT_EQ(statics[0]->lines, std::vector<std::string>{"0.05, 1., 1E-05, 0.25"});
  // Nodes sets: no P2; the clamped edge = its two ends + its midside node; NPRINT sorted.
  std::map<std::string, std::vector<std::string>> nsets;
  for (const Card* c : cardsStartingWith(d.cards, "*NSET")) nsets[c->keyword] = c->lines;
  EXPECT_EQ(nsets.count("*NSET, NSET=P2"), 0u);
  ASSERT_EQ(nsets.count("*NSET, NSET=CLAMPED"), 1u);
  const std::vector<std::string>& clamped = nsets.at("*NSET, NSET=CLAMPED");
  ASSERT_EQ(clamped.size(), 3u);
  const Eigen::Vector3d mid =
      0.5e3 * (w.mesh.nodes_W_m[static_cast<std::size_t>(fe_test::gridNode(0, 0, 4))] +
               w.mesh.nodes_W_m[static_cast<std::size_t>(fe_test::gridNode(1, 0, 4))]);
  EXPECT_LT((d.nodes_mm.at(std::stoi(clamped[2])) - mid).norm(), 1e-9);
  EXPECT_EQ(nsets.at("*NSET, NSET=NPRINT"), (std::vector<std::string>{"1", "4"}));
  const auto boundary = cardsStartingWith(d.cards, "*BOUNDARY");
  ASSERT_EQ(boundary.size(), 1u);
  EXPECT_EQ(boundary[0]->lines, (std::vector<std::string>{"P3, 1, 3", "P3, 6, 6", "CLAMPED, 1, 6"}));

  // Loads of the second step (factor 1): the pressure's z forces add up to p A, all on midside
  // nodes (ids > n); the nodal force and moment of node 3 (deck node 4).
  const auto cloads = cardsStartingWith(d.cards, "*CLOAD");
  ASSERT_EQ(cloads.size(), 2u);
  double fz = 0.0;
  for (const std::string& l : cloads[1]->lines) {
    const std::vector<double> v = numbers(l);
    ASSERT_EQ(v.size(), 3u);
    if (v[1] == 3.0) {
      EXPECT_GT(v[0], n) << l;
      fz += v[2];
    }
  }
  EXPECT_NEAR(fz, 1e-3 * 40.0 * 80.0, 1e-9);  // MPa x mm^2 = N
  EXPECT_NE(std::find(cloads[1]->lines.begin(), cloads[1]->lines.end(), "4, 2, 2."),
            cloads[1]->lines.end());
  EXPECT_NE(std::find(cloads[1]->lines.begin(), cloads[1]->lines.end(), "4, 4, 250."),
            cloads[1]->lines.end());
  EXPECT_NE(std::find(cloads[0]->lines.begin(), cloads[0]->lines.end(), "4, 4, 125."),
            cloads[0]->lines.end());
  EXPECT_EQ(cardsStartingWith(d.cards, "*NODE PRINT").size(), 2u);

  // Follower pressure: *DLOAD P on the skin instead; linear steps without NLGEOM.
  o.static_steps.load.follower_pressure = true;
  o.static_steps.load.nodal_load.resize(0);
  o.static_steps.nlgeom = false;
  const ParsedDeck f = parse(calculixDeck(w.vehicle, w.mesh, o));
  const auto dloads = cardsStartingWith(f.cards, "*DLOAD");
  ASSERT_EQ(dloads.size(), 2u);
  EXPECT_EQ(dloads[1]->lines, std::vector<std::string>{"SKIN, P, 0.001"});
  EXPECT_TRUE(cardsStartingWith(f.cards, "*CLOAD").empty());
  EXPECT_EQ(cardsStartingWith(f.cards, "*STEP")[0]->keyword, "*STEP, INC=1000");
  // Without a shrink, no thermal card at all.
  EXPECT_TRUE(cardsStartingWith(f.cards, "*EXPANSION").empty());
  EXPECT_TRUE(cardsStartingWith(f.cards, "*TEMPERATURE").empty());

  // A shrunk skin (skin_pretension.hpp): the skin material expands by 1 per degree, every node
  // starts at 0 and is at -s in every static step.
  o.static_steps.skin_shrink_strain = 2.5e-6;
  const ParsedDeck sh = parse(calculixDeck(w.vehicle, w.mesh, o));
  const auto expansion = cardsStartingWith(sh.cards, "*EXPANSION");
  ASSERT_EQ(expansion.size(), 1u);  // the skin's only: the rods do not shrink
  EXPECT_EQ(expansion[0]->lines, std::vector<std::string>{"1."});
  const auto initial = cardsStartingWith(sh.cards, "*INITIAL CONDITIONS");
  ASSERT_EQ(initial.size(), 1u);
  EXPECT_EQ(initial[0]->keyword, "*INITIAL CONDITIONS, TYPE=TEMPERATURE");
  EXPECT_EQ(initial[0]->lines, std::vector<std::string>{"NALL, 0."});
  const auto temperatures = cardsStartingWith(sh.cards, "*TEMPERATURE");
  ASSERT_EQ(temperatures.size(), 2u);
  EXPECT_EQ(temperatures[1]->lines, std::vector<std::string>{"NALL, -2.5E-06"});
  o.static_steps.skin_shrink_strain = 0.0;

  // Bad static input.
  CalculixDeckOptions bad = o;
  bad.static_steps.load.nodal_load = Eigen::VectorXd::Zero(5);
  EXPECT_THROW(calculixDeck(w.vehicle, w.mesh, bad), std::invalid_argument);
  bad = o;
  bad.static_steps.load_factors.clear();
  EXPECT_THROW(calculixDeck(w.vehicle, w.mesh, bad), std::invalid_argument);  // no step at all
  bad = o;
  bad.clamped_nodes = {n};
  EXPECT_THROW(calculixDeck(w.vehicle, w.mesh, bad), std::invalid_argument);
}

TEST(StructureCalculixResults, ReadsDisplacementTablesOfADatFile) {
  std::istringstream dat(
      "\n displacements (vx,vy,vz) for set NPRINT and time  0.5000000E+00\n\n"
      "         1  1.0E-01 -2.0E-01  3.0E+00\n         4  0.0  0.0 -1.5E+01\n\n"
      " stresses (elem, integ.pnt.,sxx,syy,szz,sxy,sxz,syz) for set EALL and time  0.5\n\n"
      "         1   1  1.0 2.0 3.0 4.0 5.0 6.0\n\n"
      " displacements (vx,vy,vz) for set NPRINT and time  0.1000000E+01\n\n"
      "         1  2.0E-01 -4.0E-01  6.0E+00\n\n");
  const std::vector<CalculixDisplacementTable> tables = readCalculixDisplacements(dat);
  ASSERT_EQ(tables.size(), 2u);
  EXPECT_EQ(tables[0].set, "NPRINT");
  EXPECT_DOUBLE_EQ(tables[0].time, 0.5);
  EXPECT_EQ(tables[0].displacement_mm.size(), 2u);
  EXPECT_DOUBLE_EQ(tables[0].displacement_mm.at(4).z(), -15.0);
  const CalculixDisplacementTable* end = calculixTableAt(tables, 1.0);
  ASSERT_NE(end, nullptr);
  EXPECT_EQ(calculixTableAt(tables, 2.0), nullptr);
  const Eigen::Matrix3Xd u = meshDisplacements(*end, 3);  // mesh node 0 = ccx node 1, in m
  EXPECT_DOUBLE_EQ(u(2, 0), 6e-3);
  EXPECT_TRUE(std::isnan(u(0, 1)));
}

}  // namespace
}  // namespace orni::structure
