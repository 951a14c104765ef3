// Builds the immutable part of the free-flight equations (free_flight_model.hpp).
#include "core/dynamics/free_flight_model.hpp"

#include <string>

#include "core/aero/mst_strip.hpp"
#include "core/model/invalid_model_error.hpp"

namespace orni {

namespace {

// Rigid wing as strips with zero modes: leading edge on the hinge line (the rigid core's
// kinematic reference, flight_core.cpp), three-quarter-chord point along -e_c (incidence applied).
// The kernel's reference point stays the leading edge (P = L, R = T): for a rigid section the
// point a force is written at does not change its action on the body.
std::vector<FlexibleStrip> rigidStrips(const FlightCoreModel& model) {
  std::vector<FlexibleStrip> out(model.strips.size());
  for (std::size_t j = 0; j < model.strips.size(); ++j) {
    FlexibleStrip& s = out[j];
    const double c = model.strip_geometry[j].chord_m;
    s.x_L_W_m = Vec3(0.0, model.strips[j].y_center_m, 0.0);
    s.x_T_W_m = s.x_L_W_m - 0.75 * c * model.e_c_W;
    s.x_P_W_m = s.x_L_W_m;
    s.x_R_W_m = s.x_T_W_m;
    s.lever_R_m = 0.75 * c;
    s.ref_aft_of_le_m = 0.0;
    s.phi_L.resize(3, 0);
    s.phi_T.resize(3, 0);
    s.phi_P.resize(3, 0);
    s.phi_R.resize(3, 0);
    s.psi_twist.resize(0);
    s.psi_mid.resize(0);
  }
  return out;
}

}  // namespace

FreeFlightModel::FreeFlightModel(const FlightCoreModel& core_model,
                                 const FlexibleWingModel* flexible)
    : core(core_model),
      flex(flexible),
      mode_count(flexible ? flexible->mode_count : 0),
      aero_state_count(core_model.aeroStateCount()),
      strips(flexible ? flexible->strips : rigidStrips(core_model)),
      rigid_stacked(flexible ? StackedStrips{}
                             : stackStrips(strips, 0, Eigen::VectorXd(), Eigen::VectorXd())) {
  if (!aero::batchKernelApplies(core.vehicle.aero))
    throw InvalidModelError(
        "free flight needs aero model mst-td with the Scherer lag and a smooth stall "
        "(stall_width_deg > 0)");
  const std::size_t ns = core.strips.size();
  const int m = mode_count;
  if (flex) {
    apparent_mass_kg = flex->apparent_mass_kg;
    const structure::InertiaInvariants& inv = flex->modal->invariants;
    wing_mass_kg = inv.mass_kg;
    wing_first_moment_W_kgm = inv.first_moment_W_kgm;
    wing_inertia_P2_W_kgm2 = inv.inertia_P2_W_kgm2;
    L = inv.translational_participation;
    H = inv.rotational_participation;
    for (std::size_t k = 0; k < 9; ++k) S[k] = inv.s[k];
    modal_mass = inv.generalized_mass;
    modal_stiffness = flex->stiffness;
    modal_damping = flex->damping;
    // docs/theory.md 3.6: C_1 = P_32 - P_23, C_2 = P_13 - P_31, C_3 = P_21 - P_12 (1-based).
    C[0] = inv.P(2, 1) - inv.P(1, 2);
    C[1] = inv.P(0, 2) - inv.P(2, 0);
    C[2] = inv.P(1, 0) - inv.P(0, 1);
    S_trace = inv.S(0, 0) + inv.S(1, 1) + inv.S(2, 2);
  } else {
    apparent_mass_kg.resize(static_cast<Eigen::Index>(ns));
    for (std::size_t j = 0; j < ns; ++j) {
      const double c = core.strip_geometry[j].chord_m;
      apparent_mass_kg[static_cast<Eigen::Index>(j)] =
          aero::apparentMassPerSpan_kgpm(core.vehicle.air.density_kgpm3, c) *
          core.strip_geometry[j].width_m;
    }
    const RigidBodyInertia& wi = core.wing_mass.total;
    wing_mass_kg = wi.mass_kg;
    wing_first_moment_W_kgm = wi.first_moment_W_kgm;
    wing_inertia_P2_W_kgm2 = wi.inertia_P2_W_kgm2;
    L.resize(3, 0);
    H.resize(3, 0);
    modal_mass.resize(0, 0);
    modal_stiffness.resize(0);
    modal_damping.resize(0);
    S_trace.resize(0);
  }
  p_P1P2_B_m = core.p_P1P2_B;
  const Vec3& r2 = p_P1P2_B_m;
  const Vec3& c0 = wing_first_moment_W_kgm;
  const double m_w = wing_mass_kg;
  // Fuselage only (docs/theory.md 4.2): the vehicle minus both wings at zero flap angle.
  const double wing_pitch_inertia_P1 = wing_inertia_P2_W_kgm2(1, 1) +
                                       m_w * (r2.x() * r2.x() + r2.z() * r2.z()) +
                                       2.0 * (r2.x() * c0.x() + r2.z() * c0.z());
  fuselage_mass_kg = core.vehicle.body.mass_kg - 2.0 * m_w;
  fuselage_pitch_inertia_kgm2 = core.vehicle.body.pitch_inertia_kgm2 - 2.0 * wing_pitch_inertia_P1;
  if (!(fuselage_mass_kg > 0.0))
    throw InvalidModelError("free flight: body.mass_kg (" +
                            std::to_string(core.vehicle.body.mass_kg) +
                            " kg) must exceed the mass of both wings (" +
                            std::to_string(2.0 * m_w) + " kg)");
  // The paper's P1 is the centre of gravity: put the fuselage's own CG where the whole vehicle's
  // CG lands on P1 with the wings at zero flap angle and undeformed.
  fuselage_cg_B_m = Vec3(-2.0 * (m_w * r2 + c0) / fuselage_mass_kg);
  fuselage_cg_B_m.y() = 0.0;
  if (!(fuselage_pitch_inertia_kgm2 > 0.0))
    throw InvalidModelError(
        "free flight: body.pitch_inertia_kgm2 (" +
        std::to_string(core.vehicle.body.pitch_inertia_kgm2) +
        " kg m^2) must exceed the pitch inertia of both wings about P1 (" +
        std::to_string(2.0 * wing_pitch_inertia_P1) + " kg m^2)");

  Pstack.setZero(9 * m, m);
  Cstack.setZero(3 * m, m);
  Smat.setZero(9, m);
  if (m > 0) {
    for (int k = 0; k < 9; ++k) {
      Pstack.middleRows(k * m, m) = flex->inertial_stiffness.spin[static_cast<std::size_t>(k)];
      Smat.row(k) = S[static_cast<std::size_t>(k)].transpose();
    }
    for (int k = 0; k < 3; ++k) Cstack.middleRows(k * m, m) = C[static_cast<std::size_t>(k)];
    linear_loads = flex->inertial_stiffness.linear_loads;
    Gstack = flex->inertial_stiffness.linear_stack;
  }
}

}  // namespace orni
