#include "core/dynamics/free_flight_system.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "core/aero/mst_strip.hpp"
#include "core/dynamics/flapping.hpp"
#include "core/model/invalid_model_error.hpp"

namespace orni {

namespace {

// Rigid wing as strips with zero modes: leading edge on the hinge line (the rigid core's
// kinematic reference, flight_core.cpp), three-quarter-chord point along -e_c (incidence applied).
std::vector<FlexibleStrip> rigidStrips(const FlightCoreModel& model) {
  std::vector<FlexibleStrip> out(model.strips.size());
  for (std::size_t j = 0; j < model.strips.size(); ++j) {
    FlexibleStrip& s = out[j];
    const double c = model.strip_geometry[j].chord_m;
    s.x_L_W_m = Vec3(0.0, model.strips[j].y_center_m, 0.0);
    s.x_T_W_m = s.x_L_W_m - 0.75 * c * model.e_c_W;
    s.lever_T_m = 0.75 * c;
    s.phi_L.resize(3, 0);
    s.phi_T.resize(3, 0);
    s.psi_twist.resize(0);
    s.psi_mid.resize(0);
  }
  return out;
}

}  // namespace

FreeFlightSystem::FreeFlightSystem(const FlightCoreModel& model, const FlexibleWingModel* flex,
                                   const ControlInput& control, double reference_speed_mps)
    : model_(model),
      flex_(flex),
      control_(control),
      mode_count_(flex ? flex->mode_count : 0),
      reference_speed_mps_(reference_speed_mps),
      n_aero_(model.aeroStateCount()),
      data_(model),
      strips_(flex ? flex->strips : rigidStrips(model)),
      rigid_stacked_(flex ? StackedStrips{}
                          : stackStrips(strips_, 0, Eigen::VectorXd(), Eigen::VectorXd())),
      kin_(flex ? flex->stacked : rigid_stacked_, mode_count_),
      chol_(3 + mode_count_) {
  if (!(reference_speed_mps > 0.0) || !std::isfinite(reference_speed_mps))
    throw std::invalid_argument("free flight: the reference speed must be > 0 m/s");
  if (!aero::batchKernelApplies(model.vehicle.aero))
    throw InvalidModelError(
        "free flight needs aero model mst-td with the Scherer lag and a smooth stall "
        "(stall_width_deg > 0)");
  const std::size_t ns = model.strips.size();
  if (flex) {
    apparent_mass_kg_ = flex->apparent_mass_kg;
    const structure::InertiaInvariants& inv = flex->modal->invariants;
    m_w_ = inv.mass_kg;
    c0_ = inv.first_moment_W_kgm;
    J0_ = inv.inertia_P2_W_kgm2;
    L_ = inv.translational_participation;
    H_ = inv.rotational_participation;
    for (int k = 0; k < 9; ++k) S_[static_cast<std::size_t>(k)] = inv.s[static_cast<std::size_t>(k)];
    M_qq_ = inv.generalized_mass;
    stiffness_ = flex->stiffness;
    damping_ = flex->damping;
    // structure.md 3.3: C_1 = P_32 - P_23, C_2 = P_13 - P_31, C_3 = P_21 - P_12 (1-based).
    C_[0] = inv.P(2, 1) - inv.P(1, 2);
    C_[1] = inv.P(0, 2) - inv.P(2, 0);
    C_[2] = inv.P(1, 0) - inv.P(0, 1);
    S_trace_ = inv.S(0, 0) + inv.S(1, 1) + inv.S(2, 2);
  } else {
    apparent_mass_kg_.resize(static_cast<Eigen::Index>(ns));
    for (std::size_t j = 0; j < ns; ++j) {
      const double c = model.strip_geometry[j].chord_m;
      apparent_mass_kg_[static_cast<Eigen::Index>(j)] =
          aero::apparentMassPerSpan_kgpm(model.vehicle.air.density_kgpm3, c) *
          model.strip_geometry[j].width_m;
    }
    const RigidBodyInertia& wi = model.wing_mass.total;
    m_w_ = wi.mass_kg;
    c0_ = wi.first_moment_W_kgm;
    J0_ = wi.inertia_P2_W_kgm2;
    L_.resize(3, 0);
    H_.resize(3, 0);
    M_qq_.resize(0, 0);
    stiffness_.resize(0);
    damping_.resize(0);
    S_trace_.resize(0);
  }
  r2_B_ = model.p_P1P2_B;
  // Fuselage only (structure.md 3.2): the vehicle minus both wings at zero flap angle.
  const double wing_pitch_inertia_P1 =
      J0_(1, 1) + m_w_ * (r2_B_.x() * r2_B_.x() + r2_B_.z() * r2_B_.z()) +
      2.0 * (r2_B_.x() * c0_.x() + r2_B_.z() * c0_.z());
  m_f_ = model.vehicle.body.mass_kg - 2.0 * m_w_;
  I_f_ = model.vehicle.body.pitch_inertia_kgm2 - 2.0 * wing_pitch_inertia_P1;
  if (!(m_f_ > 0.0))
    throw InvalidModelError("free flight: body.mass_kg (" +
                                std::to_string(model.vehicle.body.mass_kg) +
                                " kg) must exceed the mass of both wings (" +
                                std::to_string(2.0 * m_w_) + " kg)");
  // The paper's P1 is the centre of gravity: put the fuselage's own CG where the whole vehicle's
  // CG lands on P1 with the wings at zero flap angle and undeformed.
  r_f_B_ = m_f_ > 0.0 ? Vec3(-2.0 * (m_w_ * r2_B_ + c0_) / m_f_) : Vec3::Zero();
  r_f_B_.y() = 0.0;
  if (!(I_f_ > 0.0))
    throw InvalidModelError(
        "free flight: body.pitch_inertia_kgm2 (" +
        std::to_string(model.vehicle.body.pitch_inertia_kgm2) +
        " kg m^2) must exceed the pitch inertia of both wings about P1 (" +
        std::to_string(2.0 * wing_pitch_inertia_P1) + " kg m^2)");

  n_u_ = 3 + mode_count_;
  q_.setZero(mode_count_);
  qd_.setZero(mode_count_);
  ud_.setZero(n_u_);
  f_.setZero(n_u_);
  scratch_modes_.setZero(mode_count_);
  // Stacked invariants: one product per evaluation instead of one per matrix. Pstack_ holds the
  // stiffness of the inertial loads per w_k w_l, softening and stiffening (structure.md 3.3, 3.7),
  // Gstack_ the geometric stiffness of the acceleration loads that stress the wing.
  Pstack_.setZero(9 * mode_count_, mode_count_);
  Cstack_.setZero(3 * mode_count_, mode_count_);
  Smat_.setZero(9, mode_count_);
  if (mode_count_ > 0) {
    for (int k = 0; k < 9; ++k) {
      Pstack_.middleRows(k * mode_count_, mode_count_) =
          flex->inertial_stiffness.spin[static_cast<std::size_t>(k)];
      Smat_.row(k) = S_[static_cast<std::size_t>(k)].transpose();
    }
    for (int k = 0; k < 3; ++k) Cstack_.middleRows(k * mode_count_, mode_count_) = C_[k];
    linear_loads_ = flex->inertial_stiffness.linear_loads;
    Gstack_ = flex->inertial_stiffness.linear_stack;
  }
  Gq_all_.setZero(Gstack_.rows());
  correction_.setZero(n_u_);
  Pq_all_.setZero(9 * mode_count_);
  Cq_all_.setZero(3 * mode_count_);
  Cqd_all_.setZero(3 * mode_count_);
  A_.setZero(n_u_, n_u_);
  const auto nsi = static_cast<Eigen::Index>(ns);
  b_strip_.setZero(nsi);
  k_twist_.setZero(nsi);
  nuU_.setZero(nsi);
  nuW_.setZero(nsi);
  nuQ_.setZero(nsi);
  nutQ_.setZero(nsi);
  extra_force_.setZero(nsi);
  extra_couple_.setZero(nsi);
  zero_ns_.setZero(nsi);
  tmp_ns_.setZero(nsi);
  twist_mid_ud_.setZero(2 * nsi);
  packed_.setZero(static_cast<Eigen::Index>(mode_count_) * (mode_count_ + 1) / 2);
  data_.batch.airx.setZero();
  data_.batch.airy.setZero();
  data_.batch.airz.setZero();
  if (flex) split_ = std::make_unique<ModalImplicitSplit>(*flex, kBody, stateCount());
  setFrictionSpeed(reference_speed_mps_);
}

void FreeFlightSystem::setFrictionSpeed(double speed_mps) {
  // M11 skin friction depends on the Reynolds number; it is frozen at the initial speed (the
  // speed varies by a few per cent in flight; Cd_f ~ Re^-0.2 moves by a fraction of that).
  for (std::size_t j = 0; j < model_.strips.size(); ++j)
    data_.batch.friction_coefficient[static_cast<Eigen::Index>(j)] = aero::frictionCoefficient(
        speed_mps * model_.strip_geometry[j].chord_m / model_.vehicle.air.kinematic_viscosity_m2ps);
  aero::prepareStripBatch(model_.aero_context, data_.batch);
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
  initialAeroStates(model_, bm, control_, t_s, y + aeroOffset());
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
  const int per = model_.aero_states_per_strip;
  for (int i = aeroOffset() + per - 1; i < powerOffset(); i += per)
    (*atol)[static_cast<std::size_t>(i)] = separation_abs_tol;
  const auto scales = quadratureScales(model_, reference_speed_mps_);
  (*atol)[static_cast<std::size_t>(powerOffset())] = 0.1 * rel_tol * scales[3] / control_.freq_hz;
}

void FreeFlightSystem::evaluate(double t_s, const double* y, double* aero_derivatives) {
  const double theta = y[2], U = y[3], W = y[4], Q = y[5];
  q_ = Eigen::Map<const Eigen::VectorXd>(y + kBody, mode_count_);
  qd_ = Eigen::Map<const Eigen::VectorXd>(y + kBody + mode_count_, mode_count_);
  const FlapState flap = flapStateAt(model_.vehicle.flapping.amplitude_rad, control_.freq_hz, t_s);
  R_BW_ = rotX(flap.phi_rad);
  const Mat3 Rt = R_BW_.transpose();
  const Vec3 ex = Vec3::UnitX();
  const Vec3 exW = Rt.col(0), eyW = Rt.col(1), ezW = Rt.col(2);  // R^T e_x, R^T e_y, R^T e_z
  omega_W_ = Q * eyW + flap.phi_dot_radps * ex;
  alpha0_W_ = flap.phi_ddot_radps2 * ex + (Q * eyW).cross(flap.phi_dot_radps * ex);
  const Vec3& r2 = r2_B_;
  const Vec3 ey_x_r2(r2.z(), 0.0, -r2.x());  // e_y x r2
  const Vec3 v_P2_B = Vec3(U, 0.0, W) + Q * ey_x_r2;
  // Acceleration of P2 at u' = 0: a_P1 = (Q W, 0, -Q U) plus the centripetal Q^2 term.
  const Vec3 a_P2_0_B = Vec3(Q * W, 0.0, -Q * U) - Q * Q * Vec3(r2.x(), 0.0, r2.z());
  const double g = model_.vehicle.air.gravity_mps2;
  const Vec3 g_B(-g * std::sin(theta), 0.0, g * std::cos(theta));
  const Vec3 v_O = Rt * v_P2_B;
  a_O0_W_ = Rt * a_P2_0_B;
  g_W_ = Rt * g_B;
  const Vec3 dQlin = Rt * ey_x_r2;  // partial velocity of P2 for Q (W components)

  f_.setZero();
  A_.setZero();
  aero::StripBatch& b = data_.batch;
  F_aero_W_.setZero();
  M_aero_P2_W_.setZero();
  power_aero_one_wing_W_ = 0.0;
  separated_fraction_ = 0.0;
  if (switches_.aerodynamics) {
    // Strip kinematics from rigid plus modal motion (structure.md 4.2) at u' = 0.
    WingFrameMotion fm;
    fm.v_O_W = v_O;
    fm.a_O0_W = a_O0_W_;
    fm.omega_W = omega_W_;
    fm.alpha0_W = alpha0_W_;
    fm.omega_rel_W = flap.phi_dot_radps * ex;
    kin_.compute(q_, qd_, fm, b);
    aero::evalMstTdBatch(model_.aero_context, b, y + aeroOffset(), aero_derivatives);

    // Generalised aerodynamic forces (structure.md 4.3) and the apparent air mass along each
    // strip's mid-chord normal acceleration (4.4), A += b_j nu_j nu_j^T, b_j = 0.5 (1 + f) m_a,
    // with the body partials nu = (n.e_x, n.e_z, n.(e_y x rho_mid)) and the modal ones psi_mid;
    // plus the apparent rotary inertia of the kernel's couple -f k theta'' (M17) about e_s, with
    // theta'' partials (0, 0, e_y.e_s, psi_twist).
    kin_.resultant(b, zero_ns_, zero_ns_, fm.omega_rel_W, &F_aero_W_, &M_aero_P2_W_, nullptr);
    b_strip_ = (0.5 * (1.0 + b.separation_f) * apparent_mass_kg_.array()).matrix();
    k_twist_ = (b.separation_f * b.k_couple2).matrix();
    const Vec3 rQ = dQlin;  // n.(dQlin + eyW x mid)
    nuU_ = (b.nx * exW.x() + b.ny * exW.y() + b.nz * exW.z()).matrix();
    nuW_ = (b.nx * ezW.x() + b.ny * ezW.y() + b.nz * ezW.z()).matrix();
    nuQ_ = (b.nx * (rQ.x() + eyW.y() * kin_.midz() - eyW.z() * kin_.midy()) +
            b.ny * (rQ.y() + eyW.z() * kin_.midx() - eyW.x() * kin_.midz()) +
            b.nz * (rQ.z() + eyW.x() * kin_.midy() - eyW.y() * kin_.midx()))
               .matrix();
    nutQ_ = (kin_.esx() * eyW.x() + kin_.esy() * eyW.y() + kin_.esz() * eyW.z()).matrix();
    const Eigen::VectorXd* nus[3] = {&nuU_, &nuW_, &nuQ_};
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c <= r; ++c)
        A_(r, c) += 2.0 * (b_strip_.array() * nus[r]->array() * nus[c]->array()).sum();
    A_(2, 2) += 2.0 * (k_twist_.array() * nutQ_.array().square()).sum();
    if (mode_count_ > 0) {
      const StackedStrips& st = flex_->stacked;
      kin_.modalForce(b, &scratch_modes_);
      f_.tail(mode_count_) += 2.0 * scratch_modes_;
      auto Aqb = A_.block(3, 0, mode_count_, 3);
      for (int c = 0; c < 3; ++c) {
        tmp_ns_ = b_strip_.cwiseProduct(*nus[c]);
        Aqb.col(c).noalias() += 2.0 * (st.psi_mid().transpose() * tmp_ns_);
      }
      tmp_ns_ = k_twist_.cwiseProduct(nutQ_);
      Aqb.col(2).noalias() += 2.0 * (st.psi_twist().transpose() * tmp_ns_);
      addApparentModalMass(st, b.separation_f, 2.0, &packed_,
                           A_.bottomRightCorner(mode_count_, mode_count_));
    }
    separated_fraction_ = ((1.0 - b.separation_f) * b.chord_m * b.width_m).sum() /
                          (b.chord_m * b.width_m).sum();
    f_[0] += 2.0 * exW.dot(F_aero_W_);
    f_[1] += 2.0 * ezW.dot(F_aero_W_);
    f_[2] += 2.0 * (dQlin.dot(F_aero_W_) + eyW.dot(M_aero_P2_W_));
  } else if (aero_derivatives) {
    for (int i = 0; i < n_aero_; ++i) aero_derivatives[i] = 0.0;
  }

