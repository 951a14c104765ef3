// The flexible wing's strip loads at the quarter chord, spread over the section nodes L, Q, T, E
// as a flat plate's loading, and the section motion the kernel sees taken with the same weights
// (core/dynamics/chordwise_weights.*, flexible_wing.cpp, strip_kinematics.cpp; docs/theory.md 6.3):
// the weights against an independent quadrature; power consistency of the modal force and of the
// resultant's power with the kinematics the kernel was given; a static flat-plate strip load
// against nodal loads formed from the FE mode shapes directly (the old coupling misses it); the
// resultant about P2 equal to the nodal loads' resultant.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <random>
#include <stdexcept>

#include "core/dynamics/chordwise_weights.hpp"
#include "core/dynamics/flight_core.hpp"
#include "core/dynamics/strip_kinematics.hpp"
#include "core/structure/modal_wing.hpp"
#include "tests/support/magpie_vehicle.hpp"

namespace orni {
namespace {

// Consistent nodal loads of Birnbaum's (birnbaum = true) or the elliptic loading of unit
// resultant on hat functions over the nodes x (0 = x_0 < ... < x_3 = c), by the midpoint rule in
// the Glauert angle (x = c (1 - cos t)/2 removes the leading-edge singularity; the densities per
// dt are (1 + cos t)/pi and 2 sin^2 t/pi). Independent of the closed form in chordwise_weights.
std::array<double, 4> lumpedByQuadrature(const std::array<double, 4>& x, bool birnbaum) {
  constexpr int kPoints = 200000;
  std::array<double, 4> f{};
  const double c = x[3], dt = kPi / kPoints;
  for (int m = 0; m < kPoints; ++m) {
    const double t = (m + 0.5) * dt;
    const double xi = 0.5 * c * (1.0 - std::cos(t));
    const double s = std::sin(t);
    const double p = birnbaum ? (1.0 + std::cos(t)) / kPi : 2.0 * s * s / kPi;
    for (int k = 0; k < 3; ++k) {
      if (xi > x[k + 1]) continue;
      const double u = (xi - x[k]) / (x[k + 1] - x[k]);
      f[k] += (1.0 - u) * p * dt;
      f[k + 1] += u * p * dt;
      break;
    }
  }
  return f;
}

TEST(ChordwiseWeights, FlatPlateLoadingsLumpedOnTheSectionNodes) {
  // The magpie's root section (nodes at c/4 and 3c/4) and an uneven one.
  for (const std::array<double, 4>& x :
       {std::array<double, 4>{0.0, 0.026, 0.078, 0.104},
        std::array<double, 4>{0.0, 0.017, 0.061, 0.09}}) {
    const ChordwiseWeights w = flatPlateChordwiseWeights(x);
    const auto a = lumpedByQuadrature(x, true), e = lumpedByQuadrature(x, false);
    double sum_a = 0, sum_e = 0, sum_b = 0, ax = 0, ex = 0, bx = 0;
    for (int i = 0; i < 4; ++i) {
      EXPECT_NEAR(w.force[i], a[i], 1e-8) << "Birnbaum, node " << i;
      EXPECT_NEAR(w.mid_chord[i], e[i], 1e-8) << "elliptic, node " << i;
      sum_a += w.force[i];
      sum_e += w.mid_chord[i];
      sum_b += w.moment[i];
      ax += w.force[i] * x[i];
      ex += w.mid_chord[i] * x[i];
      bx += w.moment[i] * x[i];
    }
    const double c = x[3];
    EXPECT_NEAR(sum_a, 1.0, 1e-14);
    EXPECT_NEAR(sum_e, 1.0, 1e-14);
    EXPECT_NEAR(ax, 0.25 * c, 1e-14 * c);  // the centroid of Birnbaum's loading: c/4
    EXPECT_NEAR(ex, 0.5 * c, 1e-14 * c);
    EXPECT_NEAR(w.reference_aft_m, 0.25 * c, 1e-14 * c);
    EXPECT_NEAR(w.mid_chord_aft_m, 0.5 * c, 1e-14 * c);
    EXPECT_NEAR(sum_b * c, 0.0, 1e-13);   // a pure couple ...
    EXPECT_NEAR(bx, -1.0, 1e-13);         // ... of unit nose-up moment
  }
  // Nodes at c/4 and 3c/4: the quarter-chord lift goes 41 % to L, 39 % to Q, 17 % to T, 2 % to E
  // (the old coupling: 2/3 to L, 1/3 to T).
  const ChordwiseWeights w = flatPlateChordwiseWeights({0.0, 0.25, 0.75, 1.0});
  EXPECT_NEAR(w.force[0], 0.4135, 1e-4);
  EXPECT_NEAR(w.force[1], 0.3910, 1e-4);
  EXPECT_NEAR(w.force[2], 0.1730, 1e-4);
  EXPECT_NEAR(w.force[3], 0.0225, 1e-4);
  EXPECT_THROW(flatPlateChordwiseWeights({0.0, 0.5, 0.4, 1.0}), std::invalid_argument);
  EXPECT_THROW(flatPlateChordwiseWeights({0.1, 0.2, 0.4, 1.0}), std::invalid_argument);
}

class ChordwiseCouplingTest : public ::testing::Test {
 protected:
  ChordwiseCouplingTest()
      : vehicle_(testing::magpieVehicle()), model_(vehicle_), flex_(*model_.flexible),
        mw_(*flex_.modal), data_(model_), kin_(flex_.stacked, flex_.mode_count) {
    kin_.setReferencePoints(data_.batch);
  }
  // Chordwise positions of L, Q, T, E aft of L, and their node ids.
  void sectionNodes(std::size_t j, std::array<int, 4>* node, std::array<double, 4>* x) const {
    const structure::StripSampleNodes& sn = mw_.mesh.strip_nodes[j];
    *node = {sn.leading_edge, sn.quarter_chord, sn.three_quarter_chord, sn.trailing_edge};
    const Vec3& xL = mw_.mesh.nodes_W_m[static_cast<std::size_t>(sn.leading_edge)];
    for (int i = 0; i < 4; ++i)
      (*x)[i] = xL.x() - mw_.mesh.nodes_W_m[static_cast<std::size_t>((*node)[i])].x();
  }

