// The right-hand side's SPD solver (core/dynamics/small_cholesky.hpp, L D L^T on padded
// columns) against Eigen's LLT, and the packed layout shared with the apparent-mass stack
// (flexible_wing.hpp).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include <Eigen/Cholesky>
#include <Eigen/QR>

#include "core/dynamics/flexible_wing.hpp"
#include "core/dynamics/small_cholesky.hpp"

namespace orni {
namespace {

// Random SPD matrix with condition number about 1e3: solutions agree to ~cond * eps.
Eigen::MatrixXd randomSpd(int n, std::mt19937* rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Eigen::MatrixXd R(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) R(i, j) = u(*rng);
  const Eigen::HouseholderQR<Eigen::MatrixXd> qr(R);
  const Eigen::MatrixXd Q = qr.householderQ();
  Eigen::VectorXd d(n);
  for (int i = 0; i < n; ++i) d[i] = std::pow(10.0, 3.0 * (0.5 + 0.5 * u(*rng)));
  return Q * d.asDiagonal() * Q.transpose();
}

constexpr double kSolveRelTol = 1e-11;  // cond ~1e3 times eps, with margin

TEST(SmallCholesky, SolvesLikeEigenLltForEverySizeUpToTheConvergenceModeCount) {
  std::mt19937 rng(7);
  for (int n = 1; n <= 27; ++n) {  // 27 = 3 + 24 modes, the free-flight convergence check
    const Eigen::MatrixXd A = randomSpd(n, &rng);
    const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, -1.0, 2.0);
    const Eigen::VectorXd x_ref = A.llt().solve(b);
    SmallCholesky chol(n);
    ASSERT_TRUE(chol.factor(A)) << "n = " << n;
    Eigen::VectorXd x = b;
    chol.solveInPlace(x);
    EXPECT_LT((x - x_ref).norm(), kSolveRelTol * x_ref.norm()) << "n = " << n;
    // The packed entry point gives the same factor, bit for bit.
    SmallCholesky packed(n);
    ASSERT_TRUE(packed.factorPacked(packedLower(A).data()));
    Eigen::VectorXd xp = b;
    packed.solveInPlace(xp);
    EXPECT_EQ((xp - x).cwiseAbs().maxCoeff(), 0.0) << "n = " << n;
  }
}

TEST(SmallCholesky, ReadsOnlyTheLowerTriangle) {
  std::mt19937 rng(11);
  Eigen::MatrixXd A = randomSpd(12, &rng);
  const Eigen::VectorXd b = Eigen::VectorXd::Ones(12);
  const Eigen::VectorXd x_ref = A.llt().solve(b);
  A.triangularView<Eigen::StrictlyUpper>().setConstant(1e9);  // garbage above the diagonal
  SmallCholesky chol(12);
  ASSERT_TRUE(chol.factor(A));
  Eigen::VectorXd x = b;
  chol.solveInPlace(x);
  EXPECT_LT((x - x_ref).norm(), kSolveRelTol * x_ref.norm());
}

TEST(SmallCholesky, ReusedFactorGivesTheBitsOfAFreshOne) {
  // The padded rows above the diagonal are scratch of the blocked update: what an earlier,
  // larger-scaled or failed factorisation left there must not reach the next solve.
  std::mt19937 rng(13);
  for (int n : {5, 12, 24, 27}) {
    const Eigen::MatrixXd A = randomSpd(n, &rng), B = randomSpd(n, &rng);
    const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, 2.0, -1.0);
    SmallCholesky fresh(n), reused(n);
    ASSERT_TRUE(fresh.factor(B));
    Eigen::VectorXd x_fresh = b;
    fresh.solveInPlace(x_fresh);
    ASSERT_TRUE(reused.factor(1e6 * A));
    Eigen::MatrixXd bad = A;
    bad(n / 2, n / 2) = -1.0;
    reused.factor(bad);  // fails part-way (or not), leaving partial values behind
    ASSERT_TRUE(reused.factor(B));
    Eigen::VectorXd x = b;
    reused.solveInPlace(x);
    EXPECT_EQ((x - x_fresh).cwiseAbs().maxCoeff(), 0.0) << "n = " << n;
  }
}

TEST(SmallCholesky, RejectsMatricesThatAreNotPositiveDefinite) {
  Eigen::MatrixXd A = Eigen::MatrixXd::Identity(4, 4);
  A(2, 2) = -1.0;  // indefinite
  SmallCholesky chol(4);
  EXPECT_FALSE(chol.factor(A));
  A(2, 2) = 0.0;  // singular
  EXPECT_FALSE(chol.factor(A));
  A(2, 2) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(chol.factor(A));
  Eigen::MatrixXd B(2, 2);  // symmetric, positive diagonal, but det < 0
  B << 1.0, 2.0, 2.0, 1.0;
  SmallCholesky chol2(2);
  EXPECT_FALSE(chol2.factor(B));
}

TEST(SmallCholesky, PackedLowerIsColumnByColumn) {
  Eigen::MatrixXd A(3, 3);
  A << 1, 9, 9,
       2, 4, 9,
       3, 5, 6;
  const Eigen::VectorXd p = packedLower(A);
  ASSERT_EQ(p.size(), 6);
  EXPECT_EQ(p, (Eigen::VectorXd(6) << 1, 2, 3, 4, 5, 6).finished());
}

}  // namespace
}  // namespace orni
