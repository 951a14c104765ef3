// Builds the ModalWing (docs/theory.md 3.2, 3.4-3.6).
#include "core/structure/modal_wing.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <stdexcept>

#include "core/structure/craig_bampton.hpp"
#include "core/structure/dof_partition.hpp"
#include "core/structure/product_blocking.hpp"
#include "core/structure/skin_pretension.hpp"
#include "core/structure/static_shapes.hpp"
#include "core/structure/von_karman.hpp"
#include "core/model/invalid_model_error.hpp"

namespace orni::structure {
namespace {

constexpr double kTwoPi = 2.0 * 3.14159265358979323846;

struct Basis {
  Eigen::VectorXd omega2;
  Eigen::MatrixXd shapes;  // 6n x count
};

Basis fixedInterfaceBasis(const WingFeModel& fe, const DofPartition& part,
                          const ModalWingOptions& options) {
  const SparseMatrix k_ii = extractBlock(fe.stiffness, part.interior, part.interior);
  const SparseMatrix m_ii = extractBlock(fe.mass, part.interior, part.interior);
  const int count =
      std::min(options.selection.max_modes, static_cast<int>(part.interior.size()));
  const EigenSolution sol = lowestEigenpairs(k_ii, m_ii, count, options.eigen);
  if (!sol.success)
    throw std::runtime_error("buildModalWing: fixed-interface eigen-solution failed: " +
                             sol.message);
  return {sol.eigenvalues, expandRows(sol.vectors, part.interior, fe.dofCount())};
}

Basis craigBamptonBasis(const WingFeModel& fe, const DofPartition& part,
                        const ModalWingOptions& options) {
  CraigBamptonOptions cbo;
  cbo.max_modes = options.selection.max_modes;
  cbo.eigen = options.eigen;
  const CraigBamptonModel cb = craigBampton(fe.stiffness, fe.mass, part, cbo);
  const OrthonormalModes on = orthonormalise(cb);
  std::vector<Eigen::Index> elastic;
  for (Eigen::Index k = 0; k < on.eigenvalues.size(); ++k)
    if (!on.rigid[static_cast<std::size_t>(k)]) elastic.push_back(k);
  Basis b;
  b.omega2.resize(static_cast<Eigen::Index>(elastic.size()));
  b.shapes.resize(fe.dofCount(), static_cast<Eigen::Index>(elastic.size()));
  for (std::size_t j = 0; j < elastic.size(); ++j) {
    b.omega2(static_cast<Eigen::Index>(j)) = on.eigenvalues(elastic[j]);
    b.shapes.col(static_cast<Eigen::Index>(j)) = on.shapes.col(elastic[j]);
  }
  return b;
}

}  // namespace

bool ModalWingOptions::IsValid(std::string* why) const {
  if (!selection.IsValid(why)) return false;
  if (!(damping_ratio >= 0.0 && damping_ratio < 1.0)) {
    if (why != nullptr) *why = "damping_ratio: expected in [0, 1)";
    return false;
  }
  if (!(membrane_rank_tolerance >= 0.0 && membrane_rank_tolerance < 1.0)) {
    if (why != nullptr) *why = "membrane_rank_tolerance: expected in [0, 1)";
    return false;
  }
  if (!static_shape_pressures_pa.empty()) {
    if (static_cast<int>(static_shape_pressures_pa.size()) > kMaxStaticShapes) {
      if (why != nullptr)
        *why = "static_shape_pressures_pa: at most " + std::to_string(kMaxStaticShapes) +
               " pressures";
      return false;
    }
    for (double p : static_shape_pressures_pa)
      if (!(p > 0.0 && p <= kMaxStaticShapePressure_Pa)) {
        if (why != nullptr) *why = "static_shape_pressures_pa: each expected in (0, 1000] Pa";
        return false;
      }
    if (!nonlinear) {
      if (why != nullptr)
        *why = "static_shape_pressures_pa: nonlinear static shapes need the nonlinear wing";
      return false;
    }
    if (!free_boundary_dofs.empty()) {
      if (why != nullptr)
        *why = "static_shape_pressures_pa: only with the fixed-interface basis";
      return false;
    }
  }
  return true;
}

Eigen::VectorXd ModalWing::stiffnessDiagonal() const {
  return (kTwoPi * frequencies_hz).cwiseAbs2();
}

Eigen::VectorXd ModalWing::dampingDiagonal() const {
  return 2.0 * damping_ratios.cwiseProduct(kTwoPi * frequencies_hz);
}

ModalWingOptions modalWingOptionsOf(const WingFeSettings& fe) {
  ModalWingOptions options;
  options.support = WingSupport::of(fe);
  options.selection.max_modes = fe.max_modes;
  options.selection.cutoff_hz = fe.cutoff_hz;
  options.damping_ratio = fe.damping_ratio;
  options.nonlinear = fe.nonlinear;
  options.static_shape_pressures_pa = fe.static_shapes_pa;
  return options;
}

ModalWing buildModalWing(const WingStructure& wing_structure, const WingMesh& mesh,
                         const ModalWingOptions& options) {
  planProductsWithFixedCacheSizes();  // the same bits on every CPU (docs/theory.md 3.7)
  std::string why;
  if (!options.IsValid(&why)) throw std::invalid_argument("buildModalWing: " + why);
  if (mesh.p2_node < 0 || mesh.p2_node >= mesh.nodeCount())
    throw std::invalid_argument("buildModalWing: the mesh has no valid P2 node");

  FeAssemblyOptions fe_options;
  fe_options.mass = options.mass;
  WingFeModel fe = assembleWingFe(wing_structure, mesh, fe_options);
  // A pretensioned skin is a prestressed structure: its modes and every static solution use
  // K + K_G(N0) (docs/theory.md 4.6, 4.7).
  addSkinPretension(wing_structure, mesh, options.support, &fe);
  const DofPartition part = makeDofPartition(
      fe.active, wingBoundaryDofs(mesh, options.support), options.free_boundary_dofs);
  if (part.interior.empty()) throw std::invalid_argument("buildModalWing: no interior DOF");

  const Basis basis = part.boundary_free.empty() ? fixedInterfaceBasis(fe, part, options)
                                                 : craigBamptonBasis(fe, part, options);
  const Eigen::VectorXd freq_all =
      basis.omega2.cwiseMax(0.0).cwiseSqrt() / kTwoPi;
  const Vec3 p2 = mesh.nodes_W_m[static_cast<std::size_t>(mesh.p2_node)];
  const EffectiveMassTable table_all =
      effectiveMassTable(fe.mass, basis.shapes, mesh.nodes_W_m, p2, Vec3::UnitX());

  ModalWing w;
  w.selection = selectModes(freq_all, table_all, options.selection);
  const int m = w.selection.count;
  // A flexible wing without one flexible mode is an input mistake (a cut-off below the first
  // mode), not a rigid wing: the rigid wing is its own model. Reported, not built with empty
  // mode shapes (whose row blocks would point into no storage).
  if (m == 0)
    throw InvalidModelError("buildModalWing: no mode kept: the cut-off " +
                            std::to_string(options.selection.cutoff_hz) +
                            " Hz lies below the first mode (" +
                            std::to_string(freq_all.size() > 0 ? freq_all(0) : 0.0) +
                            " Hz); raise wing.fe.cutoff_hz, or set it 0 for no cut-off");
  w.mesh = mesh;
  w.frequencies_hz = freq_all.head(m);
  w.mode_shapes = basis.shapes.leftCols(m);
  w.effective_mass = table_all;
  for (Eigen::VectorXd* v : {&w.effective_mass.flap_fraction, &w.effective_mass.heave_fraction,
                             &w.effective_mass.flap_cumulative,
                             &w.effective_mass.heave_cumulative})
    v->conservativeResize(m);
  std::optional<VonKarmanTerms> terms;
  if (options.nonlinear) terms.emplace(wing_structure, mesh);
  if (!options.static_shape_pressures_pa.empty()) {
    // The modes and the nonlinear static shapes, replaced by their Rayleigh-Ritz vectors
    // (static_shapes.hpp): an ordinary modal basis of m + k vectors for everything below.
    const Eigen::MatrixXd extra = nonlinearStaticShapes(fe.stiffness, *terms, part, mesh,
                                                        options.static_shape_pressures_pa);
    const RitzBasis ritz = rayleighRitzBasis(fe.stiffness, fe.mass, w.mode_shapes, extra);
    w.mode_shapes = ritz.shapes;
    w.frequencies_hz = ritz.omega2.cwiseMax(0.0).cwiseSqrt() / kTwoPi;
    w.static_shape_count = static_cast<int>(ritz.shapes.cols()) - m;
    w.effective_mass = effectiveMassTable(fe.mass, w.mode_shapes, mesh.nodes_W_m, p2, Vec3::UnitX());
  }
  const int kept = static_cast<int>(w.mode_shapes.cols());
  w.damping_ratios.resize(kept);
  for (int k = 0; k < kept; ++k) {
    const double f = w.frequencies_hz(k);
    w.damping_ratios(k) = options.damping_schedule == ModalDampingSchedule::kConstant
                              ? options.damping_ratio
                          : f < 100.0  ? 0.01
                          : f < 1000.0 ? 0.1
                                       : 1.0;
  }

  const int n = mesh.nodeCount();
  w.phi_W.resize(static_cast<std::size_t>(n));
  w.psi_W.resize(static_cast<std::size_t>(n));
  for (int p = 0; p < n; ++p) {
    w.phi_W[static_cast<std::size_t>(p)] = w.mode_shapes.middleRows<3>(globalDof(p, kU));
    w.psi_W[static_cast<std::size_t>(p)] = w.mode_shapes.middleRows<3>(globalDof(p, kThetaX));
  }
  const LumpedNodalMass lumped = lumpedNodalMass(wing_structure, mesh, fe_options.beam_orientation_W);
  w.nodal_mass_kg = lumped.mass_kg;
  w.nodal_rotary_W_kgm2 = lumped.rotary_W_kgm2;
  w.invariants = invariantsOperatorForm(fe.mass, w.mode_shapes, mesh.nodes_W_m, p2);
  w.lumped_sums = lumpedInertiaSums(w.nodal_mass_kg, w.nodal_rotary_W_kgm2, w.phi_W, mesh.nodes_W_m);
  if (options.geometric_stiffness)
    w.geometric_stiffness =
        modalGeometricStiffness(wing_structure, mesh, fe, part, w.mode_shapes, fe_options);
  if (options.nonlinear) {
    // Truncated at the pairs' energy for the static response to unit modal forces (1/omega^2).
    MembraneCondensationOptions condensation;
    condensation.keep_relaxation = options.keep_membrane_relaxation;
    condensation.mode_amplitude = w.stiffnessDiagonal().cwiseInverse();
    condensation.rank_tolerance = options.membrane_rank_tolerance;
    w.membrane = modalMembraneStiffness(*terms, fe.stiffness, part,
                                        mesh.nodes_W_m, w.mode_shapes, condensation);
  }
  w.member_mass_kg = fe.member_mass_kg;
  w.skin_mass_kg = fe.skin_mass_kg;
  w.wing_mass_kg = fe.totalMass_kg();
  return w;
}

}  // namespace orni::structure