  // Wing inertia from the invariants (structure.md 3.3-3.5), one wing, W components.
  c_W_ = c0_;
  J_W_ = J0_;
  Vec3 Lqd = Vec3::Zero(), Mcor = Vec3::Zero();
  if (mode_count_ > 0) {
    c_W_.noalias() += L_ * q_;
    Lqd.noalias() = L_ * qd_;
    Sq_.noalias() = Smat_ * q_;
    Sqd_.noalias() = Smat_ * qd_;
    Mat3 T;  // T_kl = S_kl . q: the first moment of the deformation, J(q) linear part
    for (int k = 0; k < 3; ++k)
      for (int l = 0; l < 3; ++l) T(k, l) = Sq_[3 * k + l];
    J_W_ += 2.0 * T.trace() * Mat3::Identity() - T - T.transpose();
    // Coriolis moment 2 sum m s x (w x Phi q') = 2 [w (sum_k S_kk.q') - sum_l w_l (S_kl.q')_k].
    Mat3 Td;
    for (int k = 0; k < 3; ++k)
      for (int l = 0; l < 3; ++l) Td(k, l) = Sqd_[3 * k + l];
    Mcor = 2.0 * (omega_W_ * Td.trace() - Td * omega_W_);
  }
  const Vec3 F_acc0 = m_w_ * a_O0_W_ + alpha0_W_.cross(c_W_) +
                      omega_W_.cross(omega_W_.cross(c_W_)) + 2.0 * omega_W_.cross(Lqd);
  const Vec3 M_acc0 = c_W_.cross(a_O0_W_) + J_W_ * alpha0_W_ + omega_W_.cross(J_W_ * omega_W_) +
                      Mcor;
  const Vec3 F_in = m_w_ * g_W_ - F_acc0;         // gravity minus inertia at u' = 0, about P2
  const Vec3 M_in = c_W_.cross(g_W_) - M_acc0;
  f_[0] += 2.0 * exW.dot(F_in);
  f_[1] += 2.0 * ezW.dot(F_in);
  f_[2] += 2.0 * (dQlin.dot(F_in) + eyW.dot(M_in));

