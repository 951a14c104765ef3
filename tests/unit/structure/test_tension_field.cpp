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
// - no principal stress below the residual fraction kappa of the elastic one;
// - with a compression cap Nc: a compressed strip with free sides carries min(elastic, Nc), a
//   shear panel is elastic to its buckling shear Nc and then an incomplete diagonal tension field
//   (Kuhn), and no principal stress falls below -Nc (plus kappa's share).
#include <cmath>
#include <cstdlib>
#include <string>

#include <Eigen/Eigenvalues>
#include <gtest/gtest.h>

#include "core/structure/tension_field.hpp"

namespace orni::structure {
namespace {

constexpr double kEt = 4e6;   // E t of Table 1's skin (100 GPa x 0.04 mm), N/m
constexpr double kNu = 0.31;
constexpr double kKappa = 1e-4;
constexpr double kCap = 20.0;  // a compression cap, N/m: the EFW skin's panels buckle at 10-60 N/m

Eigen::Matrix3d elastic() {
  Eigen::Matrix3d c;
  c << 1.0, kNu, 0.0, kNu, 1.0, 0.0, 0.0, 0.0, 0.5 * (1.0 - kNu);
  return kEt / (1.0 - kNu * kNu) * c;
}

FilmLaw law(double kappa, double cap_npm = 0.0) {
  FilmLaw l;
  l.residual_stiffness = kappa;
  l.compression_cap_n_per_m = cap_npm;
  return l;
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
  for (const double cap : {0.0, kCap}) for (int k = 0; k < 4; ++k) {
    SCOPED_TRACE("compression cap " + std::to_string(cap) + " N/m");
    const RelaxedMembrane m = relaxedMembrane(strains[k], kEt, kNu, law(kKappa, cap));
    // Without the tangent: the same energy and stress, bit for bit, and no tangent.
    const RelaxedMembrane lean =
        relaxedMembrane(strains[k], kEt, kNu, law(kKappa, cap), FilmOutput::kEnergyAndStress);
    EXPECT_EQ(lean.energy_j_per_m2, m.energy_j_per_m2);
    EXPECT_EQ(lean.stress_n_per_m, m.stress_n_per_m);
    EXPECT_EQ(lean.state, m.state);
    EXPECT_TRUE(lean.tangent_n_per_m.isZero(0.0));
    EXPECT_EQ(m.state, expected[k]) << k;
    const double h = 1e-9;  // strains ~ 1e-3, the states' boundaries >= 1e-4 away
    for (int i = 0; i < 3; ++i) {
      Eigen::Vector3d p = strains[k], q = strains[k];
      p(i) += h;
      q(i) -= h;
      const RelaxedMembrane mp = relaxedMembrane(p, kEt, kNu, law(kKappa, cap));
      const RelaxedMembrane mq = relaxedMembrane(q, kEt, kNu, law(kKappa, cap));
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
  // With a compression cap Nc the boundaries move to e2 + nu e1 = -Nc (1 - nu^2) / (E t) and e1 =
  // -(1 - nu) Nc / (E t).
  const double d = 1e-12;
  for (const double cap : {0.0, kCap}) for (const double kappa : {0.0, kKappa}) {
    SCOPED_TRACE("kappa " + std::to_string(kappa) + ", cap " + std::to_string(cap) + " N/m");
    const double t_w = -kNu * 1e-3 - cap * (1.0 - kNu * kNu) / kEt;
    const double t_s = -(1.0 - kNu) * cap / kEt;
    const RelaxedMembrane taut = relaxedMembrane({1e-3, t_w + d, 0.0}, kEt, kNu, law(kappa, cap));
    const RelaxedMembrane wrinkled = relaxedMembrane({1e-3, t_w - d, 0.0}, kEt, kNu, law(kappa, cap));
    EXPECT_EQ(taut.state, FilmState::kTaut);
    EXPECT_EQ(wrinkled.state, FilmState::kWrinkled);
    EXPECT_NEAR(taut.energy_j_per_m2, wrinkled.energy_j_per_m2, 1e-9 * taut.energy_j_per_m2);
    EXPECT_LT((taut.stress_n_per_m - wrinkled.stress_n_per_m).norm(), 1e-6 * taut.stress_n_per_m.norm());
    const RelaxedMembrane w2 = relaxedMembrane({t_s + d, -2e-3, 0.0}, kEt, kNu, law(kappa, cap));
    const RelaxedMembrane slack = relaxedMembrane({t_s - d, -2e-3, 0.0}, kEt, kNu, law(kappa, cap));
    EXPECT_EQ(w2.state, FilmState::kWrinkled);
    EXPECT_EQ(slack.state, FilmState::kSlack);
    EXPECT_NEAR(w2.energy_j_per_m2, slack.energy_j_per_m2, 1e-9 * (1.0 + kappa * 8.0));
    EXPECT_LT((w2.stress_n_per_m - slack.stress_n_per_m).norm(), 2.0 * kEt * d);  // E t e1 at e1 = d
  }
}

TEST(TensionField, UniaxialTensionIsElasticUntilTheFilmContractsMoreThanPoisson) {
  const double e = 1e-3;
  // Free lateral contraction -nu e: both stresses >= 0 (N_yy = 0): taut, elastic, N_xx = E t e.
  const RelaxedMembrane free = relaxedMembrane({e, -kNu * e * (1.0 - 1e-9), 0.0}, kEt, kNu, law(0.0));
  EXPECT_EQ(free.state, FilmState::kTaut);
  EXPECT_NEAR(free.stress_n_per_m(0), kEt * e, 1e-6 * kEt * e);
  EXPECT_NEAR(free.stress_n_per_m(1), 0.0, 1e-6 * kEt * e);
  // Held narrower (-0.8 e): the elastic film would be compressed across (N_yy < 0); the tension
  // field carries E t e along x and nothing across.
  const Eigen::Vector3d narrow(e, -0.8 * e, 0.0);
  EXPECT_LT((elastic() * narrow)(1), 0.0);
  const RelaxedMembrane w = relaxedMembrane(narrow, kEt, kNu, law(0.0));
  EXPECT_EQ(w.state, FilmState::kWrinkled);
  EXPECT_NEAR(w.stress_n_per_m(0), kEt * e, 1e-9 * kEt * e);
  EXPECT_NEAR(w.stress_n_per_m(1), 0.0, 1e-9 * kEt * e);
  EXPECT_NEAR(w.stress_n_per_m(2), 0.0, 1e-9 * kEt * e);
}

TEST(TensionField, PureShearIsWagnersDiagonalTensionField) {
  const double gamma = 2e-3;
  const RelaxedMembrane m = relaxedMembrane({0.0, 0.0, gamma}, kEt, kNu, law(0.0));
  EXPECT_EQ(m.state, FilmState::kWrinkled);
  const double tau = kEt * gamma / 4.0;  // Wagner: effective shear stiffness E t / 4
  EXPECT_NEAR(m.stress_n_per_m(2), tau, 1e-12 * tau);
  EXPECT_NEAR(m.stress_n_per_m(0), tau, 1e-12 * tau);  // sigma_1 = 2 tau at 45 deg resolves
  EXPECT_NEAR(m.stress_n_per_m(1), tau, 1e-12 * tau);  // into N_xx = N_yy = N_xy = tau
  EXPECT_NEAR(m.energy_j_per_m2, 0.5 * tau * gamma, 1e-12 * tau * gamma);
  // The elastic panel: G t = E t / (2 (1 + nu)), 1.31 times Wagner's at nu 0.31.
  EXPECT_NEAR((elastic() * Eigen::Vector3d(0, 0, gamma))(2) / tau, 2.0 / (1.0 + kNu), 1e-12);
  // With kappa the residual elastic part adds kappa (G t - E t / 4) gamma.
  const RelaxedMembrane mk = relaxedMembrane({0.0, 0.0, gamma}, kEt, kNu, law(kKappa));
  const double g_t = kEt / (2.0 * (1.0 + kNu));
  EXPECT_NEAR(mk.stress_n_per_m(2), (1.0 - kKappa) * tau + kKappa * g_t * gamma, 1e-12 * tau);
}

// A strip compressed along x with its sides free (N_yy = 0): elastic until the compression reaches
// the cap, then it carries the cap and no more, as a plate beyond its buckling load carries about
// that load (the post-buckling plateau the cap idealises).
TEST(TensionField, CompressedStripCarriesTheCapBeyondIt) {
  for (const double x : {0.5, 0.99, 1.5, 4.0}) {  // compression / (Nc / E t)
    const double exx = -x * kCap / kEt;
    // Free sides: N_yy = 0 gives e_yy = nu x Nc / E t (elastic) or nu Nc / E t (capped).
    const double eyy = kNu * std::min(x, 1.0) * kCap / kEt;
    const RelaxedMembrane m = relaxedMembrane({exx, eyy, 0.0}, kEt, kNu, law(0.0, kCap));
    EXPECT_EQ(m.state, x < 1.0 ? FilmState::kTaut : FilmState::kWrinkled) << x;
    EXPECT_NEAR(m.stress_n_per_m(0), -std::min(x, 1.0) * kCap, 1e-9 * kCap) << x;
    EXPECT_NEAR(m.stress_n_per_m(1), 0.0, 1e-9 * kCap) << x;
  }
  // Compressed both ways beyond the cap: slack, an isotropic compression Nc.
  const RelaxedMembrane both = relaxedMembrane({-3e-5, -2e-5, 1e-5}, kEt, kNu, law(0.0, kCap));
  EXPECT_EQ(both.state, FilmState::kSlack);
  EXPECT_LT((both.stress_n_per_m - Eigen::Vector3d(-kCap, -kCap, 0.0)).norm(), 1e-9 * kCap);
}

// A shear panel with a buckling shear Nc: elastic up to gamma_cr = Nc / (G t), beyond it the
// incomplete diagonal tension field of the engineering idealisation (Kuhn, Stress Analysis of
// Aircraft Structures): the buckling shear plus Wagner's E t / 4 of the further shear strain,
// N_xy = Nc + E t (gamma - gamma_cr) / 4, and the diagonal tension's normal components growing from
// zero at buckling, N_xx = N_yy = E t (gamma - gamma_cr) / 4.
TEST(TensionField, ShearPanelIsElasticToItsBucklingShearThenAnIncompleteDiagonalTensionField) {
  const double g_t = kEt / (2.0 * (1.0 + kNu));
  const double gamma_cr = kCap / g_t;
  for (const double ratio : {0.5, 1.0 + 1e-9, 2.0, 10.0}) {
    const double gamma = ratio * gamma_cr;
    const RelaxedMembrane m = relaxedMembrane({0.0, 0.0, gamma}, kEt, kNu, law(0.0, kCap));
    if (ratio < 1.0) {
      EXPECT_EQ(m.state, FilmState::kTaut);
      EXPECT_NEAR(m.stress_n_per_m(2), g_t * gamma, 1e-12 * kCap);
      continue;
    }
    EXPECT_EQ(m.state, FilmState::kWrinkled) << ratio;
    const double beyond = kEt * (gamma - gamma_cr) / 4.0;
    EXPECT_NEAR(m.stress_n_per_m(2), kCap + beyond, 1e-9 * (kCap + beyond)) << ratio;
    EXPECT_NEAR(m.stress_n_per_m(0), beyond, 1e-9 * (kCap + beyond)) << ratio;
    EXPECT_NEAR(m.stress_n_per_m(1), beyond, 1e-9 * (kCap + beyond)) << ratio;
  }
}

TEST(TensionField, LawOutsideItsRangeIsRefusedWithItsName) {
  std::string why;
  EXPECT_TRUE(law(kKappa, kCap).IsValid(&why));
  EXPECT_FALSE(law(0.0).IsValid(&why));
  EXPECT_NE(why.find("kappa"), std::string::npos) << why;
  EXPECT_FALSE(law(kKappa, -1.0).IsValid(&why));
  EXPECT_NE(why.find("compression cap"), std::string::npos) << why;
  EXPECT_FALSE(law(kKappa, std::nan("")).IsValid(&why));
}

TEST(TensionField, NoPrincipalStressBelowTheResidualFractionOfTheElasticOne) {
  std::srand(7);
  int states[3] = {0, 0, 0};
  for (int k = 0; k < 2000; ++k) {
    const Eigen::Vector3d eps = 2e-3 * Eigen::Vector3d::Random();
    const RelaxedMembrane m = relaxedMembrane(eps, kEt, kNu, law(kKappa));
    ++states[static_cast<int>(m.state)];
    const double floor = kKappa * std::min(0.0, minPrincipal(elastic() * eps));
    EXPECT_GE(minPrincipal(m.stress_n_per_m), floor - 1e-9) << eps.transpose();
    // Kappa 0: no compression at all.
    EXPECT_GE(minPrincipal(relaxedMembrane(eps, kEt, kNu, law(0.0)).stress_n_per_m), -1e-9 * kEt * 2e-3);
    // With a cap: no compression beyond it (plus kappa's share), and the cap is reached wherever
    // the elastic film would exceed it (kappa 0: exactly -Nc).
    const double elastic_min = minPrincipal(elastic() * eps);
    const double capped = minPrincipal(relaxedMembrane(eps, kEt, kNu, law(kKappa, kCap)).stress_n_per_m);
    EXPECT_GE(capped, -(1.0 - kKappa) * kCap + kKappa * std::min(0.0, elastic_min) - 1e-9) << eps.transpose();
    if (elastic_min < -kCap) {
      EXPECT_NEAR(minPrincipal(relaxedMembrane(eps, kEt, kNu, law(0.0, kCap)).stress_n_per_m), -kCap,
                  1e-9 * kEt * 2e-3) << eps.transpose();
    }
  }
  for (int s = 0; s < 3; ++s) EXPECT_GT(states[s], 100) << "state " << s << " barely sampled";
}

}  // namespace
}  // namespace orni::structure
