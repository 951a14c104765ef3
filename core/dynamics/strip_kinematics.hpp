// Strip kinematics of the wing from rigid frame motion plus modes (docs/theory.md 6.2), for all
// strips at once in structure-of-arrays form (the batch layout of the MST-TD kernel), and the
// projection of the strip loads back on the modes (6.3). Shared by the tethered and the free
// flexible wing; with zero modes it is the rigid wing. No allocation after construction.
#pragma once

#include <Eigen/Core>

#include "core/aero/mst_td_batch.hpp"
#include "core/dynamics/flexible_wing.hpp"
#include "core/model/frames.hpp"

namespace orni {

/// Motion of the wing frame W at one instant, W components; "0" = the part without the
/// generalised accelerations the caller solves for (docs/theory.md 4.2: a = V u' + a0).
struct WingFrameMotion {
  Vec3 v_O_W = Vec3::Zero();       ///< velocity of P2
  Vec3 a_O0_W = Vec3::Zero();      ///< acceleration of P2
  Vec3 omega_W = Vec3::Zero();     ///< angular velocity of W
  Vec3 alpha0_W = Vec3::Zero();    ///< angular acceleration of W
  Vec3 omega_rel_W = Vec3::Zero(); ///< angular velocity of W relative to the fuselage (power)
};

/// Per-strip kinematic results (component-major stacks: x of all strips, then y, then z).
class StripKinematics {
 public:
  StripKinematics(const StackedStrips& stacked, int mode_count);

  /// Deformed section points, frames and inertial motion of every strip into the kernel batch
  /// (e_c, n, v_P, a_P at the kernel's reference point P, w_s, wdot_s). P is
  /// StackedStrips::ref_aft_of_le_m aft of the leading edge: the batch's ref_aft_of_le_m must be
  /// the same (setReferencePoints() before aero::prepareStripBatch()).
  void compute(const Eigen::VectorXd& q, const Eigen::VectorXd& qd, const WingFrameMotion& m,
               aero::StripBatch& b);

  /// The kernel's reference point of every strip into the batch (call before
  /// aero::prepareStripBatch()): the quarter chord for the flexible wing, the leading edge for the
  /// rigid one.
  void setReferencePoints(aero::StripBatch& b) const;

  /// After the kernel: generalised aerodynamic force on the modes, Phi_P^T F + psi_twist^T m_P
  /// (docs/theory.md 6.3; the flat-plate nodal loads of chordwise_weights.hpp). `Q` has mode_count
  /// entries.
  void modalForce(const aero::StripBatch& b, Eigen::VectorXd* Q);

  /// Resultant of the strip loads on one wing about P2 (W components) including the
  /// apparent-mass force along n at mid-chord (extra_force per strip) and couple about e_s
  /// (extra_couple per strip), and their power relative to the fuselage (M19 sign: power put
  /// into the air).
  void resultant(const aero::StripBatch& b, const Eigen::VectorXd& extra_force,
                 const Eigen::VectorXd& extra_couple, const Vec3& omega_rel_W, Vec3* F_W,
                 Vec3* M_P2_W, double* power_W);

  /// The power part of resultant() alone (the same value), for callers that have the force and
  /// moment already.
  double power(const aero::StripBatch& b, const Eigen::VectorXd& extra_force,
               const Eigen::VectorXd& extra_couple, const Vec3& omega_rel_W);
  int strips() const { return ns_; }
  // Component arrays of the last compute() (length ns).
  const Eigen::ArrayXd& esx() const { return esx_; }
  const Eigen::ArrayXd& esy() const { return esy_; }
  const Eigen::ArrayXd& esz() const { return esz_; }
  const Eigen::ArrayXd& midx() const { return midx_; }
  const Eigen::ArrayXd& midy() const { return midy_; }
  const Eigen::ArrayXd& midz() const { return midz_; }

 private:
  const StackedStrips& st_;
  int mode_count_;
  int ns_;
  Eigen::VectorXd S_;      // deformed section points [s_R; s_P] (6 ns)
  Eigen::VectorXd rates_;  // [u'_P (3 ns); twist' (ns)]
  Eigen::VectorXd loads_;  // [F (3 ns); pitching moment about e_s (ns)], modalForce() workspace
  Eigen::ArrayXd esx_, esy_, esz_, midx_, midy_, midz_;
  // Per-strip contributions to the resultant force, moment about P2 and power.
  Eigen::ArrayXd cFx_, cFy_, cFz_, cMx_, cMy_, cMz_, cP_;
  void contributions(const aero::StripBatch& b, const Eigen::VectorXd& extra_force,
                     const Eigen::VectorXd& extra_couple, const Vec3& omega_rel_W,
                     bool with_power);
};

}  // namespace orni