  // Mass matrix: fuselage + both wings (symmetric; lower triangle filled, then mirrored).
  const Vec3 c_B = R_BW_ * c_W_;
  const Vec3 f1 = m_w_ * r2 + c_B;  // first moment of one wing about P1 (B)
  const double J_P1_yy = eyW.dot(J_W_ * eyW) + m_w_ * (r2.x() * r2.x() + r2.z() * r2.z()) +
                         2.0 * (r2.x() * c_B.x() + r2.z() * c_B.z());
  A_(0, 0) += 2.0 * m_w_;
  A_(1, 1) += 2.0 * m_w_;
  A_(2, 2) += 2.0 * J_P1_yy;
  A_(2, 0) += 2.0 * f1.z();
  A_(2, 1) += -2.0 * f1.x();

  if (mode_count_ > 0) {
    auto Aqb = A_.block(3, 0, mode_count_, 3);
    Aqb.col(0).noalias() += 2.0 * (L_.transpose() * exW);
    Aqb.col(1).noalias() += 2.0 * (L_.transpose() * ezW);
    Aqb.col(2).noalias() += 2.0 * (L_.transpose() * dQlin + H_.transpose() * eyW);
    A_.bottomRightCorner(mode_count_, mode_count_) += 2.0 * M_qq_;

    // Modal rows (structure.md 3.4): -L^T (a_O - g) - H^T alpha - h_w(w) - 2 C(w) q'
    // - [K_w(w) + K_G(p) + C(alpha)] q - D q' - K q, at u' = 0. The geometric stiffness K_G
    // (3.7) of the loads at u' = 0 here; its share of the body accelerations after the solve.
    const Vec3& w = omega_W_;
    const Vec3& al = alpha0_W_;
    Eigen::VectorXd& r = scratch_modes_;
    r.noalias() = -(L_.transpose() * (a_O0_W_ - g_W_));
    r.noalias() -= H_.transpose() * al;
    // [K_w + K_G](w) q = sum_kl w_k w_l spin_kl q (spin_kl = P_kl - delta_kl sum_j P_jj +
    // K^_G,kl, structure/inertial_stiffness.hpp);
    // h_w = sum_kl w_k w_l S_kl - |w|^2 sum S_kk.
    Pq_all_.noalias() = Pstack_ * q_;
    Cq_all_.noalias() = Cstack_ * q_;
    Cqd_all_.noalias() = Cstack_ * qd_;
    for (int k = 0; k < 3; ++k)
      for (int l = 0; l < 3; ++l) {
        const double wkl = w[k] * w[l];
        const int idx = 3 * k + l;
        r -= wkl * Pq_all_.segment(idx * mode_count_, mode_count_);
        r -= wkl * S_[static_cast<std::size_t>(idx)];
      }
    r += w.squaredNorm() * S_trace_;
    if (Gstack_.rows() > 0) {
      Gq_all_.noalias() = Gstack_ * q_;
      const Vec3 a_minus_g = a_O0_W_ - g_W_;
      for (std::size_t j = 0; j < linear_loads_.size(); ++j)
        r -= structure::linearLoadValue(linear_loads_[j], a_minus_g, al) *
             Gq_all_.segment(static_cast<Eigen::Index>(j) * mode_count_, mode_count_);
    }
    for (int k = 0; k < 3; ++k) {
      r -= (2.0 * w[k]) * Cqd_all_.segment(k * mode_count_, mode_count_);
      r -= al[k] * Cq_all_.segment(k * mode_count_, mode_count_);
    }
    r.noalias() -= stiffness_.cwiseProduct(q_);
    if (switches_.damping) r.noalias() -= damping_.cwiseProduct(qd_);
    f_.tail(mode_count_).noalias() += 2.0 * r;
  }

