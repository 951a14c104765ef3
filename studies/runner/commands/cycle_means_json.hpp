// The "mean" object of summary.json (simulate, trim): the cycle means of the tethered loads.
#pragma once

#include "core/dynamics/tethered_simulation.hpp"
#include "studies/runner/output/json_writer.hpp"

namespace orni::studies {

/// {"FV_N", "FH_N", "M_Nm", "power_W" (aerodynamic), "hinge_power_W"}, in that order.
JsonObject cycleMeansJson(const CycleMeans& mean);

}  // namespace orni::studies
