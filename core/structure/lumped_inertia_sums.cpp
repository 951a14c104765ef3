#include "core/structure/lumped_inertia_sums.hpp"

#include <stdexcept>

namespace orni::structure {

namespace {

Mat3 skew(const Vec3& v) {
  Mat3 s;
  s << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
  return s;
}

/// T = sum_p m_p (G_p a)(G_p b)^T, T(k, l) = a^T B_kl b, from aB = a^T [B_00 ... B_22].
Mat3 secondMoment(const Eigen::RowVectorXd& aB, const Eigen::VectorXd& b) {
  const Eigen::Index n = b.size();
  Mat3 t;
  for (int k = 0; k < 3; ++k)
    for (int l = 0; l < 3; ++l) t(k, l) = aB.segment((3 * k + l) * n, n).dot(b.transpose());
  return t;
}

/// sum_p m_p x_p x (A y_p) from T_xy = sum_p m_p x_p y_p^T: component i is eps_ijk (T_xy A^T)_jk.
Vec3 crossSum(const Mat3& T_xy, const Mat3& A) {
  const Mat3 z = T_xy * A.transpose();
  return Vec3(z(1, 2) - z(2, 1), z(2, 0) - z(0, 2), z(0, 1) - z(1, 0));
}

}  // namespace

LumpedInertiaSums lumpedInertiaSums(const Eigen::VectorXd& nodal_mass_kg,
                                    const std::vector<Mat3>& nodal_rotary_W_kgm2,
                                    const std::vector<Eigen::Matrix3Xd>& phi_W,
                                    const std::vector<Vec3>& nodes_W_m) {
  const std::size_t n = nodes_W_m.size();
  if (static_cast<std::size_t>(nodal_mass_kg.size()) != n || phi_W.size() != n ||
      (!nodal_rotary_W_kgm2.empty() && nodal_rotary_W_kgm2.size() != n))
    throw std::invalid_argument("lumpedInertiaSums: one mass, rotary block and shape per node");
  const Eigen::Index modes = n == 0 ? 0 : phi_W.front().cols();
  LumpedInertiaSums sums;
  sums.first_moments = Eigen::Matrix3Xd::Zero(3, modes + 1);
  const Eigen::Index n_g = modes + 1;
  sums.second_moments = Eigen::MatrixXd::Zero(n_g, 9 * n_g);
  Eigen::Matrix3Xd g(3, modes + 1);
  for (std::size_t p = 0; p < n; ++p) {
    if (!nodal_rotary_W_kgm2.empty()) sums.rotary_W_kgm2 += nodal_rotary_W_kgm2[p];
    const double m = nodal_mass_kg[static_cast<Eigen::Index>(p)];
    if (m <= 0.0) continue;
    g.col(0) = nodes_W_m[p];
    g.rightCols(modes) = phi_W[p];
    sums.first_moments += m * g;
    for (int k = 0; k < 3; ++k)
      for (int l = 0; l < 3; ++l)
        sums.second_moments.middleCols((3 * k + l) * n_g, n_g).noalias() +=
            m * g.row(k).transpose() * g.row(l);
  }
  sums.modal_mass = sums.second_moments.block(1, 1, modes, modes) +
                    sums.second_moments.block(1, 4 * n_g + 1, modes, modes) +
                    sums.second_moments.block(1, 8 * n_g + 1, modes, modes);
  return sums;
}

WingInertialLoads wingInertialLoads(const LumpedInertiaSums& sums, const Eigen::VectorXd& q,
                                    const Eigen::VectorXd& qd, const Eigen::VectorXd& qdd,
                                    const Vec3& omega_W, const Vec3& alpha_W,
                                    LumpedInertiaWorkspace* ws) {
  const int modes = sums.modeCount();
  if (ws->c_x.size() != modes + 1 || ws->cx_B.size() != 9 * (modes + 1) ||
      ws->mass_qdd.size() != modes)
    ws->resize(modes);
  ws->c_x(0) = 1.0;
  ws->c_x.tail(modes) = q;
  ws->c_u.tail(modes) = qd;  // c_u(0) = c_w(0) = 0 from resize
  ws->c_w.tail(modes) = qdd;
  const Eigen::VectorXd &cx = ws->c_x, &cu = ws->c_u, &cw = ws->c_w;

  // First moments: sum m x, sum m u, sum m w.
  const Vec3 Sx = sums.first_moments * cx, Su = sums.first_moments * cu,
             Sw = sums.first_moments * cw;
  const Mat3 Wx = skew(omega_W), Ax = skew(alpha_W), W2 = Wx * Wx;
  // Second moments T_ab = sum m a b^T.
  ws->cx_B.noalias() = cx.transpose() * sums.second_moments;
  const Mat3 Txx = secondMoment(ws->cx_B, cx), Txu = secondMoment(ws->cx_B, cu),
             Txw = secondMoment(ws->cx_B, cw);
  ws->mass_qdd.noalias() = sums.modal_mass * qdd;
  const double trace_Tuw = qd.dot(ws->mass_qdd);  // sum m u.w

  WingInertialLoads out;
  out.force_W_N = -(alpha_W.cross(Sx) + omega_W.cross(omega_W.cross(Sx)) +
                    2.0 * omega_W.cross(Su) + Sw);
  out.rotary_moment_W_Nm = sums.rotary_W_kgm2 * alpha_W;
  out.moment_W_Nm = -(crossSum(Txx, Ax + W2) + crossSum(Txu, 2.0 * Wx) +
                      crossSum(Txw, Mat3::Identity())) -
                    out.rotary_moment_W_Nm;
  // sum m a.v with a = (A + W2) x + 2 W u + w and v = W x + u; (W u).u = 0 node by node.
  // sum m (A y).(C z) = trace(A^T C T_zy).
  const Mat3 AW2 = Ax + W2;
  out.kinetic_energy_rate_W = (AW2.transpose() * Wx * Txx).trace() +
                              (AW2.transpose() * Txu.transpose()).trace() +
                              (2.0 * Wx.transpose() * Wx * Txu).trace() +
                              (Wx * Txw).trace() + trace_Tuw;
  return out;
}

}  // namespace orni::structure
