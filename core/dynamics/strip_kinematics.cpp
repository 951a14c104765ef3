#include "core/dynamics/strip_kinematics.hpp"

#include <cmath>

namespace orni {

StripKinematics::StripKinematics(const StackedStrips& stacked, int mode_count)
    : st_(stacked),
      M_(mode_count),
      ns_(static_cast<int>(stacked.x_L.size() / 3)),
      SL_(stacked.x_L),
      ST_(stacked.x_T),
      UdL_(Eigen::VectorXd::Zero(3 * ns_)),
      twist_rate_(Eigen::VectorXd::Zero(ns_)),
      Fall_(Eigen::VectorXd::Zero(3 * ns_)),
      mpitch_(Eigen::VectorXd::Zero(ns_)),
      esx_(ns_), esy_(ns_), esz_(ns_), midx_(ns_), midy_(ns_), midz_(ns_),
      t0_(ns_), t1_(ns_), vx_(ns_), vy_(ns_), vz_(ns_), wsx_(ns_), wsy_(ns_), wsz_(ns_),
      vmn_(ns_) {}

void StripKinematics::compute(const Eigen::VectorXd& q, const Eigen::VectorXd& qd,
                              const WingFrameMotion& m, aero::StripBatch& b) {
  const Eigen::Index n = ns_;
  if (M_ > 0) {
    SL_ = st_.x_L;
    SL_.noalias() += st_.phi_L * q;
    ST_ = st_.x_T;
    ST_.noalias() += st_.phi_T * q;
    UdL_.noalias() = st_.phi_L * qd;
    twist_rate_.noalias() = st_.psi_twist * qd;
  }
  // One pass over the strips (the compiler vectorises it; every intermediate stays in a
  // register instead of a temporary array).
  const double* __restrict Lx = SL_.data();
  const double* __restrict Ly = Lx + n;
  const double* __restrict Lz = Lx + 2 * n;
  const double* __restrict Tx = ST_.data();
  const double* __restrict Ty = Tx + n;
  const double* __restrict Tz = Tx + 2 * n;
  const double* __restrict Ux = UdL_.data();
  const double* __restrict Uy = Ux + n;
  const double* __restrict Uz = Ux + 2 * n;
  const double* __restrict tr = twist_rate_.data();
  const double* __restrict chord = b.chord_m.data();
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
    const double sx = Lx[j], sy = Ly[j], sz = Lz[j];
    const double ux = Ux[j], uy = Uy[j], uz = Uz[j];
    // e_c = (s_L - s_T)/|.| (TE -> LE); e_s = (e_y - (e_c.e_y) e_c)/|.|; n = e_s x e_c (up).
    double cx = sx - Tx[j], cy = sy - Ty[j], cz = sz - Tz[j];
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
    const double half_c = 0.5 * chord[j];
    midx[j] = sx - half_c * cx;
    midy[j] = sy - half_c * cy;
    midz[j] = sz - half_c * cz;
    // v = v_O + w x s_L + u'_L; a0 = a_O0 + alpha x s_L + w (w.s_L) - |w|^2 s_L + 2 w x u'_L.
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

void StripKinematics::modalForce(const aero::StripBatch& b, Eigen::VectorXd* Q) {
  const Eigen::Index n = ns_;
  Fall_.segment(0, n) = b.Fx.matrix();
  Fall_.segment(n, n) = b.Fy.matrix();
  Fall_.segment(2 * n, n) = b.Fz.matrix();
  mpitch_ = (b.Mx * esx_ + b.My * esy_ + b.Mz * esz_).matrix();
  Q->noalias() = st_.phi_L.transpose() * Fall_;
  Q->noalias() += st_.psi_twist.transpose() * mpitch_;
}

void StripKinematics::resultant(const aero::StripBatch& b, const Eigen::VectorXd& extra_force,
                                const Eigen::VectorXd& extra_couple, const Vec3& omega_rel_W,
                                Vec3* F_W, Vec3* M_P2_W, double* power_W) {
  const Eigen::Index n = ns_;
  const auto sx = SL_.segment(0, n).array(), sy = SL_.segment(n, n).array(),
             sz = SL_.segment(2 * n, n).array();
  const auto ef = extra_force.array(), ec = extra_couple.array();
  // Apparent-mass force along n at mid-chord and couple about e_s.
  const Vec3 F(b.Fx.sum() + (ef * b.nx).sum(), b.Fy.sum() + (ef * b.ny).sum(),
               b.Fz.sum() + (ef * b.nz).sum());
  Vec3 M;
  M.x() = (sy * b.Fz - sz * b.Fy).sum() + b.Mx.sum() +
          (ef * (midy_ * b.nz - midz_ * b.ny)).sum() + (ec * esx_).sum();
  M.y() = (sz * b.Fx - sx * b.Fz).sum() + b.My.sum() +
          (ef * (midz_ * b.nx - midx_ * b.nz)).sum() + (ec * esy_).sum();
  M.z() = (sx * b.Fy - sy * b.Fx).sum() + b.Mz.sum() +
          (ef * (midx_ * b.ny - midy_ * b.nx)).sum() + (ec * esz_).sum();
  *F_W = F;
  *M_P2_W = M;
  if (power_W) *power_W = power(b, extra_force, extra_couple, omega_rel_W);
}

double StripKinematics::power(const aero::StripBatch& b, const Eigen::VectorXd& extra_force,
                              const Eigen::VectorXd& extra_couple, const Vec3& omega_rel_W) {
  const Eigen::Index n = ns_;
  const auto sx = SL_.segment(0, n).array(), sy = SL_.segment(n, n).array(),
             sz = SL_.segment(2 * n, n).array();
  const auto ux = UdL_.segment(0, n).array(), uy = UdL_.segment(n, n).array(),
             uz = UdL_.segment(2 * n, n).array();
  const auto ef = extra_force.array(), ec = extra_couple.array();
  // Relative motion: v_rel_L = w_rel x s_L + u'_L, w_strip = w_rel + twist' e_s,
  // v_rel_mid . n = (v_rel_L + w_strip x (mid - s_L)) . n.
  const Vec3& w = omega_rel_W;
  const auto tr = twist_rate_.array();
  vx_ = (w.y() * sz - w.z() * sy) + ux;
  vy_ = (w.z() * sx - w.x() * sz) + uy;
  vz_ = (w.x() * sy - w.y() * sx) + uz;
  wsx_ = w.x() + tr * esx_;
  wsy_ = w.y() + tr * esy_;
  wsz_ = w.z() + tr * esz_;
  vmn_ = (vx_ + wsy_ * (midz_ - sz) - wsz_ * (midy_ - sy)) * b.nx +
         (vy_ + wsz_ * (midx_ - sx) - wsx_ * (midz_ - sz)) * b.ny +
         (vz_ + wsx_ * (midy_ - sy) - wsy_ * (midx_ - sx)) * b.nz;
  return -((b.Fx * vx_ + b.Fy * vy_ + b.Fz * vz_).sum() +
           (b.Mx * wsx_ + b.My * wsy_ + b.Mz * wsz_).sum() + (ef * vmn_).sum() +
           (ec * (esx_ * wsx_ + esy_ * wsy_ + esz_ * wsz_)).sum());
}

}  // namespace orni
