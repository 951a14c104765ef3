// The loads on the fuselage about P1 at one instant (paper Eq. 2): a result type of its own, so
// that the headers that fill or read it (the flight-path frame, the recorders, the summaries)
// need not include the flight core that computes it.
#pragma once

namespace orni {

/// Loads on the fuselage about P1 at one instant, resolved in the flight-path frame:
/// FV perpendicular to the flight velocity (up), FH along it (forward), M nose-up (paper Eq. 2).
struct LoadSample {
  double FV_N = 0, FH_N = 0, M_Nm = 0;              ///< total: wings (aero + inertial) + tail
  double FV_wing_aero_N = 0, FH_wing_aero_N = 0, M_wing_aero_Nm = 0;
  double FV_wing_inertial_N = 0, FH_wing_inertial_N = 0, M_wing_inertial_Nm = 0;
  double FV_tail_N = 0, FH_tail_N = 0, M_tail_Nm = 0;
  double FH_body_N = 0;       ///< fuselage parasite drag (body.drag_area_m2), at P1
  double power_aero_W = 0;    ///< aerodynamic input power of both wings (M19 generalised)
  double power_hinge_W = 0;   ///< mechanical power at the two hinges (aero + wing inertia)
  double separated_fraction = 0;  ///< area-weighted mean of (1 - f) over the strips
  double tail_alpha_rad = 0;
  double tip_deflection_m = 0;    ///< flexible wing: elastic deflection of the tip LE, up +
  double tip_twist_rad = 0;       ///< flexible wing: elastic twist of the tip strip, nose-up +
};

/// Channels integrated as quadrature states for exact cycle means.
constexpr int kQuadratureChannels = 5;  // FV, FH, M, power_aero, power_hinge

}  // namespace orni
