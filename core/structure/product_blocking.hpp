// The cache sizes Eigen's matrix products plan with, fixed so that results do not depend on the
// CPU they run on (docs/theory.md 3.7).
#pragma once

#include <cstddef>

namespace orni::structure {

/// Eigen splits a matrix product's inner dimension into blocks sized from the CPU's L1 and L2
/// caches, which it queries at run time, and the split sets the order of the sums. The same binary
/// therefore gave other last bits for every flexible-wing run on an AMD EPYC (L1d 32 KiB) than on
/// an Intel Xeon (48 KiB): the Craig-Bampton and membrane products over the FE model's thousands of
/// DOF, while the rigid runs (no product that large) were byte-identical. The slack-membrane
/// vehicle's long free flights amplified those bits into another Eq. (5) verdict. Planning every
/// product with the same sizes makes the bits the binary's, not the machine's; the values are the
/// ones Eigen read on the Intel Xeon that made the committed results (so those stay as they were).
/// Only the blocking changes with them, i.e. the speed on another machine, never the arithmetic.
inline constexpr std::ptrdiff_t kPlannedL1CacheBytes = 48 * 1024;
inline constexpr std::ptrdiff_t kPlannedL2CacheBytes = 2 * 1024 * 1024;
inline constexpr std::ptrdiff_t kPlannedL3CacheBytes = 300 * 1024 * 1024;

/// Sets Eigen's cache sizes to the planned ones if anything changed them. They are set when the
/// library is loaded (before main, so before any thread), which makes this a read in the normal
/// path; the structure's entry points (FE model, Craig-Bampton, modes, membrane identification,
/// nonlinear statics) call it before their products.
void planProductsWithFixedCacheSizes();

/// True when Eigen currently plans with the fixed sizes.
bool productsPlannedWithFixedCacheSizes();

}  // namespace orni::structure
