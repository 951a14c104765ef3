// 3-D Euler-Bernoulli beam element, 12 DOF (docs/theory.md 2.2): stiffness, consistent and lumped
// mass, geometric stiffness. Matrices are returned in W components for the DOF order
// (u, v, w, theta_x, theta_y, theta_z) of node 1, then node 2.
#pragma once

#include "core/structure/fe_types.hpp"

namespace orni::structure {

/// Cross-section constants (docs/theory.md 2.2 table). Local axes: x' along the beam, z' from the
/// orientation vector (the wing normal), y' = z' x x'.
struct BeamSection {
  double area_m2 = 0.0;         ///< A
  double inertia_y_m4 = 0.0;    ///< I_y' = int z'^2 dA: bending in the x'-z' plane (w, theta_y)
  double inertia_z_m4 = 0.0;    ///< I_z' = int y'^2 dA: bending in the x'-y' plane (v, theta_z)
  double torsion_j_m4 = 0.0;    ///< J, torsion constant
  double polar_ip_m4 = 0.0;     ///< I_p, polar moment for the torsional mass
};

/// Solid circular rod of diameter d (> 0).
BeamSection solidRodSection(double diameter_m);

/// Section plus isotropic material: everything an element needs.
struct BeamProperties {
  BeamSection section;
  double youngs_modulus_pa = 0.0;  ///< E
  double shear_modulus_pa = 0.0;   ///< G = E / (2 (1 + nu))
  double density_kgpm3 = 0.0;      ///< rho
};

BeamProperties makeBeamProperties(const BeamSection& section, double youngs_modulus_pa,
                                  double poisson_ratio, double density_kgpm3);

/// Rotation Lambda whose rows are x', y', z' in W: x' = (x2 - x1)/L,
/// z' = normalize(n - (n.x') x') with n = orientation_W (x_W if n is parallel to the axis),
/// y' = z' x x'.
Mat3 beamTriad(const Vec3& x1_W_m, const Vec3& x2_W_m, const Vec3& orientation_W);

/// Elastic stiffness K = T^T K' T (12 x 12, N/m, N, N m).
Mat12 beamStiffness(const Vec3& x1_W_m, const Vec3& x2_W_m, const Vec3& orientation_W,
                    const BeamProperties& p);

/// Consistent mass (axial, torsion, Hermitian bending; no rotary bending inertia),
/// kg, kg m, kg m^2.
Mat12 beamConsistentMass(const Vec3& x1_W_m, const Vec3& x2_W_m, const Vec3& orientation_W,
                         const BeamProperties& p);

/// Lumped mass: rho A L / 2 per node and direction; rotations by HRZ scaling of the consistent
/// diagonal (rho A L^3 / 78 about y', z'; rho I_p L / 2 about x'), rotated to W (3 x 3 blocks).
Mat12 beamLumpedMass(const Vec3& x1_W_m, const Vec3& x2_W_m, const Vec3& orientation_W,
                     const BeamProperties& p);

/// Geometric stiffness for the axial force N (tension positive, N), both bending planes;
/// `wagner_torsion` adds N I_p / (A L) on the torsion DOFs (docs/theory.md 2.2).
Mat12 beamGeometricStiffness(const Vec3& x1_W_m, const Vec3& x2_W_m, const Vec3& orientation_W,
                             const BeamProperties& p, double axial_force_n,
                             bool wagner_torsion = false);

}  // namespace orni::structure
