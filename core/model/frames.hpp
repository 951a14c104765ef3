// Frames and naming (docs/design.md 7.2).
//
//   I  inertial: x_I forward (horizontal), z_I down; altitude h = -z_I.
//   B  body at P1 (the CG and moment reference): x_B forward, y_B right, z_B down; pitch theta.
//   W  right wing at the hinge P2: x_W forward along the root chord, y_W outboard, z_W down at
//      zero flap angle. R_BW = Rot(x_B, phi) with phi = -delta_M, so delta_M > 0 raises the tip.
//   E  strip section: e_c (TE -> LE), n (towards the upper surface), a_pitch = e_c x n (nose-up).
//
// Names: p_P1P2_B is the point P1 to P2 expressed in B; R_BW maps W components to B; v_P_B is the
// velocity of P in B components. R_IW = R_IB * R_BW composes by eye.
#pragma once

#include <cmath>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace orni {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;

/// Rotation about the x axis by angle a (right hand).
inline Mat3 rotX(double a) {
  const double c = std::cos(a), s = std::sin(a);
  Mat3 r;
  r << 1, 0, 0, 0, c, -s, 0, s, c;
  return r;
}

/// Rotation about the y axis by angle a (right hand); R_IB = rotY(theta) (docs/theory.md 4.1).
inline Mat3 rotY(double a) {
  const double c = std::cos(a), s = std::sin(a);
  Mat3 r;
  r << c, 0, s, 0, 1, 0, -s, 0, c;
  return r;
}

/// Skew-symmetric cross-product matrix: skew(a) * b == a.cross(b).
inline Mat3 skew(const Vec3& a) {
  Mat3 m;
  m << 0, -a.z(), a.y(), a.z(), 0, -a.x(), -a.y(), a.x(), 0;
  return m;
}

constexpr double kPi = 3.14159265358979323846;
constexpr double kDegToRad = kPi / 180.0;
constexpr double kRadToDeg = 180.0 / kPi;

}  // namespace orni
