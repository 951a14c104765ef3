// Geometric stiffness of the inertial loads (docs/theory.md 2.2, 4.6).
#include "core/structure/geometric_stiffness.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include <Eigen/SparseCholesky>

#include "core/structure/beam_element.hpp"
#include "core/structure/shell_element.hpp"

namespace orni::structure {
namespace {

using Vec2 = Eigen::Vector2d;
using Triplet = Eigen::Triplet<double, int>;

std::array<Vec3, 3> facetNodes(const WingMesh& mesh, const std::array<int, 3>& tri) {
  return {mesh.nodes_W_m[static_cast<std::size_t>(tri[0])],
          mesh.nodes_W_m[static_cast<std::size_t>(tri[1])],
          mesh.nodes_W_m[static_cast<std::size_t>(tri[2])]};
}

// The facet in its triad: local 2-D vertex coordinates (origin at vertex 1), the gradients of the
// linear shape functions G (2 x 3: rows d/dx, d/dy) and the area.
struct FacetFrame {
  Mat3 triad;
  std::array<Vec2, 3> xy;
  Eigen::Matrix<double, 2, 3> grad;
  double area_m2 = 0.0;
};

FacetFrame facetFrame(const std::array<Vec3, 3>& x) {
  FacetFrame f;
  f.triad = shellTriad(x);
  for (int i = 0; i < 3; ++i) {
    const Vec3 d = x[static_cast<std::size_t>(i)] - x[0];
    f.xy[static_cast<std::size_t>(i)] = Vec2(f.triad.row(0).dot(d), f.triad.row(1).dot(d));
  }
  const Eigen::Matrix<double, 3, 6> bm = cstStrainMatrix(f.xy);  // rows eps_x, eps_y, gamma
  for (int a = 0; a < 3; ++a) {
    f.grad(0, a) = bm(0, 2 * a);      // dN_a/dx
    f.grad(1, a) = bm(1, 2 * a + 1);  // dN_a/dy
  }
  f.area_m2 = triangleArea(x);
  return f;
}

Mat3 planeStressStiffness(const ShellProperties& p) {
  const double nu = p.poisson_ratio;
  Mat3 c;
  c << 1.0, nu, 0.0, nu, 1.0, 0.0, 0.0, 0.0, 0.5 * (1.0 - nu);
  return (p.youngs_modulus_pa * p.thickness_m / (1.0 - nu * nu)) * c;
}

const BeamProperties& beamProps(const std::vector<BeamProperties>& props, const BeamElement& b) {
  if (b.member < 0 || b.member >= static_cast<int>(props.size()))
    throw std::invalid_argument("geometric stiffness: beam member index " +
                                std::to_string(b.member) + " outside [0, " +
                                std::to_string(props.size()) + ")");
  return props[static_cast<std::size_t>(b.member)];
}

// Rows of the 12 element DOFs (node a then node b) of a 6n x cols matrix.
Eigen::Matrix<double, 12, Eigen::Dynamic> beamRows(const Eigen::MatrixXd& a, const BeamElement& b) {
  Eigen::Matrix<double, 12, Eigen::Dynamic> out(12, a.cols());
  out.topRows<6>() = a.middleRows<6>(globalDof(b.nodes[0], 0));
  out.bottomRows<6>() = a.middleRows<6>(globalDof(b.nodes[1], 0));
  return out;
}

}  // namespace

InertialLoad spinLoad(int k, int l) {
  if (k > l) std::swap(k, l);
  if (k == l) return static_cast<InertialLoad>(kLoadSpinXX + k);
  if (k == 0) return l == 1 ? kLoadSpinXY : kLoadSpinXZ;
  return kLoadSpinYZ;
}

Eigen::MatrixXd unitInertialAccelerations(const std::vector<Vec3>& nodes_W_m,
                                          const Vec3& origin_W_m) {
  const auto n = static_cast<Eigen::Index>(nodes_W_m.size());
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(kDofsPerNode * n, kInertialLoadCount);
  for (Eigen::Index p = 0; p < n; ++p) {
    const Vec3 x = nodes_W_m[static_cast<std::size_t>(p)] - origin_W_m;
    auto t = [&](int load) { return a.block<3, 1>(kDofsPerNode * p, load); };
    for (int k = 0; k < 3; ++k) {
      const Vec3 e = Vec3::Unit(k);
      t(kLoadAccelX + k) = e;
      t(kLoadAlphaX + k) = e.cross(x);
      a(kDofsPerNode * p + 3 + k, kLoadAlphaX + k) = 1.0;
      t(kLoadSpinXX + k) = x(k) * e - x;  // w x (w x x) for w = e_k
      for (int l = k + 1; l < 3; ++l) t(spinLoad(k, l)) = x(l) * e + x(k) * Vec3::Unit(l);
    }
  }
  return a;
}

bool isInPlaneLoad(InertialLoad load) {
  switch (load) {
    case kLoadAccelZ:
    case kLoadAlphaX:
    case kLoadAlphaY:
    case kLoadSpinXZ:
    case kLoadSpinYZ:
      return false;
    default:
      return true;
  }
}

UnitInertialLoadSolution solveUnitInertialLoads(const WingFeModel& fe, const DofPartition& part,
                                                const std::vector<Vec3>& nodes_W_m,
                                                const Vec3& origin_W_m) {
  if (static_cast<int>(nodes_W_m.size()) != fe.node_count)
    throw std::invalid_argument("unit inertial loads: one position per FE node expected");
  UnitInertialLoadSolution s;
  s.loads = -(fe.mass * unitInertialAccelerations(nodes_W_m, origin_W_m));
  double extent = 0.0, height = 0.0;
  for (const Vec3& x : nodes_W_m) {
    extent = std::max(extent, (x - origin_W_m).norm());
    height = std::max(height, std::abs(x.z() - origin_W_m.z()));
  }
  s.flat = height <= 1e-12 * extent;
  std::vector<int> free;
  for (int d : part.retained()) {
    const int slot = d % kDofsPerNode;
    if (!s.flat || slot == kU || slot == kV || slot == kThetaZ) free.push_back(d);
  }
  std::sort(free.begin(), free.end());
  std::vector<int> loads;
  for (int i = 0; i < kInertialLoadCount; ++i) {
    s.solved[static_cast<std::size_t>(i)] = !s.flat || isInPlaneLoad(static_cast<InertialLoad>(i));
    if (s.solved[static_cast<std::size_t>(i)]) loads.push_back(i);
  }
  if (free.empty()) throw std::invalid_argument("unit inertial loads: no free DOF");
  const SparseMatrix k_ff = extractBlock(fe.stiffness, free, free);
  Eigen::SimplicialLDLT<SparseMatrix, Eigen::Lower, Eigen::AMDOrdering<int>> ldlt(k_ff);
  if (ldlt.info() != Eigen::Success)
    throw std::runtime_error("unit inertial loads: the stiffness over the free DOFs is singular");
  Eigen::MatrixXd f_free(static_cast<Eigen::Index>(free.size()),
                         static_cast<Eigen::Index>(loads.size()));
  for (std::size_t i = 0; i < free.size(); ++i)
    for (std::size_t j = 0; j < loads.size(); ++j)
      f_free(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) =
          s.loads(free[i], loads[j]);
  const Eigen::MatrixXd u_free = ldlt.solve(f_free);
  if (ldlt.info() != Eigen::Success || !u_free.allFinite())
    throw std::runtime_error("unit inertial loads: the static solve failed");
  const Eigen::MatrixXd u = expandRows(u_free, free, fe.dofCount());
  s.displacements.setZero(fe.dofCount(), kInertialLoadCount);
  for (std::size_t j = 0; j < loads.size(); ++j)
    s.displacements.col(loads[j]) = u.col(static_cast<Eigen::Index>(j));
  return s;
}

ElementStresses recoverElementStresses(const WingStructure& wing_structure, const WingMesh& mesh,
                                       const Eigen::MatrixXd& displacements) {
  if (displacements.rows() != kDofsPerNode * static_cast<Eigen::Index>(mesh.nodeCount()))
    throw std::invalid_argument("element stresses: displacements must have 6 rows per node");
  const Eigen::Index fields = displacements.cols();
  ElementStresses out;
  out.beam_axial_force_N.setZero(static_cast<Eigen::Index>(mesh.beams.size()), fields);
  out.skin_membrane_force_Npm.setZero(3 * static_cast<Eigen::Index>(mesh.triangles.size()),
                                      fields);
  const std::vector<BeamProperties> members = memberBeamProperties(wing_structure);
  for (std::size_t e = 0; e < mesh.beams.size(); ++e) {
    const BeamElement& b = mesh.beams[e];
    const Vec3& x1 = mesh.nodes_W_m[static_cast<std::size_t>(b.nodes[0])];
    const Vec3& x2 = mesh.nodes_W_m[static_cast<std::size_t>(b.nodes[1])];
    const BeamProperties& p = beamProps(members, b);
    const double length = (x2 - x1).norm();
    const Vec3 axis = (x2 - x1) / length;
    const double ea_per_l = p.youngs_modulus_pa * p.section.area_m2 / length;
    out.beam_axial_force_N.row(static_cast<Eigen::Index>(e)) =
        ea_per_l * axis.transpose() *
        (displacements.middleRows<3>(globalDof(b.nodes[1], kU)) -
         displacements.middleRows<3>(globalDof(b.nodes[0], kU)));
  }
  if (mesh.triangles.empty()) return out;
  const ShellProperties skin = skinShellProperties(wing_structure);
  const Mat3 c_t = planeStressStiffness(skin);
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    const std::array<int, 3>& tri = mesh.triangles[f];
    const FacetFrame fr = facetFrame(facetNodes(mesh, tri));
    const Eigen::Matrix<double, 3, 6> bm = cstStrainMatrix(fr.xy);
    Eigen::MatrixXd membrane(6, fields);  // (u, v) in the triad of the three vertices
    for (int a = 0; a < 3; ++a)
      membrane.middleRows<2>(2 * a) =
          fr.triad.topRows<2>() * displacements.middleRows<3>(globalDof(tri[static_cast<std::size_t>(a)], kU));
    out.skin_membrane_force_Npm.middleRows<3>(3 * static_cast<Eigen::Index>(f)) =
        c_t * (bm * membrane);
  }
  return out;
}

