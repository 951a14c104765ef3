#include "core/dynamics/free_flight_system.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "core/aero/mst_strip.hpp"
#include "core/dynamics/flapping.hpp"
#include "core/dynamics/flight_path_frame.hpp"

namespace orni {

FreeFlightWorkspace::FreeFlightWorkspace(const FreeFlightModel& model)
    : data(model.core),
      kin(model.stacked(), model.mode_count),
      chol(3 + model.mode_count),
      membrane_ws(model.flex ? structure::ModalMembraneStiffness::Workspace(model.flex->membrane())
                              : structure::ModalMembraneStiffness::Workspace()) {
  const int m = model.mode_count;
  const auto ns = static_cast<Eigen::Index>(model.core.strips.size());
  n_u = 3 + m;
  q.setZero(m);
  qd.setZero(m);
  ud.setZero(n_u);
  f.setZero(n_u);
  scratch_modes.setZero(m);
  Gq_all.setZero(model.Gstack.rows());
  correction.setZero(n_u);
  Pq_all.setZero(9 * m);
  Cq_all.setZero(3 * m);
  Cqd_all.setZero(3 * m);
  Sq.setZero(9);
  Sqd.setZero(9);
  A.setZero(n_u, n_u);
  b_strip.setZero(ns);
  k_twist.setZero(ns);
  nuU.setZero(ns);
  nuW.setZero(ns);
  nuQ.setZero(ns);
  nutQ.setZero(ns);
  extra_force.setZero(ns);
  extra_couple.setZero(ns);
  zero_ns.setZero(ns);
  tmp_ns.setZero(ns);
  twist_mid_ud.setZero(2 * ns);
  packed.setZero(static_cast<Eigen::Index>(m) * (m + 1) / 2);
  data.batch.airx.setZero();
  data.batch.airy.setZero();
  data.batch.airz.setZero();
}

FreeFlightSystem::FreeFlightSystem(std::shared_ptr<const FreeFlightModel> model,
                                   const ControlInput& control, double reference_speed_mps)
    : model_(std::move(model)),
      control_(control),
      mode_count_(model_->mode_count),
      n_aero_(model_->aero_state_count),
      reference_speed_mps_(reference_speed_mps),
      ws_(*model_) {
  if (!(reference_speed_mps > 0.0) || !std::isfinite(reference_speed_mps))
    throw std::invalid_argument("free flight: the reference speed must be > 0 m/s");
  if (model_->flex) {
    split_ = std::make_unique<ModalImplicitSplit>(*model_->flex, kBody, stateCount());
    modal_mass_.resize(mode_count_, mode_count_);
    coupling_.resize(mode_count_, 3);
  }
  setFrictionSpeed(reference_speed_mps_);
}

FreeFlightSystem::FreeFlightSystem(const FlightCoreModel& model, const FlexibleWingModel* flex,
                                   const ControlInput& control, double reference_speed_mps)
    : FreeFlightSystem(std::make_shared<const FreeFlightModel>(model, flex), control,
                       reference_speed_mps) {}

void FreeFlightSystem::setFrictionSpeed(double speed_mps) {
  // M11 skin friction depends on the Reynolds number; it is frozen at the initial speed (the
  // speed varies by a few per cent in flight; Cd_f ~ Re^-0.2 moves by a fraction of that).
  const FlightCoreModel& core = model_->core;
  for (std::size_t j = 0; j < core.strips.size(); ++j)
    ws_.data.batch.friction_coefficient[static_cast<Eigen::Index>(j)] =
        aero::frictionCoefficient(speed_mps * core.strip_geometry[j].chord_m /
                                  core.vehicle.air.kinematic_viscosity_m2ps);
  ws_.kin.setReferencePoints(ws_.data.batch);  // flexible: the quarter chord; rigid: the LE
  aero::prepareStripBatch(core.aero_context, ws_.data.batch);
}

void FreeFlightSystem::initialState(double t_s, const BodyState& body, double* y) {
  y[0] = body.x_I_m;
  y[1] = body.h_m;
  y[2] = body.theta_rad;
  y[3] = body.U_mps;
  y[4] = body.W_mps;
  y[5] = body.Q_radps;
  for (int i = 0; i < 2 * mode_count_; ++i) y[kBody + i] = 0.0;
  BodyMotion bm;
  bm.v_P1_B = Vec3(body.U_mps, 0.0, body.W_mps);
  bm.theta_rad = body.theta_rad;
  bm.Q_radps = body.Q_radps;
  initialAeroStates(model_->core, bm, control_, t_s, y + aeroOffset());
  y[powerOffset()] = 0.0;
  setFrictionSpeed(std::hypot(body.U_mps, body.W_mps));
}

void FreeFlightSystem::absoluteTolerances(double rel_tol, double lag_abs_tol,
                                          double separation_abs_tol,
                                          std::vector<double>* atol) const {
  atol->assign(static_cast<std::size_t>(stateCount()), lag_abs_tol);
  // Body states at rel_tol times a scale: 10 m (x), 0.1 m (h), 0.1 rad, 1 m/s, 1 rad/s.
  const double scale[kBody] = {10.0, 0.1, 0.1, 1.0, 1.0, 1.0};
  for (int i = 0; i < kBody; ++i) (*atol)[static_cast<std::size_t>(i)] = rel_tol * scale[i];
  modalAbsoluteTolerances(rel_tol, mode_count_, kBody, atol);  // as the tethered flexible wing
  const int per = model_->core.aero_states_per_strip;
  for (int i = aeroOffset() + per - 1; i < powerOffset(); i += per)
    (*atol)[static_cast<std::size_t>(i)] = separation_abs_tol;
  const auto scales = quadratureScales(model_->core, reference_speed_mps_);
  (*atol)[static_cast<std::size_t>(powerOffset())] = 0.1 * rel_tol * scales[3] / control_.freq_hz;
}

struct FreeFlightSystem::Frame {
  double theta = 0, U = 0, W = 0, Q = 0;
  FlapState flap;
  Vec3 exW, eyW, ezW;  // R^T e_x, R^T e_y, R^T e_z
  Vec3 dQlin;          // partial velocity of P2 for Q (W components)
  Vec3 v_O;            // velocity of P2 (W)
  Vec3 g_B;            // gravity (B)
};

FreeFlightSystem::Frame FreeFlightSystem::frameAt(double t_s, const double* y) {
  Frame fr;
  fr.theta = y[2];
  fr.U = y[3];
  fr.W = y[4];
  fr.Q = y[5];
  const double theta = fr.theta, U = fr.U, W = fr.W, Q = fr.Q;
  ws_.q = Eigen::Map<const Eigen::VectorXd>(y + kBody, mode_count_);
  ws_.qd = Eigen::Map<const Eigen::VectorXd>(y + kBody + mode_count_, mode_count_);
  fr.flap = flapStateAt(model_->core.vehicle.flapping.amplitude_rad, control_.freq_hz, t_s);
  const FlapState& flap = fr.flap;
  last_.R_BW = rotX(flap.phi_rad);
  const Mat3 Rt = last_.R_BW.transpose();
  const Vec3 ex = Vec3::UnitX();
  fr.exW = Rt.col(0);
  fr.eyW = Rt.col(1);
  fr.ezW = Rt.col(2);
  const Vec3& eyW = fr.eyW;
  last_.omega_W = Q * eyW + flap.phi_dot_radps * ex;
  last_.alpha0_W = flap.phi_ddot_radps2 * ex + (Q * eyW).cross(flap.phi_dot_radps * ex);
  const Vec3& r2 = model_->p_P1P2_B_m;
  const Vec3 ey_x_r2(r2.z(), 0.0, -r2.x());  // e_y x r2
  const Vec3 v_P2_B = Vec3(U, 0.0, W) + Q * ey_x_r2;
  // Acceleration of P2 at u' = 0: a_P1 = (Q W, 0, -Q U) plus the centripetal Q^2 term.
  const Vec3 a_P2_0_B = Vec3(Q * W, 0.0, -Q * U) - Q * Q * Vec3(r2.x(), 0.0, r2.z());
  const double g = model_->core.vehicle.air.gravity_mps2;
  fr.g_B = Vec3(-g * std::sin(theta), 0.0, g * std::cos(theta));
  fr.v_O = Rt * v_P2_B;
  last_.a_O0_W = Rt * a_P2_0_B;
  last_.g_W = Rt * fr.g_B;
  fr.dQlin = Rt * ey_x_r2;
  return fr;
}

// Strip kinematics from rigid plus modal motion (docs/theory.md 6.2) at u' = 0, the kernel, the
// generalised aerodynamic forces (6.3) and the apparent air mass along each strip's mid-chord
// normal acceleration (6.4), A += b_j nu_j nu_j^T, b_j = 0.5 (1 + f) m_a, with the body partials
// nu = (n.e_x, n.e_z, n.(e_y x rho_mid)) and the modal ones psi_mid; plus the apparent rotary
// inertia of the kernel's couple -f k theta'' (M17) about e_s, with theta'' partials
// (0, 0, e_y.e_s, psi_twist).
void FreeFlightSystem::addWingAerodynamics(const Frame& fr, const double* y,
                                           double* aero_derivatives) {
  const FreeFlightModel& md = *model_;
  FreeFlightWorkspace& w = ws_;
  aero::StripBatch& b = w.data.batch;
  const Vec3 ex = Vec3::UnitX();
  const Vec3 &exW = fr.exW, &eyW = fr.eyW, &ezW = fr.ezW;
  WingFrameMotion fm;
  fm.v_O_W = fr.v_O;
  fm.a_O0_W = last_.a_O0_W;
  fm.omega_W = last_.omega_W;
  fm.alpha0_W = last_.alpha0_W;
  fm.omega_rel_W = fr.flap.phi_dot_radps * ex;
  w.kin.compute(w.q, w.qd, fm, b);
  aero::evalMstTdBatch(md.core.aero_context, b, y + aeroOffset(), aero_derivatives);

  w.kin.resultant(b, w.zero_ns, w.zero_ns, fm.omega_rel_W, &last_.F_aero_W, &last_.M_aero_P2_W,
                  nullptr);
  w.b_strip = (0.5 * (1.0 + b.separation_f) * md.apparent_mass_kg.array()).matrix();
  w.k_twist = (b.separation_f * b.k_couple2).matrix();
  const Vec3 rQ = fr.dQlin;  // n.(dQlin + eyW x mid)
  const StripKinematics& kin = w.kin;
  w.nuU = (b.nx * exW.x() + b.ny * exW.y() + b.nz * exW.z()).matrix();
  w.nuW = (b.nx * ezW.x() + b.ny * ezW.y() + b.nz * ezW.z()).matrix();
  w.nuQ = (b.nx * (rQ.x() + eyW.y() * kin.midz() - eyW.z() * kin.midy()) +
           b.ny * (rQ.y() + eyW.z() * kin.midx() - eyW.x() * kin.midz()) +
           b.nz * (rQ.z() + eyW.x() * kin.midy() - eyW.y() * kin.midx()))
              .matrix();
  w.nutQ = (kin.esx() * eyW.x() + kin.esy() * eyW.y() + kin.esz() * eyW.z()).matrix();
  const Eigen::VectorXd* nus[3] = {&w.nuU, &w.nuW, &w.nuQ};
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c <= r; ++c)
      w.A(r, c) += 2.0 * (w.b_strip.array() * nus[r]->array() * nus[c]->array()).sum();
  w.A(2, 2) += 2.0 * (w.k_twist.array() * w.nutQ.array().square()).sum();
  const int m = mode_count_;
  if (m > 0) {
    const StackedStrips& st = md.flex->stacked;
    w.kin.modalForce(b, &w.scratch_modes);
    w.f.tail(m) += 2.0 * w.scratch_modes;
    auto Aqb = w.A.block(3, 0, m, 3);
    for (int c = 0; c < 3; ++c) {
      w.tmp_ns = w.b_strip.cwiseProduct(*nus[c]);
      Aqb.col(c).noalias() += 2.0 * (st.psi_mid().transpose() * w.tmp_ns);
    }
    w.tmp_ns = w.k_twist.cwiseProduct(w.nutQ);
    Aqb.col(2).noalias() += 2.0 * (st.psi_twist().transpose() * w.tmp_ns);
    addApparentModalMass(st, b.separation_f, 2.0, &w.packed, w.A.bottomRightCorner(m, m));
  }
  last_.separated_fraction = ((1.0 - b.separation_f) * b.chord_m * b.width_m).sum() /
                             (b.chord_m * b.width_m).sum();
  w.f[0] += 2.0 * exW.dot(last_.F_aero_W);
  w.f[1] += 2.0 * ezW.dot(last_.F_aero_W);
  w.f[2] += 2.0 * (fr.dQlin.dot(last_.F_aero_W) + eyW.dot(last_.M_aero_P2_W));
}

