#include "studies/runner/commands/continuation_command.hpp"
#include "studies/runner/output/console.hpp"

#include <complex>
#include <stdexcept>
#include <chrono>
#include <string>
#include <string_view>
#include <vector>

#include "core/dynamics/flight_core.hpp"
#include "core/model/cancellation.hpp"
#include "core/model/frames.hpp"
#include "studies/runner/config/continuation_section.hpp"
#include "studies/runner/output/atomic_file.hpp"
#include "studies/runner/output/continuation_journal.hpp"
#include "studies/runner/output/csv_table.hpp"
#include "studies/runner/output/json_writer.hpp"
#include "studies/runner/output/point_journal.hpp"
#include "studies/runner/output/summary_file.hpp"
#include "studies/runner/plotting/gnuplot.hpp"
#include "studies/runner/plotting/trim_figures.hpp"

namespace orni::studies {

namespace fs = std::filesystem;

namespace {

double parameterFileValue(PeriodicControl parameter, const TrimContinuationPoint& p) {
  const double v = continuationParameterValue(parameter, p.solution, p.cg_shift_m);
  return parameter == PeriodicControl::kTailAngle ? v * kRadToDeg : v;
}

std::string parameterUnit(PeriodicControl parameter) {
  switch (parameter) {
    case PeriodicControl::kFrequency: return "Hz";
    case PeriodicControl::kTailAngle: return "deg";
    case PeriodicControl::kCgPosition: return "m";
  }
  return "-";
}

CsvTable branchTable(PeriodicControl parameter, const std::vector<TrimContinuationPoint>& pts) {
  using P = TrimContinuationPoint;
  auto leading = [](const P& p) {
    return p.orbit.multipliers.size() ? p.orbit.multipliers[0] : std::complex<double>(0.0, 0.0);
  };
  return RowTable("continuation.csv", pts)
      .number("point", [](const P& p) { return p.orbit.index; })
      .number(continuationParameterName(parameter), parameterUnit(parameter),
              [&](const P& p) { return parameterFileValue(parameter, p); })
      .number("freq_hz", [](const P& p) { return p.solution.freq_hz; })
      .number("theta_mean_deg", [](const P& p) { return p.solution.theta_rad * kRadToDeg; })
      .number("speed_mps", [](const P& p) { return p.solution.speed_mps; })
      .number("tail_angle_deg", [](const P& p) { return p.solution.tail_angle_rad * kRadToDeg; })
      .number("cg_shift_m", [](const P& p) { return p.cg_shift_m; })
      .number("power_aero_W", [](const P& p) { return p.mean.power_aero_W; })
      .number("max_modulus", [](const P& p) { return p.orbit.max_modulus; })
      .number("stable", [](const P& p) { return p.orbit.stable ? 1.0 : 0.0; })
      .number("leading_mu_real", [&](const P& p) { return leading(p).real(); })
      .number("leading_mu_imag", [&](const P& p) { return leading(p).imag(); })
      .number("periodic_residual", [](const P& p) { return p.orbit.residual_max; })
      .number("corrector_iterations", [](const P& p) { return p.orbit.corrector_iterations; })
      .number("arclength", [](const P& p) { return p.orbit.arclength; })
      .number("theta_min_deg", [](const P& p) { return p.mean.theta_min_rad * kRadToDeg; })
      .number("theta_max_deg", [](const P& p) { return p.mean.theta_max_rad * kRadToDeg; })
      .number("altitude_p2p_m", [](const P& p) { return p.mean.altitude_p2p_m; })
      .text("event", [](const P& p) { return p.orbit.event; })
      .text("leading_label", [](const P& p) { return p.leading_label; })
      .table();
}

// Stable stretches as [from, to] of the parameter (file units), in branch order.
std::vector<JsonObject> stableStretches(PeriodicControl parameter,
                                        const std::vector<TrimContinuationPoint>& pts) {
  std::vector<JsonObject> out;
  bool open = false;
  double start = 0.0, last = 0.0;
  for (const TrimContinuationPoint& p : pts) {
    const double v = parameterFileValue(parameter, p);
    if (p.orbit.stable && !open) {
      open = true;
      start = v;
    } else if (!p.orbit.stable && open) {
      out.push_back(JsonObject().set("from", start).set("to", last));
      open = false;
    }
    last = v;
  }
  if (open) out.push_back(JsonObject().set("from", start).set("to", last));
  return out;
}

JsonObject startObject(const PeriodicTrimSummary& s) {
  JsonObject o;
  o.set("converged", s.converged).set("message", s.message);
  setOperatingPoint(o, s.solution)
      .set("cg_shift_m", s.cg_shift_m)
      .set("friction_speed_mps", s.friction_speed_mps);
  if (s.converged)
    o.set("periodic_residual", s.shooting.residual_max);
  else
    o.setNull("periodic_residual");
  return o;
}

}  // namespace

int runContinuationStudy(const Study& study, const fs::path& out_dir, int threads) {
  const auto t0 = std::chrono::steady_clock::now();
  TrimContinuationOptions co = study.continuation();
  co.threads = threads;
  const FlightCoreModel model(study.vehicle);
  const std::string resolved = resolvedStudyToml(study);
  const std::uint64_t fingerprint = fnv1a64(versionString() + "\n" + resolved);
  fs::create_directories(out_dir);

  // Records: the start, at most max_points regular points and as many events.
  const std::size_t capacity = 2 * static_cast<std::size_t>(co.max_points) + 2;
  PointJournalResume resume;
  PointJournal journal(
      out_dir / kContinuationJournalName, "continuation", fingerprint, capacity,
      [](std::size_t, std::string_view payload) {
        TrimContinuationPoint p;
        return decodeContinuationPoint(payload, &p);
      },
      &resume);
  // The recorded branch: the longest run of records from the first, cut after its last regular
  // point (an event's point is recomputed with the step that finds it).
  std::vector<TrimContinuationPoint> done;
  for (std::size_t i = 0; i < capacity && resume.payloads[i]; ++i) {
    TrimContinuationPoint p;
    decodeContinuationPoint(*resume.payloads[i], &p);
    done.push_back(p);
  }
  while (!done.empty() && !done.back().orbit.event.empty()) done.pop_back();
  if (resume.existed && !resume.fingerprint_matched)
    consoleErr() << "continuation: " << journal.path().string()
              << " discarded: starting afresh\n";
  else if (!done.empty())
    consoleErr() << "continuation: resuming from " << journal.path().string() << " after point "
              << done.back().orbit.index << " (" << done.size() << " records)\n";

  std::vector<TrimContinuationPoint> points = done;
  const TrimContinuationSummary s = continueTrim(
      model, study.trim, co,
      [&](const TrimContinuationPoint& p) {
        journal.append(points.size(), encodeContinuationPoint(p));
        throwIfCancelled();  // a cancellation point per point, after it is journaled
        // The point as the journal holds it, so that a resumed run writes the same bytes.
        TrimContinuationPoint exact;
        if (!decodeContinuationPoint(encodeContinuationPoint(p), &exact))
          throw std::logic_error("continuation: a point does not survive its journal encoding");
        points.push_back(exact);
        consoleErr() << "continuation: " << (p.orbit.event.empty() ? "point " : p.orbit.event + " ")
                  << p.orbit.index << ": " << continuationParameterName(co.parameter) << " "
                  << parameterFileValue(co.parameter, p)
                  << (p.orbit.stable ? " stable" : " unstable") << ", max |mu| "
                  << p.orbit.max_modulus << "\n";
        return true;
      },
      done);

  const bool failed = s.status == ContinuationStatus::kFailed;
  writeFileAtomic(out_dir / "study.resolved.toml", resolved);
  writeFileAtomic(out_dir / "continuation.csv", branchTable(co.parameter, points).toString());
  std::vector<JsonObject> events;
  int stable_points = 0, regular = 0;
  for (const TrimContinuationPoint& p : points) {
    if (!p.orbit.event.empty()) {
      events.push_back(JsonObject()
                           .set("event", p.orbit.event)
                           .set(continuationParameterName(co.parameter),
                                parameterFileValue(co.parameter, p))
                           .set("theta_mean_deg", p.solution.theta_rad * kRadToDeg)
                           .set("speed_mps", p.solution.speed_mps)
                           .set("tail_angle_deg", p.solution.tail_angle_rad * kRadToDeg)
                           .set("max_modulus", p.orbit.max_modulus)
                           .set("leading_label", p.leading_label));
    } else {
      ++regular;
      stable_points += p.orbit.stable ? 1 : 0;
    }
  }
  const double wall_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  JsonObject summary = summaryHeader("continuation", toString(s.status), s.message, wall_s);
  summary.set("parameter", continuationParameterName(co.parameter))
      .set("parameter_unit", parameterUnit(co.parameter))
      .set("control", toString(study.trim.periodic.control))
      .set("to", co.parameter == PeriodicControl::kTailAngle ? co.to * kRadToDeg : co.to)
      .set("points", regular)
      .set("points_stable", stable_points)
      .set("points_resumed", static_cast<int>(done.size()))
      .setObjects("events", events)
      .setObjects("stable_stretches", stableStretches(co.parameter, points))
      .set("start", startObject(s.start))
      .set("friction_note",
           "skin friction frozen during each step at the previous point's mean airspeed (a "
           "periodic trim solved at a point directly takes its own orbit's: they differ by "
           "that one step)")
      .set("stability_note",
           std::string("stable = every Floquet multiplier of the orbit's states (body, wing "
                       "modes, MST-TD states; altitude and position excluded) inside the unit "
                       "circle; ") +
               (study.trim.periodic.multipliers > 0
                    ? "the leading " + std::to_string(study.trim.periodic.multipliers) +
                          " multipliers by Arnoldi at every point (trim.periodic.multipliers; "
                          "0 = all from the full monodromy matrix)"
                    : std::string("all multipliers from the full monodromy matrix at every "
                                  "point (trim.periodic.multipliers = 0)")))
      .set("period_maps", s.period_maps);
  writeSummary(out_dir, summary);
  if (!points.empty())
    drawFigure(out_dir, "continuation",
               continuationBranchFigure(study, co.parameter, parameterUnit(co.parameter),
                                        study.trim.periodic.control, toString(s.status)));
  journal.remove();  // every point is in continuation.csv and the figure is drawn
  consoleOut() << study.name << ": continuation " << toString(s.status) << ": " << regular
            << " points, " << events.size() << " events; " << s.message << "\n  -> "
            << out_dir.string() << "\n";
  return failed ? 1 : 0;
}

}  // namespace orni::studies
