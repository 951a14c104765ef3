// Geometric nonlinearity of the wing model (core/structure/von_karman.hpp, membrane_rom.hpp,
// docs/theory.md 4.7) against independent truths:
// - the internal force is the gradient of the energy and the tangent its Hessian (finite
//   differences);
// - a clamped circular plate under uniform pressure, immovable edge: the linear solution
//   w0 = q a^4 / (64 D), Timoshenko's large-deflection approximation
//   w0/h + 0.488 (w0/h)^3 = q a^4 / (64 D h) (nu = 0.3; Timoshenko & Woinowsky-Krieger, Theory of
//   Plates and Shells, 2nd ed., sec. 97) and, in the membrane limit, Hencky's pressurised
//   membrane w0 = 0.662 a (q a / (E h))^(1/3) (nu = 0.3; ibid. sec. 99);
// - the condensed modal membrane against the full nonlinear FE solution restricted to the same
//   modes, and, with enough modes, against the full solution itself.
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <vector>

#include <Eigen/Eigenvalues>
#include <gtest/gtest.h>

#include "core/structure/fe_assembly.hpp"
#include "core/structure/membrane_rom.hpp"
#include "core/structure/modal_wing.hpp"
#include "core/structure/von_karman.hpp"
#include "fe_test_disc.hpp"
#include "fe_test_meshes.hpp"

