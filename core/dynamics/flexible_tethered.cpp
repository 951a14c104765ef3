#include "core/dynamics/flexible_tethered.hpp"

#include <cmath>
#include <limits>

#include "core/dynamics/flapping.hpp"
#include "core/dynamics/flight_path_frame.hpp"
#include "core/model/invalid_model_error.hpp"

namespace orni {

FlexibleTetheredSystem::FlexibleTetheredSystem(const FlightCoreModel& model,
                                               const FlexibleWingModel& flex,
                                               const BodyMotion& body,
                                               const ControlInput& control)
    : model_(model),
      flex_(flex),
      body_(body),
      control_(control),
      mode_count_(flex.mode_count),
      n_aero_(model.aeroStateCount()),
      data_(model),
      q_(mode_count_), qd_(mode_count_), qdd_(mode_count_), Q_(mode_count_), rhs_vec_(mode_count_),
      frame_inertia_(mode_count_),
      membrane_force_(Eigen::VectorXd::Zero(mode_count_)),
      membrane_ws_(flex.membrane()),
      mass_base_packed_(packedLower(flex.M_qq + flex.stacked.apparent_const)),
      chol_(mode_count_),
      kin_(flex.stacked, flex.mode_count),
      packed_(static_cast<Eigen::Index>(mode_count_) * (mode_count_ + 1) / 2),
      extra_force_(static_cast<Eigen::Index>(model.strips.size())),
      extra_couple_(static_cast<Eigen::Index>(model.strips.size())),
      twist_mid_qdd_(2 * static_cast<Eigen::Index>(model.strips.size())),
      split_(flex, 0, 2 * mode_count_ + n_aero_ + kQuadratureChannels),
      modal_mass_(mode_count_, mode_count_) {
  if (!aero::batchKernelApplies(model.vehicle.aero))
    throw InvalidModelError(
        "the flexible wing needs aero model mst-td with the Scherer lag and a smooth stall "
        "(stall_width_deg > 0)");
  // Friction coefficients for the tethered speed (M11 depends on U only).
  const double U = body.v_P1_B.norm();
  for (std::size_t j = 0; j < model.strips.size(); ++j)
    data_.batch.friction_coefficient[static_cast<Eigen::Index>(j)] = aero::frictionCoefficient(
        U * model.strip_geometry[j].chord_m / model.vehicle.air.kinematic_viscosity_m2ps);
  kin_.setReferencePoints(data_.batch);  // the quarter chord (flexible_wing.hpp)
  aero::prepareStripBatch(model.aero_context, data_.batch);
  data_.batch.airx.setZero();
  data_.batch.airy.setZero();
  data_.batch.airz.setZero();
}

void FlexibleTetheredSystem::initialState(double t_s, double* y) const {
  for (int i = 0; i < 2 * mode_count_; ++i) y[i] = 0.0;
  initialAeroStates(model_, body_, control_, t_s, y + aeroOffset());
  for (int c = 0; c < kQuadratureChannels; ++c) y[quadratureOffset() + c] = 0.0;
}

void FlexibleTetheredSystem::absoluteTolerances(double rel_tol, double lag_abs_tol,
                                                double separation_abs_tol,
                                                std::vector<double>* atol) const {
  atol->assign(static_cast<std::size_t>(stateCount()), lag_abs_tol);
  modalAbsoluteTolerances(rel_tol, mode_count_, 0, atol);
  const int per = model_.aero_states_per_strip;
  for (int i = aeroOffset() + per - 1; i < quadratureOffset(); i += per)
    (*atol)[static_cast<std::size_t>(i)] = separation_abs_tol;
  // Quadratures: their scale times the period, like the rigid wing.
  const auto scales = quadratureScales(model_, body_.v_P1_B.norm());
  const double T = 1.0 / control_.freq_hz;
  for (int c = 0; c < kQuadratureChannels; ++c)
    (*atol)[static_cast<std::size_t>(quadratureOffset() + c)] = 0.1 * rel_tol * scales[c] * T;
}

void FlexibleTetheredSystem::evaluate(double t_s, const double* y, double* aero_derivatives,
                                      AeroResult* aero) {
  const FlapState flap = flapStateAt(model_.vehicle.flapping.amplitude_rad, control_.freq_hz, t_s);
  R_BW_ = rotX(flap.phi_rad);
  omega_W_ = Vec3(flap.phi_dot_radps, 0.0, 0.0);  // the body does not rotate (tethered)
  alpha_W_ = Vec3(flap.phi_ddot_radps2, 0.0, 0.0);
  q_ = Eigen::Map<const Eigen::VectorXd>(y, mode_count_);
  qd_ = Eigen::Map<const Eigen::VectorXd>(y + mode_count_, mode_count_);

  // Strip kinematics from rigid motion plus modes (docs/theory.md 6.2), all strips at once.
  WingFrameMotion m;
  m.v_O_W = R_BW_.transpose() * body_.v_P1_B;
  m.omega_W = omega_W_;
  m.alpha0_W = alpha_W_;
  m.omega_rel_W = omega_W_;
  aero::StripBatch& b = data_.batch;
  kin_.compute(q_, qd_, m, b);
  aero::evalMstTdBatch(model_.aero_context, b, y + aeroOffset(), aero_derivatives);

  // Generalised aerodynamic forces (docs/theory.md 6.3) and, on the left (6.4), the apparent air
  // mass along each strip's mid-chord normal and the apparent rotary inertia about e_s.
  kin_.modalForce(b, &Q_);
  // Left-hand side M_qq + A(f) as a packed lower triangle: the f-independent part plus one
  // product over the strips (flexible_wing.hpp).
  packed_ = mass_base_packed_;
  packed_.noalias() += flex_.stacked.apparent_per_f * b.separation_f.matrix();

  // Modal equation (docs/theory.md 4.3) with w = phi' e_x, alpha = phi'' e_x.
  modalFrameInertia(flex_, q_, qd_, flap.phi_dot_radps, flap.phi_ddot_radps2, &frame_inertia_);
  rhs_vec_ = Q_ - flex_.damping.cwiseProduct(qd_) - flex_.stiffness.cwiseProduct(q_) -
             frame_inertia_;
  if (flex_.nonlinear()) {  // the skin's membrane stretching (docs/theory.md 4.7)
    membrane_force_.setZero();
    membrane_power_W_ = flex_.membrane().addForce(q_, qd_, flex_.membrane_damping_s,
                                                  &membrane_ws_, &membrane_force_);
    rhs_vec_ -= membrane_force_;
  }
  qdd_ = rhs_vec_;
  if (chol_.factorPacked(packed_.data()))
    chol_.solveInPlace(qdd_);
  else  // not positive definite: a non-finite derivative makes the integrator retry smaller
    qdd_.setConstant(std::numeric_limits<double>::quiet_NaN());

  // Aerodynamic resultant of the wing on the frame, about P2 (W), including the apparent-mass
  // force and couple of q'' that the kernel could not know.
  if (aero) {
    const StackedStrips& st = flex_.stacked;
    const Eigen::Index ns = st.ns;
    twist_mid_qdd_.noalias() = st.apparentShapes() * qdd_;
    extra_force_ = -(0.5 * (1.0 + b.separation_f) * flex_.apparent_mass_kg.array() *
                     twist_mid_qdd_.tail(ns).array()).matrix();
    extra_couple_ = -(b.separation_f * flex_.apparent_rotary_kgm2.array() *
                      twist_mid_qdd_.head(ns).array()).matrix();
    kin_.resultant(b, extra_force_, extra_couple_, omega_W_, &aero->F_W, &aero->M_P2_W,
                   &aero->power_aero_W);
  }
}

void FlexibleTetheredSystem::lastStripLoads(Eigen::Matrix3Xd* force_W_N, Eigen::VectorXd* moment_Nm,
                                            Eigen::VectorXd* separation_f) const {
  const aero::StripBatch& b = data_.batch;
  const Eigen::Index ns = b.Fx.size();
  force_W_N->resize(3, ns);
  force_W_N->row(0) = b.Fx.matrix().transpose();
  force_W_N->row(1) = b.Fy.matrix().transpose();
  force_W_N->row(2) = b.Fz.matrix().transpose();
  *moment_Nm = (b.Mx * kin_.esx() + b.My * kin_.esy() + b.Mz * kin_.esz()).matrix();
  *separation_f = b.separation_f.matrix();
}

void FlexibleTetheredSystem::updateSplit(double t_s, const double* y) {
  if (!flex_.nonlinear()) return;
  evaluate(t_s, y, nullptr, nullptr);  // the modal mass M_qq + A(f) at y, packed in packed_
  int k = 0;
  for (int j = 0; j < mode_count_; ++j)
    for (int i = j; i < mode_count_; ++i) modal_mass_(i, j) = modal_mass_(j, i) = packed_[k++];
  split_.update(y, &modal_mass_);
}

void FlexibleTetheredSystem::fuselageLoads(const AeroResult& aero, const Vec3& F_inertial_W,
                                           const Vec3& M_inertial_P2_W,
                                           double hinge_power_one_wing_W, LoadSample* out) const {
  const Vec3& p2 = model_.p_P1P2_B;
  const Vec3 Fa = R_BW_ * aero.F_W, Fi = R_BW_ * F_inertial_W;
  const Vec3 Ma = R_BW_ * aero.M_P2_W + p2.cross(Fa);
  const Vec3 Mi = R_BW_ * M_inertial_P2_W + p2.cross(Fi);
  LoadSample& o = *out;
  o = LoadSample{};
  setWingPairLoads(flightPathFrame(body_.v_P1_B), Fa, Ma, Fi, Mi, &o);
  o.power_aero_W = 2.0 * aero.power_aero_W;
  o.power_hinge_W = 2.0 * hinge_power_one_wing_W;
  o.separated_fraction = aero.separated_fraction;
  addTailAndTotals(model_, body_, control_, &o);
}

void FlexibleTetheredSystem::rhs(double t_s, const double* y, double* ydot) {
  AeroResult aero;
  evaluate(t_s, y, ydot + aeroOffset(), &aero);
  for (int i = 0; i < mode_count_; ++i) {
    ydot[i] = y[mode_count_ + i];
    ydot[mode_count_ + i] = qdd_[i];
  }
  LoadSample s;
  // The membrane's power on q' is its dissipation plus dV_NL/dt, whose integral over a period
  // vanishes like that of the linear strain energy left out here (the cycle means are exact).
  const double damping_power = qd_.dot(flex_.damping.cwiseProduct(qd_)) + membrane_power_W_;
  fuselageLoads(aero, Vec3::Zero(), Vec3::Zero(), aero.power_aero_W + damping_power, &s);
  double* quad = ydot + quadratureOffset();
  quad[0] = s.FV_N;
  quad[1] = s.FH_N;
  quad[2] = s.M_Nm;
  quad[3] = s.power_aero_W;
  quad[4] = s.power_hinge_W;
}

void FlexibleTetheredSystem::sample(double t_s, const double* y, LoadSample* out) {
  AeroResult aero;
  evaluate(t_s, y, nullptr, &aero);
  const aero::StripBatch& b = data_.batch;  // area share of separated flow (histories only)
  aero.separated_fraction =
      ((1.0 - b.separation_f) * b.chord_m * b.width_m).sum() / (b.chord_m * b.width_m).sum();
  // Inertial loads of the wing by nodal sums over the FE mesh (docs/theory.md 4.4, level L3):
  // a_p = alpha x s + w x (w x s) + 2 w x Phi q' + Phi q'', the sums taken as bilinear forms of
  // the lumped mesh (lumped_inertia_sums.hpp; equal to the per-node loop up to round-off).
  const structure::WingInertialLoads inertial = structure::wingInertialLoads(
      flex_.modal->lumped_sums, q_, qd_, qdd_, omega_W_, alpha_W_, &inertia_ws_);
  const Vec3& F = inertial.force_W_N;
  const Vec3& M = inertial.moment_W_Nm;  // incl. the nodes' rigid rotary inertia J alpha
  const Vec3& J_alpha = inertial.rotary_moment_W_Nm;  // (w x J w vanishes about the hinge axis)
  const double kinetic_rate = inertial.kinetic_energy_rate_W;
  // Hinge power into one wing: motor moment about x times phi' = aero power + rate of kinetic
  // energy + rate of strain energy (elastic and, with w_x^2 K_G, geometric: the nodal sums above
  // hold the spin softening but not the stiffening, docs/theory.md 4.6) + damping dissipation.
  // The membrane's share, dV_NL/dt plus its strain-rate dissipation, is the power evaluate()
  // already found (ModalMembraneStiffness::addForce; 0 for the linear wing).
  const double strain_rate = strainEnergyRate();
  const double damping_power = qd_.dot(flex_.damping.cwiseProduct(qd_));
  const double hinge = aero.power_aero_W + kinetic_rate + omega_W_.dot(J_alpha) + strain_rate +
                       damping_power + membrane_power_W_;
  fuselageLoads(aero, F, M, hinge, out);
  setTip(out);
}

double FlexibleTetheredSystem::strainEnergyRate() {
  rhs_vec_.noalias() = flex_.geometric_stiffness_x * q_;
  return qd_.dot(flex_.stiffness.cwiseProduct(q_)) +
         omega_W_.x() * omega_W_.x() * qd_.dot(rhs_vec_);
}

void FlexibleTetheredSystem::setTip(LoadSample* out) const {
  const FlexibleStrip& tip = flex_.strips[static_cast<std::size_t>(flex_.tip_strip)];
  out->tip_deflection_m = -(tip.phi_L * q_).z();  // z_W is down
  out->tip_twist_rad = tip.psi_twist.dot(q_);
}

bool FlexibleTetheredSystem::sampleFromDerivative(double t_s, const double* y, const double* ydot,
                                                  LoadSample* out) {
  if (!(model_.aero_context.params->separation_lag_tf0 > 0.0)) return false;
  const FlapState flap = flapStateAt(model_.vehicle.flapping.amplitude_rad, control_.freq_hz, t_s);
  R_BW_ = rotX(flap.phi_rad);
  omega_W_ = Vec3(flap.phi_dot_radps, 0.0, 0.0);
  alpha_W_ = Vec3(flap.phi_ddot_radps2, 0.0, 0.0);
  q_ = Eigen::Map<const Eigen::VectorXd>(y, mode_count_);
  qd_ = Eigen::Map<const Eigen::VectorXd>(y + mode_count_, mode_count_);
  qdd_ = Eigen::Map<const Eigen::VectorXd>(ydot + mode_count_, mode_count_);
  // The inertial loads and the hinge power's kinetic and strain terms as in sample().
  const structure::WingInertialLoads inertial = structure::wingInertialLoads(
      flex_.modal->lumped_sums, q_, qd_, qdd_, omega_W_, alpha_W_, &inertia_ws_);
  const double strain_rate = strainEnergyRate();
  const double* quad = ydot + quadratureOffset();  // rhs(): FV, FH, M (aero + tail), powers
  LoadSample& o = *out;
  o = LoadSample{};
  const Vec3& p2 = model_.p_P1P2_B;
  const Vec3 Fi = R_BW_ * inertial.force_W_N;
  const Vec3 Mi = R_BW_ * inertial.moment_W_Nm + p2.cross(Fi);
  setWingPairLoads(flightPathFrame(body_.v_P1_B), Vec3::Zero(), Vec3::Zero(), Fi, Mi, &o);
  addTailAndTotals(model_, body_, control_, &o);  // the tail's and the body's (constant here)
  o.FV_wing_aero_N = quad[0] - o.FV_tail_N;
  o.FH_wing_aero_N = quad[1] - o.FH_tail_N - o.FH_body_N;
  o.M_wing_aero_Nm = quad[2] - o.M_tail_Nm;
  o.FV_N = o.FV_wing_aero_N + o.FV_wing_inertial_N + o.FV_tail_N;
  o.FH_N = o.FH_wing_aero_N + o.FH_wing_inertial_N + o.FH_tail_N + o.FH_body_N;
  o.M_Nm = o.M_wing_aero_Nm + o.M_wing_inertial_Nm + o.M_tail_Nm;
  o.power_aero_W = quad[3];
  // rhs()'s hinge row is 2 (aero power + modal and membrane damping); sample() adds the rates of
  // kinetic and strain energy.
  o.power_hinge_W = quad[4] + 2.0 * (inertial.kinetic_energy_rate_W +
                                     omega_W_.dot(inertial.rotary_moment_W_Nm) + strain_rate);
  // The separated area share from the separation states, clamped as the kernel clamps them.
  const aero::StripBatch& b = data_.batch;
  const int per = model_.aero_states_per_strip;
  double separated = 0.0, area = 0.0;
  for (Eigen::Index j = 0; j < b.chord_m.size(); ++j) {
    const double f = std::max(std::min(y[aeroOffset() + per * j + per - 1], 1.0), 0.0);
    const double a = b.chord_m[j] * b.width_m[j];
    separated += (1.0 - f) * a;
    area += a;
  }
  o.separated_fraction = separated / area;
  setTip(&o);
  return true;
}

}  // namespace orni
