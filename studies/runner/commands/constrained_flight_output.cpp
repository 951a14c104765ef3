#include "studies/runner/commands/constrained_flight_output.hpp"

#include <limits>
#include <optional>

#include "core/dynamics/flapping.hpp"
#include "core/model/frames.hpp"
#include "studies/runner/output/atomic_file.hpp"

namespace orni::studies {

namespace {

/// NaN (written as null by JsonObject) for an undefined value.
double orNull(const std::optional<double>& v) {
  return v ? *v : std::numeric_limits<double>::quiet_NaN();
}

JsonObject statsJson(const ChannelStats& s) {
  return JsonObject()
      .set("mean", s.mean)
      .set("min", s.min)
      .set("max", s.max)
      .set("amplitude", s.amplitude);
}

JsonObject epsilonJson(const EpsilonMetrics& m) {
  return JsonObject()
      .set("samples", m.samples)
      .set("defined_samples", m.defined_samples)
      .set("weighted_mean", orNull(m.weighted_mean))
      .set("of_mean_loads", orNull(m.of_mean_loads))
      .set("min", orNull(m.min))
      .set("max", orNull(m.max));
}

}  // namespace

CsvTable zmpTable(const ConstrainedFlightTest& test) {
  using S = ZmpSample;
  return RowTable("zmp.csv", test.samples)
      .text("t", [](const S& s) { return formatCell(s.t_s); })
      .text("delta_M", [](const S& s) { return formatCell(s.delta_rad * kRadToDeg); })
      .text("stroke", [](const S& s) { return std::string(toString(s.stroke)); })
      .text("CF_V", [](const S& s) { return formatCell(s.coefficients.CF_V); })
      .text("CF_H", [](const S& s) { return formatCell(s.coefficients.CF_H); })
      .text("CM_CG", [](const S& s) { return formatCell(s.coefficients.CM_CG); })
      .text("epsilon",
            [](const S& s) { return s.epsilon ? formatCell(*s.epsilon) : std::string(); })
      .text("CF_normal", [](const S& s) { return formatCell(s.denominator); })
      .table();
}

JsonObject zmpSummary(const ConstrainedFlightTest& test) {
  const CoefficientReference& r = test.reference;
  return JsonObject()
      .set("cycle_samples", static_cast<int>(test.samples.size()))
      .set("reference", JsonObject()
                            .set("dynamic_pressure_Pa", r.dynamic_pressure_Pa)
                            .set("wing_area_m2", r.wing_area_m2)
                            .set("mean_chord_m", r.mean_chord_m)
                            .set("theta_mean_deg", r.theta_mean_rad * kRadToDeg))
      .set("CF_V", statsJson(test.CF_V))
      .set("CF_H", statsJson(test.CF_H))
      .set("CM_CG", statsJson(test.CM_CG))
      .set("epsilon",
           JsonObject()
               .set("definition",
                    "(x_ZMP - x_CG)/c_mean = -CM_CG/(CF_V cos theta - CF_H sin theta), "
                    "> 0: ZMP aft of the CG")
               .set("singular_fraction", test.options.singular_fraction)
               .set("CF_normal_max_abs", test.denominator_max_abs)
               .set("singular_threshold", test.singular_threshold)
               .set("cycle", epsilonJson(test.cycle))
               .set("upstroke", epsilonJson(test.upstroke))
               .set("downstroke", epsilonJson(test.downstroke)));
}

}  // namespace orni::studies
