// MST-TD over all strips of a wing at once, in structure-of-arrays form so that Eigen vectorises
// every step (aero-mst.md 9.5). Same equations, same order of operations, as evalMstTd() (the
// scalar reference, tests/unit/aero/test_mst_td_batch.cpp checks them against each other); only
// atan2 is replaced by a branch-free vectorisable version accurate to a few ulp.
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
ArrayXd& atan2Array(const ArrayXd& y, const ArrayXd& x, ArrayXd& out, ArrayXd& scratch_a,
                    ArrayXd& scratch_b, ArrayXd& scratch_c);

struct StripBatch {
  explicit StripBatch(int strip_count = 0) { resize(strip_count); }
  void resize(int strip_count);
  int size() const { return static_cast<int>(chord_m.size()); }

  // Geometry and cached coefficients (set once per model / flight speed).
  ArrayXd chord_m, width_m, ref_aft_of_le_m, friction_coefficient;
  // Kinematics per evaluation (aero-mst.md 2.3), one frame for all vectors.
  ArrayXd ecx, ecy, ecz, nx, ny, nz;            ///< chord TE->LE, upper normal
  ArrayXd vx, vy, vz, ax, ay, az;               ///< v_P, a_P
  ArrayXd wx, wy, wz, wdx, wdy, wdz;            ///< w_s, wdot_s
  ArrayXd airx, airy, airz;                     ///< local air velocity
  // Outputs per strip.
  ArrayXd Fx, Fy, Fz;                           ///< force, N
  ArrayXd Mx, My, Mz;                           ///< moment about P, N m
  ArrayXd separation_f;                         ///< f used in the loads
  // Scratch.
  ArrayXd t[24];
};

/// Evaluate all strips: loads into batch outputs, state derivatives (interleaved [z, f] per strip,
/// like `states`) into `state_derivatives` (may be null).
void evalMstTdBatch(const StripContext& context, StripBatch& batch, const double* states,
                    double* state_derivatives);

}  // namespace orni::aero