namespace orni::structure {
namespace {

using fe_test::kTestPi;

using fe_test::discMesh;
using fe_test::pressureLoad;

// The clamped circular plate: every DOF of the rim held (immovable clamped edge).
struct ClampedDisc {
  VehicleModel vehicle;
  WingMesh mesh;
  WingFeModel fe;
  DofPartition part;
  double radius_m, thickness_m, youngs_pa, nu;
  double rigidity() const {
    return youngs_pa * std::pow(thickness_m, 3) / (12.0 * (1.0 - nu * nu));
  }
};

ClampedDisc clampedDisc(int rings) {
  ClampedDisc d;
  d.radius_m = 0.05;
  d.thickness_m = 1e-3;
  d.youngs_pa = 70e9;
  d.nu = 0.3;
  d.vehicle = fe_test::skinVehicle(d.thickness_m, d.youngs_pa, d.nu, 2700.0);
  d.mesh = discMesh(d.radius_m, rings);
  d.fe = assembleWingFe(d.vehicle, d.mesh);
  std::vector<int> held;
  for (int n = 0; n < d.mesh.nodeCount(); ++n)
    if (d.mesh.nodes_W_m[static_cast<std::size_t>(n)].norm() > d.radius_m * (1.0 - 1e-9))
      for (int k = 0; k < kDofsPerNode; ++k) held.push_back(globalDof(n, k));
  d.part = makeDofPartition(d.fe.active, held);
  return d;
}

double centreDeflection(const ClampedDisc& d, double pressure_pa, bool nonlinear) {
  const VonKarmanTerms terms(d.vehicle, d.mesh);
  NonlinearStaticOptions options;
  options.nonlinear = nonlinear;
  options.load_steps = 10;
  const NonlinearStaticResult r =
      solveNonlinearStatic(d.fe.stiffness, terms, d.part, pressureLoad(d.mesh, pressure_pa), options);
  EXPECT_TRUE(r.converged) << r.message;
  return r.displacement(globalDof(0, kW));
}

// Timoshenko's approximation solved for w0/h.
double timoshenkoDeflectionRatio(double load_parameter) {
  double x = load_parameter;  // w0/h + 0.488 (w0/h)^3 = load_parameter, by Newton
  for (int i = 0; i < 100; ++i) x -= (x + 0.488 * x * x * x - load_parameter) / (1.0 + 1.464 * x * x);
  return x;
}

// Largest errors of the force against central differences of the energy and of the tangent
// against central differences of the force, over every DOF, at u with step h.
struct FiniteDifferenceErrors {
  double force = 0.0, tangent = 0.0;
};
FiniteDifferenceErrors finiteDifferenceErrors(const VonKarmanTerms& terms, const Eigen::VectorXd& u,
                                              const Eigen::VectorXd& f, const Eigen::MatrixXd& k,
                                              double h) {
  FiniteDifferenceErrors e;
  for (int i = 0; i < terms.dofCount(); ++i) {
    Eigen::VectorXd up = u, um = u;
    up(i) += h;
    um(i) -= h;
    e.force = std::max(e.force, std::abs((terms.energy(up) - terms.energy(um)) / (2 * h) - f(i)));
    const Eigen::VectorXd col = (terms.internalForce(up) - terms.internalForce(um)) / (2 * h);
    e.tangent = std::max(e.tangent, (col - k.col(i)).cwiseAbs().maxCoeff());
  }
  return e;
}

// Both member-stretch models (von_karman.hpp, MemberStretch): each force is its energy's gradient
// and each tangent its force's Jacobian; they differ exactly by the members' in-plane terms.
TEST(FeVonKarman, ForceIsTheGradientOfTheEnergyAndTheTangentItsHessian) {
  fe_test::MiniWing w = fe_test::miniWing(4, 6);
  for (const MemberStretch stretch : {MemberStretch::kBothTransverse, MemberStretch::kOutOfPlaneOnly}) {
    SCOPED_TRACE(stretch == MemberStretch::kBothTransverse ? "both transverse" : "out of plane only");
    const VonKarmanTerms terms(w.vehicle, w.mesh, stretch);
    const int n = terms.dofCount();
    std::srand(1);
    Eigen::VectorXd u = 1e-3 * Eigen::VectorXd::Random(n);  // deflections ~ 1 mm, slopes ~ 0.1
    const Eigen::VectorXd f = terms.internalForce(u);
    const Eigen::MatrixXd k = Eigen::MatrixXd(terms.tangent(u));
    const FiniteDifferenceErrors e = finiteDifferenceErrors(terms, u, f, k, 1e-7);
    // Central differences: truncation ~ h^2 times the third derivative, round-off ~ 1e-16 |Pi| / h.
    EXPECT_LT(e.force, 1e-6 * f.cwiseAbs().maxCoeff());
    EXPECT_LT(e.tangent, 1e-6 * k.cwiseAbs().maxCoeff());
    EXPECT_LT((k - k.transpose()).cwiseAbs().maxCoeff(), 1e-9 * k.cwiseAbs().maxCoeff());
    // The nonlinear terms vanish at u = 0 (they start at second order).
    EXPECT_EQ(terms.internalForce(Eigen::VectorXd::Zero(n)).cwiseAbs().maxCoeff(), 0.0);
  }
  // The tension-field film (tension_field.hpp) through the same assembly: u large enough that
  // facets are taut, wrinkled and slack; without and with a compression cap (20 N/m).
  for (const double cap_npm : {0.0, 20.0}) {
    SCOPED_TRACE("tension field, compression cap " + std::to_string(cap_npm) + " N/m");
    FilmLaw film;
    film.compression_cap_n_per_m = cap_npm;
    const VonKarmanTerms terms(w.vehicle, w.mesh, MemberStretch::kBothTransverse,
                               SkinMembrane::kTensionField, film);
    const int n = terms.dofCount();
    std::srand(3);
    const Eigen::VectorXd u = 1e-3 * Eigen::VectorXd::Random(n);
    const Eigen::VectorXd f = terms.internalForce(u);
    const Eigen::MatrixXd k = Eigen::MatrixXd(terms.tangent(u));
    // The states met (principal forces of the relaxed stress: both > 0 taut; one ~ 0 wrinkled).
    const Eigen::Matrix3Xd nf = terms.membraneForces(u);
    int wrinkled_or_slack = 0;
    for (Eigen::Index c = 0; c < nf.cols(); ++c) {
      Eigen::Matrix2d s;
      s << nf(0, c), nf(2, c), nf(2, c), nf(1, c);
      const Eigen::Vector2d ev = Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(s).eigenvalues();
      if (ev(0) < 1e-3 * std::abs(ev(1)) - cap_npm) ++wrinkled_or_slack;
    }
    EXPECT_GT(wrinkled_or_slack, 0);
    EXPECT_LT(wrinkled_or_slack, nf.cols());
    // h smaller than for the smooth law: a state boundary within h of a facet's strain is rare.
    const FiniteDifferenceErrors e = finiteDifferenceErrors(terms, u, f, k, 1e-9);
    EXPECT_LT(e.force, 1e-5 * f.cwiseAbs().maxCoeff());
    EXPECT_LT(e.tangent, 1e-5 * k.cwiseAbs().maxCoeff());
    EXPECT_LT((k - k.transpose()).cwiseAbs().maxCoeff(), 1e-9 * k.cwiseAbs().maxCoeff());
  }
  // With only out-of-plane displacements the two models agree; in-plane ones separate them.
  const VonKarmanTerms both(w.vehicle, w.mesh), out_of_plane(w.vehicle, w.mesh, MemberStretch::kOutOfPlaneOnly);
  const int n = both.dofCount();
  std::srand(2);
  const Eigen::VectorXd u = 1e-3 * Eigen::VectorXd::Random(n);
  Eigen::VectorXd w_only = Eigen::VectorXd::Zero(n);
  for (int node = 0; node < n / kDofsPerNode; ++node) w_only(globalDof(node, kW)) = u(globalDof(node, kW));
  EXPECT_NEAR(both.energy(w_only), out_of_plane.energy(w_only), 1e-12 * std::abs(both.energy(w_only)));
  EXPECT_GT(std::abs(both.energy(u) - out_of_plane.energy(u)), 1e-6 * std::abs(both.energy(u)));
}

TEST(FeVonKarman, ClampedCircularPlateLinearRegime) {
  const ClampedDisc d = clampedDisc(14);
  const double q = 100.0;  // w0/h ~ 1.5e-3: linear
  const double exact = q * std::pow(d.radius_m, 4) / (64.0 * d.rigidity());
  const double linear = centreDeflection(d, q, false);
  const double nonlinear = centreDeflection(d, q, true);
  fe_test::recordError("linear_rel_error", linear / exact - 1.0);
  // 3 %: the DKT discretisation error of this 14-ring mesh (measured ~1 %).
  EXPECT_NEAR(linear / exact, 1.0, 0.03);
  EXPECT_NEAR(nonlinear / linear, 1.0, 1e-4);  // membrane effects ~ (w0/h)^2 * 0.5 ~ 1e-6
}

TEST(FeVonKarman, ClampedCircularPlateModerateDeflectionsMatchTimoshenko) {
  const ClampedDisc d = clampedDisc(14);
  // w0/h = 1 and 2: beyond, the one-term approximation's own error grows towards its membrane
  // limit, where it lies 6.4 % above Hencky's exact membrane (0.7045 a (qa/Eh)^(1/3) against
  // 0.662); measured here: -2.5 % at 1, -4.9 % at 2, -6.3 % at 3, and -1.3 % from Hencky at 20.
  for (double target_ratio : {1.0, 2.0}) {
    // The pressure at which Timoshenko's approximation gives w0/h = target_ratio.
    const double load_parameter = target_ratio + 0.488 * std::pow(target_ratio, 3);
    const double q = load_parameter * 64.0 * d.rigidity() * d.thickness_m / std::pow(d.radius_m, 4);
    const double w0 = centreDeflection(d, q, true);
    const double ratio = w0 / d.thickness_m;
    std::printf("clamped disc: Timoshenko w0/h %.3f, ours %.3f (%+.1f %%)\n",
                timoshenkoDeflectionRatio(load_parameter), ratio,
                100.0 * (ratio / timoshenkoDeflectionRatio(load_parameter) - 1.0));
    fe_test::recordError(("timoshenko_rel_error_" + std::to_string(static_cast<int>(target_ratio))).c_str(),
                         ratio / timoshenkoDeflectionRatio(load_parameter) - 1.0);
    // 5 %: Timoshenko's one-term energy solution is itself within a few per cent of Way's
    // (1934) series solution in this range; the mesh adds ~1 %.
    EXPECT_NEAR(ratio / target_ratio, 1.0, 0.05) << "target w0/h " << target_ratio;
    // And far below the linear answer.
    EXPECT_LT(ratio, 0.9 * load_parameter);
  }
}

TEST(FeVonKarman, ClampedCircularPlateMembraneLimitMatchesHencky) {
  const ClampedDisc d = clampedDisc(14);
  // w0/h ~ 20: the bending share of the load is ~0.5 % (Timoshenko's form), the plate is a
  // membrane. Hencky (nu = 0.3): w0 = 0.662 a (q a / (E h))^(1/3).
  const double q = std::pow(20.0 * d.thickness_m / (0.662 * d.radius_m), 3) * d.youngs_pa *
                   d.thickness_m / d.radius_m;
  const double hencky = 0.662 * d.radius_m * std::cbrt(q * d.radius_m / (d.youngs_pa * d.thickness_m));
  const double w0 = centreDeflection(d, q, true);
  fe_test::recordError("hencky_rel_error", w0 / hencky - 1.0);
  std::printf("clamped disc: Hencky w0/h %.3f, ours %.3f (%+.1f %%)\n", hencky / d.thickness_m,
              w0 / d.thickness_m, 100.0 * (w0 / hencky - 1.0));
  EXPECT_GT(w0 / d.thickness_m, 15.0);
  // 5 %: the remaining bending stiffness (< 1 %) and the mesh's membrane discretisation (linear
  // w per facet in the membrane strain).
  EXPECT_NEAR(w0 / hencky, 1.0, 0.05);
  // The linear answer at this load is ~ 4000 h: absurd.
  EXPECT_GT(q * std::pow(d.radius_m, 4) / (64.0 * d.rigidity()) / w0, 100.0);
  // A pressurised clamped membrane is taut everywhere (radial and hoop tension): the
  // tension-field film (tension_field.hpp) gives the same answer, to its residual fraction.
  const VonKarmanTerms tension_field(d.vehicle, d.mesh, MemberStretch::kBothTransverse,
                                     SkinMembrane::kTensionField);
  NonlinearStaticOptions options;
  options.load_steps = 10;
  const NonlinearStaticResult r = solveNonlinearStatic(
      d.fe.stiffness, tension_field, d.part, pressureLoad(d.mesh, q), options);
  ASSERT_TRUE(r.converged) << r.message;
  std::printf("clamped disc, tension field: w0/h %.4f (elastic %.4f)\n",
              r.displacement(globalDof(0, kW)) / d.thickness_m, w0 / d.thickness_m);
  EXPECT_NEAR(r.displacement(globalDof(0, kW)) / w0, 1.0, 1e-3);
}

// The condensed modal membrane is exactly the von Karman energy of u = Phi q + U Q(q) with the
// in-plane part relaxed: check V_NL(q) against the full model's energy at that displacement,
// its force against finite differences, and the relaxation's in-plane equilibrium.
TEST(FeMembraneRom, CondensedEnergyIsTheFullEnergyWithTheMembraneRelaxed) {
  fe_test::MiniWing w = fe_test::miniWing(6, 10);
  ModalWingOptions options;
  options.selection.max_modes = 6;
  options.nonlinear = true;
  options.keep_membrane_relaxation = true;
  const ModalWing mw = buildModalWing(w.vehicle, w.mesh, options);
  ASSERT_FALSE(mw.membrane.empty());
  const int m = mw.modeCount();
  const VonKarmanTerms terms(w.vehicle, w.mesh);
  const WingFeModel fe = assembleWingFe(w.vehicle, w.mesh);
  Eigen::VectorXd q = Eigen::VectorXd::Random(m) * 2e-6;  // 0.1 mm-size deflections
  const Eigen::VectorXd u_w = mw.mode_shapes * q;
  const Eigen::VectorXd u_m = mw.membrane.membraneDisplacement(q);
  const Eigen::VectorXd u = u_w + u_m;
  // Full energy beyond the bending: 1/2 u_m^T K u_m (the in-plane part of K) + Pi_NL(u).
  const double full = 0.5 * u_m.dot(fe.stiffness * u_m) + terms.energy(u);
  ModalMembraneStiffness::Workspace ws(mw.membrane);
  const double condensed = mw.membrane.energy(q, &ws);
  EXPECT_GT(condensed, 0.0);
  // Pi_NL(u) also holds (u_m-only) terms of order |u_m|^3 that the condensation drops: the
  // in-plane relaxation's own slopes, ~ (u_m / h)^2 relative.
  EXPECT_NEAR(full / condensed, 1.0, 1e-3);
  // In-plane equilibrium of the relaxed membrane under the quadratic strains of u_w:
  // K u_m + (in-plane part of grad Pi_NL(u_w)) = 0 on the free in-plane DOFs (the defining
  // equation of the condensation; at u = u_w + u_m the members' tension times the relaxation's own
  // transverse slopes adds terms of order q^4, ~1 % here, which the condensation drops).
  const Eigen::VectorXd f_w = terms.internalForce(u_w);
  const Eigen::VectorXd residual = fe.stiffness * u_m + f_w;
  const DofPartition part = makeDofPartition(fe.active, wingBoundaryDofs(w.mesh, options.support));
  double worst = 0.0, scale = 0.0;
  for (int dof : part.retained()) {
    const int slot = dof % kDofsPerNode;
    if (slot != kU && slot != kV) continue;
    worst = std::max(worst, std::abs(residual(dof)));
    scale = std::max(scale, std::abs(f_w(dof)));
  }
  EXPECT_LT(worst, 1e-9 * scale);  // a sparse direct solve: round-off
  // Force = gradient of the potential; tangent = its Hessian.
  Eigen::VectorXd f = Eigen::VectorXd::Zero(m);
  mw.membrane.addForce(q, &ws, &f);
  const Eigen::MatrixXd k = mw.membrane.tangent(q);
  const double h = 1e-9;
  for (int i = 0; i < m; ++i) {
    Eigen::VectorXd qp = q, qm = q;
    qp(i) += h;
    qm(i) -= h;
    EXPECT_NEAR((mw.membrane.energy(qp, &ws) - mw.membrane.energy(qm, &ws)) / (2 * h), f(i),
                1e-6 * f.cwiseAbs().maxCoeff());
    Eigen::VectorXd fp = Eigen::VectorXd::Zero(m), fm = Eigen::VectorXd::Zero(m);
    mw.membrane.addForce(qp, &ws, &fp);
    mw.membrane.addForce(qm, &ws, &fm);
    EXPECT_LT(((fp - fm) / (2 * h) - k.col(i)).cwiseAbs().maxCoeff(), 1e-6 * k.cwiseAbs().maxCoeff());
  }
}

// The strain-rate damped membrane force f = J^T C (Q + beta Q') and its Jacobians: the tangent's
// two parts sum to d f / dq at q' = 0, the Gauss-Newton part is d f / dq' over beta; its power on
// q' splits into dV/dt (the energy's rate along q') and the dissipation beta Q'^T C Q' >= 0.
void expectDampedForceMatchesFiniteDifferences(const ModalMembraneStiffness& rom) {
  const int m = rom.mode_count;
  std::srand(7);
  const Eigen::VectorXd q = Eigen::VectorXd::Random(m) * 2e-6;
  const Eigen::VectorXd qd = Eigen::VectorXd::Random(m) * 2e-2;  // q' / q ~ 1e4 1/s: damping
                                                                // matters in d f / dq
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(m);
  const double beta = 3e-4;
  EXPECT_GT(beta * qd.cwiseAbs().maxCoeff() / q.cwiseAbs().maxCoeff(), 0.5);
  ModalMembraneStiffness::Workspace ws(rom);
  ModalMembraneStiffness::TangentWorkspace tws(rom);
  Eigen::MatrixXd gn(m, m), stress(m, m), gn_d(m, m), rest_d(m, m);
  rom.tangentParts(q, zero, beta, &tws, &gn, &stress);  // at rest: the elastic tangent
  rom.tangentParts(q, qd, beta, &tws, &gn_d, &rest_d);
  EXPECT_LT((gn + stress - rom.tangent(q)).cwiseAbs().maxCoeff(),
            1e-12 * rom.tangent(q).cwiseAbs().maxCoeff());
  EXPECT_GE(Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(gn).eigenvalues().minCoeff(),
            -1e-12 * gn.cwiseAbs().maxCoeff());  // J^T C J, C positive semi-definite
  auto force = [&](const Eigen::VectorXd& qq, const Eigen::VectorXd& vv) {
    Eigen::VectorXd f = Eigen::VectorXd::Zero(m);
    rom.addForce(qq, vv, beta, &ws, &f);
    return f;
  };
  // Without rates the damped force is the elastic one.
  Eigen::VectorXd f_elastic = Eigen::VectorXd::Zero(m);
  rom.addForce(q, &ws, &f_elastic);
  EXPECT_LT((force(q, zero) - f_elastic).cwiseAbs().maxCoeff(), 1e-14 * f_elastic.norm());
  const double hq = 1e-9 * q.cwiseAbs().maxCoeff(), hv = 1e-3 * qd.cwiseAbs().maxCoeff();
  const double scale = (gn + stress).cwiseAbs().maxCoeff();
  for (int i = 0; i < m; ++i) {
    Eigen::VectorXd qp = q, qm = q, vp = qd, vm = qd;
    qp(i) += hq;
    qm(i) -= hq;
    vp(i) += hv;
    vm(i) -= hv;
    EXPECT_LT(((force(qp, zero) - force(qm, zero)) / (2 * hq) - (gn + stress).col(i))
                  .cwiseAbs()
                  .maxCoeff(),
              1e-6 * scale);
    EXPECT_LT(((force(q, vp) - force(q, vm)) / (2 * hv) - beta * gn.col(i)).cwiseAbs().maxCoeff(),
              1e-6 * beta * scale);
    // Moving: d f / dq = J^T C J + rest(q, q'), the damping force's change with q included.
    EXPECT_LT(((force(qp, qd) - force(qm, qd)) / (2 * hq) - (gn_d + rest_d).col(i))
                  .cwiseAbs()
                  .maxCoeff(),
              1e-6 * (gn_d + rest_d).cwiseAbs().maxCoeff());
  }
  const ModalMembraneStiffness::Rates rates = rom.rates(q, qd, beta, &ws);
  const double dt = 1e-4 * q.cwiseAbs().maxCoeff() / qd.cwiseAbs().maxCoeff();
  const double energy_rate = (rom.energy(q + dt * qd, &ws) - rom.energy(q - dt * qd, &ws)) / (2 * dt);
  EXPECT_NEAR(rates.strain_energy_rate_W, energy_rate, 1e-6 * std::abs(energy_rate));
  EXPECT_GT(rates.dissipation_W, 0.0);
  Eigen::VectorXd f = Eigen::VectorXd::Zero(m);
  const double power = rom.addForce(q, qd, beta, &ws, &f);
  EXPECT_NEAR(power, qd.dot(f), 1e-12 * std::abs(power));
  EXPECT_NEAR(power, rates.strain_energy_rate_W + rates.dissipation_W, 1e-12 * std::abs(power));
}

// Both storages of C (membrane_rom.hpp): the dense C and a factor G^T G of it (here the exact
// factor from C's eigen-decomposition, so the two are the same model).
TEST(FeMembraneRom, DampedForceRatesAndTangentPartsMatchFiniteDifferences) {
  fe_test::MiniWing w = fe_test::miniWing(6, 10);
  ModalWingOptions options;
  options.selection.max_modes = 6;
  options.nonlinear = true;
  const ModalWing mw = buildModalWing(w.vehicle, w.mesh, options);
  ASSERT_FALSE(mw.membrane.empty());
  ASSERT_FALSE(mw.membrane.factored());  // P = 21 pairs: the dense C is the cheaper
  {
    SCOPED_TRACE("dense C");
    expectDampedForceMatchesFiniteDifferences(mw.membrane);
  }
  ModalMembraneStiffness factored = mw.membrane;
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(mw.membrane.pair_stiffness);
  const Eigen::VectorXd lambda = eig.eigenvalues().cwiseMax(0.0);
  factored.strain_factor = lambda.cwiseSqrt().asDiagonal() * eig.eigenvectors().transpose();
  factored.pair_stiffness.resize(0, 0);
  ASSERT_TRUE(factored.factored());
  {
    SCOPED_TRACE("factor G");
    expectDampedForceMatchesFiniteDifferences(factored);
  }
  // The same force from either storage.
  ModalMembraneStiffness::Workspace ws_dense(mw.membrane), ws_factor(factored);
  std::srand(11);
  const Eigen::VectorXd q = Eigen::VectorXd::Random(mw.modeCount()) * 2e-6;
  const Eigen::VectorXd qd = Eigen::VectorXd::Random(mw.modeCount()) * 2e-2;
  Eigen::VectorXd f_dense = Eigen::VectorXd::Zero(q.size()), f_factor = f_dense;
  mw.membrane.addForce(q, qd, 3e-4, &ws_dense, &f_dense);
  factored.addForce(q, qd, 3e-4, &ws_factor, &f_factor);
  EXPECT_LT((f_dense - f_factor).norm(), 1e-10 * f_dense.norm());
}

// The truncated factor (modalMembraneStiffness with mode amplitudes): its energy G^T G never above
// C's (the left-out Schur complement is positive semi-definite), exact at tolerance 0 (R = 34 of
// 136 pairs: C's numerical rank is far below P), and at the default tolerance the clamped film's
// large deflection (w/t ~ 6) within 1e-4 of the dense C's. Larger tolerances (printed) drop real
// strain directions: 1e-3 keeps 13 and moves the centre by 1 %.
// A clamped 40 mm square of polyester film (t = 0.04 mm, 6 x 6 grid: 25 interior nodes) and its
// lowest out-of-plane modes (more out-of-plane than in-plane motion), at most `max_bending` of them:
// the membrane tests' plate.
struct ClampedFilm {
  static constexpr double kSide_m = 0.04;
  static constexpr double kThickness_m = 4e-5;
  VehicleModel vehicle = fe_test::skinVehicle(kThickness_m, 4e9, 0.3, 1400.0);
  WingMesh mesh;
  WingFeModel fe;
  DofPartition part;
  Eigen::MatrixXd all_modes;      // every interior mode (6n x interior DOF)
  Eigen::VectorXd all_omega2;     // their eigenvalues, (rad/s)^2
  Eigen::MatrixXd shapes;         // the out-of-plane ones (6n x M)
  Eigen::VectorXd omega2;         // theirs
  int centre = fe_test::gridNode(3, 3, 6);

