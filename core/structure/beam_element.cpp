// 3-D Euler-Bernoulli beam (docs/theory.md 2.2; Przemieniecki 1968).
#include "core/structure/beam_element.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace orni::structure {
namespace {

constexpr double kPiLocal = 3.14159265358979323846;

using Mat4 = Eigen::Matrix4d;

// Local DOF indices of the two bending planes: (v1, theta_z1, v2, theta_z2) and
// (w1, theta_y1, w2, theta_y2).
constexpr int kPlaneXY[4] = {1, 5, 7, 11};
constexpr int kPlaneXZ[4] = {2, 4, 8, 10};

// Adds a 4 x 4 bending-plane matrix; `flip` negates the translation-rotation coupling terms
// (x'-z' plane, theta_y = -dw/dx).
void addPlane(Mat12& k, const Mat4& plane, const int (&dofs)[4], bool flip) {
  constexpr double kSign[4] = {1.0, -1.0, 1.0, -1.0};
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c)
      k(dofs[r], dofs[c]) += flip ? kSign[r] * kSign[c] * plane(r, c) : plane(r, c);
}

void addPair(Mat12& k, int i, int j, double diag, double off) {
  k(i, i) += diag;
  k(j, j) += diag;
  k(i, j) += off;
  k(j, i) += off;
}

double beamLength(const Vec3& x1, const Vec3& x2) {
  const double length = (x2 - x1).norm();
  if (!(length > 0.0)) throw std::invalid_argument("beam element: expected length > 0, got 0");
  return length;
}

// K = T^T K' T with T = blockdiag(Lambda, Lambda, Lambda, Lambda).
Mat12 toGlobal(const Mat12& local, const Mat3& lambda) {
  Mat12 out;
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b)
      out.block<3, 3>(3 * a, 3 * b).noalias() =
          lambda.transpose() * local.block<3, 3>(3 * a, 3 * b) * lambda;
  return out;
}

Mat4 hermiteStiffness(double ei, double l) {
  const double l2 = l * l;
  Mat4 k;
  k << 12, 6 * l, -12, 6 * l,
       6 * l, 4 * l2, -6 * l, 2 * l2,
       -12, -6 * l, 12, -6 * l,
       6 * l, 2 * l2, -6 * l, 4 * l2;
  return (ei / (l2 * l)) * k;
}

Mat4 hermiteMass(double rho_a, double l) {
  const double l2 = l * l;
  Mat4 m;
  m << 156, 22 * l, 54, -13 * l,
       22 * l, 4 * l2, 13 * l, -3 * l2,
       54, 13 * l, 156, -22 * l,
       -13 * l, -3 * l2, -22 * l, 4 * l2;
  return (rho_a * l / 420.0) * m;
}

Mat4 hermiteGeometric(double axial_force, double l) {
  const double l2 = l * l;
  Mat4 k;
  k << 36, 3 * l, -36, 3 * l,
       3 * l, 4 * l2, -3 * l, -l2,
       -36, -3 * l, 36, -3 * l,
       3 * l, -l2, -3 * l, 4 * l2;
  return (axial_force / (30.0 * l)) * k;
}

}  // namespace

BeamSection solidRodSection(double diameter_m) {
  if (!(diameter_m > 0.0))
    throw std::invalid_argument("solidRodSection: expected diameter > 0, got " +
                                std::to_string(diameter_m));
  const double d2 = diameter_m * diameter_m;
  BeamSection s;
  s.area_m2 = kPiLocal * d2 / 4.0;
  s.inertia_y_m4 = kPiLocal * d2 * d2 / 64.0;
  s.inertia_z_m4 = s.inertia_y_m4;
  s.torsion_j_m4 = kPiLocal * d2 * d2 / 32.0;
  s.polar_ip_m4 = s.torsion_j_m4;
  return s;
}

BeamProperties makeBeamProperties(const BeamSection& section, double youngs_modulus_pa,
                                  double poisson_ratio, double density_kgpm3) {
  BeamProperties p;
  p.section = section;
  p.youngs_modulus_pa = youngs_modulus_pa;
  p.shear_modulus_pa = youngs_modulus_pa / (2.0 * (1.0 + poisson_ratio));
  p.density_kgpm3 = density_kgpm3;
  return p;
}

