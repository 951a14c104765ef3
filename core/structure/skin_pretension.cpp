// The prestress of a skin shrunk onto its frame, and its geometric stiffness (docs/theory.md 4.7).
#include "core/structure/skin_pretension.hpp"

#include <algorithm>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/SparseCholesky>

#include "core/model/invalid_model_error.hpp"
#include "core/structure/dof_partition.hpp"
#include "core/structure/von_karman.hpp"

namespace orni::structure {

double skinShrinkStrain(const WingStructure& wing_structure, double pretension_Npm) {
  const ShellProperties skin = skinShellProperties(wing_structure);
  return pretension_Npm * (1.0 - skin.poisson_ratio) / (skin.youngs_modulus_pa * skin.thickness_m);
}

SkinPrestress shrunkSkinPrestress(const WingStructure& wing_structure, const WingMesh& mesh,
                                  const WingSupport& support, double pretension_Npm) {
  const int n = kDofsPerNode * mesh.nodeCount();
  SkinPrestress out;
  out.displacement = Eigen::VectorXd::Zero(n);
  out.stresses.beam_axial_force_N.setZero(static_cast<Eigen::Index>(mesh.beams.size()), 1);
  out.stresses.skin_membrane_force_Npm.setZero(3 * static_cast<Eigen::Index>(mesh.triangles.size()), 1);
  if (pretension_Npm == 0.0 || mesh.triangles.empty()) return out;

  const double s = skinShrinkStrain(wing_structure, pretension_Npm);
  const VonKarmanTerms terms(wing_structure, mesh);  // facet and member geometry
  const Mat3& c = terms.membraneStiffness();
  const Vec3 sigma_held = c * Vec3(s, s, 0.0);  // (N_xx, N_yy, N_xy) of a fully held facet: N0, N0, 0

  // f_s: the nodal forces that hold the shrinking film, -A B_m^T C s (1, 1, 0), in W.
  Eigen::VectorXd f = Eigen::VectorXd::Zero(n);
  for (const VonKarmanTerms::Facet& e : terms.facets()) {
    const Eigen::Matrix<double, 6, 1> f_local = -e.area_m2 * (e.b_m.transpose() * sigma_held);
    for (int a = 0; a < 3; ++a)
      f.segment<3>(globalDof(e.nodes[static_cast<std::size_t>(a)], kU)) +=
          e.triad.topRows<2>().transpose() * f_local.segment<2>(2 * a);
  }

  const WingFeModel fe = assembleWingFe(wing_structure, mesh);
  const DofPartition part = makeDofPartition(fe.active, wingBoundaryDofs(mesh, support));
  std::vector<int> free = part.retained();
  std::sort(free.begin(), free.end());
  const SparseMatrix k_ff = extractBlock(fe.stiffness, free, free);
  Eigen::VectorXd f_free(static_cast<Eigen::Index>(free.size()));
  for (std::size_t i = 0; i < free.size(); ++i) f_free(static_cast<Eigen::Index>(i)) = f(free[i]);
  const Eigen::SimplicialLDLT<SparseMatrix, Eigen::Lower, Eigen::AMDOrdering<int>> ldlt(k_ff);
  if (ldlt.info() != Eigen::Success)
    throw std::runtime_error("skin pretension: the wing's stiffness could not be factorised");
  const Eigen::VectorXd d_free = ldlt.solve(f_free);
  if (ldlt.info() != Eigen::Success || !d_free.allFinite())
    throw std::runtime_error("skin pretension: the in-plane solve failed");
  for (std::size_t i = 0; i < free.size(); ++i) out.displacement(free[i]) = d_free(static_cast<Eigen::Index>(i));

  const Eigen::VectorXd& u = out.displacement;
  for (std::size_t k = 0; k < terms.facets().size(); ++k) {
    const VonKarmanTerms::Facet& e = terms.facets()[k];
    Eigen::Matrix<double, 6, 1> d;
    for (int a = 0; a < 3; ++a)
      d.segment<2>(2 * a) =
          e.triad.topRows<2>() * u.segment<3>(globalDof(e.nodes[static_cast<std::size_t>(a)], kU));
    out.stresses.skin_membrane_force_Npm.middleRows<3>(3 * static_cast<Eigen::Index>(k)) =
        c * (e.b_m * d) + sigma_held;
  }
  for (std::size_t k = 0; k < terms.members().size(); ++k) {
    const VonKarmanTerms::Member& m = terms.members()[k];
    const Vec3 du = u.segment<3>(globalDof(m.nodes[1], kU)) - u.segment<3>(globalDof(m.nodes[0], kU));
    out.stresses.beam_axial_force_N(static_cast<Eigen::Index>(k), 0) =
        m.axial_stiffness_n * m.axis.dot(du) / m.length_m;
  }
  return out;
}

SparseMatrix skinPretensionStiffness(const WingStructure& wing_structure, const WingMesh& mesh,
                                     const WingSupport& support, double pretension_Npm) {
  const int n = kDofsPerNode * mesh.nodeCount();
  if (pretension_Npm == 0.0 || mesh.triangles.empty()) return SparseMatrix(n, n);
  const SkinPrestress p = shrunkSkinPrestress(wing_structure, mesh, support, pretension_Npm);
  return assembleGeometricStiffness(wing_structure, mesh, p.stresses, 0);
}

namespace {

// Negative pivots of the LDL^T factorisation of K + lambda K_G on the retained DOFs (Sylvester's
// inertia: the number of negative eigenvalues), or -1 if it fails.
int negativePivots(const SparseMatrix& k_ff, const SparseMatrix& k_g_ff, double lambda) {
  const SparseMatrix a = k_ff + lambda * k_g_ff;
  const Eigen::SimplicialLDLT<SparseMatrix, Eigen::Lower, Eigen::AMDOrdering<int>> ldlt(a);
  if (ldlt.info() != Eigen::Success) return -1;
  int negative = 0;
  for (Eigen::Index i = 0; i < ldlt.vectorD().size(); ++i) negative += ldlt.vectorD()(i) <= 0.0;
  return negative;
}

// The largest factor in [0, 1] of K_G for which K + factor K_G stays positive definite on the
// retained DOFs of the support: 1 when the whole prestress is held, else by bisection (the
// prestress is linear in N0; 40 halvings, 1e-12 relative).
double heldFactor(const SparseMatrix& stiffness, const SparseMatrix& prestress_stiffness,
                  const std::vector<bool>& active, const WingMesh& mesh, const WingSupport& support) {
  const DofPartition part = makeDofPartition(active, wingBoundaryDofs(mesh, support));
  std::vector<int> free = part.retained();
  std::sort(free.begin(), free.end());
  const SparseMatrix k_ff = extractBlock(stiffness, free, free);
  const SparseMatrix k_g_ff = extractBlock(prestress_stiffness, free, free);
  if (negativePivots(k_ff, k_g_ff, 1.0) == 0) return 1.0;
  double held = 0.0, buckled = 1.0;
  for (int i = 0; i < 40; ++i) {
    const double mid = 0.5 * (held + buckled);
    (negativePivots(k_ff, k_g_ff, mid) == 0 ? held : buckled) = mid;
  }
  return held;
}

}  // namespace

double skinPretensionBucklingLimit(const WingStructure& wing_structure, const WingMesh& mesh,
                                   const WingSupport& support, double pretension_Npm) {
  if (pretension_Npm <= 0.0 || mesh.triangles.empty()) return pretension_Npm;
  const WingFeModel fe = assembleWingFe(wing_structure, mesh);
  return pretension_Npm *
         heldFactor(fe.stiffness, skinPretensionStiffness(wing_structure, mesh, support, pretension_Npm),
                    fe.active, mesh, support);
}

void addSkinPretension(const WingStructure& wing_structure, const WingMesh& mesh,
                       const WingSupport& support, WingFeModel* fe) {
  const double n0 = wing_structure.wing.skin.pretension_N_per_m;
  if (n0 == 0.0) return;
  const SparseMatrix k_g = skinPretensionStiffness(wing_structure, mesh, support, n0);
  const double factor = heldFactor(fe->stiffness, k_g, fe->active, mesh, support);
  if (factor < 1.0) {
    char numbers[256];
    std::snprintf(numbers, sizeof numbers, "%.6g N/m: the wing cannot hold that film; shrunk onto "
                  "the frame it buckles the wing from %.4g N/m", n0, factor * n0);
    throw InvalidModelError(
        std::string("wing.skin.pretension_N_per_m = ") + numbers +
        " (the stiffness with the prestress is no longer positive definite). What a film holds is "
        "in equilibrium with the frame, which yields, and with the free trailing edge "
        "(docs/theory.md 4.7); lower the pretension or stiffen the frame");
  }
  fe->stiffness += k_g;
}

}  // namespace orni::structure
