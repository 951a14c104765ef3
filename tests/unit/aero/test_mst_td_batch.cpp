// The vectorised MST-TD kernel against the scalar reference evalMstTd(), strip by strip, over
// random kinematics that cover attached, stalled, reversed and near-zero flow.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "core/aero/mst_td_batch.hpp"

namespace orni::aero {
namespace {

// Both kernels evaluate the same expressions; only atan2 differs (a few ulp), and the lag and
// separation equations amplify that by O(1): 1e-12 relative to the load scale is round-off.
constexpr double kBatchRelTol = 1e-12;
// Vectorised atan2 vs std::atan2: the series is truncated below 1e-19; the result may differ by
// 2 ulp at most, and an ulp of values near pi is 4.4e-16.
constexpr double kAtan2AbsTol = 8.9e-16;

TEST(AeroMstTdBatch, Atan2MatchesStd) {
  std::mt19937_64 rng(20261122);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const int n = 20000;
  ArrayXd y(n), x(n), out(n);
  for (int i = 0; i < n; ++i) {
    const double scale = std::pow(10.0, 6.0 * u(rng));
    y[i] = u(rng) * scale;
    x[i] = u(rng) * (i % 7 == 0 ? 1e-9 : 1.0) * scale;
  }
  y[0] = 0.0; x[0] = 0.0;   // at rest
  y[1] = 0.0; x[1] = 2.0;   // exactly on the axes
  y[2] = 3.0; x[2] = 0.0;
  y[3] = 1.0; x[3] = 1.0;   // the octant boundary
  y[4] = -2.0; x[4] = -2.0;
  atan2Array(y, x, out);
  double worst = 0.0;
  for (int i = 0; i < n; ++i) worst = std::max(worst, std::abs(out[i] - std::atan2(y[i], x[i])));
  EXPECT_LT(worst, kAtan2AbsTol);
  EXPECT_EQ(out[0], 0.0);
}

TEST(AeroMstTdBatch, MatchesScalarKernelStripByStrip) {
  AeroParameters params;  // MST-TD, Scherer lag, smooth stall (defaults)
  params.zero_lift_angle_rad = 0.03;
  params.moment_coefficient_ac = -0.04;
  ASSERT_TRUE(batchKernelApplies(params));
  StripContext ctx;
  ctx.params = &params;
  ctx.constants = MstConstants::fromAspectRatio(5.58);
  const int n = 64;
  StripBatch b(n);
  std::vector<double> states(2 * n), d_batch(2 * n), d_scalar(2 * n);
  std::vector<SectionKinematics> kin(n);
  std::vector<StripGeometry> geo(n);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int i = 0; i < n; ++i) {
    geo[i] = StripGeometry{0.02 + 0.1 * std::abs(u(rng)), 0.01, 0.02 * std::abs(u(rng))};
    SectionKinematics& k = kin[i];
    const double pitch = 0.6 * u(rng);
    k.e_c = Vec3(std::cos(pitch), 0.2 * u(rng), -std::sin(pitch)).normalized();
    k.n = Vec3(-std::sin(pitch), 0.0, -std::cos(pitch));
    k.n = (k.n - k.n.dot(k.e_c) * k.e_c).normalized();
    const double speed = (i % 9 == 0) ? 0.1 : 8.0;  // some near-zero flow
    k.v_P = Vec3(speed * (i % 5 == 0 ? -1.0 : 1.0), u(rng), 6.0 * u(rng));  // some reversed
    k.a_P = 300.0 * Vec3(u(rng), u(rng), u(rng));
    k.w_s = 40.0 * Vec3(u(rng), u(rng), u(rng));
    k.wdot_s = 3000.0 * Vec3(u(rng), u(rng), u(rng));
    k.v_air = Vec3(u(rng), 0.0, u(rng));
    k.flight_speed_mps = 8.0;
    k.friction_coefficient = 0.015 + 0.005 * u(rng);
    states[2 * i] = 0.8 * u(rng);
    states[2 * i + 1] = 0.5 + 0.6 * u(rng);  // includes values outside [0, 1]
    b.chord_m[i] = geo[i].chord_m;
    b.width_m[i] = geo[i].width_m;
    b.ref_aft_of_le_m[i] = geo[i].ref_aft_of_le_m;
    b.friction_coefficient[i] = k.friction_coefficient;
    b.ecx[i] = k.e_c.x(); b.ecy[i] = k.e_c.y(); b.ecz[i] = k.e_c.z();
    b.nx[i] = k.n.x(); b.ny[i] = k.n.y(); b.nz[i] = k.n.z();
    b.vx[i] = k.v_P.x(); b.vy[i] = k.v_P.y(); b.vz[i] = k.v_P.z();
    b.ax[i] = k.a_P.x(); b.ay[i] = k.a_P.y(); b.az[i] = k.a_P.z();
    b.wx[i] = k.w_s.x(); b.wy[i] = k.w_s.y(); b.wz[i] = k.w_s.z();
    b.wdx[i] = k.wdot_s.x(); b.wdy[i] = k.wdot_s.y(); b.wdz[i] = k.wdot_s.z();
    b.airx[i] = k.v_air.x(); b.airy[i] = k.v_air.y(); b.airz[i] = k.v_air.z();
  }
  prepareStripBatch(ctx, b);
  evalMstTdBatch(ctx, b, states.data(), d_batch.data());
  for (int i = 0; i < n; ++i) {
    const SectionLoads L = evalMstTd(ctx, geo[i], kin[i], &states[2 * i], &d_scalar[2 * i]);
    Vec3 F, M;
    resolveSectionLoads(L, geo[i], kin[i].e_c, kin[i].n, &F, &M);
    const double scale = std::max(1e-6, F.norm());
    EXPECT_NEAR(b.Fx[i], F.x(), kBatchRelTol * scale) << i;
    EXPECT_NEAR(b.Fy[i], F.y(), kBatchRelTol * scale) << i;
    EXPECT_NEAR(b.Fz[i], F.z(), kBatchRelTol * scale) << i;
    const double mscale = std::max(1e-9, M.norm());
    EXPECT_NEAR(b.My[i], M.y(), kBatchRelTol * mscale) << i;
    EXPECT_NEAR(b.Mx[i], M.x(), kBatchRelTol * mscale) << i;
    EXPECT_NEAR(b.separation_f[i], L.separation_f, 1e-14) << i;
    EXPECT_NEAR(d_batch[2 * i], d_scalar[2 * i], kBatchRelTol * std::max(1.0, std::abs(d_scalar[2 * i]))) << i;
    EXPECT_NEAR(d_batch[2 * i + 1], d_scalar[2 * i + 1], kBatchRelTol * std::max(1.0, std::abs(d_scalar[2 * i + 1]))) << i;
  }
}

// The rigid wing's kernel (one frame for all strips, read from element 0) against the general one
// with that frame copied into every element: the same equations with the frame-only terms hoisted
// out of the loop, so equal to round-off (kBatchRelTol, the general kernel's own tolerance).
TEST(AeroMstTdBatch, UniformFrameMatchesGeneralKernel) {
  AeroParameters params;
  params.zero_lift_angle_rad = 0.03;
  StripContext ctx;
  ctx.params = &params;
  ctx.constants = MstConstants::fromAspectRatio(5.58);
  const int n = 27;
  StripBatch general(n), uniform(n);
  std::vector<double> states(2 * n), d_general(2 * n), d_uniform(2 * n);
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const Vec3 e_c = Vec3(0.95, 0.1, -0.3).normalized();
  const Vec3 nrm = (Vec3(-0.3, 0.0, -0.95) - Vec3(-0.3, 0.0, -0.95).dot(e_c) * e_c).normalized();
  const Vec3 w(3.0, 25.0, -4.0), wd(900.0, -2000.0, 150.0);
  for (StripBatch* b : {&general, &uniform}) {
    std::mt19937_64 r(5);
    for (int i = 0; i < n; ++i) {
      b->chord_m[i] = 0.05 + 0.1 * std::abs(u(r));
      b->width_m[i] = 0.01;
      b->ref_aft_of_le_m[i] = 0.0;
      b->friction_coefficient[i] = 0.01;
      b->vx[i] = 6.0 + u(r); b->vy[i] = u(r); b->vz[i] = 5.0 * u(r);
      b->ax[i] = 300.0 * u(r); b->ay[i] = 30.0 * u(r); b->az[i] = 300.0 * u(r);
      b->airx[i] = 0.0; b->airy[i] = 0.0; b->airz[i] = 0.0;
    }
    const int m = b == &general ? n : 1;  // the uniform kernel reads element 0 only
    for (int i = 0; i < m; ++i) {
      b->ecx[i] = e_c.x(); b->ecy[i] = e_c.y(); b->ecz[i] = e_c.z();
      b->nx[i] = nrm.x(); b->ny[i] = nrm.y(); b->nz[i] = nrm.z();
      b->wx[i] = w.x(); b->wy[i] = w.y(); b->wz[i] = w.z();
      b->wdx[i] = wd.x(); b->wdy[i] = wd.y(); b->wdz[i] = wd.z();
    }
    for (int i = m; i < n; ++i) {  // garbage where the uniform kernel must not read
      b->ecx[i] = b->ecy[i] = b->ecz[i] = b->nx[i] = b->ny[i] = b->nz[i] =
          std::numeric_limits<double>::quiet_NaN();
      b->wx[i] = b->wy[i] = b->wz[i] = b->wdx[i] = b->wdy[i] = b->wdz[i] =
          std::numeric_limits<double>::quiet_NaN();
    }
    prepareStripBatch(ctx, *b);
  }
  for (int i = 0; i < n; ++i) {
    states[2 * i] = 0.5 * u(rng);
    states[2 * i + 1] = 0.5 + 0.5 * u(rng);
  }
  evalMstTdBatch(ctx, general, states.data(), d_general.data());
  evalMstTdBatchUniformFrame(ctx, uniform, states.data(), d_uniform.data());
  for (int i = 0; i < n; ++i) {
    const double scale = std::max(1e-6, std::abs(general.Fx[i]) + std::abs(general.Fz[i]));
    EXPECT_NEAR(uniform.Fx[i], general.Fx[i], kBatchRelTol * scale) << i;
    EXPECT_NEAR(uniform.Fy[i], general.Fy[i], kBatchRelTol * scale) << i;
    EXPECT_NEAR(uniform.Fz[i], general.Fz[i], kBatchRelTol * scale) << i;
    EXPECT_NEAR(uniform.My[i], general.My[i], kBatchRelTol * std::max(1e-9, std::abs(general.My[i]))) << i;
    EXPECT_EQ(std::isfinite(uniform.Fx[i]), true) << i;
    EXPECT_NEAR(uniform.separation_f[i], general.separation_f[i], 1e-14) << i;
    for (int k = 0; k < 2; ++k)
      EXPECT_NEAR(d_uniform[2 * i + k], d_general[2 * i + k],
                  kBatchRelTol * std::max(1.0, std::abs(d_general[2 * i + k]))) << i;
  }
}

}  // namespace
}  // namespace orni::aero
