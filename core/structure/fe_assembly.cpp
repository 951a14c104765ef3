// Triplet assembly of the wing FE model (docs/theory.md 2.6).
#include "core/structure/fe_assembly.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "core/structure/beam_element.hpp"
#include "core/structure/shell_element.hpp"

namespace orni::structure {
namespace {

using Triplet = Eigen::Triplet<double, int>;

const Material& requireMaterial(const WingStructure& wing_structure, const std::string& name,
                                const char* what) {
  const Material* m = wing_structure.findMaterial(name);
  if (m == nullptr)
    throw std::invalid_argument(std::string("wing FE model: ") + what + " material '" + name +
                                "' not found in [materials]");
  return *m;
}

}  // namespace

std::vector<BeamProperties> memberBeamProperties(const WingStructure& wing_structure) {
  std::vector<BeamProperties> props;
  props.reserve(wing_structure.wing.members.size());
  for (const WingMember& member : wing_structure.wing.members) {
    const Material& mat = requireMaterial(wing_structure, member.material, "member");
    props.push_back(makeBeamProperties(solidRodSection(wing_structure.wing.memberDiameter(member)), mat.youngs_modulus_pa,
                                       mat.poisson_ratio, mat.density_kgpm3));
  }
  return props;
}

ShellProperties skinShellProperties(const WingStructure& wing_structure) {
  const WingSkin& skin = wing_structure.wing.skin;
  if (!(skin.thickness_m > 0.0))
    throw std::invalid_argument("wing FE model: expected skin thickness > 0, got " +
                                std::to_string(skin.thickness_m));
  const Material& mat = requireMaterial(wing_structure, skin.material, "skin");
  ShellProperties p;
  p.thickness_m = skin.thickness_m;
  p.youngs_modulus_pa = mat.youngs_modulus_pa;
  p.poisson_ratio = mat.poisson_ratio;
  p.density_kgpm3 = mat.density_kgpm3;
  return p;
}

namespace {

void checkNode(int node, int node_count) {
  if (node < 0 || node >= node_count)
    throw std::invalid_argument("wing FE model: node index " + std::to_string(node) +
                                " outside [0, " + std::to_string(node_count) + ")");
}

const BeamProperties& beamProps(const std::vector<BeamProperties>& props, const BeamElement& b) {
  if (b.member < 0 || b.member >= static_cast<int>(props.size()))
    throw std::invalid_argument("wing FE model: beam member index " + std::to_string(b.member) +
                                " outside [0, " + std::to_string(props.size()) + ")");
  return props[static_cast<std::size_t>(b.member)];
}

// Scatters the nonzero entries of an element matrix (nodes.size() * 6 square).
template <typename Matrix, std::size_t N>
void scatter(const Matrix& ke, const std::array<int, N>& nodes, std::vector<Triplet>& out) {
  for (std::size_t b = 0; b < N; ++b)
    for (int j = 0; j < kDofsPerNode; ++j) {
      const int col = globalDof(nodes[b], j);
      const int cl = kDofsPerNode * static_cast<int>(b) + j;
      for (std::size_t a = 0; a < N; ++a)
        for (int i = 0; i < kDofsPerNode; ++i) {
          const double v = ke(kDofsPerNode * static_cast<int>(a) + i, cl);
          if (v != 0.0) out.emplace_back(globalDof(nodes[a], i), col, v);
        }
    }
}

std::array<Vec3, 3> facetNodes(const WingMesh& mesh, const std::array<int, 3>& tri) {
  return {mesh.nodes_W_m[static_cast<std::size_t>(tri[0])],
          mesh.nodes_W_m[static_cast<std::size_t>(tri[1])],
          mesh.nodes_W_m[static_cast<std::size_t>(tri[2])]};
}

}  // namespace

std::vector<bool> dofActivityMask(const WingMesh& mesh) {
  const int n = mesh.nodeCount();
  std::vector<bool> on_beam(static_cast<std::size_t>(n), false);
  std::vector<bool> on_facet(static_cast<std::size_t>(n), false);
  for (const BeamElement& b : mesh.beams)
    for (int node : b.nodes) {
      checkNode(node, n);
      on_beam[static_cast<std::size_t>(node)] = true;
    }
  for (const auto& tri : mesh.triangles)
    for (int node : tri) {
      checkNode(node, n);
      on_facet[static_cast<std::size_t>(node)] = true;
    }
  std::vector<bool> active(static_cast<std::size_t>(kDofsPerNode * n), false);
  for (int p = 0; p < n; ++p) {
    const bool beam = on_beam[static_cast<std::size_t>(p)];
    const bool any = beam || on_facet[static_cast<std::size_t>(p)];
    for (int d = 0; d < kDofsPerNode; ++d)
      active[static_cast<std::size_t>(globalDof(p, d))] = any && (beam || d != kThetaZ);
  }
  return active;
}

WingSupport WingSupport::of(const WingFeSettings& fe) {
  WingSupport s;
  s.p3_joint = fe.p3_joint;
  s.p3_cross_axis =
      fe.p3_cross_axis_normal ? UniversalJointCrossAxis::kZW : UniversalJointCrossAxis::kYW;
  s.root_edge_pinned = fe.root_edge_pinned;
  return s;
}

std::vector<int> p3HeldRotations(const WingSupport& support) {
  switch (support.p3_joint) {
    case P3Joint::kUniversal:
      return {support.p3_cross_axis == UniversalJointCrossAxis::kZW ? kThetaZ : kThetaY};
    case P3Joint::kSpherical: return {};
    case P3Joint::kRevoluteX: return {kThetaY, kThetaZ};
    case P3Joint::kClamped: return {kThetaX, kThetaY, kThetaZ};
  }
  return {};
}

std::vector<int> rootChordNodes(const WingMesh& mesh) {
  std::vector<int> nodes;
  for (int p = 0; p < mesh.nodeCount(); ++p)
    if (mesh.nodes_W_m[static_cast<std::size_t>(p)].y() == 0.0) nodes.push_back(p);
  return nodes;
}

std::vector<int> wingBoundaryDofs(const WingMesh& mesh, const WingSupport& support) {
  std::vector<int> dofs;
  if (mesh.p2_node >= 0) {
    checkNode(mesh.p2_node, mesh.nodeCount());
    for (int d = 0; d < kDofsPerNode; ++d) dofs.push_back(globalDof(mesh.p2_node, d));
  }
  if (mesh.p3_node >= 0 && mesh.p3_node != mesh.p2_node) {
    checkNode(mesh.p3_node, mesh.nodeCount());
    for (int d : {kU, kV, kW}) dofs.push_back(globalDof(mesh.p3_node, d));
    for (int d : p3HeldRotations(support)) dofs.push_back(globalDof(mesh.p3_node, d));
  }
  if (support.root_edge_pinned)
    for (int p : rootChordNodes(mesh))
      for (int d : {kU, kV, kW}) dofs.push_back(globalDof(p, d));
  std::sort(dofs.begin(), dofs.end());
  dofs.erase(std::unique(dofs.begin(), dofs.end()), dofs.end());
  return dofs;
}

WingFeModel assembleWingFe(const WingStructure& wing_structure, const WingMesh& mesh,
                           const FeAssemblyOptions& options) {
  const int n = mesh.nodeCount();
  WingFeModel model;
  model.node_count = n;
  model.active = dofActivityMask(mesh);  // also validates node indices

  const std::vector<BeamProperties> members = memberBeamProperties(wing_structure);
  const bool lumped = options.mass == MassLumping::kLumped;

  std::vector<Triplet> k_triplets, m_triplets;
  const std::size_t estimate = 144 * mesh.beams.size() + 120 * mesh.triangles.size();
  k_triplets.reserve(estimate);
  m_triplets.reserve(estimate);

  for (const BeamElement& b : mesh.beams) {
    const BeamProperties& p = beamProps(members, b);
    const Vec3& x1 = mesh.nodes_W_m[static_cast<std::size_t>(b.nodes[0])];
    const Vec3& x2 = mesh.nodes_W_m[static_cast<std::size_t>(b.nodes[1])];
    const Vec3& n_W = options.beam_orientation_W;
    scatter(beamStiffness(x1, x2, n_W, p), b.nodes, k_triplets);
    scatter(lumped ? beamLumpedMass(x1, x2, n_W, p) : beamConsistentMass(x1, x2, n_W, p), b.nodes,
            m_triplets);
    model.member_mass_kg += p.density_kgpm3 * p.section.area_m2 * (x2 - x1).norm();
  }

  if (!mesh.triangles.empty()) {
    const ShellProperties skin = skinShellProperties(wing_structure);
    for (const auto& tri : mesh.triangles) {
      const std::array<Vec3, 3> x = facetNodes(mesh, tri);
      scatter(shellStiffness(x, skin), tri, k_triplets);
      scatter(lumped ? shellLumpedMass(x, skin) : shellConsistentMass(x, skin), tri, m_triplets);
      model.skin_mass_kg += skin.density_kgpm3 * skin.thickness_m * triangleArea(x);
    }
  }

  const int dofs = model.dofCount();
  model.stiffness.resize(dofs, dofs);
  model.mass.resize(dofs, dofs);
  model.stiffness.setFromTriplets(k_triplets.begin(), k_triplets.end());
  model.mass.setFromTriplets(m_triplets.begin(), m_triplets.end());
  return model;
}

LumpedNodalMass lumpedNodalMass(const WingStructure& wing_structure, const WingMesh& mesh,
                                const Vec3& beam_orientation_W) {
  const int n = mesh.nodeCount();
  LumpedNodalMass out;
  out.mass_kg = Eigen::VectorXd::Zero(n);
  out.rotary_W_kgm2.assign(static_cast<std::size_t>(n), Mat3::Zero());
  const std::vector<BeamProperties> members = memberBeamProperties(wing_structure);
  for (const BeamElement& b : mesh.beams) {
    for (int node : b.nodes) checkNode(node, n);
    const Mat12 m = beamLumpedMass(mesh.nodes_W_m[static_cast<std::size_t>(b.nodes[0])],
                                   mesh.nodes_W_m[static_cast<std::size_t>(b.nodes[1])],
                                   beam_orientation_W, beamProps(members, b));
    for (int a = 0; a < 2; ++a) {
      out.mass_kg(b.nodes[static_cast<std::size_t>(a)]) += m(6 * a, 6 * a);
      out.rotary_W_kgm2[static_cast<std::size_t>(b.nodes[static_cast<std::size_t>(a)])] +=
          m.block<3, 3>(6 * a + 3, 6 * a + 3);
    }
  }
  if (!mesh.triangles.empty()) {
    const ShellProperties skin = skinShellProperties(wing_structure);
    for (const auto& tri : mesh.triangles) {
      for (int node : tri) checkNode(node, n);
      const Mat18 m = shellLumpedMass(facetNodes(mesh, tri), skin);
      for (int a = 0; a < 3; ++a) {
        out.mass_kg(tri[static_cast<std::size_t>(a)]) += m(6 * a, 6 * a);
        out.rotary_W_kgm2[static_cast<std::size_t>(tri[static_cast<std::size_t>(a)])] +=
            m.block<3, 3>(6 * a + 3, 6 * a + 3);
      }
    }
  }
  return out;
}

}  // namespace orni::structure