// Wing inertia from the invariants (docs/theory.md 3.6, 4.3, 4.4), one wing, W components: gravity
// minus inertia at u' = 0 about P2, projected on the body's generalised speeds.
void FreeFlightSystem::addWingInertiaAndGravity(const Frame& fr) {
  const FreeFlightModel& md = *model_;
  FreeFlightWorkspace& w = ws_;
  const int m = mode_count_;
  const Vec3& om = last_.omega_W;
  const Vec3& al = last_.alpha0_W;
  Vec3& c_W = last_.c_W;
  Mat3& J_W = last_.J_W;
  c_W = md.wing_first_moment_W_kgm;
  J_W = md.wing_inertia_P2_W_kgm2;
  Vec3 Lqd = Vec3::Zero(), Mcor = Vec3::Zero();
  if (m > 0) {
    c_W.noalias() += md.L * w.q;
    Lqd.noalias() = md.L * w.qd;
    w.Sq.noalias() = md.Smat * w.q;
    w.Sqd.noalias() = md.Smat * w.qd;
    Mat3 T;  // T_kl = S_kl . q: the first moment of the deformation, J(q) linear part
    for (int k = 0; k < 3; ++k)
      for (int l = 0; l < 3; ++l) T(k, l) = w.Sq[3 * k + l];
    J_W += 2.0 * T.trace() * Mat3::Identity() - T - T.transpose();
    // Coriolis moment 2 sum m s x (w x Phi q') = 2 [w (sum_k S_kk.q') - sum_l w_l (S_kl.q')_k].
    Mat3 Td;
    for (int k = 0; k < 3; ++k)
      for (int l = 0; l < 3; ++l) Td(k, l) = w.Sqd[3 * k + l];
    Mcor = 2.0 * (om * Td.trace() - Td * om);
  }
  const double m_w = md.wing_mass_kg;
  const Vec3 F_acc0 = m_w * last_.a_O0_W + al.cross(c_W) + om.cross(om.cross(c_W)) +
                      2.0 * om.cross(Lqd);
  const Vec3 M_acc0 = c_W.cross(last_.a_O0_W) + J_W * al + om.cross(J_W * om) + Mcor;
  const Vec3 F_in = m_w * last_.g_W - F_acc0;  // gravity minus inertia at u' = 0, about P2
  const Vec3 M_in = c_W.cross(last_.g_W) - M_acc0;
  w.f[0] += 2.0 * fr.exW.dot(F_in);
  w.f[1] += 2.0 * fr.ezW.dot(F_in);
  w.f[2] += 2.0 * (fr.dQlin.dot(F_in) + fr.eyW.dot(M_in));
}

