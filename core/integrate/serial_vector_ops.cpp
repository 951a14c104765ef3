#include "core/integrate/serial_vector_ops.hpp"

#include <cmath>

namespace orni::detail {

// Four independent accumulators the compiler keeps in vector registers; X[0][j] is read before
// z[j] is written, so z may alias X[0] (allowed by the N_Vector API).
int linearCombinationSinglePass(int nvec, sunrealtype* c, N_Vector* X, N_Vector z) {
  const sunindextype n = NV_LENGTH_S(z);
  sunrealtype* zd = NV_DATA_S(z);
  constexpr int kMaxVectors = 32;
  if (nvec < 1) return -1;
  if (nvec > kMaxVectors) {  // never happens for the tables we use; keep the general path
    for (sunindextype j = 0; j < n; ++j) {
      sunrealtype s = c[0] * NV_DATA_S(X[0])[j];
      for (int i = 1; i < nvec; ++i) s += c[i] * NV_DATA_S(X[i])[j];
      zd[j] = s;
    }
    return 0;
  }
  const sunrealtype* xd[kMaxVectors];
  for (int i = 0; i < nvec; ++i) xd[i] = NV_DATA_S(X[i]);
  sunindextype j = 0;
  for (; j + 4 <= n; j += 4) {
    sunrealtype s0 = c[0] * xd[0][j], s1 = c[0] * xd[0][j + 1];
    sunrealtype s2 = c[0] * xd[0][j + 2], s3 = c[0] * xd[0][j + 3];
    for (int i = 1; i < nvec; ++i) {
      const sunrealtype* x = xd[i] + j;
      s0 += c[i] * x[0];
      s1 += c[i] * x[1];
      s2 += c[i] * x[2];
      s3 += c[i] * x[3];
    }
    zd[j] = s0;
    zd[j + 1] = s1;
    zd[j + 2] = s2;
    zd[j + 3] = s3;
  }
  for (; j < n; ++j) {
    sunrealtype s = c[0] * xd[0][j];
    for (int i = 1; i < nvec; ++i) s += c[i] * xd[i][j];
    zd[j] = s;
  }
  return 0;
}

void linearSumPlain(sunrealtype a, N_Vector x, sunrealtype b, N_Vector y, N_Vector z) {
  const sunindextype n = NV_LENGTH_S(z);
  const sunrealtype* xd = NV_DATA_S(x);
  const sunrealtype* yd = NV_DATA_S(y);
  sunrealtype* zd = NV_DATA_S(z);
  for (sunindextype j = 0; j < n; ++j) zd[j] = a * xd[j] + b * yd[j];
}

void scalePlain(sunrealtype c, N_Vector x, N_Vector z) {
  const sunindextype n = NV_LENGTH_S(z);
  const sunrealtype* xd = NV_DATA_S(x);
  sunrealtype* zd = NV_DATA_S(z);
  for (sunindextype j = 0; j < n; ++j) zd[j] = c * xd[j];
}

void constPlain(sunrealtype c, N_Vector z) {
  const sunindextype n = NV_LENGTH_S(z);
  sunrealtype* zd = NV_DATA_S(z);
  for (sunindextype j = 0; j < n; ++j) zd[j] = c;
}

sunrealtype wrmsNormPlain(N_Vector x, N_Vector w) {
  const sunindextype n = NV_LENGTH_S(x);
  const sunrealtype* xd = NV_DATA_S(x);
  const sunrealtype* wd = NV_DATA_S(w);
  sunrealtype s0 = 0, s1 = 0, s2 = 0, s3 = 0;  // fixed association: same sum on every run
  sunindextype j = 0;
  for (; j + 4 <= n; j += 4) {
    const sunrealtype a = xd[j] * wd[j], b = xd[j + 1] * wd[j + 1];
    const sunrealtype c = xd[j + 2] * wd[j + 2], d = xd[j + 3] * wd[j + 3];
    s0 += a * a;
    s1 += b * b;
    s2 += c * c;
    s3 += d * d;
  }
  for (; j < n; ++j) s0 += (xd[j] * wd[j]) * (xd[j] * wd[j]);
  return std::sqrt(((s0 + s1) + (s2 + s3)) / static_cast<sunrealtype>(n));
}

}  // namespace orni::detail
