#include "core/model/wing_inertia.hpp"

#include <cmath>
#include <stdexcept>

#include "core/model/wing_geometry.hpp"

namespace orni {

RigidBodyInertia rodInertia(const Vec3& a_W_m, const Vec3& b_W_m, double mass_kg) {
  const Vec3 d = b_W_m - a_W_m;
  // Integral over t in [0, 1] of r r^T with r = a + t d.
  const Mat3 rrT = a_W_m * a_W_m.transpose() +
                   0.5 * (a_W_m * d.transpose() + d * a_W_m.transpose()) +
                   d * d.transpose() / 3.0;
  RigidBodyInertia out;
  out.mass_kg = mass_kg;
  out.first_moment_W_kgm = mass_kg * (a_W_m + 0.5 * d);
  out.inertia_P2_W_kgm2 = mass_kg * (rrT.trace() * Mat3::Identity() - rrT);
  return out;
}

namespace {

const Material& requireMaterial(const VehicleModel& v, const std::string& name) {
  const Material* m = v.findMaterial(name);
  if (!m) throw std::invalid_argument("wing references unknown material '" + name + "'");
  return *m;
}

// Skin: surface density sigma over x in [-c(y), 0], y in [0, s], z = 0.
RigidBodyInertia skinInertia(const WingModel& wing, double sigma_kgpm2) {
  // Second moments of the planform: S0 = int c dy, Sx = int -c^2/2 dy, Sy = int y c dy,
  // Sxx = int c^3/3 dy, Syy = int y^2 c dy, Sxy = int y (-c^2/2) dy.
  double S0 = 0, Sx = 0, Sy = 0, Sxx = 0, Syy = 0, Sxy = 0;
  const int panels = 400;
  // 4-point Gauss-Legendre on each panel.
  const double gx[4] = {-0.8611363115940526, -0.3399810435848563, 0.3399810435848563,
                        0.8611363115940526};
  const double gw[4] = {0.3478548451374538, 0.6521451548625461, 0.6521451548625461,
                        0.3478548451374538};
  const double s = wing.semispan_m;
  const bool ellipse = wing.planform == Planform::kQuarterEllipse;
  // Ellipse: y = s sin(phi), dy = s cos(phi) dphi, phi in [0, pi/2] (smooth integrand).
  const double upper = ellipse ? 0.5 * kPi : s;
  const double h = upper / panels;
  for (int p = 0; p < panels; ++p) {
    const double mid = (p + 0.5) * h;
    for (int g = 0; g < 4; ++g) {
      const double u = mid + 0.5 * h * gx[g];
      const double y = ellipse ? s * std::sin(u) : u;
      const double jac = ellipse ? s * std::cos(u) : 1.0;
      const double w = 0.5 * h * gw[g] * jac;
      const double c = chordAt(wing, y);
      S0 += w * c;
      Sx += w * (-0.5 * c * c);
      Sy += w * y * c;
      Sxx += w * c * c * c / 3.0;
      Syy += w * y * y * c;
      Sxy += w * y * (-0.5 * c * c);
    }
  }
  RigidBodyInertia out;
  out.mass_kg = sigma_kgpm2 * S0;
  out.first_moment_W_kgm = sigma_kgpm2 * Vec3(Sx, Sy, 0.0);
  Mat3 rrT;
  rrT << Sxx, Sxy, 0, Sxy, Syy, 0, 0, 0, 0;
  rrT *= sigma_kgpm2;
  out.inertia_P2_W_kgm2 = rrT.trace() * Mat3::Identity() - rrT;
  return out;
}

}  // namespace

WingMassBreakdown computeWingInertia(const VehicleModel& vehicle) {
  WingMassBreakdown out;
  for (const WingMember& m : vehicle.wing.members) {
    const Material& mat = requireMaterial(vehicle, m.material);
    const Vec3 a(m.start_x_W_m, m.start_y_W_m, 0.0);
    const Vec3 b(m.end_x_W_m, m.end_y_W_m, 0.0);
    const double d = vehicle.wing.memberDiameter(m);
    const double area_m2 = 0.25 * kPi * d * d;
    const double mass = mat.density_kgpm3 * area_m2 * (b - a).norm();
    out.total += rodInertia(a, b, mass);
    out.members_kg += mass;
  }
  if (!vehicle.wing.skin.material.empty()) {
    const Material& mat = requireMaterial(vehicle, vehicle.wing.skin.material);
    const RigidBodyInertia skin =
        skinInertia(vehicle.wing, mat.density_kgpm3 * vehicle.wing.skin.thickness_m);
    out.total += skin;
    out.skin_kg = skin.mass_kg;
  }
  return out;
}

}  // namespace orni
