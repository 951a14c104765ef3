// Options of a settled free flight (free_flight_trim.hpp); light header for the study files.
#pragma once

namespace orni {

struct SettledFlightOptions {
  int cycles = 120;            ///< flapping cycles flown, [6, 100000]
  int window_cycles = 40;      ///< the last cycles averaged, [1, cycles - 1]
  double settled_theta_drift_rad = 0.0035;  ///< max change of the theta mean between the two
                                            ///< halves of the window (0.2 deg)
};

}  // namespace orni
