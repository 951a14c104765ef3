#include "studies/runner/commands/cycle_means_json.hpp"

namespace orni::studies {

JsonObject cycleMeansJson(const CycleMeans& mean) {
  return JsonObject()
      .set("FV_N", mean.FV_N)
      .set("FH_N", mean.FH_N)
      .set("M_Nm", mean.M_Nm)
      .set("power_W", mean.power_aero_W)
      .set("hinge_power_W", mean.power_hinge_W);
}

}  // namespace orni::studies
