// CST membrane + DKT plate facet (docs/theory.md 2.3; Batoz, Bathe & Ho 1980).
#include "core/structure/shell_element.hpp"

#include <cmath>
#include <stdexcept>

namespace orni::structure {
namespace {

using Vec2 = Eigen::Vector2d;
using Vec9 = Eigen::Matrix<double, 9, 1>;
using Mat6 = Eigen::Matrix<double, 6, 6>;

Mat3 planeStressMatrix(double nu) {
  Mat3 c;
  c << 1.0, nu, 0.0, nu, 1.0, 0.0, 0.0, 0.0, 0.5 * (1.0 - nu);
  return c;
}

// Local 2-D coordinates of the vertices in the facet triad, origin at vertex 1.
std::array<Vec2, 3> localCoordinates(const std::array<Vec3, 3>& x, const Mat3& triad) {
  std::array<Vec2, 3> xy;
  for (int i = 0; i < 3; ++i) {
    const Vec3 d = x[static_cast<std::size_t>(i)] - x[0];
    xy[static_cast<std::size_t>(i)] = Vec2(triad.row(0).dot(d), triad.row(1).dot(d));
  }
  return xy;
}

// Per-side DKT coefficients a_k, b_k, c_k, d_k, e_k; side s = 0, 1, 2 is mid-side node 4, 5, 6 of
// Batoz et al., joining vertices (1,2), (2,0), (0,1) (0-based).
struct DktSides {
  double a[3], b[3], c[3], d[3], e[3];
};

DktSides dktSides(const std::array<Vec2, 3>& xy) {
  constexpr int kI[3] = {1, 2, 0};
  constexpr int kJ[3] = {2, 0, 1};
  DktSides s{};
  for (int k = 0; k < 3; ++k) {
    const Vec2 dij = xy[static_cast<std::size_t>(kI[k])] - xy[static_cast<std::size_t>(kJ[k])];
    const double x = dij.x(), y = dij.y();
    const double l2 = x * x + y * y;
    s.a[k] = -x / l2;
    s.b[k] = 0.75 * x * y / l2;
    s.c[k] = (0.25 * x * x - 0.5 * y * y) / l2;
    s.d[k] = -y / l2;
    s.e[k] = (0.25 * y * y - 0.5 * x * x) / l2;
  }
  return s;
}

// H_x and H_y (or one of their derivatives) from the six quadratic shape-function values (or
// their derivatives) n[0..5] = N1..N6: the table of docs/theory.md 2.3 is linear in the N.
void dktH(const DktSides& s, const double (&n)[6], Vec9& hx, Vec9& hy) {
  for (int i = 0; i < 3; ++i) {
    const int p = (i + 2) % 3;  // side (i, i+1)
    const int q = (i + 1) % 3;  // side (i-1, i)
    const double np = n[3 + p], nq = n[3 + q];
    hx(3 * i) = 1.5 * (s.a[p] * np - s.a[q] * nq);
    hx(3 * i + 1) = s.b[p] * np + s.b[q] * nq;
    hx(3 * i + 2) = n[i] - s.c[p] * np - s.c[q] * nq;
    hy(3 * i) = 1.5 * (s.d[p] * np - s.d[q] * nq);
    hy(3 * i + 1) = -n[i] + s.e[p] * np + s.e[q] * nq;
    hy(3 * i + 2) = -hx(3 * i + 1);
  }
}

Mat3x9 dktCurvature(const std::array<Vec2, 3>& xy, const DktSides& s, double xi, double eta) {
  const double zeta = 1.0 - xi - eta;
  const double dxi[6] = {1.0 - 4.0 * zeta, 4.0 * xi - 1.0, 0.0,
                         4.0 * eta, -4.0 * eta, 4.0 * (zeta - xi)};
  const double deta[6] = {1.0 - 4.0 * zeta, 0.0, 4.0 * eta - 1.0,
                          4.0 * xi, 4.0 * (zeta - eta), -4.0 * xi};
  Vec9 hx_xi, hy_xi, hx_eta, hy_eta;
  dktH(s, dxi, hx_xi, hy_xi);
  dktH(s, deta, hx_eta, hy_eta);
  const double x31 = xy[2].x() - xy[0].x(), y31 = xy[2].y() - xy[0].y();
  const double x12 = xy[0].x() - xy[1].x(), y12 = xy[0].y() - xy[1].y();
  const double two_area = x31 * y12 - x12 * y31;
  Mat3x9 b;
  b.row(0) = (y31 * hx_xi + y12 * hx_eta).transpose();
  b.row(1) = (-x31 * hy_xi - x12 * hy_eta).transpose();
  b.row(2) = (-x31 * hx_xi - x12 * hx_eta + y31 * hy_xi + y12 * hy_eta).transpose();
  return b / two_area;
}

double twiceSignedArea(const std::array<Vec2, 3>& xy) {
  return (xy[1].x() - xy[0].x()) * (xy[2].y() - xy[0].y()) -
         (xy[2].x() - xy[0].x()) * (xy[1].y() - xy[0].y());
}

Mat18 rotateToGlobal(const Mat18& local, const Mat3& triad) {
  if (triad.isIdentity(0.0)) return local;
  Mat18 out;
  for (int a = 0; a < 6; ++a)
    for (int b = 0; b < 6; ++b)
      out.block<3, 3>(3 * a, 3 * b).noalias() =
          triad.transpose() * local.block<3, 3>(3 * a, 3 * b) * triad;
  return out;
}

Mat18 shellMass(const std::array<Vec3, 3>& x_W_m, const ShellProperties& p, bool lumped) {
  const double area = triangleArea(x_W_m);
  const double mass = p.density_kgpm3 * p.thickness_m * area;
  const double rotary =
      p.density_kgpm3 * p.thickness_m * p.thickness_m * p.thickness_m / 12.0 * area / 3.0;
  Mat18 m = Mat18::Zero();
  for (int a = 0; a < 3; ++a) {
    for (int b = 0; b < 3; ++b) {
      const double mab = lumped ? (a == b ? mass / 3.0 : 0.0) : mass / 12.0 * (a == b ? 2.0 : 1.0);
      for (int d = 0; d < 3; ++d) m(6 * a + d, 6 * b + d) = mab;
    }
    for (int r = 3; r < 6; ++r) m(6 * a + r, 6 * a + r) = rotary;
  }
  return m;
}

}  // namespace

double triangleArea(const std::array<Vec3, 3>& x_W_m) {
  return 0.5 * (x_W_m[1] - x_W_m[0]).cross(x_W_m[2] - x_W_m[0]).norm();
}

Mat3 shellTriad(const std::array<Vec3, 3>& x_W_m) {
  const Vec3 e12 = x_W_m[1] - x_W_m[0];
  const Vec3 cross = e12.cross(x_W_m[2] - x_W_m[0]);
  const double norm = cross.norm();
  if (!(norm > 1e-14 * e12.squaredNorm()))
    throw std::invalid_argument("shell facet: expected a non-degenerate triangle");
  const Vec3 n = cross / norm;
  Vec3 e1 = Vec3::UnitX() - n.x() * n;
  if (e1.norm() < 1e-8) e1 = e12;
  e1.normalize();
  Mat3 triad;
  triad.row(0) = e1.transpose();
  triad.row(1) = n.cross(e1).transpose();
  triad.row(2) = n.transpose();
  return triad;
}

Mat3x6 cstStrainMatrix(const std::array<Vec2, 3>& xy_m) {
  const double x1 = xy_m[0].x(), x2 = xy_m[1].x(), x3 = xy_m[2].x();
  const double y1 = xy_m[0].y(), y2 = xy_m[1].y(), y3 = xy_m[2].y();
  const double two_area = (x2 - x1) * (y3 - y1) - (x3 - x1) * (y2 - y1);
  Mat3x6 b;
  b << y2 - y3, 0, y3 - y1, 0, y1 - y2, 0,
       0, x3 - x2, 0, x1 - x3, 0, x2 - x1,
       x3 - x2, y2 - y3, x1 - x3, y3 - y1, x2 - x1, y1 - y2;
  return b / two_area;
}

Mat3x9 dktCurvatureMatrix(const std::array<Vec2, 3>& xy_m, double xi, double eta) {
  return dktCurvature(xy_m, dktSides(xy_m), xi, eta);
}

Mat9 dktStiffness(const std::array<Vec2, 3>& xy_m, const ShellProperties& p) {
  const double t = p.thickness_m, nu = p.poisson_ratio;
  const double rigidity = p.youngs_modulus_pa * t * t * t / (12.0 * (1.0 - nu * nu));
  const Mat3 db = rigidity * planeStressMatrix(nu);
  const DktSides sides = dktSides(xy_m);
  const double weight = std::abs(twiceSignedArea(xy_m)) / 6.0;  // 3-point mid-side rule
  constexpr double kPoints[3][2] = {{0.5, 0.0}, {0.5, 0.5}, {0.0, 0.5}};
  Mat9 k = Mat9::Zero();
  for (const auto& pt : kPoints) {
    const Mat3x9 b = dktCurvature(xy_m, sides, pt[0], pt[1]);
    k.noalias() += weight * (b.transpose() * db * b);
  }
  return k;
}

Mat18 shellStiffness(const std::array<Vec3, 3>& x_W_m, const ShellProperties& p) {
  const Mat3 triad = shellTriad(x_W_m);
  const std::array<Vec2, 3> xy = localCoordinates(x_W_m, triad);
  const double area = 0.5 * twiceSignedArea(xy);
  const double nu = p.poisson_ratio;
  const Mat3 c = (p.youngs_modulus_pa / (1.0 - nu * nu)) * planeStressMatrix(nu);
  const Mat3x6 bm = cstStrainMatrix(xy);
  const Mat6 km = (p.thickness_m * area) * (bm.transpose() * c * bm);
  const Mat9 kb = dktStiffness(xy, p);

  Mat18 k = Mat18::Zero();
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) {
      for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j) k(6 * a + i, 6 * b + j) = km(2 * a + i, 2 * b + j);
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) k(6 * a + 2 + i, 6 * b + 2 + j) = kb(3 * a + i, 3 * b + j);
    }
  return rotateToGlobal(k, triad);
}

Mat18 shellConsistentMass(const std::array<Vec3, 3>& x_W_m, const ShellProperties& p) {
  return shellMass(x_W_m, p, false);
}

Mat18 shellLumpedMass(const std::array<Vec3, 3>& x_W_m, const ShellProperties& p) {
  return shellMass(x_W_m, p, true);
}

}  // namespace orni::structure