  // Fuselage (paper Eq. 1) with its CG at r_f: m_f (g - a_f at u' = 0), and its moment about P1.
  const Vec3& rf = r_f_B_;
  const Vec3 F_f = m_f_ * (g_B - Vec3(Q * W, 0.0, -Q * U) + Q * Q * Vec3(rf.x(), 0.0, rf.z()));
  f_[0] += F_f.x();
  f_[1] += F_f.z();
  f_[2] += rf.z() * F_f.x() - rf.x() * F_f.z();
  A_(0, 0) += m_f_;
  A_(1, 1) += m_f_;
  A_(2, 2) += I_f_;
  A_(2, 0) += m_f_ * rf.z();
  A_(2, 1) += -m_f_ * rf.x();

  // Tail (paper Eq. 3 with the incidence of aero-mst.md 10), B components.
  tail_ = LoadSample{};
  if (switches_.tail) {  // tail and fuselage drag
    BodyMotion bm;
    bm.v_P1_B = Vec3(U, 0.0, W);
    bm.theta_rad = theta;
    bm.Q_radps = Q;
    addTailAndTotals(model_, bm, control_, &tail_);
    // The flight-path frame written out, not flightPathFrame(): with the shared helper GCC fuses
    // these multiply-adds differently (-ffp-contract=fast, the C++ default) and the free-flight
    // outputs move at 1e-12; kept until the outputs may change (issue 15 note).
    const double speed = bm.v_P1_B.norm();
    const Vec3 e_v = speed > 0.0 ? Vec3(bm.v_P1_B / speed) : Vec3::UnitX();
    const Vec3 e_L(e_v.z(), 0.0, -e_v.x());
    const Vec3 F_tail = (tail_.FH_tail_N + tail_.FH_body_N) * e_v + tail_.FV_tail_N * e_L;
    f_[0] += F_tail.x();
    f_[1] += F_tail.z();
    f_[2] += tail_.M_tail_Nm;
  }

