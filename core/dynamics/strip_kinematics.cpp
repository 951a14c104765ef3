#include "core/dynamics/strip_kinematics.hpp"

#include <cmath>

namespace orni {

StripKinematics::StripKinematics(const StackedStrips& stacked, int mode_count)
    : st_(stacked),
      mode_count_(mode_count),
      ns_(static_cast<int>(stacked.ns)),
      S_(stacked.points),
      rates_(Eigen::VectorXd::Zero(4 * ns_)),
      loads_(Eigen::VectorXd::Zero(4 * ns_)),
      esx_(ns_), esy_(ns_), esz_(ns_), midx_(ns_), midy_(ns_), midz_(ns_),
      cFx_(Eigen::ArrayXd::Zero(ns_)), cFy_(Eigen::ArrayXd::Zero(ns_)),
      cFz_(Eigen::ArrayXd::Zero(ns_)), cMx_(Eigen::ArrayXd::Zero(ns_)),
      cMy_(Eigen::ArrayXd::Zero(ns_)), cMz_(Eigen::ArrayXd::Zero(ns_)),
      cP_(Eigen::ArrayXd::Zero(ns_)) {}

void StripKinematics::compute(const Eigen::VectorXd& q, const Eigen::VectorXd& qd,
                              const WingFrameMotion& m, aero::StripBatch& b) {
  const Eigen::Index n = ns_;
  if (mode_count_ > 0) {
    // [s_R; s_P] = x + [phi_R; phi_P] q, [u'_P; twist'] = [phi_P; psi_twist] q' (P: the kernel's
    // reference point, where the strip force acts; R: the section's 3/4 chord, flexible_wing.hpp)
    S_ = st_.points;
    S_.noalias() += st_.pointShapes() * q;
    rates_.noalias() = st_.rateShapes() * qd;
  }
  // One pass over the strips (the compiler vectorises it; every intermediate stays in a
  // register instead of a temporary array).
  const double* __restrict Rx = S_.data();
  const double* __restrict Ry = Rx + n;
  const double* __restrict Rz = Rx + 2 * n;
  const double* __restrict Px = Rx + 3 * n;
  const double* __restrict Py = Rx + 4 * n;
  const double* __restrict Pz = Rx + 5 * n;
  const double* __restrict Ux = rates_.data();
  const double* __restrict Uy = Ux + n;
  const double* __restrict Uz = Ux + 2 * n;
  const double* __restrict tr = Ux + 3 * n;
  const double* __restrict chord = b.chord_m.data();
  const double* __restrict x_P = st_.ref_aft_of_le_m.data();
  double* __restrict ecx = b.ecx.data();
  double* __restrict ecy = b.ecy.data();
  double* __restrict ecz = b.ecz.data();
  double* __restrict nx = b.nx.data();
  double* __restrict ny = b.ny.data();
  double* __restrict nz = b.nz.data();
  double* __restrict esx = esx_.data();
  double* __restrict esy = esy_.data();
  double* __restrict esz = esz_.data();
  double* __restrict midx = midx_.data();
  double* __restrict midy = midy_.data();
  double* __restrict midz = midz_.data();
  double* __restrict vx = b.vx.data();
  double* __restrict vy = b.vy.data();
  double* __restrict vz = b.vz.data();
  double* __restrict ax = b.ax.data();
  double* __restrict ay = b.ay.data();
  double* __restrict az = b.az.data();
  double* __restrict wx = b.wx.data();
  double* __restrict wy = b.wy.data();
  double* __restrict wz = b.wz.data();
  double* __restrict wdx = b.wdx.data();
  double* __restrict wdy = b.wdy.data();
  double* __restrict wdz = b.wdz.data();
  // Frame motion as plain scalars (loop invariants the vectoriser can broadcast).
  const double w_x = m.omega_W.x(), w_y = m.omega_W.y(), w_z = m.omega_W.z();
  const double al_x = m.alpha0_W.x(), al_y = m.alpha0_W.y(), al_z = m.alpha0_W.z();
  const double vO_x = m.v_O_W.x(), vO_y = m.v_O_W.y(), vO_z = m.v_O_W.z();
  const double aO_x = m.a_O0_W.x(), aO_y = m.a_O0_W.y(), aO_z = m.a_O0_W.z();
  const double w2 = w_x * w_x + w_y * w_y + w_z * w_z;
#pragma GCC ivdep  // the outputs are distinct arrays (GCC ignores restrict on local pointers)
  for (Eigen::Index j = 0; j < n; ++j) {
    const double sx = Px[j], sy = Py[j], sz = Pz[j];
    const double ux = Ux[j], uy = Uy[j], uz = Uz[j];
    // e_c = (s_P - s_R)/|.| (TE -> LE); e_s = (e_y - (e_c.e_y) e_c)/|.|; n = e_s x e_c (up).
    double cx = sx - Rx[j], cy = sy - Ry[j], cz = sz - Rz[j];
    const double inv_c = 1.0 / std::sqrt(cx * cx + cy * cy + cz * cz);
    cx *= inv_c;
    cy *= inv_c;
    cz *= inv_c;
    double ex = -cy * cx, ey = 1.0 - cy * cy, ez = -cy * cz;
    const double inv_s = 1.0 / std::sqrt(ex * ex + ey * ey + ez * ez);
    ex *= inv_s;
    ey *= inv_s;
    ez *= inv_s;
    ecx[j] = cx;
    ecy[j] = cy;
    ecz[j] = cz;
    esx[j] = ex;
    esy[j] = ey;
    esz[j] = ez;
    nx[j] = ey * cz - ez * cy;
    ny[j] = ez * cx - ex * cz;
    nz[j] = ex * cy - ey * cx;
    const double half_c = 0.5 * chord[j] - x_P[j];  // P to the kernel's mid-chord
    midx[j] = sx - half_c * cx;
    midy[j] = sy - half_c * cy;
    midz[j] = sz - half_c * cz;
    // v = v_O + w x s_P + u'_P; a0 = a_O0 + alpha x s_P + w (w.s_P) - |w|^2 s_P + 2 w x u'_P.
    vx[j] = vO_x + (w_y * sz - w_z * sy) + ux;
    vy[j] = vO_y + (w_z * sx - w_x * sz) + uy;
    vz[j] = vO_z + (w_x * sy - w_y * sx) + uz;
    const double ws = w_x * sx + w_y * sy + w_z * sz;
    ax[j] = aO_x + (al_y * sz - al_z * sy) + w_x * ws - w2 * sx +
            2.0 * (w_y * uz - w_z * uy);
    ay[j] = aO_y + (al_z * sx - al_x * sz) + w_y * ws - w2 * sy +
            2.0 * (w_z * ux - w_x * uz);
    az[j] = aO_z + (al_x * sy - al_y * sx) + w_z * ws - w2 * sz +
            2.0 * (w_x * uy - w_y * ux);
    // w_s = w + twist' e_s; wdot0 = alpha + w x (twist' e_s).
    const double t = tr[j];
    wx[j] = w_x + t * ex;
    wy[j] = w_y + t * ey;
    wz[j] = w_z + t * ez;
    wdx[j] = al_x + t * (w_y * ez - w_z * ey);
    wdy[j] = al_y + t * (w_z * ex - w_x * ez);
    wdz[j] = al_z + t * (w_x * ey - w_y * ex);
  }
}

void StripKinematics::setReferencePoints(aero::StripBatch& b) const {
  b.ref_aft_of_le_m = st_.ref_aft_of_le_m.array();
}

void StripKinematics::modalForce(const aero::StripBatch& b, Eigen::VectorXd* Q) {
  const Eigen::Index n = ns_;
  loads_.segment(0, n) = b.Fx.matrix();
  loads_.segment(n, n) = b.Fy.matrix();
  loads_.segment(2 * n, n) = b.Fz.matrix();
  loads_.segment(3 * n, n) = (b.Mx * esx_ + b.My * esy_ + b.Mz * esz_).matrix();
  Q->noalias() = st_.rateShapes().transpose() * loads_;
}

void StripKinematics::resultant(const aero::StripBatch& b, const Eigen::VectorXd& extra_force,
                                const Eigen::VectorXd& extra_couple, const Vec3& omega_rel_W,
                                Vec3* F_W, Vec3* M_P2_W, double* power_W) {
  contributions(b, extra_force, extra_couple, omega_rel_W, power_W != nullptr);
  *F_W = Vec3(cFx_.sum(), cFy_.sum(), cFz_.sum());
  *M_P2_W = Vec3(cMx_.sum(), cMy_.sum(), cMz_.sum());
  if (power_W) *power_W = cP_.sum();
}

double StripKinematics::power(const aero::StripBatch& b, const Eigen::VectorXd& extra_force,
                              const Eigen::VectorXd& extra_couple, const Vec3& omega_rel_W) {
  contributions(b, extra_force, extra_couple, omega_rel_W, true);
  return cP_.sum();
}

void StripKinematics::contributions(const aero::StripBatch& b, const Eigen::VectorXd& extra_force,
                                    const Eigen::VectorXd& extra_couple, const Vec3& omega_rel_W,
                                    bool with_power) {
  const Eigen::Index n = ns_;
  const double* __restrict Px = S_.data() + 3 * n;
  const double* __restrict Py = Px + n;
  const double* __restrict Pz = Px + 2 * n;
  const double* __restrict Ux = rates_.data();
  const double* __restrict Uy = Ux + n;
  const double* __restrict Uz = Ux + 2 * n;
  const double* __restrict tr = Ux + 3 * n;
  const double* __restrict ef = extra_force.data();
  const double* __restrict ec = extra_couple.data();
  const double *__restrict Fx = b.Fx.data(), *__restrict Fy = b.Fy.data(),
               *__restrict Fz = b.Fz.data();
  const double *__restrict Mx = b.Mx.data(), *__restrict My = b.My.data(),
               *__restrict Mz = b.Mz.data();
  const double *__restrict nx = b.nx.data(), *__restrict ny = b.ny.data(),
               *__restrict nz = b.nz.data();
  const double *__restrict esx = esx_.data(), *__restrict esy = esy_.data(),
               *__restrict esz = esz_.data();
  const double *__restrict midx = midx_.data(), *__restrict midy = midy_.data(),
               *__restrict midz = midz_.data();
  double *__restrict cFx = cFx_.data(), *__restrict cFy = cFy_.data(), *__restrict cFz = cFz_.data();
  double *__restrict cMx = cMx_.data(), *__restrict cMy = cMy_.data(), *__restrict cMz = cMz_.data();
  double* __restrict cP = cP_.data();
  const double w_x = omega_rel_W.x(), w_y = omega_rel_W.y(), w_z = omega_rel_W.z();
  // Per strip: force and moment about P2 with the apparent-mass force along n at mid-chord and
  // couple about e_s; the power uses the motion relative to the fuselage:
  // v_rel_P = w_rel x s_P + u'_P, w_strip = w_rel + twist' e_s,
  // v_rel_mid . n = (v_rel_P + w_strip x (mid - s_P)) . n (M19 sign: power put into the air).
  // The kernel's force acts at P and its moment is about P (docs/theory.md 5.5), so the moment
  // about P2 is s_P x F + M_P.
#pragma GCC ivdep  // distinct arrays (GCC ignores restrict on local pointers)
  for (Eigen::Index j = 0; j < n; ++j) {
    const double sx = Px[j], sy = Py[j], sz = Pz[j];
    const double e = ef[j];
    cFx[j] = Fx[j] + e * nx[j];
    cFy[j] = Fy[j] + e * ny[j];
    cFz[j] = Fz[j] + e * nz[j];
    cMx[j] = (sy * Fz[j] - sz * Fy[j]) + Mx[j] + e * (midy[j] * nz[j] - midz[j] * ny[j]) +
             ec[j] * esx[j];
    cMy[j] = (sz * Fx[j] - sx * Fz[j]) + My[j] + e * (midz[j] * nx[j] - midx[j] * nz[j]) +
             ec[j] * esy[j];
    cMz[j] = (sx * Fy[j] - sy * Fx[j]) + Mz[j] + e * (midx[j] * ny[j] - midy[j] * nx[j]) +
             ec[j] * esz[j];
    if (!with_power) continue;
    const double vx = (w_y * sz - w_z * sy) + Ux[j];
    const double vy = (w_z * sx - w_x * sz) + Uy[j];
    const double vz = (w_x * sy - w_y * sx) + Uz[j];
    const double t = tr[j];
    const double wsx = w_x + t * esx[j], wsy = w_y + t * esy[j], wsz = w_z + t * esz[j];
    const double dx = midx[j] - sx, dy = midy[j] - sy, dz = midz[j] - sz;
    const double vmn = (vx + wsy * dz - wsz * dy) * nx[j] + (vy + wsz * dx - wsx * dz) * ny[j] +
                       (vz + wsx * dy - wsy * dx) * nz[j];
    cP[j] = -((Fx[j] * vx + Fy[j] * vy + Fz[j] * vz) + (Mx[j] * wsx + My[j] * wsy + Mz[j] * wsz) +
              e * vmn + ec[j] * (esx[j] * wsx + esy[j] * wsy + esz[j] * wsz));
  }
}

}  // namespace orni