Mat18 shellMembraneGeometricStiffness(const std::array<Vec3, 3>& x_W_m,
                                      const Vec3& membrane_force_Npm) {
  const FacetFrame fr = facetFrame(x_W_m);
  Eigen::Matrix2d n;
  n << membrane_force_Npm(0), membrane_force_Npm(2), membrane_force_Npm(2), membrane_force_Npm(1);
  const Mat3 k_w = fr.area_m2 * (fr.grad.transpose() * n * fr.grad);
  // Facet-normal displacement of node a: n^T u_a, n = row 2 of the triad.
  const Vec3 normal = fr.triad.row(2).transpose();
  Mat18 k = Mat18::Zero();
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b)
      k.block<3, 3>(6 * a, 6 * b) = k_w(a, b) * normal * normal.transpose();
  return k;
}

SparseMatrix assembleGeometricStiffness(const WingStructure& wing_structure, const WingMesh& mesh,
                                        const ElementStresses& stresses, int field,
                                        const FeAssemblyOptions& options) {
  const std::vector<BeamProperties> members = memberBeamProperties(wing_structure);
  std::vector<Triplet> trip;
  trip.reserve(144 * mesh.beams.size() + 36 * mesh.triangles.size());
  auto scatter = [&trip](const auto& ke, const auto& nodes) {
    const int count = static_cast<int>(nodes.size());
    for (int a = 0; a < count; ++a)
      for (int i = 0; i < kDofsPerNode; ++i)
        for (int b = 0; b < count; ++b)
          for (int j = 0; j < kDofsPerNode; ++j) {
            const double v = ke(kDofsPerNode * a + i, kDofsPerNode * b + j);
            if (v != 0.0)
              trip.emplace_back(globalDof(nodes[static_cast<std::size_t>(a)], i),
                                globalDof(nodes[static_cast<std::size_t>(b)], j), v);
          }
  };
  for (std::size_t e = 0; e < mesh.beams.size(); ++e) {
    const BeamElement& b = mesh.beams[e];
    scatter(beamGeometricStiffness(mesh.nodes_W_m[static_cast<std::size_t>(b.nodes[0])],
                                   mesh.nodes_W_m[static_cast<std::size_t>(b.nodes[1])],
                                   options.beam_orientation_W, beamProps(members, b),
                                   stresses.beam_axial_force_N(static_cast<Eigen::Index>(e), field),
                                   true),
            b.nodes);
  }
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f)
    scatter(shellMembraneGeometricStiffness(
                facetNodes(mesh, mesh.triangles[f]),
                stresses.skin_membrane_force_Npm.block<3, 1>(3 * static_cast<Eigen::Index>(f),
                                                             field)),
            mesh.triangles[f]);
  const int dofs = kDofsPerNode * mesh.nodeCount();
  SparseMatrix k(dofs, dofs);
  k.setFromTriplets(trip.begin(), trip.end());
  return k;
}