// Both wings' share of the mass matrix (lower triangle): rigid body rows and the modal coupling.
void FreeFlightSystem::addWingMassMatrix(const Frame& fr) {
  const FreeFlightModel& md = *model_;
  Eigen::MatrixXd& A = ws_.A;
  const Vec3& r2 = md.p_P1P2_B_m;
  const double m_w = md.wing_mass_kg;
  const Vec3 c_B = last_.R_BW * last_.c_W;
  const Vec3 f1 = m_w * r2 + c_B;  // first moment of one wing about P1 (B)
  const double J_P1_yy = fr.eyW.dot(last_.J_W * fr.eyW) +
                         m_w * (r2.x() * r2.x() + r2.z() * r2.z()) +
                         2.0 * (r2.x() * c_B.x() + r2.z() * c_B.z());
  A(0, 0) += 2.0 * m_w;
  A(1, 1) += 2.0 * m_w;
  A(2, 2) += 2.0 * J_P1_yy;
  A(2, 0) += 2.0 * f1.z();
  A(2, 1) += -2.0 * f1.x();
  const int m = mode_count_;
  if (m == 0) return;
  auto Aqb = A.block(3, 0, m, 3);
  Aqb.col(0).noalias() += 2.0 * (md.L.transpose() * fr.exW);
  Aqb.col(1).noalias() += 2.0 * (md.L.transpose() * fr.ezW);
  Aqb.col(2).noalias() += 2.0 * (md.L.transpose() * fr.dQlin + md.H.transpose() * fr.eyW);
  A.bottomRightCorner(m, m) += 2.0 * md.modal_mass;
}

