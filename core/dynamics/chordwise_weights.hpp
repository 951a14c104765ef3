// Chordwise weights of a strip's section nodes for the aerodynamic coupling of the flexible wing
// (docs/theory.md 6.1, 6.3): the strip load distributed over the nodes L, Q, T, E of its
// mid-station as a flat plate's loading, and the section motion the MST kernel sees taken with the
// same weights, so that the load operators are the exact transposes of the kinematic ones.
//
// Why a distribution and not a point load at Q_j: the magpie's modal basis keeps local skin modes
// (a 0.04 mm skin between 0.4 mm rods: 17 of its 24 modes move Q_j off the L-T chord line by more
// than 30 % of the section's largest displacement, tests/unit/dynamics/
// test_chordwise_coupling.cpp), and on this wing Q_j (like T_j) is a bare skin node, not a member
// node. docs/theory.md 6.3: a point load on a skin node is harmless only in a truncated global
// basis; otherwise distribute the load with chordwise weights and use the same weights for the
// kinematics. The old coupling (force at L with the moment about L as a force pair on L and T,
// i.e. 2/3 of the quarter-chord lift on the leading-edge node and 1/3 as a point load on the bare
// skin node T) and a point load on Q both load one skin node with a third to all of the lift: on
// the magpie basis the old coupling's generalised force of a flat-plate strip load is 86 % off
// the consistent nodal loads. With the linear skin the load path shows in the loads: at Table 3's
// point with the wing held still (amplitude 1e-4 deg), mean FV 0.542 N (old: the point load on T
// pitches the L-T line it loads nose-down), 0.598 N (this distribution), 0.782 N (a point load on
// Q with the pitch from L and T: the dent under the load is never seen by the section angle).
//
// The weights: the nodal displacement between the four nodes is linear in the chordwise
// coordinate (hat functions), and a chordwise pressure p(x) has the consistent nodal loads
// f_i = integral N_i p dx (virtual work on that interpolation). The MST kernel's normal force has
// two parts with known flat-plate distributions (docs/theory.md 5.4, 5.5): the circulatory force at
// c/4, Birnbaum's  p ~ sqrt((c - x)/x), and the mid-chord force (apparent mass, separated
// cross-flow), p ~ sqrt(x (c - x)) (the apparent mass of the flat plate). Their lumped weights are
// `force` (a_i, sum 1, centroid exactly c/4: hat functions reproduce linear fields) and
// `mid_chord` (e_i, centroid c/2). The kernel returns a force F and a moment M about its
// reference point P; with P at the quarter chord (the centroid of a) the nodal loads
//   f_i = a_i F + b_i M n,   b_i = (a_i - e_i) / (x_e - x_a)
// (x_a, x_e the centroids) put the circulatory force on the nodes as a_i and the mid-chord force
// (moment -(x_e - x_a) dN2 about P) as e_i: both with their flat-plate distribution. b has
// sum b_i = 0 and sum b_i x_i = -1 (x aft of L), so f_i is statically equivalent to F at P plus
// the nose-up moment M (any couple of the kernel is spread as a_i - e_i per unit moment).
// Kinematics with the same weights: v_P = sum a_i v_i, section twist rate = sum b_i n.v_i, and
// the chord direction e_c from the same b (docs/theory.md 6.3: kinematic and load operators
// transposes). Two choices, on purpose:
// * Not e_c from L and T (docs/theory.md 6.2). With the twist rate from b, e_c from L-T would give
//   the kernel a section angle and a pitch rate of two different chord lines; e_c ~ sum b_i s_i
//   (unit for the undeformed section) has exactly the rate sum b_i n.u_i'. For a section that
//   stays straight both agree, and the kernel's 3/4-chord point R = P - (c/2) e_c is then T.
// * "The same weights" is what virtual work needs (power consistency); it is not thin-airfoil
//   theory's lift sensing, which weights the normal wash by sqrt(x/(c - x)) (reverse flow, centroid
//   3c/4) while the loading is Birnbaum's (centroid c/4). The kernel senses at the 3/4-chord
//   point of the straight chord fitted with these weights (v_P, twist rate), exact for a straight
//   section; the section's bending between the nodes (camber) enters only through that fit, as it
//   entered the old coupling only through the L-T line.
#pragma once

#include <array>

namespace orni {

struct ChordwiseWeights {
  std::array<double, 4> force{};      ///< a_i of L, Q, T, E: lumped Birnbaum loading (sum 1)
  std::array<double, 4> mid_chord{};  ///< e_i: lumped elliptic (apparent-mass) loading (sum 1)
  std::array<double, 4> moment{};     ///< b_i, 1/m: (a_i - e_i)/(x_e - x_a); sum 0, sum b x = -1
  double reference_aft_m = 0.0;       ///< x_a = sum a_i x_i: the quarter chord, aft of L
  double mid_chord_aft_m = 0.0;       ///< x_e = sum e_i x_i: mid-chord, aft of L
};

/// Weights for nodes at x_aft_m (aft of the leading edge along the chord): 0 = x_0 < x_1 < x_2 <
/// x_3 = chord (L, Q, T, E). Closed-form integrals in the Glauert angle (x = c (1 - cos t)/2).
/// Throws std::invalid_argument unless the positions increase strictly from 0.
ChordwiseWeights flatPlateChordwiseWeights(const std::array<double, 4>& x_aft_m);

}  // namespace orni
