// The flexible wing on the prescribed hinge: floating frame W attached to the P2 node, linear modal
// deformation q (fixed-interface modes, docs/theory.md 3.2), strip kinematics from rigid motion
// plus modes and strip loads projected back on the modes (docs/theory.md 3.6, 4.1-4.3, 6.1-6.4).
//
// Level L2 of docs/theory.md 4.5: every term linear in q and q-dot of the modal equation
//   (M_qq + A(f)) q'' + [D + 2 C(w)] q' + [K + K_w(w) + K_G(w) + C(alpha)] q
//     = Q_aero - H^T alpha - h_w(w)
// (docs/theory.md 4.3, tethered: the fuselage does not move, so a_O = 0 and w = phi' e_x), with
// the apparent air mass A = sum_j b_j m_a,j psi_mid,j psi_mid,j^T on the left-hand side (6.4) and
// the geometric stiffening K_G of the wing's own inertial loads (4.6; wing.fe.inertial_stiffness
// selects softening and stiffening).
#pragma once

#include <array>
#include <cstddef>
#include <memory>
#include <vector>

#include <Eigen/Cholesky>
#include <Eigen/Core>

#include "core/model/frames.hpp"
#include "core/model/vehicle_model.hpp"
#include "core/structure/inertial_stiffness.hpp"
#include "core/structure/modal_wing.hpp"

namespace orni {

/// Per-strip modal data (W components). Sample nodes of the mid-station (docs/theory.md 6.1):
/// L = leading edge, Q = quarter chord, T = three-quarter chord, E = trailing edge. The strip load
/// is distributed over L, Q, T, E with flat-plate chordwise weights and the section motion the
/// kernel sees is taken with the same weights (chordwise_weights.hpp: why, and the weights).
struct FlexibleStrip {
  Vec3 x_L_W_m, x_T_W_m;            ///< undeformed sample nodes L and T
  Eigen::Matrix3Xd phi_L, phi_T;    ///< translational mode shapes at L and T (3 x M)
  /// The kernel's section (docs/theory.md 6.2, 6.3): reference point P = sum a_i x_i (the quarter
  /// chord; the strip force acts here, the moment is about it) and rear point R = P - lever_R e_c
  /// (its three-quarter chord) = sum (a_i - lever_R b_i) x_i, so that e_c = (s_P - s_R)/|.| has
  /// the rate of the section twist sum b_i n.u_i'. The rigid wing: P = L, R = T (zero modes).
  Vec3 x_P_W_m, x_R_W_m;
  Eigen::Matrix3Xd phi_P, phi_R;    ///< their mode shapes (3 x M)
  double lever_R_m = 0.0;           ///< |x_P - x_R|
  double ref_aft_of_le_m = 0.0;     ///< the kernel's x_P (docs/theory.md 5.1): c/4 flexible, 0 rigid
  Eigen::RowVectorXd psi_twist;     ///< elastic twist per unit q, nose-up (1 x M):
                                    ///< sum_i b_i n_W^T Phi_i over L, Q, T, E
  Eigen::VectorXd psi_mid;          ///< normal displacement of the kernel's mid-chord per unit q
                                    ///< (M): (Phi_P^T n_W - (c/2 - x_P) psi_twist^T)
  // The nodal form of the same operators (for a full-order model of the same wing,
  // structure/wing_transient.hpp): the mesh nodes L, Q, T, E and their chordwise weights, so that
  // phi_P = sum a_i Phi_i, psi_twist = sum b_i n_W^T Phi_i and the strip load is a_i F + b_i m n_W.
  std::array<int, 4> section_nodes{};
  std::array<double, 4> force_weights{};   ///< a_i
  std::array<double, 4> moment_weights{};  ///< b_i (1/m)
};

/// The strips' modal data stacked for one matrix product per use. Point data are component-major:
/// row k ns + j is component k (x, y, z) of strip j; scalar data row j. All shapes live in one
/// matrix, rows [phi_R (3 ns); phi_P (3 ns); psi_twist (ns); psi_mid (ns)], so that the products
/// of an evaluation that share a vector are one product over adjacent row blocks.
struct StackedStrips {
  Eigen::Index ns = 0;                  ///< strips
  Eigen::VectorXd points;               ///< undeformed section points [x_R; x_P] (6 ns)
  Eigen::VectorXd ref_aft_of_le_m;      ///< the kernel's reference point per strip (ns)
  Eigen::MatrixXd shapes;               ///< (8 ns) x M, see above
  // The row blocks the evaluations multiply with (adjacent, so one product each).
  auto pointShapes() const { return shapes.topRows(6 * ns); }           ///< [phi_R; phi_P]
  auto rateShapes() const { return shapes.middleRows(3 * ns, 4 * ns); }  ///< [phi_P; psi_twist]
  auto apparentShapes() const { return shapes.bottomRows(2 * ns); }      ///< [psi_twist; psi_mid]
  auto psi_twist() const { return shapes.middleRows(6 * ns, ns); }  ///< elastic twist (ns x M)
  auto psi_mid() const { return shapes.middleRows(7 * ns, ns); }    ///< mid-chord normal (ns x M)
  /// Apparent air mass on the modes (docs/theory.md 6.4) with separation fractions f_j:
  ///   A(f) = sum_j 0.5 (1 + f_j) m_a,j psi_mid psi_mid^T + f_j k_j psi_t^T psi_t
  /// (k_j = rho pi c^4/128 dy, the apparent rotary inertia of M17) = apparent_const +
  /// unpack(apparent_per_f f), the second as packed lower triangles (M(M+1)/2 x ns).
  Eigen::MatrixXd apparent_const;
  Eigen::MatrixXd apparent_per_f;
};

/// Stack per-strip modal data with M modes (M = 0: rigid wing, positions only); m_a and k per
/// strip for the apparent mass.
StackedStrips stackStrips(const std::vector<FlexibleStrip>& strips, int mode_count,
                          const Eigen::VectorXd& apparent_mass_kg,
                          const Eigen::VectorXd& apparent_rotary_kgm2);

/// The lower triangle of a square matrix, packed column by column (rows j .. n-1 of column j):
/// the layout of StackedStrips::apparent_per_f and SmallCholesky::factorPacked().
Eigen::VectorXd packedLower(const Eigen::MatrixXd& A);

/// out (lower triangle only) += scale * A(f) of StackedStrips; `packed` is workspace of
/// M(M+1)/2 entries. No allocation.
void addApparentModalMass(const StackedStrips& st, const Eigen::ArrayXd& f, double scale,
                          Eigen::VectorXd* packed, Eigen::Ref<Eigen::MatrixXd> out);

/// Built once from the vehicle and its ModalWing; immutable.
struct FlexibleWingModel {
  std::shared_ptr<const structure::ModalWing> modal;
  int mode_count = 0;
  std::vector<FlexibleStrip> strips;
  Eigen::VectorXd stiffness;        ///< omega_k^2
  Eigen::VectorXd damping;          ///< 2 zeta_k omega_k
  Eigen::MatrixXd M_qq;             ///< generalised mass Phi^T M Phi
  Eigen::MatrixXd C1;               ///< gyroscopic matrix about x_W: P_zy - P_yz (skew)
  /// K_w + K_G per w_x^2 (rotation about x_W): softening P_xx - sum_k P_kk plus the geometric
  /// stiffness of the unit w_x^2 load, as wing.fe.inertial_stiffness selects (docs/theory.md 4.6)
  Eigen::MatrixXd spin_stiffness_x;
  Eigen::MatrixXd geometric_stiffness_x;  ///< its K_G part alone (zero without stiffening)
  structure::ModalInertialStiffness inertial_stiffness;  ///< every w_k w_l and acceleration load
  Eigen::VectorXd h_x;              ///< S_xx - sum_k S_kk (centrifugal load about x_W per w^2)
  Eigen::VectorXd H_x;              ///< row x of H (Euler load per unit alpha_x)
  Eigen::VectorXd apparent_mass_kg; ///< m_a,j = rho pi c_j^2/4 dy_j per strip
  Eigen::VectorXd apparent_rotary_kgm2;  ///< k_j = rho pi c_j^4/128 dy_j per strip (M17)
  Eigen::Index tip_strip = 0;
  StackedStrips stacked;

