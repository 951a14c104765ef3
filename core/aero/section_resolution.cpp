// Resolution of strip loads into a force and a moment about the strip reference point P
// (docs/theory.md 5.5, M18 generalised to any point on the chord line).
#include <Eigen/Geometry>

#include "core/aero/mst_strip.hpp"

namespace orni::aero {

void resolveSectionLoads(const SectionLoads& loads, const StripGeometry& geometry,
                         const Vec3& e_c, const Vec3& n, Vec3* force_N, Vec3* moment_P_Nm) {
  const double c = geometry.chord_m;
  const double x_P = geometry.ref_aft_of_le_m;
  // 5.5: F = dN n + dFx e_c (dFx acts on the chord line: no lever arm about P on the chord).
  if (force_N != nullptr) *force_N = (loads.dN_c4_N + loads.dN_c2_N) * n + loads.dFx_N * e_c;
  if (moment_P_Nm != nullptr) {
    // A normal force N at x aft of the LE has r = -(x - x_P) e_c from P: r x (N n) =
    // -(x - x_P) N (e_c x n). Couples act about a_pitch = e_c x n (nose-up).
    const double moment_about_pitch_axis_Nm = -(0.25 * c - x_P) * loads.dN_c4_N -
                                              (0.5 * c - x_P) * loads.dN_c2_N +
                                              loads.dM_couple_Nm;
    *moment_P_Nm = moment_about_pitch_axis_Nm * e_c.cross(n);
  }
}

}  // namespace orni::aero
