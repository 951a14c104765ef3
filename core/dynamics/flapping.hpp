// Prescribed flapping at the hinge P2: delta_M(t) = A sin(2 pi f t) (paper section 3, Fig. 3),
// phi = -delta_M is the rotation of W about x_B (frames.hpp).
#pragma once

#include <cmath>

#include "core/model/frames.hpp"

namespace orni {

struct FlapState {
  double delta_rad = 0.0, delta_dot_radps = 0.0, delta_ddot_radps2 = 0.0;
  double phi_rad = 0.0, phi_dot_radps = 0.0, phi_ddot_radps2 = 0.0;  ///< phi = -delta_M
};

/// Flap angle and its derivatives at time t for amplitude A (rad) and frequency f (Hz).
inline FlapState flapStateAt(double amplitude_rad, double freq_hz, double t_s) {
  const double w = 2.0 * kPi * freq_hz;
  const double s = std::sin(w * t_s), c = std::cos(w * t_s);
  FlapState st;
  st.delta_rad = amplitude_rad * s;
  st.delta_dot_radps = amplitude_rad * w * c;
  st.delta_ddot_radps2 = -amplitude_rad * w * w * s;
  st.phi_rad = -st.delta_rad;
  st.phi_dot_radps = -st.delta_dot_radps;
  st.phi_ddot_radps2 = -st.delta_ddot_radps2;
  return st;
}

}  // namespace orni
