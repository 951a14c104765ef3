// Eigen's product blocking fixed, so that a flexible wing gives the same bits on every CPU
// (core/structure/product_blocking.hpp, docs/theory.md 3.7).
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <cmath>
#include <cstring>

#include "core/structure/modal_solver.hpp"
#include "core/structure/product_blocking.hpp"

namespace orni::structure {
namespace {

// Eigen's query on the AMD EPYC whose flexible-wing runs differed in their last bits from the
// Intel Xeon's: L1d 32 KiB (the size that sets the inner-dimension split), L2 512 KiB, L3 32 MiB.
void planLikeAnotherCpu() { Eigen::setCpuCacheSizes(32 * 1024, 512 * 1024, 32 * 1024 * 1024); }

// Restores the fixed plan whatever a test did to Eigen's cache sizes.
struct RestorePlan {
  ~RestorePlan() { planProductsWithFixedCacheSizes(); }
};

// A product shaped like the reduction's (modes^T x DOF times DOF x modes), inner dimension 2000:
// more than one inner block at either CPU's L1 size (Eigen's largest block is 376 at 48 KiB and
// 248 at 32 KiB), with entries of every magnitude so that the order of the sums shows in the bits.
Eigen::MatrixXd reductionLikeProduct() {
  const int dofs = 2000;
  const int modes = 60;
  Eigen::MatrixXd a(modes, dofs);
  Eigen::MatrixXd b(dofs, modes);
  for (int i = 0; i < modes; ++i)
    for (int k = 0; k < dofs; ++k) {
      a(i, k) = std::sin(0.37 * i + 1.91 * k) * std::exp(0.003 * ((k * 7 + i) % 997));
      b(k, i) = std::cos(0.53 * i - 0.71 * k) * std::exp(-0.004 * ((k * 11 + i) % 991));
    }
  Eigen::MatrixXd c = a * b;
  return c;
}

bool sameBits(const Eigen::MatrixXd& x, const Eigen::MatrixXd& y) {
  return x.rows() == y.rows() && x.cols() == y.cols() &&
         std::memcmp(x.data(), y.data(), sizeof(double) * static_cast<std::size_t>(x.size())) == 0;
}

TEST(ProductBlocking, FixedWhenTheLibraryLoads) {
  // Nothing in this process has called an entry point yet: the plan was set at load.
  EXPECT_TRUE(productsPlannedWithFixedCacheSizes());
  EXPECT_EQ(Eigen::l1CacheSize(), kPlannedL1CacheBytes);
  EXPECT_EQ(Eigen::l2CacheSize(), kPlannedL2CacheBytes);
  EXPECT_EQ(Eigen::l3CacheSize(), kPlannedL3CacheBytes);
}

TEST(ProductBlocking, AnotherCpusCacheSizesChangeTheBitsAndThePlanRestoresThem) {
  RestorePlan restore;
  const Eigen::MatrixXd planned = reductionLikeProduct();
  planLikeAnotherCpu();
  const Eigen::MatrixXd other_cpu = reductionLikeProduct();
  // What the fix is for: the same binary, other cache sizes, other last bits (not other values).
  EXPECT_FALSE(sameBits(planned, other_cpu));
  EXPECT_LT((planned - other_cpu).cwiseAbs().maxCoeff(), 1e-12 * planned.cwiseAbs().maxCoeff());
  planProductsWithFixedCacheSizes();
  EXPECT_TRUE(sameBits(planned, reductionLikeProduct()));
}

TEST(ProductBlocking, EveryStructureEntryPointPlansBeforeItsProducts) {
  RestorePlan restore;
  // The eigen-solution is the first product-heavy call of every modal wing (buildModalWing and
  // craigBampton go through it and plan themselves too).
  planLikeAnotherCpu();
  ASSERT_FALSE(productsPlannedWithFixedCacheSizes());
  const int n = 12;
  SparseMatrix k(n, n);
  SparseMatrix m(n, n);
  for (int i = 0; i < n; ++i) {
    k.insert(i, i) = 1.0 + i;
    m.insert(i, i) = 1.0;
  }
  const EigenSolution sol = lowestEigenpairs(k, m, 3, EigenSolveOptions{});
  ASSERT_TRUE(sol.success) << sol.message;
  EXPECT_TRUE(productsPlannedWithFixedCacheSizes());
}

}  // namespace
}  // namespace orni::structure