  ud_ = f_;
  if (!chol_.factor(A_)) {  // SPD mass matrix; reads the lower triangle only
    // Not positive definite: a non-finite derivative makes the integrator retry smaller.
    ud_.setConstant(std::numeric_limits<double>::quiet_NaN());
    return;
  }
  chol_.solveInPlace(ud_);
  if (Gstack_.rows() == 0) return;
  // The body accelerations' share of the K_G loads, -K_G(dp(u')) q with dp linear in u', would
  // make the system bilinear; one fixed-point step with the u' just solved leaves an error of
  // order (A^-1 K_G q)^2: da = R^T (U' e_x + W' e_z + Q' e_y x r2), dalpha = Q' R^T e_y.
  const Vec3 da = ud_[0] * exW + ud_[1] * ezW + ud_[2] * dQlin;
  const Vec3 dal = ud_[2] * eyW;
  correction_.head<3>().setZero();
  auto modal = correction_.tail(mode_count_);
  modal.setZero();
  for (std::size_t j = 0; j < linear_loads_.size(); ++j)
    modal -= (2.0 * structure::linearLoadValue(linear_loads_[j], da, dal)) *
             Gq_all_.segment(static_cast<Eigen::Index>(j) * mode_count_, mode_count_);
  chol_.solveInPlace(correction_);
  ud_ += correction_;
}