// Modal rows (docs/theory.md 4.3): -L^T (a_O - g) - H^T alpha - h_w(w) - 2 C(w) q'
// - [K_w(w) + K_G(p) + C(alpha)] q - D q' - K q, at u' = 0. The geometric stiffness K_G (4.6) of
// the loads at u' = 0 here; its share of the body accelerations after the solve.
void FreeFlightSystem::addModalRows() {
  const int m = mode_count_;
  if (m == 0) return;
  const FreeFlightModel& md = *model_;
  FreeFlightWorkspace& ws = ws_;
  const Vec3& w = last_.omega_W;
  const Vec3& al = last_.alpha0_W;
  Eigen::VectorXd& r = ws.scratch_modes;
  r.noalias() = -(md.L.transpose() * (last_.a_O0_W - last_.g_W));
  r.noalias() -= md.H.transpose() * al;
  // [K_w + K_G](w) q = sum_kl w_k w_l spin_kl q (spin_kl = P_kl - delta_kl sum_j P_jj +
  // K^_G,kl, structure/inertial_stiffness.hpp);
  // h_w = sum_kl w_k w_l S_kl - |w|^2 sum S_kk.
  ws.Pq_all.noalias() = md.Pstack * ws.q;
  ws.Cq_all.noalias() = md.Cstack * ws.q;
  ws.Cqd_all.noalias() = md.Cstack * ws.qd;
  for (int k = 0; k < 3; ++k)
    for (int l = 0; l < 3; ++l) {
      const double wkl = w[k] * w[l];
      const int idx = 3 * k + l;
      r -= wkl * ws.Pq_all.segment(idx * m, m);
      r -= wkl * md.S[static_cast<std::size_t>(idx)];
    }
  r += w.squaredNorm() * md.S_trace;
  if (md.Gstack.rows() > 0) {
    ws.Gq_all.noalias() = md.Gstack * ws.q;
    const Vec3 a_minus_g = last_.a_O0_W - last_.g_W;
    for (std::size_t j = 0; j < md.linear_loads.size(); ++j)
      r -= structure::linearLoadValue(md.linear_loads[j], a_minus_g, al) *
           ws.Gq_all.segment(static_cast<Eigen::Index>(j) * m, m);
  }
  for (int k = 0; k < 3; ++k) {
    r -= (2.0 * w[k]) * ws.Cqd_all.segment(k * m, m);
    r -= al[k] * ws.Cq_all.segment(k * m, m);
  }
  r.noalias() -= md.modal_stiffness.cwiseProduct(ws.q);
  if (md.flex != nullptr && md.flex->nonlinear())  // membrane stretching (docs/theory.md 4.7)
    md.flex->membrane().addForce(ws.q, ws.qd, switches_.damping ? md.flex->membrane_damping_s : 0.0,
                                 &ws.membrane_ws, &r, -1.0);
  if (switches_.damping) r.noalias() -= md.modal_damping.cwiseProduct(ws.qd);
  ws.f.tail(m).noalias() += 2.0 * r;
}

