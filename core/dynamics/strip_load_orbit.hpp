// One cycle of a flexible wing's tethered periodic orbit, sampled with what a full-order model of
// the same wing needs to be driven by it (studies/tools/orni_flapping_reference, docs/theory.md 4.7
// "A flapping reference"): the modal state and the strip loads the kernel gave at every sample.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/dynamics/flight_core.hpp"

namespace orni {

struct StripLoadOrbit {
  std::vector<double> t_s;                 ///< samples 0..S of the cycle after the settling ones
  std::vector<Eigen::VectorXd> q, qd;      ///< modal state (M each)
  std::vector<Eigen::Matrix3Xd> force_W;   ///< strip forces (3 x ns, W, one wing; without the
                                           ///< apparent-mass force of q'', which is A(f) q'')
  std::vector<Eigen::VectorXd> moment_Nm;  ///< moment about e_s per strip (ns, nose-up)
  std::vector<Eigen::VectorXd> separation_f;  ///< f of A(f) per strip (ns)
};

/// The tethered run of `model` (flexible wing) at `point` with the default simulation options,
/// `settle_cycles` cycles and then one more sampled `samples` times (S + 1 samples, both ends).
/// Throws std::runtime_error when the integration fails, std::invalid_argument for a rigid wing.
StripLoadOrbit recordStripLoadOrbit(const FlightCoreModel& model, const OperatingPoint& point,
                                    int settle_cycles, int samples);

}  // namespace orni
