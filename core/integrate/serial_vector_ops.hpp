// Single-pass fused vector operations for SUNDIALS' serial N_Vector (internal to core/integrate).
#pragma once

#include <nvector/nvector_serial.h>

namespace orni::detail {

/// z = sum_i c_i X_i in one pass over z (SUNDIALS' serial version makes one pass per term): the
/// operation behind every Runge-Kutta stage and solution update. Same arithmetic order per element
/// (c_0 x_0 + c_1 x_1 + ...), so results are identical to the term-by-term sum. z may alias X[0].
int linearCombinationSinglePass(int nvec, sunrealtype* c, N_Vector* X, N_Vector z);

/// z = a x + b y, z = c x, z = c, and the weighted root-mean-square norm, as plain loops the
/// compiler vectorises (SUNDIALS' serial versions branch per special case and are compiled for the
/// generic x86-64 level; for the ~100-state wing they cost as much as a fifth of the RHS).
void linearSumPlain(sunrealtype a, N_Vector x, sunrealtype b, N_Vector y, N_Vector z);
void scalePlain(sunrealtype c, N_Vector x, N_Vector z);
void constPlain(sunrealtype c, N_Vector z);
sunrealtype wrmsNormPlain(N_Vector x, N_Vector w);

/// Enable the fused operations of `v` with the single-pass linear combination and the plain loops
/// above. Call before an integrator clones the vector, so that every work vector inherits them.
inline void installSinglePassOps(N_Vector v) {
  N_VEnableFusedOps_Serial(v, SUNTRUE);
  v->ops->nvlinearcombination = &linearCombinationSinglePass;
  v->ops->nvlinearsum = &linearSumPlain;
  v->ops->nvscale = &scalePlain;
  v->ops->nvconst = &constPlain;
  v->ops->nvwrmsnorm = &wrmsNormPlain;
}

}  // namespace orni::detail
