// The full-order nonlinear wing in time (structure/wing_transient.hpp) against independent
// truths: the first mode's frequency from the eigen-solution (linear free vibration), the energy
// of the undamped trapezoidal rule, and the full nonlinear static solution (a slowly applied load
// with damping settles on it).
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "core/structure/fe_assembly.hpp"
#include "core/structure/modal_wing.hpp"
#include "core/structure/skin_pretension.hpp"
#include "core/structure/static_shapes.hpp"
#include "core/structure/von_karman.hpp"
#include "core/structure/wing_mesh.hpp"
#include "core/structure/wing_transient.hpp"
#include "fe_test_meshes.hpp"
#include "tests/support/magpie_vehicle.hpp"

namespace orni::structure {
namespace {

struct Rig {
  VehicleModel vehicle = testing::magpieVehicle();
  WingMesh mesh;
  ModalWingOptions options;
  WingFeModel fe;
  DofPartition part;
  std::unique_ptr<VonKarmanTerms> terms;
  std::vector<Eigen::Vector3d> nodes;
  explicit Rig(double element_m) {
    mesh = buildWingMesh(vehicle, element_m);
    options = modalWingOptionsOf(vehicle.wing.fe);
    fe = assembleWingFe(vehicle, mesh);
    addSkinPretension(vehicle, mesh, options.support, &fe);
    part = makeDofPartition(fe.active, wingBoundaryDofs(mesh, options.support));
    terms = std::make_unique<VonKarmanTerms>(vehicle, mesh);
    const Eigen::Vector3d p2 = mesh.nodes_W_m[static_cast<std::size_t>(mesh.p2_node)];
    for (const auto& x : mesh.nodes_W_m) nodes.push_back(x - p2);
  }
  WingTransient transient(const WingTransientOptions& o) const {
    return WingTransient(fe.stiffness, fe.mass, *terms, part, nodes, o);
  }
};

// Free vibration in the first mode at an amplitude where the membrane is negligible (1 um at the
// mode's largest translation): the period of the undamped average-acceleration rule is the
// mode's, lengthened by (omega h)^2/12 (Newmark), and its energy is conserved.
TEST(FeWingTransient, LinearFreeVibrationHasTheFirstModesFrequencyAndKeepsItsEnergy) {
  const Rig rig(0.02);
  ModalWingOptions mo = rig.options;
  mo.selection.max_modes = 1;
  mo.geometric_stiffness = false;
  const ModalWing mw = buildModalWing(rig.vehicle, rig.mesh, mo);
  const double f1 = mw.frequencies_hz(0);
  Eigen::VectorXd shape = mw.mode_shapes.col(0);
  shape *= 1e-6 / shape.cwiseAbs().maxCoeff();
  WingTransientOptions o;
  o.hht_alpha = 0.0;
  WingTransient tr = rig.transient(o);
  const WingTransientLoads none;
  tr.setState(shape, Eigen::VectorXd::Zero(shape.size()), none);
  const double e0 = tr.strainEnergy();
  const int steps_per_period = 100;
  const double h = 1.0 / f1 / steps_per_period;
  // Track the modal coordinate by the mass projection, and time its upward zero crossings.
  const Eigen::VectorXd m_phi = rig.fe.mass * mw.mode_shapes.col(0);
  double prev = m_phi.dot(tr.displacement()), t = 0.0;
  std::vector<double> crossings;
  double worst_energy = 0.0;
  for (int i = 0; i < 3 * steps_per_period; ++i) {
    const auto rep = tr.step(h, none);
    ASSERT_TRUE(rep.converged) << rep.message;
    t += h;
    const double x = m_phi.dot(tr.displacement());
    if (prev < 0.0 && x >= 0.0) crossings.push_back(t - h * x / (x - prev));
    prev = x;
    worst_energy = std::max(worst_energy,
                            std::abs(tr.kineticEnergy() + tr.strainEnergy() - e0) / e0);
  }
  ASSERT_GE(crossings.size(), 2u);
  const double period = crossings[1] - crossings[0];
  const double omega_h = 2.0 * fe_test::kTestPi / steps_per_period;
  const double expected = (1.0 / f1) * (1.0 + omega_h * omega_h / 12.0);
  std::printf("first mode %.3f Hz: period %.6f s, expected %.6f s; energy drift %.2e\n", f1,
              period, expected, worst_energy);
  EXPECT_NEAR(period / expected, 1.0, 2e-3);  // the other modes the start excites are < 1e-3
  EXPECT_LT(worst_energy, 1e-6);
}

// A uniform lift applied slowly (a 0.2 s ramp, then held) on the damped nonlinear wing settles on
// the full nonlinear static solution (von_karman.hpp), well into the membrane regime.
TEST(FeWingTransient, SlowlyAppliedLiftSettlesOnTheNonlinearStaticSolution) {
  const Rig rig(0.02);
  const Eigen::VectorXd load = uniformLiftLoad(rig.mesh, 2.0);
  const NonlinearStaticResult stat =
      solveNonlinearStatic(rig.fe.stiffness, *rig.terms, rig.part, load);
  ASSERT_TRUE(stat.converged) << stat.message;
  WingTransientOptions o;
  o.damping_s = 2e-3;
  WingTransient tr = rig.transient(o);
  Eigen::VectorXd f = Eigen::VectorXd::Zero(load.size());
  WingTransientLoads l;
  l.force = &f;
  tr.setState(f, f, l);
  const double h = 1e-3;
  for (int i = 1; i <= 400; ++i) {
    f = load * std::min(1.0, i * h / 0.2);
    const auto rep = tr.step(h, l);
    ASSERT_TRUE(rep.converged) << "step " << i << ": " << rep.message;
  }
  const Eigen::VectorXd u = tr.displacement();
  const double err = (u - stat.displacement).norm() / stat.displacement.norm();
  std::printf("2 Pa: static |u| %.4e, transient after 0.4 s: relative difference %.2e\n",
              stat.displacement.norm(), err);
  EXPECT_LT(err, 1e-2);
}


}  // namespace
}  // namespace orni::structure
