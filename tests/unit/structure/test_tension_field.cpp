// The tension-field film (core/structure/tension_field.hpp, docs/theory.md 4.7) against
// independent truths:
// - the stress is the gradient of the relaxed energy and the tangent its Hessian (central
//   differences), in each of the three states;
// - energy and stress are continuous where the wrinkled state meets the taut and the slack one
//   (the relaxed energy is C1: Pipkin 1986);
// - uniaxial tension with free lateral contraction is taut and elastic; with more contraction the
//   film wrinkles and carries the uniaxial stress E t e1;
// - pure shear gamma of a wrinkled panel is Wagner's diagonal tension field: N_xx = N_yy = N_xy =
//   E t gamma / 4 (the diagonal tension 2 tau at 45 deg, an effective shear stiffness E t / 4
//   against the elastic G t; Wagner 1929; Kuhn, Stress Analysis of Aircraft Structures);
// - no principal stress below the residual fraction kappa of the elastic one.
#include <cmath>
#include <cstdlib>

#include <Eigen/Eigenvalues>
#include <gtest/gtest.h>

#include "core/structure/tension_field.hpp"

namespace orni::structure {
namespace {

constexpr double kEt = 4e6;   // E t of Table 1's skin (100 GPa x 0.04 mm), N/m
constexpr double kNu = 0.31;
constexpr double kKappa = 1e-4;

Eigen::Matrix3d elastic() {
  Eigen::Matrix3d c;
  c << 1.0, kNu, 0.0, kNu, 1.0, 0.0, 0.0, 0.0, 0.5 * (1.0 - kNu);
  return kEt / (1.0 - kNu * kNu) * c;
}

double minPrincipal(const Eigen::Vector3d& n) {
  Eigen::Matrix2d s;
  s << n(0), n(2), n(2), n(1);
  return Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(s).eigenvalues()(0);
}

TEST(TensionField, StressIsTheEnergysGradientAndTheTangentItsHessianInEachState) {
  const Eigen::Vector3d strains[] = {
      {1e-3, 8e-4, 2e-4},     // taut
      {1e-3, -6e-4, 3e-4},    // wrinkled
      {2e-4, -1.5e-3, -7e-4}, // wrinkled, rotated
      {-1e-3, -4e-4, 1e-4},   // slack
  };
  const FilmState expected[] = {FilmState::kTaut, FilmState::kWrinkled, FilmState::kWrinkled,
                                FilmState::kSlack};
  for (int k = 0; k < 4; ++k) {
    const RelaxedMembrane m = relaxedMembrane(strains[k], kEt, kNu, kKappa);
    EXPECT_EQ(m.state, expected[k]) << k;
    const double h = 1e-9;  // strains ~ 1e-3, the states' boundaries >= 1e-4 away
    for (int i = 0; i < 3; ++i) {
      Eigen::Vector3d p = strains[k], q = strains[k];
      p(i) += h;
      q(i) -= h;
      const RelaxedMembrane mp = relaxedMembrane(p, kEt, kNu, kKappa);
      const RelaxedMembrane mq = relaxedMembrane(q, kEt, kNu, kKappa);
      // Central differences: truncation ~ h^2 |W'''| and round-off ~ 1e-16 |W| / h, both below
      // 1e-6 of the stress scale E t |eps| ~ 4e3 N/m.
      EXPECT_NEAR((mp.energy_j_per_m2 - mq.energy_j_per_m2) / (2 * h), m.stress_n_per_m(i), 1e-6 * 4e3)
          << "state " << k << " component " << i;
      const Eigen::Vector3d col = (mp.stress_n_per_m - mq.stress_n_per_m) / (2 * h);
      EXPECT_LT((col - m.tangent_n_per_m.col(i)).cwiseAbs().maxCoeff(), 1e-6 * kEt)
          << "state " << k << " component " << i;
    }
    EXPECT_LT((m.tangent_n_per_m - m.tangent_n_per_m.transpose()).cwiseAbs().maxCoeff(), 1e-9 * kEt);
    // Convex: the tangent is positive semi-definite (definite with kappa > 0).
    EXPECT_GT(Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(m.tangent_n_per_m).eigenvalues()(0), 0.0);
  }
}

TEST(TensionField, EnergyAndStressAreContinuousAcrossTheStates) {
  // Along e = (1e-3, t, 0): taut for t > -nu 1e-3, wrinkled below; then along e = (t, -2e-3, 0)
  // through e1 = 0 into the slack state.
  const double d = 1e-12;
  for (const double kappa : {0.0, kKappa}) {
    const double t_w = -kNu * 1e-3;
    const RelaxedMembrane taut = relaxedMembrane({1e-3, t_w + d, 0.0}, kEt, kNu, kappa);
    const RelaxedMembrane wrinkled = relaxedMembrane({1e-3, t_w - d, 0.0}, kEt, kNu, kappa);
    EXPECT_EQ(taut.state, FilmState::kTaut);
    EXPECT_EQ(wrinkled.state, FilmState::kWrinkled);
    EXPECT_NEAR(taut.energy_j_per_m2, wrinkled.energy_j_per_m2, 1e-9 * taut.energy_j_per_m2);
    EXPECT_LT((taut.stress_n_per_m - wrinkled.stress_n_per_m).norm(), 1e-6 * taut.stress_n_per_m.norm());
    const RelaxedMembrane w2 = relaxedMembrane({d, -2e-3, 0.0}, kEt, kNu, kappa);
    const RelaxedMembrane slack = relaxedMembrane({-d, -2e-3, 0.0}, kEt, kNu, kappa);
    EXPECT_EQ(w2.state, FilmState::kWrinkled);
    EXPECT_EQ(slack.state, FilmState::kSlack);
    EXPECT_NEAR(w2.energy_j_per_m2, slack.energy_j_per_m2, 1e-9 * (1.0 + kappa * 8.0));
    EXPECT_LT((w2.stress_n_per_m - slack.stress_n_per_m).norm(), 2.0 * kEt * d);  // E t e1 at e1 = d
  }
}

TEST(TensionField, UniaxialTensionIsElasticUntilTheFilmContractsMoreThanPoisson) {
  const double e = 1e-3;
  // Free lateral contraction -nu e: both stresses >= 0 (N_yy = 0): taut, elastic, N_xx = E t e.
  const RelaxedMembrane free = relaxedMembrane({e, -kNu * e * (1.0 - 1e-9), 0.0}, kEt, kNu, 0.0);
  EXPECT_EQ(free.state, FilmState::kTaut);
  EXPECT_NEAR(free.stress_n_per_m(0), kEt * e, 1e-6 * kEt * e);
  EXPECT_NEAR(free.stress_n_per_m(1), 0.0, 1e-6 * kEt * e);
  // Held narrower (-0.8 e): the elastic film would be compressed across (N_yy < 0); the tension
  // field carries E t e along x and nothing across.
  const Eigen::Vector3d narrow(e, -0.8 * e, 0.0);
  EXPECT_LT((elastic() * narrow)(1), 0.0);
  const RelaxedMembrane w = relaxedMembrane(narrow, kEt, kNu, 0.0);
  EXPECT_EQ(w.state, FilmState::kWrinkled);
  EXPECT_NEAR(w.stress_n_per_m(0), kEt * e, 1e-9 * kEt * e);
  EXPECT_NEAR(w.stress_n_per_m(1), 0.0, 1e-9 * kEt * e);
  EXPECT_NEAR(w.stress_n_per_m(2), 0.0, 1e-9 * kEt * e);
}

TEST(TensionField, PureShearIsWagnersDiagonalTensionField) {
  const double gamma = 2e-3;
  const RelaxedMembrane m = relaxedMembrane({0.0, 0.0, gamma}, kEt, kNu, 0.0);
  EXPECT_EQ(m.state, FilmState::kWrinkled);
  const double tau = kEt * gamma / 4.0;  // Wagner: effective shear stiffness E t / 4
  EXPECT_NEAR(m.stress_n_per_m(2), tau, 1e-12 * tau);
  EXPECT_NEAR(m.stress_n_per_m(0), tau, 1e-12 * tau);  // sigma_1 = 2 tau at 45 deg resolves
  EXPECT_NEAR(m.stress_n_per_m(1), tau, 1e-12 * tau);  // into N_xx = N_yy = N_xy = tau
  EXPECT_NEAR(m.energy_j_per_m2, 0.5 * tau * gamma, 1e-12 * tau * gamma);
  // The elastic panel: G t = E t / (2 (1 + nu)), 1.31 times Wagner's at nu 0.31.
  EXPECT_NEAR((elastic() * Eigen::Vector3d(0, 0, gamma))(2) / tau, 2.0 / (1.0 + kNu), 1e-12);
  // With kappa the residual elastic part adds kappa (G t - E t / 4) gamma.
  const RelaxedMembrane mk = relaxedMembrane({0.0, 0.0, gamma}, kEt, kNu, kKappa);
  const double g_t = kEt / (2.0 * (1.0 + kNu));
  EXPECT_NEAR(mk.stress_n_per_m(2), (1.0 - kKappa) * tau + kKappa * g_t * gamma, 1e-12 * tau);
}

TEST(TensionField, NoPrincipalStressBelowTheResidualFractionOfTheElasticOne) {
  std::srand(7);
  int states[3] = {0, 0, 0};
  for (int k = 0; k < 2000; ++k) {
    const Eigen::Vector3d eps = 2e-3 * Eigen::Vector3d::Random();
    const RelaxedMembrane m = relaxedMembrane(eps, kEt, kNu, kKappa);
    ++states[static_cast<int>(m.state)];
    const double floor = kKappa * std::min(0.0, minPrincipal(elastic() * eps));
    EXPECT_GE(minPrincipal(m.stress_n_per_m), floor - 1e-9) << eps.transpose();
    // Kappa 0: no compression at all.
    EXPECT_GE(minPrincipal(relaxedMembrane(eps, kEt, kNu, 0.0).stress_n_per_m), -1e-9 * kEt * 2e-3);
  }
  for (int s = 0; s < 3; ++s) EXPECT_GT(states[s], 100) << "state " << s << " barely sampled";
}

}  // namespace
}  // namespace orni::structure