Mat3 beamTriad(const Vec3& x1_W_m, const Vec3& x2_W_m, const Vec3& orientation_W) {
  const Vec3 ex = (x2_W_m - x1_W_m) / beamLength(x1_W_m, x2_W_m);
  Vec3 ez = orientation_W - orientation_W.dot(ex) * ex;
  if (ez.norm() < 1e-8 * orientation_W.norm()) {
    const Vec3 fallback = Vec3::UnitX();
    ez = fallback - fallback.dot(ex) * ex;
    if (ez.norm() < 1e-8) ez = Vec3::UnitY() - ex.y() * ex;
  }
  ez.normalize();
  const Vec3 ey = ez.cross(ex);
  Mat3 lambda;
  lambda.row(0) = ex.transpose();
  lambda.row(1) = ey.transpose();
  lambda.row(2) = ez.transpose();
  return lambda;
}

Mat12 beamStiffness(const Vec3& x1_W_m, const Vec3& x2_W_m, const Vec3& orientation_W,
                    const BeamProperties& p) {
  const double l = beamLength(x1_W_m, x2_W_m);
  const BeamSection& s = p.section;
  Mat12 k = Mat12::Zero();
  const double ea = p.youngs_modulus_pa * s.area_m2 / l;
  addPair(k, 0, 6, ea, -ea);
  const double gj = p.shear_modulus_pa * s.torsion_j_m4 / l;
  addPair(k, 3, 9, gj, -gj);
  addPlane(k, hermiteStiffness(p.youngs_modulus_pa * s.inertia_z_m4, l), kPlaneXY, false);
  addPlane(k, hermiteStiffness(p.youngs_modulus_pa * s.inertia_y_m4, l), kPlaneXZ, true);
  return toGlobal(k, beamTriad(x1_W_m, x2_W_m, orientation_W));
}

Mat12 beamConsistentMass(const Vec3& x1_W_m, const Vec3& x2_W_m, const Vec3& orientation_W,
                         const BeamProperties& p) {
  const double l = beamLength(x1_W_m, x2_W_m);
  const BeamSection& s = p.section;
  const double rho_a = p.density_kgpm3 * s.area_m2;
  Mat12 m = Mat12::Zero();
  addPair(m, 0, 6, rho_a * l / 3.0, rho_a * l / 6.0);
  const double rho_ip = p.density_kgpm3 * s.polar_ip_m4;
  addPair(m, 3, 9, rho_ip * l / 3.0, rho_ip * l / 6.0);
  const Mat4 bend = hermiteMass(rho_a, l);
  addPlane(m, bend, kPlaneXY, false);
  addPlane(m, bend, kPlaneXZ, true);
  return toGlobal(m, beamTriad(x1_W_m, x2_W_m, orientation_W));
}

Mat12 beamLumpedMass(const Vec3& x1_W_m, const Vec3& x2_W_m, const Vec3& orientation_W,
                     const BeamProperties& p) {
  const double l = beamLength(x1_W_m, x2_W_m);
  const BeamSection& s = p.section;
  const double mass = p.density_kgpm3 * s.area_m2 * l;
  // HRZ: consistent rotational diagonal 4 L^2 (rho A L / 420) scaled by 420 / 312.
  const double bending_rotary = mass * l * l / 78.0;
  const double torsion_rotary = p.density_kgpm3 * s.polar_ip_m4 * l / 2.0;
  Mat12 m = Mat12::Zero();
  for (int node = 0; node < 2; ++node) {
    const int o = 6 * node;
    for (int i = 0; i < 3; ++i) m(o + i, o + i) = mass / 2.0;
    m(o + 3, o + 3) = torsion_rotary;
    m(o + 4, o + 4) = bending_rotary;
    m(o + 5, o + 5) = bending_rotary;
  }
  return toGlobal(m, beamTriad(x1_W_m, x2_W_m, orientation_W));
}

Mat12 beamGeometricStiffness(const Vec3& x1_W_m, const Vec3& x2_W_m, const Vec3& orientation_W,
                             const BeamProperties& p, double axial_force_n, bool wagner_torsion) {
  const double l = beamLength(x1_W_m, x2_W_m);
  Mat12 k = Mat12::Zero();
  const Mat4 plane = hermiteGeometric(axial_force_n, l);
  addPlane(k, plane, kPlaneXY, false);
  addPlane(k, plane, kPlaneXZ, true);
  if (wagner_torsion) {
    const double kt = axial_force_n * p.section.polar_ip_m4 / (p.section.area_m2 * l);
    addPair(k, 3, 9, kt, -kt);
  }
  return toGlobal(k, beamTriad(x1_W_m, x2_W_m, orientation_W));
}

}  // namespace orni::structure
