// The co-rotational wing (core/structure/corotational.hpp, docs/theory.md 4.7 "Large
// rotations"): it is the linear wing to first order, stores no energy in a rigid motion of any
// size, and its force and tangent derive from its energy. Its answers against Euler's elastica
// are in test_fe_von_karman_validity.cpp, against CalculiX NLGEOM and the plate formulas in
// test_fe_calculix_nonlinear.cpp.
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "core/structure/corotational.hpp"
#include "core/structure/fe_assembly.hpp"
#include "core/structure/von_karman.hpp"
#include "tests/unit/structure/fe_test_disc.hpp"
#include "tests/unit/structure/fe_test_meshes.hpp"

namespace orni::structure {
namespace {

// A deformation with rotations of up to ~0.3 rad and translations of up to ~1 mm, smooth in the
// node positions (deterministic).
Eigen::VectorXd moderateDeformation(const WingMesh& mesh) {
  Eigen::VectorXd u = Eigen::VectorXd::Zero(kDofsPerNode * mesh.nodeCount());
  for (int n = 0; n < mesh.nodeCount(); ++n) {
    const Vec3& x = mesh.nodes_W_m[static_cast<std::size_t>(n)];
    const double s = 20.0 * x.x(), t = 20.0 * x.y();
    u(globalDof(n, kU)) = 1e-4 * std::sin(3.0 * t + s);
    u(globalDof(n, kV)) = 2e-4 * std::cos(2.0 * s - t);
    u(globalDof(n, kW)) = 1e-3 * (s * s + 0.5 * t);
    u(globalDof(n, kThetaX)) = 0.3 * std::sin(t + 0.3);
    u(globalDof(n, kThetaY)) = -0.2 * std::cos(2.0 * s);
    u(globalDof(n, kThetaZ)) = 0.05 * std::sin(s - t);
  }
  return u;
}

TEST(FeCoRotational, AtRestItIsTheLinearWing) {
  const fe_test::MiniWing w = fe_test::miniWing();
  const WingFeModel fe = assembleWingFe(w.vehicle, w.mesh);
  const CoRotationalTerms cr(w.vehicle, w.mesh, fe.stiffness);
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(cr.dofCount());
  // Round-off only (the rods' E A / L ~ 6e6 N/m times length errors of ~1e-18 m).
  EXPECT_LT(std::abs(cr.strainEnergy(zero)), 1e-24);
  EXPECT_LT(cr.strainForce(zero).lpNorm<Eigen::Infinity>(), 1e-9);
  // The tangent at rest is K: the central differences' error (step 1e-6) and round-off.
  const Eigen::MatrixXd k = Eigen::MatrixXd(fe.stiffness);
  const Eigen::MatrixXd h = Eigen::MatrixXd(cr.strainTangent(zero));
  double worst = 0.0;
  for (int j = 0; j < k.cols(); ++j)
    for (int i = 0; i < k.rows(); ++i) {
      // Relative to the larger diagonal of the two DOFs (the rods' E A / L and the film's
      // bending lie 10 orders of magnitude apart).
      const double scale = std::sqrt(std::abs(k(i, i) * k(j, j)));
      if (scale > 0.0) worst = std::max(worst, std::abs(h(i, j) - k(i, j)) / scale);
    }
  std::printf("co-rotational tangent at rest against K: largest error %.2e of the diagonal\n", worst);
  fe_test::recordError("tangent_at_rest_error", worst);
  EXPECT_LT(worst, 1e-6);
}

TEST(FeCoRotational, RigidMotionsOfAnySizeStoreNoEnergy) {
  const fe_test::MiniWing w = fe_test::miniWing();
  const WingFeModel fe = assembleWingFe(w.vehicle, w.mesh);
  const CoRotationalTerms cr(w.vehicle, w.mesh, fe.stiffness);
  // A deformation's energy for scale: the moderate one, 1 % of it.
  const double reference = cr.strainEnergy(0.01 * moderateDeformation(w.mesh));
  ASSERT_GT(reference, 0.0);
  for (const double angle : {0.3, 1.2, 2.5}) {
    const Eigen::Vector3d axis = Eigen::Vector3d(1.0, -2.0, 0.7).normalized();
    const Mat3 q = Eigen::AngleAxisd(angle, axis).toRotationMatrix();
    const Vec3 shift(0.01, -0.02, 0.03);
    Eigen::VectorXd u(cr.dofCount());
    for (int n = 0; n < w.mesh.nodeCount(); ++n) {
      const Vec3& x = w.mesh.nodes_W_m[static_cast<std::size_t>(n)];
      u.segment<3>(globalDof(n, kU)) = q * x + shift - x;
      u.segment<3>(globalDof(n, kThetaX)) = angle * axis;
    }
    const double energy = cr.strainEnergy(u);
    const double force = cr.strainForce(u).lpNorm<Eigen::Infinity>();
    std::printf("rigid rotation by %.1f rad: energy %.2e J (a 1e-2 deformation: %.2e J), largest "
                "force %.2e N\n",
                angle, energy, reference, force);
    // Round-off: the rods' E A / L ~ 1e8 N/m times length errors of ~1e-17 m.
    EXPECT_LT(std::abs(energy), 1e-12 * reference);
    EXPECT_LT(force, 1e-6);
    // Every facet's plane turns by the angle between z_W and Q z_W, and a film stays taut.
    EXPECT_NEAR(cr.largestFacetTilt(u), std::acos(q(2, 2)), 1e-9);
    FilmLaw film;
    film.compression_cap_n_per_m = 20.0;
    const CoRotationalTerms wrinkling(w.vehicle, w.mesh, fe.stiffness, SkinMembrane::kTensionField,
                                      film);
    for (const FilmState state : wrinkling.facetStates(u)) EXPECT_EQ(state, FilmState::kTaut);
  }
}

TEST(FeCoRotational, ForceAndTangentDeriveFromTheEnergy) {
  const fe_test::MiniWing w = fe_test::miniWing();
  const WingFeModel fe = assembleWingFe(w.vehicle, w.mesh);
  for (const SkinMembrane law : {SkinMembrane::kElastic, SkinMembrane::kTensionField}) {
    FilmLaw film;
    film.compression_cap_n_per_m = 20.0;
    const CoRotationalTerms cr(w.vehicle, w.mesh, fe.stiffness, law, film,
                               FacetTangent::kDifferences);
    const CoRotationalTerms fast(w.vehicle, w.mesh, fe.stiffness, law, film);
    const Eigen::VectorXd u = moderateDeformation(w.mesh);
    const Eigen::VectorXd f = cr.strainForce(u);
    const SparseMatrix k = cr.strainTangent(u);
    // The default facet tangent leaves out the bending moments' geometric term only.
    const double fast_error = Eigen::MatrixXd(fast.strainTangent(u) - k).lpNorm<Eigen::Infinity>() /
                              Eigen::MatrixXd(k).lpNorm<Eigen::Infinity>();
    double force_error = 0.0, tangent_error = 0.0;
    // Every DOF of a node inside the skin, one on the leading-edge rod and one on the diagonal.
    for (const int node : {fe_test::gridNode(1, 3, 4), fe_test::gridNode(4, 5, 4),
                           fe_test::gridNode(3, 1, 4)})
      for (int d = 0; d < kDofsPerNode; ++d) {
        const int dof = globalDof(node, d);
        const double h = d < 3 ? 1e-7 : 1e-6;
        Eigen::VectorXd up = u, um = u;
        up(dof) += h;
        um(dof) -= h;
        const double fd = (cr.strainEnergy(up) - cr.strainEnergy(um)) / (2.0 * h);
        force_error = std::max(force_error, std::abs(fd - f(dof)) / f.lpNorm<Eigen::Infinity>());
        const Eigen::VectorXd column = (cr.strainForce(up) - cr.strainForce(um)) / (2.0 * h);
        const Eigen::VectorXd tangent_column = Eigen::MatrixXd(k).col(dof);
        tangent_error = std::max(tangent_error, (column - tangent_column).lpNorm<Eigen::Infinity>() /
                                                    tangent_column.lpNorm<Eigen::Infinity>());
      }
    std::printf("%s skin: force against the energy's differences %.2e, tangent against the "
                "force's %.2e, the default (membrane-exact) tangent against it %.2e (relative)\n",
                law == SkinMembrane::kElastic ? "elastic" : "wrinkling", force_error, tangent_error,
                fast_error);
    EXPECT_LT(force_error, 1e-6);
    // The tangent is a central difference with step 1e-6 (and the film's law has kinks).
    EXPECT_LT(tangent_error, 1e-5);
  }
}

// A plate's rotations stay small up to w0/h of a few: there the co-rotational and the von
// Karman answers agree (clamped disc, a = 50 mm, h = 1 mm, Timoshenko's w0/h = 1 and 4).
TEST(FeCoRotational, ModerateRotationsAgreeWithVonKarman) {
  const double radius = 0.05, thickness = 1e-3, e = 70e9, nu = 0.3;
  const VehicleModel vehicle = fe_test::skinVehicle(thickness, e, nu, 2700.0);
  const WingMesh mesh = fe_test::discMesh(radius, 8);
  const WingFeModel fe = assembleWingFe(vehicle, mesh);
  std::vector<int> held;
  for (int n : fe_test::discRimNodes(mesh, radius))
    for (int k = 0; k < kDofsPerNode; ++k) held.push_back(globalDof(n, k));
  const DofPartition part = makeDofPartition(fe.active, held);
  const VonKarmanTerms vk(vehicle, mesh);
  const CoRotationalTerms cr(vehicle, mesh, fe.stiffness);
  const double d = e * thickness * thickness * thickness / (12.0 * (1.0 - nu * nu));
  for (const double ratio : {1.0, 4.0}) {
    const double q = (ratio + 0.488 * ratio * ratio * ratio) * 64.0 * d * thickness /
                     std::pow(radius, 4);
    NonlinearStaticOptions o;
    o.load_steps = 6;
    const Eigen::VectorXd load = fe_test::pressureLoad(mesh, q);
    const NonlinearStaticResult a = solveNonlinearStatic(fe.stiffness, vk, part, load, o);
    const NonlinearStaticResult b = solveNonlinearStatic(fe.stiffness, cr, part, load, o);
    ASSERT_TRUE(a.converged) << a.message;
    ASSERT_TRUE(b.converged) << b.message;
    const double w_vk = a.displacement(globalDof(0, kW)), w_cr = b.displacement(globalDof(0, kW));
    std::printf("clamped disc, Timoshenko w0/h %.0f: von Karman %.4f h, co-rotational %.4f h "
                "(%d / %d Newton iterations)\n",
                ratio, w_vk / thickness, w_cr / thickness, a.newton_iterations, b.newton_iterations);
    // The slopes reach 0.02-0.1: the two strain measures differ by their squares' share.
    EXPECT_NEAR(w_cr / w_vk, 1.0, 0.01);
  }
}

TEST(FeCoRotational, RefusesWhatItDoesNotBuild) {
  fe_test::MiniWing w = fe_test::miniWing();
  const WingFeModel fe = assembleWingFe(w.vehicle, w.mesh);
  const SparseMatrix small(6, 6);
  EXPECT_THROW(CoRotationalTerms(w.vehicle, w.mesh, small), std::invalid_argument);
  FilmLaw bad;
  bad.residual_stiffness = 0.0;
  EXPECT_THROW(CoRotationalTerms(w.vehicle, w.mesh, fe.stiffness, SkinMembrane::kTensionField, bad),
               std::invalid_argument);
  w.vehicle.wing.skin.pretension_N_per_m = 10.0;
  EXPECT_THROW(CoRotationalTerms(w.vehicle, w.mesh, fe.stiffness), std::invalid_argument);
}

}  // namespace
}  // namespace orni::structure