// Fuselage (paper Eq. 1) with its CG at r_f: m_f (g - a_f at u' = 0), and its moment about P1.
void FreeFlightSystem::addFuselage(const Frame& fr) {
  const FreeFlightModel& md = *model_;
  FreeFlightWorkspace& w = ws_;
  const double U = fr.U, W = fr.W, Q = fr.Q;
  const double m_f = md.fuselage_mass_kg;
  const Vec3& rf = md.fuselage_cg_B_m;
  const Vec3 F_f = m_f * (fr.g_B - Vec3(Q * W, 0.0, -Q * U) + Q * Q * Vec3(rf.x(), 0.0, rf.z()));
  w.f[0] += F_f.x();
  w.f[1] += F_f.z();
  w.f[2] += rf.z() * F_f.x() - rf.x() * F_f.z();
  w.A(0, 0) += m_f;
  w.A(1, 1) += m_f;
  w.A(2, 2) += md.fuselage_pitch_inertia_kgm2;
  w.A(2, 0) += m_f * rf.z();
  w.A(2, 1) += -m_f * rf.x();
}

// Tail (paper Eq. 3 with the incidence of docs/theory.md 7) and fuselage drag, B components.
void FreeFlightSystem::addTailAndBodyDrag(const Frame& fr) {
  BodyMotion bm;
  bm.v_P1_B = Vec3(fr.U, 0.0, fr.W);
  bm.theta_rad = fr.theta;
  bm.Q_radps = fr.Q;
  LoadSample& tail = last_.tail;
  addTailAndTotals(model_->core, bm, control_, &tail);
  const FlightPathFrame path = flightPathFrame(bm.v_P1_B);
  const Vec3 F_tail =
      (tail.FH_tail_N + tail.FH_body_N) * path.e_v_B + tail.FV_tail_N * path.e_L_B;
  ws_.f[0] += F_tail.x();
  ws_.f[1] += F_tail.z();
  ws_.f[2] += tail.M_tail_Nm;
}

