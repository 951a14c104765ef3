#include "core/dynamics/flight_core.hpp"

#include <cmath>
#include <stdexcept>

#include "core/aero/tail.hpp"
#include "core/dynamics/flexible_wing.hpp"
#include "core/dynamics/flight_path_frame.hpp"
#include "core/dynamics/modal_wing_cache.hpp"
#include "core/model/vehicle_validation.hpp"

namespace orni {

namespace {

/// The vehicle, checked (core/model/vehicle_validation.hpp) before anything is built from it.
const VehicleModel& checked(const VehicleModel& v, FlightCoreModel::Checks checks) {
  if (checks == FlightCoreModel::Checks::kRequired) requireValidVehicle(v);
  return v;
}

}  // namespace

FlightCoreModel::FlightCoreModel(const VehicleModel& v, Checks checks,
                                 ModalWingCache* modal_wings)
    : vehicle(checked(v, checks)),
      strips(makeStrips(v.wing)),
      wing_mass(computeWingInertia(v)),
      modal_wing_cache(modal_wings) {
  strip_geometry.reserve(strips.size());
  double area_half = 0.0;
  for (const Strip& s : strips) {
    aero::StripGeometry g;
    g.chord_m = s.chord_m;
    g.width_m = s.width_m;
    g.ref_aft_of_le_m = 0.0;  // kinematic reference point P = leading edge of the strip
    strip_geometry.push_back(g);
    area_half += s.chord_m * s.width_m;
  }
  wing_area_both_m2 = 2.0 * area_half;
  mean_chord_m = wing_area_both_m2 / (2.0 * v.wing.semispan_m);
  aero_context.params = &vehicle.aero;
  aero_context.constants = aero::MstConstants::fromAspectRatio(aerodynamicAspectRatio(v));
  aero_context.density_kgpm3 = v.air.density_kgpm3;
  aero_context.kinematic_viscosity_m2ps = v.air.kinematic_viscosity_m2ps;
  aero_states_per_strip = aero::statesPerStrip(vehicle.aero);
  p_P1P2_B = Vec3(v.flapping.hinge_x_B_m, 0.0, v.flapping.hinge_z_B_m);
  p_P1P4_B = Vec3(-v.tail.arm_m, 0.0, -v.tail.height_m);
  const double i = v.wing.incidence_rad;
  e_c_W = Vec3(std::cos(i), 0.0, -std::sin(i));  // rotY(i) e_x: nose-up incidence
  n_W = Vec3(-std::sin(i), 0.0, -std::cos(i));   // rotY(i) (-e_z)
  if (v.wing.structure == StructureLevel::kFlexible) {
    std::vector<double> chords, widths;
    for (const aero::StripGeometry& g : strip_geometry) {
      chords.push_back(g.chord_m);
      widths.push_back(g.width_m);
    }
    flexible = std::make_shared<const FlexibleWingModel>(
        v, modal_wings ? modal_wings->get(v) : buildModalWingOf(v), chords, widths);
    // The structural wing mass replaces the rigid-wing estimate (same members and skin).
  }
}

FlightCoreData::FlightCoreData(const FlightCoreModel& model)
    : separation_f(model.strips.size(), 1.0),
      friction_cd(model.strips.size(), 0.0),
      batch(static_cast<int>(model.strips.size())),
      y_strip_m(static_cast<Eigen::Index>(model.strips.size())) {
  for (std::size_t j = 0; j < model.strips.size(); ++j) {
    const auto i = static_cast<Eigen::Index>(j);
    batch.chord_m[i] = model.strip_geometry[j].chord_m;
    batch.width_m[i] = model.strip_geometry[j].width_m;
    batch.ref_aft_of_le_m[i] = model.strip_geometry[j].ref_aft_of_le_m;
    y_strip_m[i] = model.strips[j].y_center_m;
  }
}

BodyMotion tetheredBodyMotion(double speed_mps, double theta_rad) {
  BodyMotion b;
  b.v_P1_B = Vec3(speed_mps * std::cos(theta_rad), 0.0, speed_mps * std::sin(theta_rad));
  b.theta_rad = theta_rad;
  return b;
}

namespace {

// Kinematics of one strip's leading-edge point (B components), rigid wing (structure level L0).
struct StripMotion {
  aero::SectionKinematics section;
  Vec3 rho_P1_B;     // P1 -> strip LE
  Vec3 v_rel_B;      // velocity relative to the fuselage
  Vec3 a_rel_B;      // acceleration relative to the fuselage (fuselage frame derivative)
};

struct FrameAtT {
  Mat3 R_BW;
  Vec3 omega_rel_B;  // phi_dot e_x
  Vec3 alpha_rel_B;  // phi_ddot e_x
  Vec3 e_c_B, n_B;
  Vec3 omega_B;      // total angular velocity of W
  Vec3 alpha_B;      // total angular acceleration of W
};

FrameAtT frameAt(const FlightCoreModel& m, const BodyMotion& body, const FlapState& flap) {
  FrameAtT f;
  f.R_BW = rotX(flap.phi_rad);
  f.omega_rel_B = Vec3(flap.phi_dot_radps, 0.0, 0.0);
  f.alpha_rel_B = Vec3(flap.phi_ddot_radps2, 0.0, 0.0);
  f.e_c_B = f.R_BW * m.e_c_W;
  f.n_B = f.R_BW * m.n_W;
  const Vec3 Q_B(0.0, body.Q_radps, 0.0);
  f.omega_B = Q_B + f.omega_rel_B;
  f.alpha_B = Vec3(0.0, body.Qdot_radps2, 0.0) + f.alpha_rel_B + Q_B.cross(f.omega_rel_B);
  return f;
}

// Inertial velocity and acceleration (B components) of a point fixed in the rigid wing, given its
// position r_P2_B from the hinge (already rotated to B).
void pointMotion(const FlightCoreModel& m, const BodyMotion& body, const FrameAtT& fr,
                 const Vec3& r_P2_B, Vec3* rho, Vec3* v, Vec3* a, Vec3* v_rel, Vec3* a_rel) {
  const Vec3 Q_B(0.0, body.Q_radps, 0.0);
  const Vec3 Qd_B(0.0, body.Qdot_radps2, 0.0);
  *rho = m.p_P1P2_B + r_P2_B;
  *v_rel = fr.omega_rel_B.cross(r_P2_B);
  *a_rel = fr.alpha_rel_B.cross(r_P2_B) + fr.omega_rel_B.cross(*v_rel);
  *v = body.v_P1_B + Q_B.cross(*rho) + *v_rel;
  *a = body.a_P1_B + Qd_B.cross(*rho) + Q_B.cross(Q_B.cross(*rho)) + 2.0 * Q_B.cross(*v_rel) +
       *a_rel;
}

}  // namespace

void initialAeroStates(const FlightCoreModel& model, const BodyMotion& body,
                       const ControlInput& control, double t_s, double* aero_states) {
  if (model.aero_states_per_strip == 0) return;
  const FlapState flap = flapStateAt(model.vehicle.flapping.amplitude_rad, control.freq_hz, t_s);
  const FrameAtT fr = frameAt(model, body, flap);
  for (std::size_t j = 0; j < model.strips.size(); ++j) {
    const Vec3 r = fr.R_BW * Vec3(0.0, model.strips[j].y_center_m, 0.0);
    Vec3 rho, v, a, v_rel, a_rel;
    pointMotion(model, body, fr, r, &rho, &v, &a, &v_rel, &a_rel);
    aero::SectionKinematics k;
    k.e_c = fr.e_c_B;
    k.n = fr.n_B;
    k.v_P = v;
    k.a_P = a;
    k.w_s = fr.omega_B;
    k.wdot_s = fr.alpha_B;
    k.v_air = Vec3::Zero();
    k.flight_speed_mps = body.v_P1_B.norm();
    aero::initialMstTdStates(model.aero_context, model.strip_geometry[j], k,
                             aero_states + j * static_cast<std::size_t>(model.aero_states_per_strip));
  }
}

namespace {

// M11 skin friction per strip (docs/theory.md 5.2 (M11)): it depends on the flight speed U only, so
// it is cached per speed.
void updateFrictionCache(const FlightCoreModel& model, FlightCoreData& data, double flight_speed) {
  if (flight_speed == data.friction_speed_mps) return;
  data.friction_speed_mps = flight_speed;
  for (std::size_t j = 0; j < model.strips.size(); ++j) {
    data.friction_cd[j] =
        aero::frictionCoefficient(flight_speed * model.strip_geometry[j].chord_m /
                                  model.vehicle.air.kinematic_viscosity_m2ps);
    data.batch.friction_coefficient[static_cast<Eigen::Index>(j)] = data.friction_cd[j];
  }
  aero::prepareStripBatch(model.aero_context, data.batch);
}

// Rigid wing (structure level L0): every strip's leading-edge point is p_P1P2 + y e_span, so its
// velocity and acceleration are affine in y (v = v0 + y v1, a = a0 + y a1), and the moment and
// power sums need only sum(F) and sum(y F). This keeps the per-strip cost at the kernel.
struct AffineStripMotion {
  Vec3 e_span_B, e_flap_B;  // e_flap = e_x x e_span: direction of v_rel per unit phi_dot y
  Vec3 v_rel1, a_rel1;      // motion relative to the fuselage per unit y
  Vec3 v0, v1, a0, a1;
};

AffineStripMotion affineStripMotion(const FlightCoreModel& model, const BodyMotion& body,
                                    const FrameAtT& fr, const FlapState& flap) {
  AffineStripMotion m;
  m.e_span_B = fr.R_BW.col(1);
  m.e_flap_B = fr.R_BW.col(2);
  const Vec3& e_span_B = m.e_span_B;
  const Vec3 Q_B(0.0, body.Q_radps, 0.0);
  const Vec3 Qd_B(0.0, body.Qdot_radps2, 0.0);
  const Vec3& p2 = model.p_P1P2_B;
  m.v_rel1 = flap.phi_dot_radps * m.e_flap_B;
  m.a_rel1 = flap.phi_ddot_radps2 * m.e_flap_B - flap.phi_dot_radps * flap.phi_dot_radps * e_span_B;
  m.v0 = body.v_P1_B + Q_B.cross(p2);
  m.v1 = Q_B.cross(e_span_B) + m.v_rel1;
  m.a0 = body.a_P1_B + Qd_B.cross(p2) + Q_B.cross(Q_B.cross(p2));
  m.a1 = Qd_B.cross(e_span_B) + Q_B.cross(Q_B.cross(e_span_B)) + 2.0 * Q_B.cross(m.v_rel1) +
         m.a_rel1;
  return m;
}

// One wing's section loads summed over the strips (B components, moments about each strip's
// leading edge), and the separated area (1 - f) c dy over the area.
struct StripLoadSums {
  Vec3 F = Vec3::Zero(), yF = Vec3::Zero(), M_P = Vec3::Zero();
  double separated_area = 0.0, area = 0.0;
};

// Vectorised MST-TD over all strips (docs/theory.md 5.9; the same equations as scalarStripLoads).
StripLoadSums batchStripLoads(const FlightCoreModel& model, FlightCoreData& data,
                              const FrameAtT& fr, const AffineStripMotion& sm,
                              const double* aero_states, double* aero_state_derivatives) {
  StripLoadSums sums;
  aero::StripBatch& b = data.batch;
  const Eigen::ArrayXd& y = data.y_strip_m;
  const Vec3 &v0 = sm.v0, &v1 = sm.v1, &a0 = sm.a0, &a1 = sm.a1;
  // One frame for all strips: element 0 (evalMstTdBatchUniformFrame).
  b.ecx[0] = fr.e_c_B.x(); b.ecy[0] = fr.e_c_B.y(); b.ecz[0] = fr.e_c_B.z();
  b.nx[0] = fr.n_B.x(); b.ny[0] = fr.n_B.y(); b.nz[0] = fr.n_B.z();
  b.vx = v0.x() + y * v1.x(); b.vy = v0.y() + y * v1.y(); b.vz = v0.z() + y * v1.z();
  b.ax = a0.x() + y * a1.x(); b.ay = a0.y() + y * a1.y(); b.az = a0.z() + y * a1.z();
  b.wx[0] = fr.omega_B.x(); b.wy[0] = fr.omega_B.y(); b.wz[0] = fr.omega_B.z();
  b.wdx[0] = fr.alpha_B.x(); b.wdy[0] = fr.alpha_B.y(); b.wdz[0] = fr.alpha_B.z();
  aero::evalMstTdBatchUniformFrame(model.aero_context, b, aero_states, aero_state_derivatives);
  sums.F = Vec3(b.Fx.sum(), b.Fy.sum(), b.Fz.sum());
  sums.yF = Vec3((y * b.Fx).sum(), (y * b.Fy).sum(), (y * b.Fz).sum());
  sums.M_P = Vec3(b.Mx.sum(), b.My.sum(), b.Mz.sum());
  if (!aero_state_derivatives) {  // a sample: the separated fraction, a diagnostic the
                                  // right-hand side does not need
    sums.area = (b.chord_m * b.width_m).sum();
    sums.separated_area = ((1.0 - b.separation_f) * b.chord_m * b.width_m).sum();
    Eigen::Map<Eigen::ArrayXd>(data.separation_f.data(), y.size()) = b.separation_f;
  }
  return sums;
}

// Strip by strip: DeLaurier 1993 (docs/theory.md 5.1, planar inputs) or the scalar MST-TD kernel.
StripLoadSums scalarStripLoads(const FlightCoreModel& model, FlightCoreData& data,
                               const BodyMotion& body, const ControlInput& control,
                               const FrameAtT& fr, const AffineStripMotion& sm,
                               const double* aero_states,
                               double* aero_state_derivatives) {
  const VehicleModel& veh = model.vehicle;
  const bool delaurier = veh.aero.model == AeroModelKind::kDeLaurier1993;
  const int nstate = model.aero_states_per_strip;
  const double flight_speed = body.v_P1_B.norm();
  // DeLaurier's planar inputs (docs/theory.md 5.1): flapping-axis incidence theta_a relative to the
  // flight velocity, plunge direction d = e_hinge x e_span (down at zero flap).
  const double theta_a = std::atan2(body.v_P1_B.z(), body.v_P1_B.x());
  const Vec3 d_plunge_B = fr.R_BW * Vec3::UnitZ();
  const Vec3 a_pitch_B = fr.e_c_B.cross(fr.n_B);
  aero::SectionKinematics k;
  k.e_c = fr.e_c_B;
  k.n = fr.n_B;
  k.w_s = fr.omega_B;
  k.wdot_s = fr.alpha_B;
  k.v_air = Vec3::Zero();
  k.flight_speed_mps = flight_speed;
  aero::PlanarKinematics pk;
  pk.U = flight_speed;
  pk.theta_a = theta_a;
  pk.thetabar = theta_a + veh.wing.incidence_rad;
  pk.theta = pk.thetabar;  // rigid wing: no dynamic twist
  pk.thetadot = fr.omega_B.dot(a_pitch_B);
  pk.thetaddot = fr.alpha_B.dot(a_pitch_B);
  pk.omega = 2.0 * kPi * control.freq_hz;
  const double hdot1 = sm.v_rel1.dot(d_plunge_B), hddot1 = sm.a_rel1.dot(d_plunge_B);

  StripLoadSums sums;
  for (std::size_t j = 0; j < model.strips.size(); ++j) {
    const aero::StripGeometry& g = model.strip_geometry[j];
    const double y = model.strips[j].y_center_m;
    aero::SectionLoads loads;
    if (delaurier) {
      pk.hdot = y * hdot1;
      pk.hddot = y * hddot1;
      loads = aero::evalDeLaurier1993(model.aero_context, g, pk);
    } else {
      k.v_P = sm.v0 + y * sm.v1;
      k.a_P = sm.a0 + y * sm.a1;
      k.friction_coefficient = data.friction_cd[j];
      const std::size_t off = j * static_cast<std::size_t>(nstate);
      loads = aero::evalMstTd(model.aero_context, g, k, aero_states + off,
                              aero_state_derivatives ? aero_state_derivatives + off : nullptr);
    }
    Vec3 F, M_P;
    aero::resolveSectionLoads(loads, g, fr.e_c_B, fr.n_B, &F, &M_P);
    sums.F += F;
    sums.yF += y * F;
    sums.M_P += M_P;
    const double strip_area = g.chord_m * g.width_m;
    sums.separated_area += (1.0 - loads.separation_f) * strip_area;
    sums.area += strip_area;
    data.separation_f[j] = loads.separation_f;
  }
  return sums;
}

// Rigid-wing inertial loads on the fuselage: -m a_cm and -(rho_cm x m a_cm + J_cm alpha +
// omega x J_cm omega) (Newton-Euler; docs/theory.md 4.4 with no modes), and the rate of work the
// hinge does on the wing's kinetic energy (relative to the fuselage).
struct InertialLoads {
  Vec3 F = Vec3::Zero(), M_P1 = Vec3::Zero();
  double power = 0.0;
};

InertialLoads rigidWingInertialLoads(const FlightCoreModel& model, const BodyMotion& body,
                                     const FrameAtT& fr) {
  InertialLoads in;
  const RigidBodyInertia& wi = model.wing_mass.total;
  if (!(wi.mass_kg > 0.0)) return in;
  const Vec3 c_W = wi.centerOfMass_W_m();
  const Vec3 c_B = fr.R_BW * c_W;
  Vec3 rho_cm, v_cm, a_cm, v_rel_cm, a_rel_cm;
  pointMotion(model, body, fr, c_B, &rho_cm, &v_cm, &a_cm, &v_rel_cm, &a_rel_cm);
  const Mat3 J_cm_W = wi.inertia_P2_W_kgm2 -
                      wi.mass_kg * (c_W.squaredNorm() * Mat3::Identity() - c_W * c_W.transpose());
  const Mat3 J_cm_B = fr.R_BW * J_cm_W * fr.R_BW.transpose();
  const Vec3 dH_cm = J_cm_B * fr.alpha_B + fr.omega_B.cross(J_cm_B * fr.omega_B);
  in.F = -wi.mass_kg * a_cm;
  in.M_P1 = -(rho_cm.cross(wi.mass_kg * a_cm) + dH_cm);
  in.power = wi.mass_kg * a_cm.dot(v_rel_cm) + dH_cm.dot(fr.omega_rel_B);
  return in;
}

}  // namespace

void evaluateLoads(const FlightCoreModel& model, FlightCoreData& data, const BodyMotion& body,
                   const ControlInput& control, double t_s, const double* aero_states,
                   double* aero_state_derivatives, LoadSample* out) {
  const VehicleModel& veh = model.vehicle;
  const FlapState flap = flapStateAt(veh.flapping.amplitude_rad, control.freq_hz, t_s);
  const FrameAtT fr = frameAt(model, body, flap);
  const double flight_speed = body.v_P1_B.norm();
  updateFrictionCache(model, data, flight_speed);
  const AffineStripMotion sm = affineStripMotion(model, body, fr, flap);

  // The strips' aerodynamic loads (docs/theory.md 5), one wing, summed.
  const bool batch = veh.aero.model != AeroModelKind::kDeLaurier1993 &&
                     aero::batchKernelApplies(veh.aero);
  const StripLoadSums sums =
      batch ? batchStripLoads(model, data, fr, sm, aero_states, aero_state_derivatives)
            : scalarStripLoads(model, data, body, control, fr, sm, aero_states,
                               aero_state_derivatives);
  const Vec3& F_aero = sums.F;
  const Vec3 M_aero_P1 = model.p_P1P2_B.cross(sums.F) + sm.e_span_B.cross(sums.yF) + sums.M_P;
  // Power delivered to the air by the flapping motion (relative to the fuselage): the section
  // loads' power on the section's relative motion, with the sign of M19.
  const double power_aero = -(sm.v_rel1.dot(sums.yF) + sums.M_P.dot(fr.omega_rel_B));
  const InertialLoads in = rigidWingInertialLoads(model, body, fr);

  // Both wings in the flight-path frame (paper Eq. 2).
  LoadSample& o = *out;
  o = LoadSample{};
  setWingPairLoads(flightPathFrame(body.v_P1_B), F_aero, M_aero_P1, in.F, in.M_P1, &o);
  o.power_aero_W = 2.0 * power_aero;
  o.power_hinge_W = 2.0 * (power_aero + in.power);
  o.separated_fraction = sums.area > 0.0 ? sums.separated_area / sums.area : 0.0;

  addTailAndTotals(model, body, control, &o);
}

std::array<double, kQuadratureChannels> quadratureScales(const FlightCoreModel& model,
                                                         double speed_mps) {
  const double force = 0.5 * model.vehicle.air.density_kgpm3 * speed_mps * speed_mps *
                       model.wing_area_both_m2;
  return {force, force, force * model.mean_chord_m, force * speed_mps, force * speed_mps};
}

void addTailAndTotals(const FlightCoreModel& model, const BodyMotion& body,
                      const ControlInput& control, LoadSample* out) {
  LoadSample& o = *out;
  const VehicleModel& veh = model.vehicle;
  if (veh.tail.present) {
    const FlightPathFrame path = flightPathFrame(body.v_P1_B);
    const Vec3& e_v = path.e_v_B;
    const Vec3& e_L = path.e_L_B;
    const double theta_a = std::atan2(body.v_P1_B.z(), body.v_P1_B.x());
    const Vec3 Q_B(0.0, body.Q_radps, 0.0);
    aero::TailFlow flow;
    flow.theta_body_rad = body.theta_rad;
    // Flight-path angle gamma: theta minus the angle of attack of P1's velocity.
    flow.flight_path_rad = body.theta_rad - theta_a;
    flow.pitch_rate_radps = body.Q_radps;
    flow.airspeed_mps = (body.v_P1_B + Q_B.cross(model.p_P1P4_B)).norm();
    flow.wing_downwash_rad = veh.tail.downwash_factor * (theta_a + veh.wing.incidence_rad);
    flow.tail_angle_rad = control.tail_angle_rad;
    const aero::TailLoads tl = aero::evalTail(veh.tail, veh.air.density_kgpm3, flow);
    const Vec3 F_tail = tl.lift_N * e_L - tl.drag_N * e_v;
    o.FV_tail_N = F_tail.dot(e_L);
    o.FH_tail_N = F_tail.dot(e_v);
    o.M_tail_Nm = model.p_P1P4_B.cross(F_tail).y();
    o.tail_alpha_rad = tl.alpha_rad;
  }
  if (veh.body.drag_area_m2 > 0.0) {
    const double speed = body.v_P1_B.norm();
    o.FH_body_N = -0.5 * veh.air.density_kgpm3 * speed * speed * veh.body.drag_area_m2;
  }
  o.FV_N = o.FV_wing_aero_N + o.FV_wing_inertial_N + o.FV_tail_N;
  o.FH_N = o.FH_wing_aero_N + o.FH_wing_inertial_N + o.FH_tail_N + o.FH_body_N;
  o.M_Nm = o.M_wing_aero_Nm + o.M_wing_inertial_Nm + o.M_tail_Nm;
}

}  // namespace orni