std::vector<Eigen::MatrixXd> projectGeometricStiffness(const WingStructure& wing_structure,
                                                       const WingMesh& mesh,
                                                       const ElementStresses& stresses,
                                                       const Eigen::MatrixXd& shapes,
                                                       const FeAssemblyOptions& options) {
  const Eigen::Index m = shapes.cols();
  const Eigen::Index fields = stresses.beam_axial_force_N.cols();
  if (shapes.rows() != kDofsPerNode * static_cast<Eigen::Index>(mesh.nodeCount()))
    throw std::invalid_argument("geometric stiffness: shapes must have 6 rows per node");
  if (stresses.beam_axial_force_N.rows() != static_cast<Eigen::Index>(mesh.beams.size()) ||
      stresses.skin_membrane_force_Npm.rows() != 3 * static_cast<Eigen::Index>(mesh.triangles.size()) ||
      stresses.skin_membrane_force_Npm.cols() != fields)
    throw std::invalid_argument("geometric stiffness: stresses do not match the mesh");
  // K^ as column-major vec(K^) (M^2) per field: beams sum_e N_e vec(Phi_e^T K_G,e(1) Phi_e).
  Eigen::MatrixXd vec_k = Eigen::MatrixXd::Zero(m * m, fields);
  if (!mesh.beams.empty()) {
    const std::vector<BeamProperties> members = memberBeamProperties(wing_structure);
    Eigen::MatrixXd per_element(m * m, static_cast<Eigen::Index>(mesh.beams.size()));
    Eigen::MatrixXd w(m, m);
    for (std::size_t e = 0; e < mesh.beams.size(); ++e) {
      const BeamElement& b = mesh.beams[e];
      const Mat12 k1 = beamGeometricStiffness(mesh.nodes_W_m[static_cast<std::size_t>(b.nodes[0])],
                                              mesh.nodes_W_m[static_cast<std::size_t>(b.nodes[1])],
                                              options.beam_orientation_W, beamProps(members, b),
                                              1.0, true);
      const Eigen::Matrix<double, 12, Eigen::Dynamic> phi = beamRows(shapes, b);
      w.noalias() = phi.transpose() * (k1 * phi);
      per_element.col(static_cast<Eigen::Index>(e)) = Eigen::Map<const Eigen::VectorXd>(w.data(), m * m);
    }
    vec_k.noalias() += per_element * stresses.beam_axial_force_N;
  }
  std::vector<Eigen::MatrixXd> out(static_cast<std::size_t>(fields));
  for (Eigen::Index i = 0; i < fields; ++i)
    out[static_cast<std::size_t>(i)] = Eigen::Map<const Eigen::MatrixXd>(vec_k.col(i).data(), m, m);
  if (!mesh.triangles.empty()) {
    // Skin: modal gradients of the facet-normal displacement d_x, d_y (rows per facet) and
    // K^ += D_x^T diag(A N_xx) D_x + D_y^T diag(A N_yy) D_y + [D_x^T diag(A N_xy) D_y + sym.].
    const auto nf = static_cast<Eigen::Index>(mesh.triangles.size());
    Eigen::MatrixXd dx(nf, m), dy(nf, m), scaled(nf, m), cross(m, m);
    Eigen::VectorXd area(nf);
    for (Eigen::Index f = 0; f < nf; ++f) {
      const std::array<int, 3>& tri = mesh.triangles[static_cast<std::size_t>(f)];
      const FacetFrame fr = facetFrame(facetNodes(mesh, tri));
      const Vec3 normal = fr.triad.row(2).transpose();
      Eigen::Matrix<double, 3, Eigen::Dynamic> w_nodes(3, m);
      for (int a = 0; a < 3; ++a)
        w_nodes.row(a) = normal.transpose() *
                         shapes.middleRows<3>(globalDof(tri[static_cast<std::size_t>(a)], kU));
      dx.row(f) = fr.grad.row(0) * w_nodes;
      dy.row(f) = fr.grad.row(1) * w_nodes;
      area(f) = fr.area_m2;
    }
    for (Eigen::Index i = 0; i < fields; ++i) {
      if (stresses.skin_membrane_force_Npm.col(i).isZero(0.0)) continue;  // e.g. bending loads
      Eigen::VectorXd nxx(nf), nyy(nf), nxy(nf);
      for (Eigen::Index f = 0; f < nf; ++f) {
        nxx(f) = area(f) * stresses.skin_membrane_force_Npm(3 * f, i);
        nyy(f) = area(f) * stresses.skin_membrane_force_Npm(3 * f + 1, i);
        nxy(f) = area(f) * stresses.skin_membrane_force_Npm(3 * f + 2, i);
      }
      Eigen::MatrixXd& k = out[static_cast<std::size_t>(i)];
      scaled = nxx.asDiagonal() * dx;
      k.noalias() += dx.transpose() * scaled;
      scaled = nyy.asDiagonal() * dy;
      k.noalias() += dy.transpose() * scaled;
      scaled = nxy.asDiagonal() * dy;
      cross.noalias() = dx.transpose() * scaled;
      k += cross + cross.transpose();
    }
  }
  for (Eigen::MatrixXd& k : out) k = 0.5 * (k + k.transpose()).eval();
  return out;
}

ModalGeometricStiffness modalGeometricStiffness(const WingStructure& wing_structure, const WingMesh& mesh,
                                                const WingFeModel& fe, const DofPartition& part,
                                                const Eigen::MatrixXd& shapes,
                                                const FeAssemblyOptions& options) {
  if (mesh.p2_node < 0 || mesh.p2_node >= mesh.nodeCount())
    throw std::invalid_argument("geometric stiffness: the mesh has no valid P2 node");
  const UnitInertialLoadSolution unit = solveUnitInertialLoads(
      fe, part, mesh.nodes_W_m, mesh.nodes_W_m[static_cast<std::size_t>(mesh.p2_node)]);
  const ElementStresses stresses =
      recoverElementStresses(wing_structure, mesh, unit.displacements);
  std::vector<Eigen::MatrixXd> k = projectGeometricStiffness(wing_structure, mesh, stresses, shapes, options);
  ModalGeometricStiffness out;
  for (int i = 0; i < kInertialLoadCount; ++i)
    out.per_load[static_cast<std::size_t>(i)] = std::move(k[static_cast<std::size_t>(i)]);
  return out;
}

}  // namespace orni::structure
