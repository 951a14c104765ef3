// Flat triangular shell facet = CST membrane + DKT plate (docs/theory.md 2.3). 18 DOF, node order
// as given, per node (u, v, w, theta_x, theta_y, theta_z) in W components. No drilling
// stiffness (docs/theory.md 2.4).
#pragma once

#include <array>

#include "core/structure/fe_types.hpp"

namespace orni::structure {

using Mat9 = Eigen::Matrix<double, 9, 9>;
using Mat3x9 = Eigen::Matrix<double, 3, 9>;
using Mat3x6 = Eigen::Matrix<double, 3, 6>;

/// Uniform isotropic shell.
struct ShellProperties {
  double thickness_m = 0.0;        ///< t, > 0
  double youngs_modulus_pa = 0.0;  ///< E
  double poisson_ratio = 0.3;      ///< nu
  double density_kgpm3 = 0.0;      ///< rho
};

/// The facet triad: rows e1, e2, n in W, with n = normalize((x2 - x1) x (x3 - x1)) (so the
/// facet is counter-clockwise about n) and e1 the projection of x_W on the facet plane
/// (edge 1-2 if x_W is normal to it). For a counter-clockwise facet in the (x_W, y_W) plane it is
/// the identity. Throws std::invalid_argument for a degenerate triangle.
Mat3 shellTriad(const std::array<Vec3, 3>& x_W_m);

/// CST strain-displacement matrix B_m (3 x 6, local membrane DOF u1 v1 u2 v2 u3 v3) for local 2-D
/// coordinates; strains (eps_x, eps_y, gamma_xy).
Mat3x6 cstStrainMatrix(const std::array<Eigen::Vector2d, 3>& xy_m);

/// DKT curvature matrix B_b (3 x 9, local DOF w, theta_x, theta_y per node) at the reference
/// point (xi, eta); curvatures (beta_x,x, beta_y,y, beta_x,y + beta_y,x) with beta_x = theta_y,
/// beta_y = -theta_x (Batoz, Bathe & Ho 1980).
Mat3x9 dktCurvatureMatrix(const std::array<Eigen::Vector2d, 3>& xy_m, double xi, double eta);

/// DKT bending stiffness in local DOF (9 x 9), exact 3-point mid-side quadrature.
Mat9 dktStiffness(const std::array<Eigen::Vector2d, 3>& xy_m, const ShellProperties& p);

/// Facet stiffness K (18 x 18) in W: CST membrane + DKT bending, rotated with shellTriad.
Mat18 shellStiffness(const std::array<Vec3, 3>& x_W_m, const ShellProperties& p);

/// Consistent facet mass: linear-triangle translational mass rho t A / 12 [2 1 1; 1 2 1; 1 1 2]
/// per direction, plus the rotary inertia rho t^3/12 A/3 on every rotational DOF
/// (docs/theory.md 2.3).
Mat18 shellConsistentMass(const std::array<Vec3, 3>& x_W_m, const ShellProperties& p);

/// Lumped facet mass: rho t A / 3 per node and direction, the same rotary inertia.
Mat18 shellLumpedMass(const std::array<Vec3, 3>& x_W_m, const ShellProperties& p);

/// Facet area (m^2).
double triangleArea(const std::array<Vec3, 3>& x_W_m);

}  // namespace orni::structure
