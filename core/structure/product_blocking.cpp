// Fixed cache sizes for Eigen's product blocking (product_blocking.hpp, docs/theory.md 3.7).
#include "core/structure/product_blocking.hpp"

#include <Eigen/Core>

namespace orni::structure {

bool productsPlannedWithFixedCacheSizes() {
  return Eigen::l1CacheSize() == kPlannedL1CacheBytes &&
         Eigen::l2CacheSize() == kPlannedL2CacheBytes &&
         Eigen::l3CacheSize() == kPlannedL3CacheBytes;
}

void planProductsWithFixedCacheSizes() {
  if (!productsPlannedWithFixedCacheSizes())
    Eigen::setCpuCacheSizes(kPlannedL1CacheBytes, kPlannedL2CacheBytes, kPlannedL3CacheBytes);
}

namespace {
// At load: this file is linked wherever a structure entry point is, and static initialisation
// runs before main and any thread, so the entry points' call only reads.
[[maybe_unused]] const bool kPlannedAtLoad = (planProductsWithFixedCacheSizes(), true);
}  // namespace

}  // namespace orni::structure
