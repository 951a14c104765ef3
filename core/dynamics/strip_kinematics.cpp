#include "core/dynamics/strip_kinematics.hpp"

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
  const auto sx = SL_.segment(0, n).array(), sy = SL_.segment(n, n).array(),
             sz = SL_.segment(2 * n, n).array();
  const auto ux = UdL_.segment(0, n).array(), uy = UdL_.segment(n, n).array(),
             uz = UdL_.segment(2 * n, n).array();
  // e_c = (s_L - s_T)/|.| (TE -> LE); e_s = (e_y - (e_c.e_y) e_c)/|.|; n = e_s x e_c (up).
  b.ecx = sx - ST_.segment(0, n).array();
  b.ecy = sy - ST_.segment(n, n).array();
  b.ecz = sz - ST_.segment(2 * n, n).array();
  t0_ = (b.ecx.square() + b.ecy.square() + b.ecz.square()).rsqrt();
  b.ecx *= t0_;
  b.ecy *= t0_;
  b.ecz *= t0_;
  esx_ = -b.ecy * b.ecx;
  esy_ = 1.0 - b.ecy * b.ecy;
  esz_ = -b.ecy * b.ecz;
  t0_ = (esx_.square() + esy_.square() + esz_.square()).rsqrt();
  esx_ *= t0_;
  esy_ *= t0_;
  esz_ *= t0_;
  b.nx = esy_ * b.ecz - esz_ * b.ecy;
  b.ny = esz_ * b.ecx - esx_ * b.ecz;
  b.nz = esx_ * b.ecy - esy_ * b.ecx;
  midx_ = sx - 0.5 * b.chord_m * b.ecx;
  midy_ = sy - 0.5 * b.chord_m * b.ecy;
  midz_ = sz - 0.5 * b.chord_m * b.ecz;
  // v = v_O + w x s_L + u'_L; a0 = a_O0 + alpha x s_L + w (w.s_L) - |w|^2 s_L + 2 w x u'_L.
  const Vec3& w = m.omega_W;
  const Vec3& al = m.alpha0_W;
  b.vx = m.v_O_W.x() + (w.y() * sz - w.z() * sy) + ux;
  b.vy = m.v_O_W.y() + (w.z() * sx - w.x() * sz) + uy;
  b.vz = m.v_O_W.z() + (w.x() * sy - w.y() * sx) + uz;
  const double w2 = w.squaredNorm();
  t1_ = w.x() * sx + w.y() * sy + w.z() * sz;  // w . s_L
  b.ax = m.a_O0_W.x() + (al.y() * sz - al.z() * sy) + w.x() * t1_ - w2 * sx +
         2.0 * (w.y() * uz - w.z() * uy);
  b.ay = m.a_O0_W.y() + (al.z() * sx - al.x() * sz) + w.y() * t1_ - w2 * sy +
         2.0 * (w.z() * ux - w.x() * uz);
  b.az = m.a_O0_W.z() + (al.x() * sy - al.y() * sx) + w.z() * t1_ - w2 * sz +
         2.0 * (w.x() * uy - w.y() * ux);
  // w_s = w + twist' e_s; wdot0 = alpha + w x (twist' e_s).
  const auto tr = twist_rate_.array();
  b.wx = w.x() + tr * esx_;
  b.wy = w.y() + tr * esy_;
  b.wz = w.z() + tr * esz_;
  b.wdx = al.x() + tr * (w.y() * esz_ - w.z() * esy_);
  b.wdy = al.y() + tr * (w.z() * esx_ - w.x() * esz_);
  b.wdz = al.z() + tr * (w.x() * esy_ - w.y() * esx_);
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