// u' from the SPD mass matrix (lower triangle), then one fixed-point step for the body
// accelerations' share of the K_G loads: -K_G(dp(u')) q with dp linear in u' would make the
// system bilinear; the step with the u' just solved leaves an error of order (A^-1 K_G q)^2:
// da = R^T (U' e_x + W' e_z + Q' e_y x r2), dalpha = Q' R^T e_y.
void FreeFlightSystem::solveAccelerations(const Frame& fr) {
  const FreeFlightModel& md = *model_;
  FreeFlightWorkspace& w = ws_;
  w.ud = w.f;
  if (!w.chol.factor(w.A)) {
    // Not positive definite: a non-finite derivative makes the integrator retry smaller.
    w.ud.setConstant(std::numeric_limits<double>::quiet_NaN());
    return;
  }
  w.chol.solveInPlace(w.ud);
  if (md.Gstack.rows() == 0) return;
  const int m = mode_count_;
  const Vec3 da = w.ud[0] * fr.exW + w.ud[1] * fr.ezW + w.ud[2] * fr.dQlin;
  const Vec3 dal = w.ud[2] * fr.eyW;
  w.correction.head<3>().setZero();
  auto modal = w.correction.tail(m);
  modal.setZero();
  for (std::size_t j = 0; j < md.linear_loads.size(); ++j)
    modal -= (2.0 * structure::linearLoadValue(md.linear_loads[j], da, dal)) *
             w.Gq_all.segment(static_cast<Eigen::Index>(j) * m, m);
  w.chol.solveInPlace(w.correction);
  w.ud += w.correction;
}

void FreeFlightSystem::evaluate(double t_s, const double* y, double* aero_derivatives) {
  const Frame fr = frameAt(t_s, y);
  ws_.f.setZero();
  ws_.A.setZero();
  last_.F_aero_W.setZero();
  last_.M_aero_P2_W.setZero();
  last_.separated_fraction = 0.0;
  if (switches_.aerodynamics)
    addWingAerodynamics(fr, y, aero_derivatives);
  else if (aero_derivatives)
    for (int i = 0; i < n_aero_; ++i) aero_derivatives[i] = 0.0;
  addWingInertiaAndGravity(fr);
  addWingMassMatrix(fr);
  addModalRows();
  addFuselage(fr);
  last_.tail = LoadSample{};
  if (switches_.tail) addTailAndBodyDrag(fr);
  solveAccelerations(fr);
}