  VehicleModel vehicle_;
  FlightCoreModel model_;
  const FlexibleWingModel& flex_;
  const structure::ModalWing& mw_;
  FlightCoreData data_;
  StripKinematics kin_;
};

// The nodal form of each strip's operators (FlexibleStrip::section_nodes, force_weights,
// moment_weights: what a full-order model of the wing is loaded and read with,
// studies/tools/orni_flapping_reference) is the modal one: sum a_i Phi_i = phi_P, sum b_i n^T
// Phi_i = psi_twist, on the strip's own L, Q, T, E nodes.
TEST_F(ChordwiseCouplingTest, NodalFormOfTheStripOperatorsIsTheModalOne) {
  const Vec3 n_W = -Vec3::UnitZ();
  for (std::size_t j = 0; j < flex_.strips.size(); ++j) {
    const FlexibleStrip& s = flex_.strips[j];
    std::array<int, 4> node{};
    std::array<double, 4> x{};
    sectionNodes(j, &node, &x);
    EXPECT_EQ(s.section_nodes, node);
    Eigen::Matrix3Xd phi_p = Eigen::Matrix3Xd::Zero(3, flex_.mode_count);
    Eigen::RowVectorXd twist = Eigen::RowVectorXd::Zero(flex_.mode_count);
    for (std::size_t i = 0; i < 4; ++i) {
      phi_p += s.force_weights[i] * mw_.phi_W[static_cast<std::size_t>(s.section_nodes[i])];
      twist += s.moment_weights[i] * (n_W.transpose() * mw_.phi_W[static_cast<std::size_t>(s.section_nodes[i])]);
    }
    constexpr double kRoundOff = 1e-12;  // relative: the same sums in another order
    EXPECT_LT((phi_p - s.phi_P).cwiseAbs().maxCoeff(), kRoundOff * s.phi_P.cwiseAbs().maxCoeff()) << j;
    EXPECT_LT((twist - s.psi_twist).cwiseAbs().maxCoeff(),
              kRoundOff * s.psi_twist.cwiseAbs().maxCoeff()) << j;
  }
}

// docs/theory.md 6.3: the load operators are the transposes of the kinematic ones. For random q, q'
// and strip loads: Q . q' = sum_j (F_j . v_P,j + M_j . w_s,j), where v_P and w_s are the elastic
// velocity of the point the force acts at and the elastic twist rate, as the kernel was given
// them (no frame motion); the resultant's power is the same sum; and the apparent-mass force at
// the kernel's mid-chord and its couple (resultant/power) are the transposes of psi_mid and
// psi_twist, the operators of the modal apparent mass (4.4).
TEST_F(ChordwiseCouplingTest, ModalForceIsPowerConsistentWithTheKernelsKinematics) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const int M = flex_.mode_count;
  const Eigen::Index ns = flex_.stacked.ns;
  aero::StripBatch& b = data_.batch;
  for (const double q_scale : {0.0, 2e-3}) {
    Eigen::VectorXd q(M), qd(M);
    for (int k = 0; k < M; ++k) {
      q[k] = q_scale * u(rng);
      qd[k] = 0.5 * u(rng);
    }
    kin_.compute(q, qd, WingFrameMotion{}, b);  // elastic motion only
    double power = 0.0, scale = 0.0;
    for (Eigen::Index j = 0; j < ns; ++j) {
      b.Fx[j] = u(rng); b.Fy[j] = u(rng); b.Fz[j] = u(rng);
      b.Mx[j] = 0.02 * u(rng); b.My[j] = 0.02 * u(rng); b.Mz[j] = 0.02 * u(rng);
      const double p = b.Fx[j] * b.vx[j] + b.Fy[j] * b.vy[j] + b.Fz[j] * b.vz[j] +
                       b.Mx[j] * b.wx[j] + b.My[j] * b.wy[j] + b.Mz[j] * b.wz[j];
      power += p;
      scale += std::abs(p);
    }
    Eigen::VectorXd Q(M);
    kin_.modalForce(b, &Q);
    EXPECT_NEAR(Q.dot(qd), power, 1e-13 * scale) << "q scale " << q_scale;
    const Eigen::VectorXd zero = Eigen::VectorXd::Zero(ns);
    EXPECT_NEAR(-kin_.power(b, zero, zero, Vec3::Zero()), power, 1e-13 * scale);
    if (q_scale != 0.0) continue;
    // Apparent-mass force (along n at the kernel's mid-chord) and couple: exact at q = 0.
    const Eigen::VectorXd ef = Eigen::VectorXd::Random(ns), ec = 0.02 * Eigen::VectorXd::Random(ns);
    const Eigen::VectorXd rates = flex_.stacked.apparentShapes() * qd;  // [twist'; mid-chord']
    const double p_ref = ef.dot(rates.tail(ns)) + ec.dot(rates.head(ns));
    EXPECT_NEAR(-kin_.power(b, ef, ec, Vec3::Zero()) - power, p_ref,
                1e-12 * (ef.cwiseAbs().dot(rates.tail(ns).cwiseAbs()) + std::abs(p_ref)));
  }
}

// A static strip load with the flat plate's distribution, the kernel's two normal forces:
// dN4 at the quarter chord (Birnbaum) and dN2 at mid-chord (elliptic; moment -(c/4) dN2 about the
// quarter chord, c the section's chord). Its generalised force must be sum_i Phi_i^T f_i of the
// consistent nodal loads of those distributions on L, Q, T, E, formed here from the FE mode
// shapes at the nodes and an independent quadrature. The old coupling (force at L, moment about
// L as a pair on L and T: 2/3 and 1/3 of the quarter-chord force) misses it by far more.
// The resultant about P2 equals the nodal loads' resultant.
TEST_F(ChordwiseCouplingTest, StaticFlatPlateLoadMatchesTheNodalLoadsOfTheModeShapes) {
  const int M = flex_.mode_count;
  const Eigen::Index ns = flex_.stacked.ns;
  aero::StripBatch& b = data_.batch;
  const Eigen::VectorXd zero_q = Eigen::VectorXd::Zero(M);
  kin_.compute(zero_q, zero_q, WingFrameMotion{}, b);
  const Vec3 n = -Vec3::UnitZ(), e_s = Vec3::UnitY();  // the flat wing (W)
  Eigen::VectorXd Q_ref = Eigen::VectorXd::Zero(M), Q_old = Eigen::VectorXd::Zero(M);
  Vec3 F_ref = Vec3::Zero(), M_ref = Vec3::Zero();
  for (Eigen::Index j = 0; j < ns; ++j) {
    const auto s = static_cast<std::size_t>(j);
    EXPECT_LT((Vec3(b.nx[j], b.ny[j], b.nz[j]) - n).norm(), 1e-14);
    std::array<int, 4> node;
    std::array<double, 4> x;
    sectionNodes(s, &node, &x);
    const double dN4 = 0.05 + 0.02 * std::sin(0.3 * j), dN2 = 0.01 * std::cos(0.5 * j);
    const double c = x[3];
    const Vec3 F = (dN4 + dN2) * n, Mq = -0.25 * c * dN2 * e_s;
    b.Fx[j] = F.x(); b.Fy[j] = F.y(); b.Fz[j] = F.z();
    b.Mx[j] = Mq.x(); b.My[j] = Mq.y(); b.Mz[j] = Mq.z();
    const auto birnbaum = lumpedByQuadrature(x, true), elliptic = lumpedByQuadrature(x, false);
    for (int i = 0; i < 4; ++i) {
      const auto p = static_cast<std::size_t>(node[i]);
      const Vec3 f = (dN4 * birnbaum[i] + dN2 * elliptic[i]) * n;
      Q_ref += mw_.phi_W[p].transpose() * f;
      F_ref += f;
      M_ref += mw_.mesh.nodes_W_m[p].cross(f);  // P2 is the origin of W
    }
    // The old coupling: F at L, the moment about L through psi = -n^T (Phi_T - Phi_L)/|x_T - x_L|.
    const FlexibleStrip& fs = flex_.strips[s];
    const double M_L = -0.25 * c * dN4 - 0.5 * c * dN2;
    Q_old += fs.phi_L.transpose() * F -
             M_L * (fs.phi_T - fs.phi_L).transpose() * n / (fs.x_T_W_m - fs.x_L_W_m).norm();
  }
  Eigen::VectorXd Q(M);
  kin_.modalForce(b, &Q);
  EXPECT_LT((Q - Q_ref).norm(), 1e-7 * Q_ref.norm()) << "Q     " << Q.transpose()
                                                     << "\nQ_ref " << Q_ref.transpose();
  const double old_error = (Q_old - Q_ref).norm() / Q_ref.norm();
  EXPECT_GT(old_error, 0.3) << "the old coupling: " << Q_old.transpose();  // measured 0.86
  std::cout << "relative error of the generalised force: new "
            << (Q - Q_ref).norm() / Q_ref.norm() << ", old coupling " << old_error << "\n";
  Vec3 F_W, M_W;
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(ns);
  kin_.resultant(b, zero, zero, Vec3::Zero(), &F_W, &M_W, nullptr);
  EXPECT_LT((F_W - F_ref).norm(), 1e-7 * F_ref.norm());
  EXPECT_LT((M_W - M_ref).norm(), 1e-7 * M_ref.norm());
}

// The kernel's convention: the batch's reference point is the quarter chord of the aerodynamic
// strip (its circulatory force has no lever, docs/theory.md 5.5), the section's P sits at the
// quarter chord and R at the three-quarter chord of the mesh section; the rigid wing keeps the
// leading edge.
TEST_F(ChordwiseCouplingTest, ReferencePointsAtTheQuarterChord) {
  const Eigen::Index ns = flex_.stacked.ns;
  for (Eigen::Index j = 0; j < ns; ++j) {
    const auto s = static_cast<std::size_t>(j);
    EXPECT_DOUBLE_EQ(data_.batch.ref_aft_of_le_m[j], 0.25 * data_.batch.chord_m[j]);
    std::array<int, 4> node;
    std::array<double, 4> x;
    sectionNodes(s, &node, &x);
    const FlexibleStrip& fs = flex_.strips[s];
    const Vec3 xL = mw_.mesh.nodes_W_m[static_cast<std::size_t>(node[0])];
    EXPECT_LT((fs.x_P_W_m - (xL - 0.25 * x[3] * Vec3::UnitX())).norm(), 1e-14) << j;
    EXPECT_LT((fs.x_R_W_m - (xL - 0.75 * x[3] * Vec3::UnitX())).norm(), 1e-14) << j;
    EXPECT_NEAR(fs.lever_R_m, 0.5 * x[3], 1e-14) << j;
  }
  VehicleModel rigid = vehicle_;
  rigid.wing.structure = StructureLevel::kRigid;
  const FlightCoreModel rigid_model(rigid);
  EXPECT_FALSE(rigid_model.flexible);
  const FlightCoreData rigid_data(rigid_model);
  EXPECT_EQ(rigid_data.batch.ref_aft_of_le_m.abs().maxCoeff(), 0.0);
}

}  // namespace
}  // namespace orni

