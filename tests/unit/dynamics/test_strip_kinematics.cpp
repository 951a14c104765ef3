// Strip kinematics, modal force and resultant of the flexible wing (core/dynamics/
// strip_kinematics.*: stacked shapes, one vectorised pass over the strips) against a second
// implementation: the formulas of docs/theory.md 6.2-6.4 strip by strip with Vec3 algebra and the
// per-strip mode shapes of FlexibleStrip (not the stacked matrix).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/dynamics/flight_core.hpp"
#include "core/dynamics/strip_kinematics.hpp"
#include "tests/support/magpie_vehicle.hpp"

namespace orni {
namespace {

constexpr double kRelTol = 1e-12;  // same formulas, different summation order

class StripKinematicsTest : public ::testing::Test {
 protected:
  StripKinematicsTest()
      : vehicle_(testing::magpieVehicle()), model_(vehicle_), flex_(*model_.flexible),
        data_(model_), kin_(flex_.stacked, flex_.mode_count) {
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    const int M = flex_.mode_count;
    q_.resize(M);
    qd_.resize(M);
    for (int k = 0; k < M; ++k) {
      q_[k] = 2e-3 * u(rng);  // mass-normalised: a few mm of tip deflection
      qd_[k] = 0.5 * u(rng);
    }
    m_.v_O_W = Vec3(10.8, 0.3, -1.2);
    m_.a_O0_W = Vec3(0.4, -0.2, 3.0);
    m_.omega_W = Vec3(-20.0, 1.5, 0.3);
    m_.alpha0_W = Vec3(900.0, -30.0, 5.0);
    m_.omega_rel_W = Vec3(-20.0, 0.0, 0.0);
    const Eigen::Index ns = flex_.stacked.ns;
    aero::StripBatch& b = data_.batch;
    for (Eigen::Index j = 0; j < ns; ++j) {
      b.Fx[j] = u(rng); b.Fy[j] = u(rng); b.Fz[j] = u(rng);
      b.Mx[j] = 0.1 * u(rng); b.My[j] = 0.1 * u(rng); b.Mz[j] = 0.1 * u(rng);
    }
    ef_ = Eigen::VectorXd::Random(ns);
    ec_ = 0.1 * Eigen::VectorXd::Random(ns);
  }

