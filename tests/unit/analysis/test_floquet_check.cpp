// The multiplier check (core/analysis/floquet.hpp, compareWithRefined): each multiplier paired
// with the nearest unpaired one of a finer discretisation, leading first; resolved when that moves
// it by at most kResolvedChangeFraction of its modulus and the modulus is at least
// kResolvedModulusFloor. The EFW's check against a tight reference is in
// tests/unit/trim/test_periodic_trim.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <stdexcept>

#include "core/analysis/floquet.hpp"

namespace orni {
namespace {

using C = std::complex<double>;

FloquetAnalysis analysisOf(const std::vector<C>& mus) {
  FloquetAnalysis a;
  for (const C& mu : mus) {
    FloquetMultiplier m;
    m.mu = mu;
    m.modulus = std::abs(mu);
    a.multipliers.push_back(m);
  }
  return a;
}

MonodromyEigen eigenOf(const std::vector<C>& mus) {
  MonodromyEigen e;
  e.ok = true;
  e.multipliers.resize(static_cast<Eigen::Index>(mus.size()));
  for (std::size_t k = 0; k < mus.size(); ++k) e.multipliers[static_cast<Eigen::Index>(k)] = mus[k];
  return e;
}

TEST(FloquetCheck, PairsEachMultiplierWithItsNearestAndJudgesTheChange) {
  // A phugoid pair, a short-period pair, a small wing-mode multiplier; the refined spectrum in
  // another order, the wing mode moved by 20 % of its modulus, the pair by 1e-6.
  FloquetAnalysis a =
      analysisOf({C(0.98, 0.04), C(0.98, -0.04), C(0.1, 0.3), C(0.1, -0.3), C(0.05, 0.0)});
  for (const FloquetMultiplier& m : a.multipliers) {
    EXPECT_TRUE(std::isnan(m.refinement_change));
    EXPECT_FALSE(m.resolved());  // not checked is not resolved
  }
  compareWithRefined(&a,
                     eigenOf({C(0.06, 0.0), C(0.1, -0.3), C(0.98, 1e-6 - 0.04),
                              C(0.98, 0.04 + 1e-6), C(0.1, 0.3)}),
                     "a finer grid");
  EXPECT_TRUE(a.checked);
  EXPECT_EQ(a.check_method, "a finer grid");
  EXPECT_NEAR(a.multipliers[0].refinement_change, 1e-6, 1e-15);
  EXPECT_NEAR(a.multipliers[1].refinement_change, 1e-6, 1e-15);
  EXPECT_EQ(a.multipliers[2].refinement_change, 0.0);
  EXPECT_EQ(a.multipliers[3].refinement_change, 0.0);
  EXPECT_NEAR(a.multipliers[4].refinement_change, 0.01, 1e-15);
  for (int k = 0; k < 4; ++k) EXPECT_TRUE(a.multipliers[k].resolved()) << k;
  EXPECT_FALSE(a.multipliers[4].resolved());  // 0.01 > 0.05 * 0.05
  // Either side of the bound: 1.1 and 0.9 times kResolvedChangeFraction |mu|.
  FloquetAnalysis b = analysisOf({C(0.5, 0.0), C(0.25, 0.0)});
  compareWithRefined(&b,
                     eigenOf({C(0.5 + 1.1 * kResolvedChangeFraction * 0.5, 0.0),
                              C(0.25 - 0.9 * kResolvedChangeFraction * 0.25, 0.0)}),
                     "either side");
  EXPECT_FALSE(b.multipliers[0].resolved());
  EXPECT_TRUE(b.multipliers[1].resolved());
}

TEST(FloquetCheck, NoMultiplierBelowTheModulusFloorIsResolved) {
  FloquetAnalysis a =
      analysisOf({C(2.0 * kResolvedModulusFloor, 0.0), C(0.5 * kResolvedModulusFloor, 0.0)});
  compareWithRefined(
      &a, eigenOf({C(2.0 * kResolvedModulusFloor, 0.0), C(0.5 * kResolvedModulusFloor, 0.0)}),
      "unchanged");
  EXPECT_EQ(a.multipliers[1].refinement_change, 0.0);
  EXPECT_TRUE(a.multipliers[0].resolved());
  EXPECT_FALSE(a.multipliers[1].resolved());  // unchanged, but too small to be trusted
}

TEST(FloquetCheck, AMultiplierWithoutAPartnerIsNotResolved) {
  // The refined analysis found fewer (the leading ones by Arnoldi): the rest
  // get infinity.
  FloquetAnalysis a = analysisOf({C(0.9, 0.0), C(0.2, 0.0)});
  compareWithRefined(&a, eigenOf({C(0.9, 0.0)}), "leading one");
  EXPECT_TRUE(a.multipliers[0].resolved());
  EXPECT_TRUE(std::isinf(a.multipliers[1].refinement_change));
  EXPECT_FALSE(a.multipliers[1].resolved());
}

TEST(FloquetCheck, AFailedRefinedAnalysisIsRefused) {
  FloquetAnalysis a = analysisOf({C(0.9, 0.0)});
  EXPECT_THROW(compareWithRefined(&a, MonodromyEigen{}, "failed"), std::invalid_argument);
  EXPECT_FALSE(a.checked);
}

}  // namespace
}  // namespace orni