namespace orni {
namespace {

// Why the load is spread (docs/theory.md 6.3): the magpie's basis holds modes that bend the section
// chordwise between its sample nodes (skin panel modes), so a point load on a skin node is not
// "harmless in a truncated global basis". Measure, per mode, the quarter-chord node's normal
// displacement off the L-T chord line, relative to the largest normal displacement of the
// section nodes.
TEST(ChordwiseCoupling, TheMagpieBasisBendsTheSectionsChordwise) {
  const VehicleModel v = testing::magpieVehicle();
  const FlightCoreModel model(v);
  const structure::ModalWing& mw = *model.flexible->modal;
  const Vec3 n = -Vec3::UnitZ();
  // Measured: 17 of the 24 modes move Q off the line by more than 30 % (two by more than 100 %).
  int local = 0;
  for (int k = 0; k < mw.modeCount(); ++k) {
    double camber = 0.0, size = 0.0;
    for (const structure::StripSampleNodes& sn : mw.mesh.strip_nodes) {
      const auto w = [&](int node) {
        return n.dot(mw.phi_W[static_cast<std::size_t>(node)].col(k));
      };
      const double wL = w(sn.leading_edge), wQ = w(sn.quarter_chord),
                   wT = w(sn.three_quarter_chord), wE = w(sn.trailing_edge);
      camber = std::max(camber, std::abs(wQ - (2.0 * wL + wT) / 3.0));
      size = std::max({size, std::abs(wL), std::abs(wQ), std::abs(wT), std::abs(wE)});
    }
    if (camber > 0.3 * size) ++local;
  }
  EXPECT_GE(3 * local, mw.modeCount()) << local << " of " << mw.modeCount();
}

}  // namespace
}  // namespace orni
