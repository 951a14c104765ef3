#include "core/dynamics/flexible_wing.hpp"

#include <array>
#include <stdexcept>

#include <Eigen/Eigenvalues>

#include "core/aero/mst_strip.hpp"
#include "core/dynamics/chordwise_weights.hpp"
#include "core/model/invariant.hpp"

namespace orni {

FlexibleWingModel::FlexibleWingModel(const VehicleModel& vehicle,
                                     std::shared_ptr<const structure::ModalWing> modal_wing,
                                     const std::vector<double>& strip_chords_m,
                                     const std::vector<double>& strip_widths_m)
    : modal(std::move(modal_wing)) {
  const structure::ModalWing& mw = *modal;
  mode_count = mw.modeCount();
  const int M = mode_count;
  const std::size_t ns = mw.mesh.strip_nodes.size();
  if (ns != strip_chords_m.size())
    throw std::invalid_argument("flexible wing: mesh strips do not match the aerodynamic strips");
  const Vec3 n_W = -Vec3::UnitZ();  // upper-surface normal of the flat wing (docs/theory.md 2.1)
  strips.resize(ns);
  apparent_mass_kg.resize(static_cast<Eigen::Index>(ns));
  apparent_rotary_kgm2.resize(static_cast<Eigen::Index>(ns));
  const double rho = vehicle.air.density_kgpm3;
  for (std::size_t j = 0; j < ns; ++j) {
    const structure::StripSampleNodes& sn = mw.mesh.strip_nodes[j];
    FlexibleStrip& s = strips[j];
    s.x_L_W_m = mw.mesh.nodes_W_m[static_cast<std::size_t>(sn.leading_edge)];
    s.x_T_W_m = mw.mesh.nodes_W_m[static_cast<std::size_t>(sn.three_quarter_chord)];
    s.phi_L = mw.phi_W[static_cast<std::size_t>(sn.leading_edge)];
    s.phi_T = mw.phi_W[static_cast<std::size_t>(sn.three_quarter_chord)];
    const double c = strip_chords_m[j];
    // Flat-plate loading over L, Q, T, E and the same weights for the section's motion
    // (chordwise_weights.hpp: the choice and the weights; docs/theory.md 6.3).
    const int node[4] = {sn.leading_edge, sn.quarter_chord, sn.three_quarter_chord,
                         sn.trailing_edge};
    const Vec3 e_c0 = (s.x_L_W_m - mw.mesh.nodes_W_m[static_cast<std::size_t>(node[3])])
                          .normalized();  // undeformed chord, TE -> LE
    std::array<double, 4> x_aft{};
    for (int i = 1; i < 4; ++i)
      x_aft[i] = (s.x_L_W_m - mw.mesh.nodes_W_m[static_cast<std::size_t>(node[i])]).dot(e_c0);
    const ChordwiseWeights w = flatPlateChordwiseWeights(x_aft);
    s.lever_R_m = 2.0 * (w.mid_chord_aft_m - w.reference_aft_m);  // P to the 3/4 chord
    s.ref_aft_of_le_m = 0.25 * c;  // the kernel's P: its circulatory force acts there (lever 0)
    s.x_P_W_m.setZero();
    s.x_R_W_m.setZero();
    s.phi_P.setZero(3, M);
    s.phi_R.setZero(3, M);
    s.psi_twist.setZero(M);
    for (int i = 0; i < 4; ++i) {
      const auto p = static_cast<std::size_t>(node[i]);
      const double a = w.force[i], r = w.force[i] - s.lever_R_m * w.moment[i];
      s.section_nodes[static_cast<std::size_t>(i)] = node[i];
      s.force_weights[static_cast<std::size_t>(i)] = a;
      s.moment_weights[static_cast<std::size_t>(i)] = w.moment[i];
      s.x_P_W_m += a * mw.mesh.nodes_W_m[p];
      s.x_R_W_m += r * mw.mesh.nodes_W_m[p];
      s.phi_P += a * mw.phi_W[p];
      s.phi_R += r * mw.phi_W[p];
      s.psi_twist += w.moment[i] * (n_W.transpose() * mw.phi_W[p]);
    }
    s.psi_mid =
        s.phi_P.transpose() * n_W - (0.5 * c - s.ref_aft_of_le_m) * s.psi_twist.transpose();
    apparent_mass_kg[static_cast<Eigen::Index>(j)] =
        aero::apparentMassPerSpan_kgpm(rho, c) * strip_widths_m[j];
    apparent_rotary_kgm2[static_cast<Eigen::Index>(j)] =
        rho * kPi * c * c * c * c / 128.0 * strip_widths_m[j];
  }
  tip_strip = static_cast<Eigen::Index>(ns) - 1;
  stiffness = mw.stiffnessDiagonal();
  damping = mw.dampingDiagonal();
  const structure::InertiaInvariants& inv = mw.invariants;
  M_qq = inv.generalized_mass;
  // docs/theory.md 3.6: C_1 = P_32 - P_23 (1-based), K_w = sum w_k w_l P_kl - |w|^2 sum_k P_kk,
  // h_w = sum w_k w_l S_kl - |w|^2 sum_k S_kk; here w = w_x e_x (the hinge axis). K_w + K_G:
  // structure/inertial_stiffness.hpp.
  C1 = inv.P(2, 1) - inv.P(1, 2);
  inertial_stiffness = structure::modalInertialStiffness(inv, mw.geometric_stiffness,
                                                        vehicle.wing.fe.inertial_stiffness);
  spin_stiffness_x = inertial_stiffness.spinAbout(0, 0);
  geometric_stiffness_x =
      vehicle.wing.fe.inertial_stiffness == InertialStiffness::kBoth
          ? Eigen::MatrixXd(mw.geometric_stiffness[structure::kLoadSpinXX])
          : Eigen::MatrixXd::Zero(M, M);
  h_x = inv.S(0, 0) - (inv.S(0, 0) + inv.S(1, 1) + inv.S(2, 2));
  H_x = inv.rotational_participation.row(0).transpose();
  ORNI_DEMAND(M_qq.rows() == M, "flexible wing: the modal mass matrix has one row per mode");
  stacked = stackStrips(strips, M, apparent_mass_kg, apparent_rotary_kgm2);
  if (nonlinear() && M > 0 && stiffness[0] > 0.0)
    membrane_damping_s = damping[0] / stiffness[0];  // 2 zeta_1 omega_1 / omega_1^2
}

StackedStrips stackStrips(const std::vector<FlexibleStrip>& strips, int mode_count,
                          const Eigen::VectorXd& apparent_mass_kg,
                          const Eigen::VectorXd& apparent_rotary_kgm2) {
  const int M = mode_count;
  const auto ns = static_cast<Eigen::Index>(strips.size());
  StackedStrips st;
  st.ns = ns;
  st.points.resize(6 * ns);
  st.ref_aft_of_le_m.resize(ns);
  st.shapes.setZero(8 * ns, M);
  st.apparent_const.setZero(M, M);
  st.apparent_per_f.setZero(static_cast<Eigen::Index>(M) * (M + 1) / 2, ns);
  for (Eigen::Index i = 0; i < ns; ++i) {
    const FlexibleStrip& fs = strips[static_cast<std::size_t>(i)];
    st.ref_aft_of_le_m[i] = fs.ref_aft_of_le_m;
    for (int k = 0; k < 3; ++k) {  // component-major: row k ns + i of each block
      st.points[k * ns + i] = fs.x_R_W_m[k];
      st.points[3 * ns + k * ns + i] = fs.x_P_W_m[k];
      if (M > 0) {
        st.shapes.row(k * ns + i) = fs.phi_R.row(k);
        st.shapes.row(3 * ns + k * ns + i) = fs.phi_P.row(k);
      }
    }
    if (M == 0) continue;
    st.shapes.row(6 * ns + i) = fs.psi_twist;
    st.shapes.row(7 * ns + i) = fs.psi_mid.transpose();
    const Eigen::MatrixXd mid = 0.5 * apparent_mass_kg[i] * fs.psi_mid * fs.psi_mid.transpose();
    const Eigen::MatrixXd per_f =
        mid + apparent_rotary_kgm2[i] * fs.psi_twist.transpose() * fs.psi_twist;
    st.apparent_const += mid;
    Eigen::Index r = 0;
    for (int c = 0; c < M; ++c)
      for (int l = c; l < M; ++l) st.apparent_per_f(r++, i) = per_f(l, c);
  }
  return st;
}

Eigen::VectorXd packedLower(const Eigen::MatrixXd& A) {
  const Eigen::Index n = A.rows();
  Eigen::VectorXd p(n * (n + 1) / 2);
  Eigen::Index r = 0;
  for (Eigen::Index c = 0; c < n; ++c)
    for (Eigen::Index l = c; l < n; ++l) p[r++] = A(l, c);
  return p;
}

void addApparentModalMass(const StackedStrips& st, const Eigen::ArrayXd& f, double scale,
                          Eigen::VectorXd* packed, Eigen::Ref<Eigen::MatrixXd> out) {
  const auto M = st.apparent_const.rows();
  if (M == 0) return;
  packed->noalias() = st.apparent_per_f * f.matrix();
  Eigen::Index r = 0;
  for (Eigen::Index c = 0; c < M; ++c)
    for (Eigen::Index l = c; l < M; ++l)
      out(l, c) += scale * (st.apparent_const(l, c) + (*packed)[r++]);
}

void modalFrameInertia(const FlexibleWingModel& flex, const Eigen::VectorXd& q,
                       const Eigen::VectorXd& qd, double phi_dot_radps, double phi_ddot_radps2,
                       Eigen::VectorXd* out) {
  const double wx = phi_dot_radps, ax = phi_ddot_radps2;
  Eigen::VectorXd& g = *out;
  g.noalias() = (2.0 * wx) * (flex.C1 * qd);
  g.noalias() += (wx * wx) * (flex.spin_stiffness_x * q);
  g.noalias() += ax * (flex.C1 * q);
  g += ax * flex.H_x + (wx * wx) * flex.h_x;
}

}  // namespace orni