  VehicleModel vehicle_;
  FlightCoreModel model_;
  const FlexibleWingModel& flex_;
  FlightCoreData data_;
  StripKinematics kin_;
  Eigen::VectorXd q_, qd_, ef_, ec_;
  WingFrameMotion m_;
};

void expectNear(const Vec3& a, const Vec3& ref, double scale, const char* what, int j) {
  EXPECT_LT((a - ref).norm(), kRelTol * scale) << what << " of strip " << j;
}

TEST_F(StripKinematicsTest, EveryStripMatchesTheVectorFormulas) {
  aero::StripBatch& b = data_.batch;
  kin_.compute(q_, qd_, m_, b);
  const Vec3& w = m_.omega_W;
  const Vec3& al = m_.alpha0_W;
  for (std::size_t s = 0; s < flex_.strips.size(); ++s) {
    const FlexibleStrip& fs = flex_.strips[s];
    const auto j = static_cast<Eigen::Index>(s);
    const int i = static_cast<int>(s);
    const Vec3 sL = fs.x_P_W_m + fs.phi_P * q_;  // the kernel's reference point P
    const Vec3 sT = fs.x_R_W_m + fs.phi_R * q_;  // the section's 3/4 chord
    const Vec3 uL = fs.phi_P * qd_;
    const double twist_rate = fs.psi_twist.dot(qd_);
    const Vec3 ec = (sL - sT).normalized();
    const Vec3 ey = Vec3::UnitY();
    const Vec3 es = (ey - ec.dot(ey) * ec).normalized();
    const Vec3 n = es.cross(ec);
    const Vec3 v = m_.v_O_W + w.cross(sL) + uL;
    const Vec3 a = m_.a_O0_W + al.cross(sL) + w.cross(w.cross(sL)) + 2.0 * w.cross(uL);
    const Vec3 ws = w + twist_rate * es;
    const Vec3 wd = al + w.cross(twist_rate * es);
    const Vec3 mid = sL - (0.5 * b.chord_m[j] - fs.ref_aft_of_le_m) * ec;
    expectNear(Vec3(b.ecx[j], b.ecy[j], b.ecz[j]), ec, 1.0, "e_c", i);
    expectNear(Vec3(kin_.esx()[j], kin_.esy()[j], kin_.esz()[j]), es, 1.0, "e_s", i);
    expectNear(Vec3(b.nx[j], b.ny[j], b.nz[j]), n, 1.0, "n", i);
    expectNear(Vec3(kin_.midx()[j], kin_.midy()[j], kin_.midz()[j]), mid, 1.0, "mid-chord", i);
    expectNear(Vec3(b.vx[j], b.vy[j], b.vz[j]), v, v.norm(), "v_P", i);
    expectNear(Vec3(b.ax[j], b.ay[j], b.az[j]), a, a.norm(), "a_P", i);
    expectNear(Vec3(b.wx[j], b.wy[j], b.wz[j]), ws, ws.norm(), "w_s", i);
    expectNear(Vec3(b.wdx[j], b.wdy[j], b.wdz[j]), wd, wd.norm(), "wdot_s", i);
  }
}

TEST_F(StripKinematicsTest, ModalForceAndResultantMatchTheStripSums) {
  aero::StripBatch& b = data_.batch;
  kin_.compute(q_, qd_, m_, b);
  const int M = flex_.mode_count;
  Eigen::VectorXd Q(M), Q_ref = Eigen::VectorXd::Zero(M);
  kin_.modalForce(b, &Q);
  Vec3 F_ref = Vec3::Zero(), M_ref = Vec3::Zero();
  double P_ref = 0.0;
  const Vec3& wr = m_.omega_rel_W;
  for (std::size_t s = 0; s < flex_.strips.size(); ++s) {
    const FlexibleStrip& fs = flex_.strips[s];
    const auto j = static_cast<Eigen::Index>(s);
    const Vec3 sL = fs.x_P_W_m + fs.phi_P * q_;
    const Vec3 uL = fs.phi_P * qd_;
    const double twist_rate = fs.psi_twist.dot(qd_);
    const Vec3 F(b.Fx[j], b.Fy[j], b.Fz[j]), Mp(b.Mx[j], b.My[j], b.Mz[j]);
    const Vec3 es(kin_.esx()[j], kin_.esy()[j], kin_.esz()[j]);
    const Vec3 n(b.nx[j], b.ny[j], b.nz[j]);
    const Vec3 mid(kin_.midx()[j], kin_.midy()[j], kin_.midz()[j]);
    // Q = Phi_P^T F + psi_twist^T (M . e_s) (docs/theory.md 6.3).
    Q_ref += fs.phi_P.transpose() * F + fs.psi_twist.transpose() * Mp.dot(es);
    // Resultant about P2 with the apparent-mass force along n at mid-chord and couple about e_s.
    F_ref += F + ef_[j] * n;
    M_ref += sL.cross(F) + Mp + ef_[j] * mid.cross(n) + ec_[j] * es;
    // Power into the air (M19 sign) from the motion relative to the fuselage.
    const Vec3 v_rel = wr.cross(sL) + uL;
    const Vec3 w_strip = wr + twist_rate * es;
    const double v_mid_n = (v_rel + w_strip.cross(mid - sL)).dot(n);
    P_ref -= F.dot(v_rel) + Mp.dot(w_strip) + ef_[j] * v_mid_n + ec_[j] * es.dot(w_strip);
  }
  EXPECT_LT((Q - Q_ref).norm(), kRelTol * Q_ref.norm());
  Vec3 F_W, M_W;
  double P = 0.0;
  kin_.resultant(b, ef_, ec_, wr, &F_W, &M_W, &P);
  EXPECT_LT((F_W - F_ref).norm(), kRelTol * F_ref.norm());
  EXPECT_LT((M_W - M_ref).norm(), kRelTol * M_ref.norm());
  EXPECT_NEAR(P, P_ref, kRelTol * std::abs(P_ref));
  EXPECT_EQ(kin_.power(b, ef_, ec_, wr), P);
}

// The tethered right-hand side forms M_qq + A(f) as packedLower(M_qq + apparent_const) +
// apparent_per_f f; it must be the lower triangle of addApparentModalMass's matrix form, and
// A(f) must be the strip sum of docs/theory.md 6.4.
TEST_F(StripKinematicsTest, PackedApparentMassIsTheStripSum) {
  const Eigen::Index ns = flex_.stacked.ns;
  const int M = flex_.mode_count;
  Eigen::ArrayXd f(ns);
  for (Eigen::Index j = 0; j < ns; ++j) f[j] = 0.5 + 0.5 * std::sin(0.7 * static_cast<double>(j));
  Eigen::VectorXd packed = packedLower(flex_.M_qq + flex_.stacked.apparent_const);
  packed.noalias() += flex_.stacked.apparent_per_f * f.matrix();
  Eigen::MatrixXd A_ref = flex_.M_qq;
  for (Eigen::Index j = 0; j < ns; ++j) {
    const FlexibleStrip& fs = flex_.strips[static_cast<std::size_t>(j)];
    A_ref += 0.5 * (1.0 + f[j]) * flex_.apparent_mass_kg[j] * fs.psi_mid * fs.psi_mid.transpose() +
             f[j] * flex_.apparent_rotary_kgm2[j] * fs.psi_twist.transpose() * fs.psi_twist;
  }
  EXPECT_LT((packed - packedLower(A_ref)).norm(), kRelTol * A_ref.norm());
  Eigen::MatrixXd A_matrix = flex_.M_qq;
  Eigen::VectorXd scratch(packed.size());
  addApparentModalMass(flex_.stacked, f, 1.0, &scratch, A_matrix);
  EXPECT_LT((packed - packedLower(A_matrix)).norm(), kRelTol * A_ref.norm());
  EXPECT_EQ(M, A_ref.rows());
}

}  // namespace
}  // namespace orni
