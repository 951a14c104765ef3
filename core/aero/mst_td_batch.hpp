// MST-TD over all strips of a wing at once, in structure-of-arrays form (docs/theory.md 5.9): two
// fused passes over the strips that the compiler vectorises (kinematics, lag and stall angle;
// then separation and loads), with Eigen's vectorised exp for f_st between them. Same equations,
// same order of operations, as evalMstTd() (the scalar reference, tests/unit/aero/
// test_mst_td_batch.cpp checks them against each other); only atan2 and sin are replaced by
// branch-free series accurate to a few ulp, and the speed ratio uses cos^2 = 1 - sin^2.
//
// Scope: the Scherer lag (option A, states [z, f] per strip) with a smooth stall (stall width > 0);
// other settings use the scalar kernel. The workspace is sized once; evaluation never allocates.
#pragma once

#include <Eigen/Core>

#include "core/aero/mst_strip.hpp"

namespace orni::aero {

using ArrayXd = Eigen::ArrayXd;

/// True when evalMstTdBatch() handles these parameters.
bool batchKernelApplies(const AeroParameters& params);

/// Vectorisable atan2 (range reduction to |u| <= tan(pi/16), odd Taylor series to u^23):
/// |error| < 4e-16 rad; atan2(0, 0) = 0.
ArrayXd& atan2Array(const ArrayXd& y, const ArrayXd& x, ArrayXd& out);

struct StripBatch {
  explicit StripBatch(int strip_count = 0) { resize(strip_count); }
  void resize(int strip_count);
  int size() const { return static_cast<int>(chord_m.size()); }

  // Geometry and cached coefficients (set once per model / flight speed).
  ArrayXd chord_m, width_m, ref_aft_of_le_m, friction_coefficient;
  // Kinematics per evaluation (docs/theory.md 5.1), one frame for all vectors.
  ArrayXd ecx, ecy, ecz, nx, ny, nz;            ///< chord TE->LE, upper normal
  ArrayXd vx, vy, vz, ax, ay, az;               ///< v_P, a_P
  ArrayXd wx, wy, wz, wdx, wdy, wdz;            ///< w_s, wdot_s
  ArrayXd airx, airy, airz;                     ///< local air velocity
  // Outputs per strip.
  ArrayXd Fx, Fy, Fz;                           ///< force, N
  ArrayXd Mx, My, Mz;                           ///< moment about P, N m
  ArrayXd separation_f;                         ///< f used in the loads
  // Per-strip constants derived from the geometry, air and friction (prepareStripBatch()).
  ArrayXd lever25, lever50, lever75;  ///< c/4 - x_P, c/2 - x_P, 3c/4 - x_P
  ArrayXd k_q;                        ///< 0.5 rho c dy
  ArrayXd k_apparent;                 ///< rho pi c^2/4 dy (M8)
  ArrayXd k_couple1, k_couple2;       ///< rho pi c^3/16 dy, rho pi c^4/128 dy (M17)
  ArrayXd k_friction;                 ///< Cd_f 0.5 rho c dy (0 when friction is off)
  ArrayXd k_crossflow;                ///< Cd_cf 0.5 rho c dy
  ArrayXd two_over_c;                 ///< 2/c (reduced-time rate per unit speed)
  // Scratch.
  ArrayXd t[24];
};

/// Fill the per-strip constants from chord_m, width_m, ref_aft_of_le_m and friction_coefficient;
/// call again whenever one of those (or the air density) changes.
void prepareStripBatch(const StripContext& context, StripBatch& batch);

/// Evaluate all strips: loads into batch outputs, state derivatives (interleaved [z, f] per strip,
/// like `states`) into `state_derivatives` (may be null).
void evalMstTdBatch(const StripContext& context, StripBatch& batch, const double* states,
                    double* state_derivatives);

/// The same for strips that share one frame (a rigid wing): e_c, n, w_s and wdot_s are read from
/// element 0 of ecx..nz, wx..wz, wdx..wdz only (the other elements are not read).
void evalMstTdBatchUniformFrame(const StripContext& context, StripBatch& batch,
                                const double* states, double* state_derivatives);

}  // namespace orni::aero