void FreeFlightSystem::apparentAccelerations() {
  // Normal mid-chord and pitch accelerations of u' per strip; force -b nu.u', couple -k nut.u'.
  extra_force_ = nuU_ * ud_[0] + nuW_ * ud_[1] + nuQ_ * ud_[2];
  extra_couple_ = nutQ_ * ud_[2];
  if (mode_count_ > 0) {
    const StackedStrips& st = flex_->stacked;
    twist_mid_ud_.noalias() = st.apparentShapes() * ud_.tail(mode_count_);
    extra_force_ += twist_mid_ud_.tail(st.ns);
    extra_couple_ += twist_mid_ud_.head(st.ns);
  }
  extra_force_ = -b_strip_.cwiseProduct(extra_force_);
  extra_couple_ = -k_twist_.cwiseProduct(extra_couple_);
}

void FreeFlightSystem::rhs(double t_s, const double* y, double* ydot) {
  evaluate(t_s, y, ydot + aeroOffset());
  const double theta = y[2], U = y[3], W = y[4], Q = y[5];
  const double st = std::sin(theta), ct = std::cos(theta);
  ydot[0] = U * ct + W * st;   // paper Eq. (1): x_I'
  ydot[1] = U * st - W * ct;   // h' = -z_I'
  ydot[2] = Q;
  ydot[3] = ud_[0];
  ydot[4] = ud_[1];
  ydot[5] = ud_[2];
  for (int i = 0; i < mode_count_; ++i) {
    ydot[kBody + i] = y[kBody + mode_count_ + i];
    ydot[kBody + mode_count_ + i] = ud_[3 + i];
  }
  // Aerodynamic power of both wings relative to the fuselage (kernel loads plus the apparent-mass
  // force and couple of u', which the kernel could not know).
  double power = 0.0;
  if (switches_.aerodynamics) {
    apparentAccelerations();
    const FlapState flap =
        flapStateAt(model_.vehicle.flapping.amplitude_rad, control_.freq_hz, t_s);
    power = kin_.power(data_.batch, extra_force_, extra_couple_,
                       flap.phi_dot_radps * Vec3::UnitX());
  }
  ydot[powerOffset()] = 2.0 * power;
}

