// Mass properties of the rigid wing from its members (solid rods) and skin (uniform shell), about
// the hinge P2 in W components. Used by the rigid-wing level (structure L0) so that the tethered
// constraint forces contain the wing inertial loads as a load cell measures them.
#pragma once

#include "core/model/frames.hpp"
#include "core/model/vehicle_model.hpp"

namespace orni {

struct RigidBodyInertia {
  double mass_kg = 0.0;
  Vec3 first_moment_W_kgm = Vec3::Zero();   ///< sum m r, r from P2 (W components)
  Mat3 inertia_P2_W_kgm2 = Mat3::Zero();    ///< sum m (|r|^2 I - r r^T) about P2

  Vec3 centerOfMass_W_m() const {
    return mass_kg > 0.0 ? Vec3(first_moment_W_kgm / mass_kg) : Vec3::Zero();
  }
  RigidBodyInertia& operator+=(const RigidBodyInertia& o) {
    mass_kg += o.mass_kg;
    first_moment_W_kgm += o.first_moment_W_kgm;
    inertia_P2_W_kgm2 += o.inertia_P2_W_kgm2;
    return *this;
  }
};

struct WingMassBreakdown {
  RigidBodyInertia total;
  double members_kg = 0.0;
  double skin_kg = 0.0;
};

/// Inertia of a uniform thin rod from a to b (W components, about the origin P2).
RigidBodyInertia rodInertia(const Vec3& a_W_m, const Vec3& b_W_m, double mass_kg);

/// Mass properties of one (right) wing: members as thin rods, skin as a uniform surface density
/// over the planform (exact in x, Gauss quadrature in the smooth angle variable along y).
/// Throws std::invalid_argument if a referenced material is missing.
WingMassBreakdown computeWingInertia(const VehicleModel& vehicle);

}  // namespace orni