void FreeFlightSystem::updateSplit(double t_s, const double* y) {
  if (!split_ || model_->flex == nullptr || !model_->flex->nonlinear()) return;
  evaluate(t_s, y, nullptr);
  // Both wings' mass matrix (lower triangle) [A_bb A_qb^T; A_qb A_qq]: the modal accelerations
  // answer modal forces through (A_qq - A_qb A_bb^-1 A_qb^T)^-1; one wing's share is half of it.
  const int m = mode_count_;
  const Eigen::MatrixXd& A = ws_.A;
  const Mat3 Abb = A.topLeftCorner<3, 3>().selfadjointView<Eigen::Lower>();
  coupling_.noalias() = A.block(3, 0, m, 3) * Abb.inverse();
  modal_mass_ = A.bottomRightCorner(m, m).selfadjointView<Eigen::Lower>();
  modal_mass_.noalias() -= coupling_ * A.block(3, 0, m, 3).transpose();
  modal_mass_ *= 0.5;
  split_->update(y, &modal_mass_);
}

void FreeFlightSystem::apparentAccelerations() {
  // Normal mid-chord and pitch accelerations of u' per strip; force -b nu.u', couple -k nut.u'.
  FreeFlightWorkspace& w = ws_;
  w.extra_force = w.nuU * w.ud[0] + w.nuW * w.ud[1] + w.nuQ * w.ud[2];
  w.extra_couple = w.nutQ * w.ud[2];
  if (mode_count_ > 0) {
    const StackedStrips& st = model_->flex->stacked;
    w.twist_mid_ud.noalias() = st.apparentShapes() * w.ud.tail(mode_count_);
    w.extra_force += w.twist_mid_ud.tail(st.ns);
    w.extra_couple += w.twist_mid_ud.head(st.ns);
  }
  w.extra_force = -w.b_strip.cwiseProduct(w.extra_force);
  w.extra_couple = -w.k_twist.cwiseProduct(w.extra_couple);
}

void FreeFlightSystem::rhs(double t_s, const double* y, double* ydot) {
  evaluate(t_s, y, ydot + aeroOffset());
  const double theta = y[2], U = y[3], W = y[4], Q = y[5];
  const double st = std::sin(theta), ct = std::cos(theta);
  const Eigen::VectorXd& ud = ws_.ud;
  ydot[0] = U * ct + W * st;   // paper Eq. (1): x_I'
  ydot[1] = U * st - W * ct;   // h' = -z_I'
  ydot[2] = Q;
  ydot[3] = ud[0];
  ydot[4] = ud[1];
  ydot[5] = ud[2];
  const int m = mode_count_;
  for (int i = 0; i < m; ++i) {
    ydot[kBody + i] = y[kBody + m + i];
    ydot[kBody + m + i] = ud[3 + i];
  }
  // Aerodynamic power of both wings relative to the fuselage (kernel loads plus the apparent-mass
  // force and couple of u', which the kernel could not know).
  double power = 0.0;
  if (switches_.aerodynamics) {
    apparentAccelerations();
    const FlapState flap =
        flapStateAt(model_->core.vehicle.flapping.amplitude_rad, control_.freq_hz, t_s);
    power = ws_.kin.power(ws_.data.batch, ws_.extra_force, ws_.extra_couple,
                          flap.phi_dot_radps * Vec3::UnitX());
  }
  ydot[powerOffset()] = 2.0 * power;
}

