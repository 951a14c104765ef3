// The wing's inertial loads from the precomputed lumped sums (lumped_inertia_sums.hpp) against the
// per-node loop over the FE mesh they replace (docs/theory.md 4.4, level L3): an independent
// evaluation of the same sums in another order.
#include <gtest/gtest.h>

#include <random>

#include "core/structure/lumped_inertia_sums.hpp"
#include "core/structure/modal_wing.hpp"
#include "tests/unit/structure/fe_test_meshes.hpp"

namespace orni::structure {
namespace {

// The same products summed in two orders, over a few hundred nodes: round-off.
constexpr double kRoundOffTol = 1e-11;

WingInertialLoads perNodeLoop(const ModalWing& mw, const Eigen::VectorXd& q,
                              const Eigen::VectorXd& qd, const Eigen::VectorXd& qdd,
                              const Vec3& w, const Vec3& alpha) {
  WingInertialLoads out;
  for (std::size_t p = 0; p < mw.phi_W.size(); ++p) {
    out.rotary_moment_W_Nm += mw.nodal_rotary_W_kgm2[p] * alpha;
    const double m = mw.nodal_mass_kg[static_cast<Eigen::Index>(p)];
    if (m <= 0.0) continue;
    const Eigen::Matrix3Xd& phi = mw.phi_W[p];
    const Vec3 s = mw.mesh.nodes_W_m[p] + phi * q;
    const Vec3 u = phi * qd;
    const Vec3 a = alpha.cross(s) + w.cross(w.cross(s)) + 2.0 * w.cross(u) + phi * qdd;
    const Vec3 v = w.cross(s) + u;
    out.force_W_N -= m * a;
    out.moment_W_Nm -= m * s.cross(a);
    out.kinetic_energy_rate_W += m * a.dot(v);
  }
  out.moment_W_Nm -= out.rotary_moment_W_Nm;
  return out;
}

double relErr(const Vec3& a, const Vec3& b) { return (a - b).norm() / std::max(b.norm(), 1e-300); }

TEST(StructureLumpedInertiaSums, EqualThePerNodeLoopAtLargeDeflectionAndGeneralMotion) {
  const fe_test::MiniWing wing = fe_test::miniWing(6, 10, 0.04, 0.08);
  ModalWingOptions o;
  o.selection.max_modes = 8;
  const ModalWing mw = buildModalWing(wing.vehicle, wing.mesh, o);
  ASSERT_EQ(mw.lumped_sums.modeCount(), 8);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  LumpedInertiaWorkspace ws;
  for (int trial = 0; trial < 20; ++trial) {
    // Modal amplitudes up to tip deflections of a chord (the q^2 terms matter), any rotation.
    Eigen::VectorXd q(8), qd(8), qdd(8);
    for (int i = 0; i < 8; ++i) {
      q(i) = 0.3 * u(rng);
      qd(i) = 50.0 * u(rng);
      qdd(i) = 5e4 * u(rng);
    }
    const Vec3 w(100.0 * u(rng), 10.0 * u(rng), 10.0 * u(rng));
    const Vec3 alpha(5e4 * u(rng), 1e3 * u(rng), 1e3 * u(rng));
    const WingInertialLoads ref = perNodeLoop(mw, q, qd, qdd, w, alpha);
    const WingInertialLoads got = wingInertialLoads(mw.lumped_sums, q, qd, qdd, w, alpha, &ws);
    EXPECT_LT(relErr(got.force_W_N, ref.force_W_N), kRoundOffTol) << trial;
    EXPECT_LT(relErr(got.moment_W_Nm, ref.moment_W_Nm), kRoundOffTol) << trial;
    EXPECT_LT(relErr(got.rotary_moment_W_Nm, ref.rotary_moment_W_Nm), kRoundOffTol) << trial;
    EXPECT_NEAR(got.kinetic_energy_rate_W, ref.kinetic_energy_rate_W,
                kRoundOffTol * std::abs(ref.kinetic_energy_rate_W) + 1e-300)
        << trial;
  }
}

TEST(StructureLumpedInertiaSums, RigidSumsAreTheWingsMassAndFirstMoment) {
  const fe_test::MiniWing wing = fe_test::miniWing(6, 10, 0.04, 0.08);
  ModalWingOptions o;
  o.selection.max_modes = 4;
  const ModalWing mw = buildModalWing(wing.vehicle, wing.mesh, o);
  // B_kl(0, 0) = sum m x_k x_l: its trace-free part and trace are the rigid inertia's.
  double mass = 0.0;
  for (Eigen::Index p = 0; p < mw.nodal_mass_kg.size(); ++p) mass += mw.nodal_mass_kg(p);
  const Vec3 c0 = mw.lumped_sums.first_moments.col(0);
  Vec3 c0_ref = Vec3::Zero();
  for (std::size_t p = 0; p < mw.phi_W.size(); ++p)
    c0_ref += mw.nodal_mass_kg[static_cast<Eigen::Index>(p)] * mw.mesh.nodes_W_m[p];
  EXPECT_LT(relErr(c0, c0_ref), kRoundOffTol);
  // A pure spin about x with no deformation: F = -w x (w x c0), the centrifugal force.
  const Eigen::VectorXd z = Eigen::VectorXd::Zero(4);
  const Vec3 w(30.0, 0.0, 0.0);
  LumpedInertiaWorkspace ws(4);
  const WingInertialLoads got = wingInertialLoads(mw.lumped_sums, z, z, z, w, Vec3::Zero(), &ws);
  EXPECT_LT(relErr(got.force_W_N, -w.cross(w.cross(c0_ref))), kRoundOffTol);
  EXPECT_GT(mass, 0.0);
}

}  // namespace
}  // namespace orni::structure