  /// The condensed membrane of the geometrically nonlinear wing (docs/theory.md 4.7), empty for the
  /// linear wing: its restoring force f_NL(q) joins K q in the modal equation.
  const structure::ModalMembraneStiffness& membrane() const { return modal->membrane; }
  bool nonlinear() const { return !modal->membrane.empty(); }
  /// beta (s) of the membrane's strain-rate (Kelvin-Voigt) damping, f_d = beta J^T C J q'
  /// (membrane_rom.hpp): stiffness-proportional with the first mode's ratio, beta = 2 zeta_1 /
  /// omega_1, so that a mode whose stiffness is the stretched skin's, at omega, has the damping
  /// ratio zeta_1 omega / omega_1. Why: the modal damping 2 zeta omega_k is fixed at the linear
  /// frequencies, and a membrane-stiffened skin mode (1-5 kHz on the slack magpie at 1 g) would
  /// keep it, i.e. ring almost undamped at a ratio zeta omega_k / omega; a viscoelastic film and
  /// the air it pumps damp such modes strongly. At the flapping frequency the membrane responds
  /// quasi-statically and this force is zeta_1 f / f_1 ~ 1 % of its elastic part. Zero for the
  /// linear wing.
  double membrane_damping_s = 0.0;

  FlexibleWingModel(const VehicleModel& vehicle,
                    std::shared_ptr<const structure::ModalWing> modal_wing,
                    const std::vector<double>& strip_chords_m,
                    const std::vector<double>& strip_widths_m);
};

/// Generalised inertial force of the moving frame on the modes (docs/theory.md 4.3, invariant form,
/// level L2) for w = phi' e_x, alpha = phi'' e_x (the hinge axis; tethered fuselage):
///   2 C(w) q' + [K_w(w) + K_G(w) + C(alpha)] q + H^T alpha + h_w(w)
/// (K_G of alpha_x vanishes: it bends the flat wing without membrane stress, docs/theory.md 4.6).
/// `out` must have mode_count entries; no allocation.
void modalFrameInertia(const FlexibleWingModel& flex, const Eigen::VectorXd& q,
                       const Eigen::VectorXd& qd, double phi_dot_radps, double phi_ddot_radps2,
                       Eigen::VectorXd* out);

}  // namespace orni