  explicit ClampedFilm(int max_bending) {
    const double a = kSide_m;
    mesh = fe_test::plateGridMesh(a, a, 6, 6, -a / 2, -a / 2, true);
    mesh.p2_node = fe_test::gridNode(0, 0, 6);
    fe = assembleWingFe(vehicle, mesh);
    std::vector<int> held;
    for (int n = 0; n < mesh.nodeCount(); ++n) {
      const Vec3& x = mesh.nodes_W_m[static_cast<std::size_t>(n)];
      if (std::abs(std::abs(x.x()) - a / 2) < 1e-12 || std::abs(std::abs(x.y()) - a / 2) < 1e-12)
        for (int k = 0; k < kDofsPerNode; ++k) held.push_back(globalDof(n, k));
    }
    part = makeDofPartition(fe.active, held);
    const SparseMatrix k_ii = extractBlock(fe.stiffness, part.interior, part.interior);
    const SparseMatrix m_ii = extractBlock(fe.mass, part.interior, part.interior);
    const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> eig{Eigen::MatrixXd(k_ii),
                                                                       Eigen::MatrixXd(m_ii)};
    all_modes = expandRows(eig.eigenvectors(), part.interior, fe.dofCount());
    all_omega2 = eig.eigenvalues();
    std::vector<Eigen::Index> bending;
    for (Eigen::Index c = 0; c < all_modes.cols() && static_cast<int>(bending.size()) < max_bending;
         ++c)
      if (outOfPlaneShare(all_modes.col(c)) > 0.5) bending.push_back(c);
    const auto m = static_cast<Eigen::Index>(bending.size());
    shapes.resize(fe.dofCount(), m);
    omega2.resize(m);
    for (Eigen::Index j = 0; j < m; ++j) {
      shapes.col(j) = all_modes.col(bending[static_cast<std::size_t>(j)]);
      omega2(j) = all_omega2(bending[static_cast<std::size_t>(j)]);
    }
  }
  // w^2 / (u^2 + v^2 + w^2) over the nodes.
  double outOfPlaneShare(const Eigen::VectorXd& shape) const {
    double out = 0.0, in = 0.0;
    for (int n = 0; n < mesh.nodeCount(); ++n) {
      out += std::pow(shape(globalDof(n, kW)), 2);
      in += std::pow(shape(globalDof(n, kU)), 2) + std::pow(shape(globalDof(n, kV)), 2);
    }
    return out / (out + in);
  }
};

// The condensation's column blocks on several threads give C to the bit (each column is the same
// arithmetic whichever block holds it), so results do not depend on the machine's cores.
TEST(FeMembraneRom, CondensationHasTheSameBitsOnAnyNumberOfThreads) {
  const ClampedFilm film(16);  // P = 136 pairs: uneven blocks for 3 threads
  const VonKarmanTerms terms(film.vehicle, film.mesh);
  MembraneCondensationOptions options;
  options.storage = MembraneStorage::kDense;
  options.keep_relaxation = true;
  options.threads = 1;
  const ModalMembraneStiffness one = modalMembraneStiffness(
      terms, film.fe.stiffness, film.part, film.mesh.nodes_W_m, film.shapes, options);
  ASSERT_GT(one.pair_stiffness.cwiseAbs().maxCoeff(), 0.0);
  for (const int threads : {2, 3}) {
    options.threads = threads;
    const ModalMembraneStiffness many = modalMembraneStiffness(
        terms, film.fe.stiffness, film.part, film.mesh.nodes_W_m, film.shapes, options);
    EXPECT_TRUE(many.pair_stiffness == one.pair_stiffness) << threads;  // exact
    EXPECT_TRUE(many.relaxation == one.relaxation) << threads;
    EXPECT_TRUE(many.hessian_pairs == one.hessian_pairs) << threads;
  }
}

TEST(FeMembraneRom, TruncatedFactorOnlySoftensAndKeepsTheLargeDeflection) {
  const ClampedFilm film(16);  // the first 16 out-of-plane modes
  const double t = ClampedFilm::kThickness_m;
  const VonKarmanTerms terms(film.vehicle, film.mesh);
  MembraneCondensationOptions dense_options;
  dense_options.storage = MembraneStorage::kDense;
  const ModalMembraneStiffness dense =
      modalMembraneStiffness(terms, film.fe.stiffness, film.part, film.mesh.nodes_W_m,
                             film.shapes, dense_options);
  const Eigen::MatrixXd c = dense.pair_stiffness;
  MembraneCondensationOptions factor_options;
  factor_options.storage = MembraneStorage::kFactor;
  factor_options.mode_amplitude = film.omega2.cwiseInverse();
  for (const double tolerance : {0.0, 1e-10, 1e-4, 1e-3, 1e-2}) {
    SCOPED_TRACE(tolerance);
    factor_options.rank_tolerance = tolerance;
    const ModalMembraneStiffness rom =
        modalMembraneStiffness(terms, film.fe.stiffness, film.part, film.mesh.nodes_W_m,
                               film.shapes, factor_options);
    ASSERT_TRUE(rom.factored());
    const Eigen::MatrixXd left_out = c - rom.pairStiffness();
    const double c_max = c.cwiseAbs().maxCoeff();
    EXPECT_GE(Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(left_out).eigenvalues().minCoeff(),
              -1e-12 * c_max);
    if (tolerance == 0.0) {
      EXPECT_LT(left_out.cwiseAbs().maxCoeff(), 1e-10 * c_max);
    }
    Eigen::VectorXd q_dense, q_rom;
    const Eigen::VectorXd load = film.shapes.transpose() * pressureLoad(film.mesh, 40.0);
    ASSERT_TRUE(solveModalStatic(film.omega2, dense, load, &q_dense, 10));
    ASSERT_TRUE(solveModalStatic(film.omega2, rom, load, &q_rom, 10));
    const double w_dense = (film.shapes * q_dense)(globalDof(film.centre, kW));
    const double w_rom = (film.shapes * q_rom)(globalDof(film.centre, kW));
    EXPECT_GT(w_dense / t, 5.0);
    if (tolerance <= 1e-10) {
      EXPECT_NEAR(w_rom / w_dense, 1.0, 1e-4);
    }
    std::printf("tolerance %g: R = %d of P = %d, centre w %.6e vs %.6e m\n", tolerance,
                rom.rank(), rom.pairCount(), w_rom, w_dense);
  }
}

// The damped force from the stress an earlier evaluation left in its workspace: the same bits as
// a new evaluation at that state, refused at any other state or after the workspace held another
// evaluation (the explicit part of the implicit integration reuses it, modal_implicit_split.hpp).
TEST(FeMembraneRom, ForceFromAnEarlierEvaluationIsTheSameBitsAtTheSameStateOnly) {
  const ClampedFilm film(8);
  const VonKarmanTerms terms(film.vehicle, film.mesh);
  const ModalMembraneStiffness rom = modalMembraneStiffness(
      terms, film.fe.stiffness, film.part, film.mesh.nodes_W_m, film.shapes);
  const auto m = film.shapes.cols();
  Eigen::VectorXd q(m), qd(m);
  for (Eigen::Index i = 0; i < m; ++i) {
    q(i) = 1e-4 * std::sin(1.3 * static_cast<double>(i) + 0.2);
    qd(i) = 3e-2 * std::cos(0.7 * static_cast<double>(i) - 0.4);
  }
  const double beta_s = 2e-4;
  ModalMembraneStiffness::Workspace evaluated(rom), fresh(rom);
  Eigen::VectorXd f_first = Eigen::VectorXd::Zero(m);
  rom.addForce(q, qd, beta_s, &evaluated, &f_first);
  // Onto a non-zero vector with a scale, as the split and the free flight add it.
  const Eigen::VectorXd base = Eigen::VectorXd::LinSpaced(m, -1.0, 2.0);
  Eigen::VectorXd f_new = base, f_reused = base;
  rom.addForce(q, qd, beta_s, &fresh, &f_new, -1.0);
  ASSERT_TRUE(rom.addForceEvaluatedIn(evaluated, q, qd, beta_s, &f_reused, -1.0));
  EXPECT_EQ(std::memcmp(f_new.data(), f_reused.data(), sizeof(double) * static_cast<std::size_t>(m)),
            0);
  EXPECT_GT((f_new - base).norm(), 0.0);
  // Another state, another damping: refused, f untouched.
  Eigen::VectorXd untouched = base;
  Eigen::VectorXd q_other = q;
  q_other(0) = std::nextafter(q(0), 1.0);
  EXPECT_FALSE(rom.addForceEvaluatedIn(evaluated, q_other, qd, beta_s, &untouched));
  Eigen::VectorXd qd_other = qd;
  qd_other(m - 1) *= 1.0 + 1e-15;
  EXPECT_FALSE(rom.addForceEvaluatedIn(evaluated, q, qd_other, beta_s, &untouched));
  EXPECT_FALSE(rom.addForceEvaluatedIn(evaluated, q, qd, 0.0, &untouched));
  EXPECT_EQ(untouched, base);
  // The workspace used for something else no longer holds the evaluation.
  rom.energy(q, &evaluated);
  EXPECT_FALSE(rom.addForceEvaluatedIn(evaluated, q, qd, beta_s, &untouched));
}

// The pair Hessian S (d2V/dq2 = sum_s S_(ab),s Q_s) against the tangent built from C, and the
// Newton matrix from it (newtonParts) against tangentParts: its damping part is beta J^T C J
// exactly, its stiffness part the exact d f / dq less the antisymmetric part of the damping
// force's change with q; the stress it leaves gives the damped force of addForce to round-off.
TEST(FeMembraneRom, NewtonMatrixFromThePairHessianMatchesTheTangentFromC) {
  const ClampedFilm film(8);
  const VonKarmanTerms terms(film.vehicle, film.mesh);
  const ModalMembraneStiffness rom = modalMembraneStiffness(
      terms, film.fe.stiffness, film.part, film.mesh.nodes_W_m, film.shapes);
  ASSERT_FALSE(rom.factored());
  ASSERT_EQ(rom.hessian_pairs.rows(), rom.pairCount());
  const auto m = film.shapes.cols();
  Eigen::VectorXd q(m), qd(m);
  for (Eigen::Index i = 0; i < m; ++i) {
    q(i) = 1e-4 * std::sin(1.3 * static_cast<double>(i) + 0.2);
    qd(i) = 3e-2 * std::cos(0.7 * static_cast<double>(i) - 0.4);  // beta q' / q ~ 0.1
  }
  const double beta_s = 2e-4;
  ModalMembraneStiffness::TangentWorkspace tws(rom);
  Eigen::MatrixXd gn(m, m), rest(m, m), k(m, m), d(m, m);
  // At rest: both parts exact, stiffness = the tangent of V, damping = beta J^T C J.
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(m);
  rom.tangentParts(q, zero, beta_s, &tws, &gn, &rest);
  rom.newtonParts(q, zero, beta_s, &tws, &k, &d);
  const double k_scale = (gn + rest).cwiseAbs().maxCoeff();
  EXPECT_LT((k - (gn + rest)).cwiseAbs().maxCoeff(), 1e-12 * k_scale);
  EXPECT_LT((d - beta_s * gn).cwiseAbs().maxCoeff(), 1e-12 * beta_s * gn.cwiseAbs().maxCoeff());
  // Moving: the damping part still exact; the stiffness part the symmetric part of d f / dq.
  rom.tangentParts(q, qd, beta_s, &tws, &gn, &rest);
  ModalMembraneStiffness::Workspace evaluation(rom);
  rom.newtonParts(q, qd, beta_s, &tws, &k, &d, &evaluation);
  const Eigen::MatrixXd exact = gn + rest;
  const Eigen::MatrixXd symmetric = 0.5 * (exact + exact.transpose());
  EXPECT_LT((k - symmetric).cwiseAbs().maxCoeff(), 1e-12 * exact.cwiseAbs().maxCoeff());
  EXPECT_LT((d - beta_s * gn).cwiseAbs().maxCoeff(), 1e-12 * beta_s * gn.cwiseAbs().maxCoeff());
  // What is left out is small where beta q' is small next to q (here about 0.1 of it), and not
  // zero: the test would not see a newtonParts that returned the exact matrix by another route.
  const double left_out = (exact - symmetric).cwiseAbs().maxCoeff();
  EXPECT_GT(left_out, 1e-6 * exact.cwiseAbs().maxCoeff());
  EXPECT_LT(left_out, 0.2 * exact.cwiseAbs().maxCoeff());
  // The stress it leaves: the force of a damped evaluation at this state, to round-off.
  Eigen::VectorXd f_new = Eigen::VectorXd::Zero(m), f_reused = Eigen::VectorXd::Zero(m);
  ModalMembraneStiffness::Workspace fresh(rom);
  rom.addForce(q, qd, beta_s, &fresh, &f_new);
  ASSERT_TRUE(rom.addForceEvaluatedIn(evaluation, q, qd, beta_s, &f_reused));
  EXPECT_LT((f_reused - f_new).cwiseAbs().maxCoeff(), 1e-12 * f_new.cwiseAbs().maxCoeff());
  // A factored C has no pair Hessian: newtonParts refuses it.
  MembraneCondensationOptions factored;
  factored.storage = MembraneStorage::kFactor;
  const ModalMembraneStiffness rom_g = modalMembraneStiffness(
      terms, film.fe.stiffness, film.part, film.mesh.nodes_W_m, film.shapes, factored);
  ASSERT_TRUE(rom_g.factored());
  ModalMembraneStiffness::TangentWorkspace tws_g(rom_g);
  EXPECT_THROW(rom_g.newtonParts(q, qd, beta_s, &tws_g, &k, &d), std::logic_error);
}

// Modes that stretch nothing (in-plane shapes with no out-of-plane part): C = 0, whose factor has
// no rows. Every storage keeps it as the dense zero C, and the membrane adds no energy or force.
TEST(FeMembraneRom, ModesThatStretchNothingGiveAZeroMembrane) {
  const ClampedFilm film(0);
  std::vector<Eigen::Index> in_plane;
  for (Eigen::Index c = 0; c < film.all_modes.cols() && in_plane.size() < 3; ++c)
    if (film.outOfPlaneShare(film.all_modes.col(c)) < 0.5) in_plane.push_back(c);
  ASSERT_EQ(in_plane.size(), 3u);
  Eigen::MatrixXd shapes(film.fe.dofCount(), 3);
  for (Eigen::Index j = 0; j < 3; ++j) {
    shapes.col(j) = film.all_modes.col(in_plane[static_cast<std::size_t>(j)]);
    for (int n = 0; n < film.mesh.nodeCount(); ++n)
      for (const int k : {kW, kThetaX, kThetaY}) shapes(globalDof(n, k), j) = 0.0;
  }
  const VonKarmanTerms terms(film.vehicle, film.mesh);
  for (const MembraneStorage storage :
       {MembraneStorage::kCheaper, MembraneStorage::kDense, MembraneStorage::kFactor}) {
    SCOPED_TRACE(static_cast<int>(storage));
    MembraneCondensationOptions options;
    options.storage = storage;
    options.mode_amplitude = Eigen::VectorXd::Ones(3);
    options.rank_tolerance = 1e-10;
    const ModalMembraneStiffness rom = modalMembraneStiffness(
        terms, film.fe.stiffness, film.part, film.mesh.nodes_W_m, shapes, options);
    EXPECT_FALSE(rom.factored());
    ASSERT_EQ(rom.pair_stiffness.rows(), rom.pairCount());
    EXPECT_EQ(rom.pair_stiffness.cwiseAbs().maxCoeff(), 0.0);
    ModalMembraneStiffness::Workspace ws(rom);
    const Eigen::VectorXd q = Eigen::VectorXd::Constant(3, 1e-3);
    Eigen::VectorXd f = Eigen::VectorXd::Zero(3);
    rom.addForce(q, &ws, &f);
    EXPECT_EQ(f.cwiseAbs().maxCoeff(), 0.0);
    EXPECT_EQ(rom.energy(q, &ws), 0.0);
  }
}

// With every out-of-plane mode kept, the reduced static solution is the full nonlinear one:
// a clamped plate (no P3, no members) under a pressure that deflects it ~10 thicknesses.
TEST(FeMembraneRom, WithAllBendingModesTheReducedStaticIsTheFullOne) {
  // Every out-of-plane mode of the interior: 3 DOF x 25 interior nodes.
  const ClampedFilm film(std::numeric_limits<int>::max());
  ASSERT_EQ(film.shapes.cols(), 75);
  const double t = ClampedFilm::kThickness_m;
  const VonKarmanTerms terms(film.vehicle, film.mesh);
  const ModalMembraneStiffness rom =
      modalMembraneStiffness(terms, film.fe.stiffness, film.part, film.mesh.nodes_W_m, film.shapes);
  const Eigen::VectorXd load = pressureLoad(film.mesh, 40.0);
  NonlinearStaticOptions options;
  options.load_steps = 10;
  const NonlinearStaticResult full =
      solveNonlinearStatic(film.fe.stiffness, terms, film.part, load, options);
  ASSERT_TRUE(full.converged) << full.message;
  Eigen::VectorXd q;
  ASSERT_TRUE(solveModalStatic(film.omega2, rom, film.shapes.transpose() * load, &q, 10));
  const Eigen::VectorXd u_rom = film.shapes * q;
  const int centre = film.centre;
  const double w_full = full.displacement(globalDof(centre, kW));
  EXPECT_GT(w_full / t, 5.0);
  // The same energy over the same out-of-plane space; the in-plane relaxation drops only its own
  // slopes: equal to 1e-3.
  EXPECT_NEAR(u_rom(globalDof(centre, kW)) / w_full, 1.0, 1e-3);
  // The linear answer is far off.
  NonlinearStaticOptions lin = options;
  lin.nonlinear = false;
  const double w_linear =
      solveNonlinearStatic(film.fe.stiffness, terms, film.part, load, lin)
          .displacement(globalDof(centre, kW));
  EXPECT_GT(w_linear / w_full, 3.0);
}

}  // namespace
}  // namespace orni::structure