void FreeFlightSystem::sample(double t_s, const double* y, FreeFlightSample* out,
                              bool with_energy) {
  evaluate(t_s, y, nullptr);
  FreeFlightSample& s = *out;
  s = FreeFlightSample{};
  s.Udot_mps2 = ud_[0];
  s.Wdot_mps2 = ud_[1];
  s.Qdot_radps2 = ud_[2];
  const double theta = y[2], U = y[3], W = y[4], Q = y[5];
  // Aerodynamic loads of both wings about P1 in the flight-path frame, with the apparent-mass
  // force of the solved u' at each strip's mid-chord.
  Vec3 F = F_aero_W_, M = M_aero_P2_W_;
  if (switches_.aerodynamics) {
    apparentAccelerations();
    const FlapState flap =
        flapStateAt(model_.vehicle.flapping.amplitude_rad, control_.freq_hz, t_s);
    kin_.resultant(data_.batch, extra_force_, extra_couple_,
                   flap.phi_dot_radps * Vec3::UnitX(), &F, &M, nullptr);
  }
  const Vec3 F_B = R_BW_ * F;
  const Vec3 M_P1_B = R_BW_ * M + r2_B_.cross(F_B);
  const Vec3 v(U, 0.0, W);
  const double speed = v.norm();  // written out as above (flightPathFrame would move the bits)
  const Vec3 e_v = speed > 0.0 ? Vec3(v / speed) : Vec3::UnitX();
  const Vec3 e_L(e_v.z(), 0.0, -e_v.x());
  LoadSample& o = s.loads;
  o = tail_;
  o.FV_wing_aero_N = 2.0 * F_B.dot(e_L);
  o.FH_wing_aero_N = 2.0 * F_B.dot(e_v);
  o.M_wing_aero_Nm = 2.0 * M_P1_B.y();
  o.separated_fraction = separated_fraction_;
  o.FV_N = o.FV_wing_aero_N + o.FV_tail_N;
  o.FH_N = o.FH_wing_aero_N + o.FH_tail_N + o.FH_body_N;
  o.M_Nm = o.M_wing_aero_Nm + o.M_tail_Nm;
  if (mode_count_ > 0) {
    const FlexibleStrip& tip = strips_.back();
    o.tip_deflection_m = -(tip.phi_L * q_).z();  // z_W is down
    o.tip_twist_rad = tip.psi_twist.dot(q_);
  }

  if (!with_energy) return;
  // Energies (exact for the rigid wing without flapping; see the header).
  Eigen::VectorXd u(n_u_);
  u[0] = U;
  u[1] = W;
  u[2] = Q;
  if (mode_count_ > 0) u.tail(mode_count_) = qd_;
  // Kinetic energy from the structural mass matrix (apparent air mass excluded): rebuild it
  // without the air by evaluating with the aerodynamics switched off.
  const Switches saved = switches_;
  switches_.aerodynamics = false;
  evaluate(t_s, y, nullptr);
  switches_ = saved;
  s.kinetic_energy_J = 0.5 * u.dot(A_.selfadjointView<Eigen::Lower>() * u);
  const double g = model_.vehicle.air.gravity_mps2;
  const Vec3 f1 = m_w_ * r2_B_ + R_BW_ * c_W_;
  const double wing_height = std::sin(theta) * f1.x() - std::cos(theta) * f1.z();
  double strain = 0.0;
  if (mode_count_ > 0) strain = q_.dot(stiffness_.cwiseProduct(q_));  // 2 wings x 1/2 q^T K q
  const double fuselage_height = std::sin(theta) * r_f_B_.x() - std::cos(theta) * r_f_B_.z();
  s.potential_energy_J = g * (model_.vehicle.body.mass_kg * y[1] + m_f_ * fuselage_height +
                              2.0 * wing_height) +
                         strain;
}

}  // namespace orni