void FreeFlightSystem::sample(double t_s, const double* y, FreeFlightSample* out,
                              bool with_energy, const double* ydot) {
  evaluate(t_s, y, nullptr);
  if (ydot != nullptr && mode_count_ > 0) {  // u' from the dense output (rhs()'s rows of ud)
    ws_.ud[0] = ydot[3];
    ws_.ud[1] = ydot[4];
    ws_.ud[2] = ydot[5];
    for (int i = 0; i < mode_count_; ++i) ws_.ud[3 + i] = ydot[kBody + mode_count_ + i];
  }
  const FreeFlightModel& md = *model_;
  FreeFlightSample& s = *out;
  s = FreeFlightSample{};
  s.Udot_mps2 = ws_.ud[0];
  s.Wdot_mps2 = ws_.ud[1];
  s.Qdot_radps2 = ws_.ud[2];
  const double theta = y[2], U = y[3], W = y[4], Q = y[5];
  // Aerodynamic loads of both wings about P1 in the flight-path frame, with the apparent-mass
  // force of the solved u' at each strip's mid-chord.
  // Their power into the air is the right-hand side's (the power quadrature's integrand).
  Vec3 F = last_.F_aero_W, M = last_.M_aero_P2_W;
  double power_one_wing_W = 0.0;
  if (switches_.aerodynamics) {
    apparentAccelerations();
    const FlapState flap =
        flapStateAt(md.core.vehicle.flapping.amplitude_rad, control_.freq_hz, t_s);
    ws_.kin.resultant(ws_.data.batch, ws_.extra_force, ws_.extra_couple,
                      flap.phi_dot_radps * Vec3::UnitX(), &F, &M, &power_one_wing_W);
  }
  const Vec3 F_B = last_.R_BW * F;
  const Vec3 M_P1_B = last_.R_BW * M + md.p_P1P2_B_m.cross(F_B);
  const FlightPathFrame path = flightPathFrame(Vec3(U, 0.0, W));
  LoadSample& o = s.loads;
  o = last_.tail;
  o.FV_wing_aero_N = 2.0 * F_B.dot(path.e_L_B);
  o.FH_wing_aero_N = 2.0 * F_B.dot(path.e_v_B);
  o.M_wing_aero_Nm = 2.0 * M_P1_B.y();
  o.separated_fraction = last_.separated_fraction;
  o.power_aero_W = 2.0 * power_one_wing_W;
  o.FV_N = o.FV_wing_aero_N + o.FV_tail_N;
  o.FH_N = o.FH_wing_aero_N + o.FH_tail_N + o.FH_body_N;
  o.M_Nm = o.M_wing_aero_Nm + o.M_tail_Nm;
  const int m = mode_count_;
  if (m > 0) {
    const FlexibleStrip& tip = md.strips.back();
    o.tip_deflection_m = -(tip.phi_L * ws_.q).z();  // z_W is down
    o.tip_twist_rad = tip.psi_twist.dot(ws_.q);
  }

  if (!with_energy) return;
  // Energies (exact for the rigid wing without flapping; see the header).
  Eigen::VectorXd u(ws_.n_u);
  u[0] = U;
  u[1] = W;
  u[2] = Q;
  if (m > 0) u.tail(m) = ws_.qd;
  // Kinetic energy from the structural mass matrix (apparent air mass excluded): rebuild it
  // without the air by evaluating with the aerodynamics switched off.
  const Switches saved = switches_;
  switches_.aerodynamics = false;
  evaluate(t_s, y, nullptr);
  switches_ = saved;
  s.kinetic_energy_J = 0.5 * u.dot(ws_.A.selfadjointView<Eigen::Lower>() * u);
  const double g = md.core.vehicle.air.gravity_mps2;
  const Vec3 f1 = md.wing_mass_kg * md.p_P1P2_B_m + last_.R_BW * last_.c_W;
  const double wing_height = std::sin(theta) * f1.x() - std::cos(theta) * f1.z();
  double strain = 0.0;
  if (m > 0) strain = ws_.q.dot(md.modal_stiffness.cwiseProduct(ws_.q));  // 2 x 1/2 q^T K q
  if (md.flex != nullptr && md.flex->nonlinear())  // 2 wings x V_NL (docs/theory.md 4.7)
    strain += 2.0 * md.flex->membrane().energy(ws_.q, &ws_.membrane_ws);
  const Vec3& rf = md.fuselage_cg_B_m;
  const double fuselage_height = std::sin(theta) * rf.x() - std::cos(theta) * rf.z();
  s.potential_energy_J = g * (md.core.vehicle.body.mass_kg * y[1] +
                              md.fuselage_mass_kg * fuselage_height + 2.0 * wing_height) +
                         strain;
}

}  // namespace orni
