// The analysis keys of [simulate] and [trim] (studies/runner/config/analysis_fields.hpp): every
// key the field table lists for the groups simulate and trim (`ornithopter keys simulate|trim`)
// has a getter and no getter is for another key, and a change of each setting is seen by its
// getter (a sweep finds the keys that differ between its points by these getters).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "core/model/field_table.hpp"
#include "studies/runner/config/analysis_fields.hpp"
#include "studies/runner/config/study_file.hpp"

namespace orni::studies {
namespace {

namespace fs = std::filesystem;

fs::path repo() { return fs::path(ORNI_SOURCE_DIR); }

std::vector<std::string> tableKeys(std::string_view group) {
  std::vector<std::string> keys;
  for (const FieldSpec& f : fieldTable())
    if (f.group() == group) keys.emplace_back(f.key);
  std::sort(keys.begin(), keys.end());
  return keys;
}

std::vector<std::string> getterKeys(StudyKind run) {
  std::vector<std::string> keys;
  for (const AnalysisField& f : analysisFields(run)) keys.emplace_back(f.key);
  std::sort(keys.begin(), keys.end());
  return keys;
}

TEST(AnalysisFields, SameKeysAsTheFieldTable) {
  EXPECT_EQ(getterKeys(StudyKind::kSimulate), tableKeys("simulate"));
  EXPECT_EQ(getterKeys(StudyKind::kTrim), tableKeys("trim"));
  EXPECT_TRUE(analysisFields(StudyKind::kAeromap).empty());
}

/// A change of every setting, written here member by member (not through the getters).
using Change = std::function<void(Study&)>;
double moved(double x) { return x * 1.5 + 0.25; }

const std::map<std::string, Change>& changes() {
  static const std::map<std::string, Change> kChanges = {
      {"simulate.mode",
       [](Study& s) {
         s.simulate().options.mode = s.simulate().options.mode == FlightMode::kFree
                                         ? FlightMode::kTethered
                                         : FlightMode::kFree;
       }},
      {"simulate.speed_mps", [](Study& s) { s.point.speed_mps = moved(s.point.speed_mps); }},
      {"simulate.freq_hz", [](Study& s) { s.point.freq_hz = moved(s.point.freq_hz); }},
      {"simulate.theta_deg", [](Study& s) { s.point.theta_rad = moved(s.point.theta_rad); }},
      {"simulate.tail_angle_deg",
       [](Study& s) { s.point.tail_angle_rad = moved(s.point.tail_angle_rad); }},
      {"simulate.cycles", [](Study& s) { s.simulate().options.cycles += 1; }},
      {"simulate.rel_tol",
       [](Study& s) { s.simulate().options.rel_tol = moved(s.simulate().options.rel_tol); }},
      {"simulate.abs_tol",
       [](Study& s) { s.simulate().options.abs_tol = moved(s.simulate().options.abs_tol); }},
      {"simulate.separation_abs_tol",
       [](Study& s) {
         s.simulate().options.separation_abs_tol = moved(s.simulate().options.separation_abs_tol);
       }},
      {"simulate.steady_tol",
       [](Study& s) { s.simulate().options.steady_tol = moved(s.simulate().options.steady_tol); }},
      {"simulate.samples_per_cycle", [](Study& s) { s.simulate().options.samples_per_cycle += 1; }},
      {"simulate.history_every", [](Study& s) { s.simulate().history_every += 1; }},
      {"simulate.sampled_loads",
       [](Study& s) {
         s.simulate().options.interpolate_sampled_loads =
             !s.simulate().options.interpolate_sampled_loads;
       }},
      {"simulate.wing_only", [](Study& s) { s.simulate().wing_only = !s.simulate().wing_only; }},
      {"simulate.at_trim", [](Study& s) { s.simulate().at_trim = !s.simulate().at_trim; }},
      {"simulate.free.bound_speed_mps",
       [](Study& s) {
         s.simulate().options.free.bounds.U_mps = moved(s.simulate().options.free.bounds.U_mps);
       }},
      {"simulate.free.bound_W_mps",
       [](Study& s) {
         s.simulate().options.free.bounds.W_mps = moved(s.simulate().options.free.bounds.W_mps);
       }},
      {"simulate.free.bound_theta_deg",
       [](Study& s) {
         s.simulate().options.free.bounds.theta_rad =
             moved(s.simulate().options.free.bounds.theta_rad);
       }},
      {"simulate.free.bound_Q_degps",
       [](Study& s) {
         s.simulate().options.free.bounds.Q_radps = moved(s.simulate().options.free.bounds.Q_radps);
       }},
      {"simulate.free.bound_h_m",
       [](Study& s) {
         s.simulate().options.free.bounds.h_m = moved(s.simulate().options.free.bounds.h_m);
       }},
      {"simulate.free.transient_fraction",
       [](Study& s) {
         s.simulate().options.free.transient_fraction =
             moved(s.simulate().options.free.transient_fraction);
       }},
      {"simulate.free.divergence_ratio",
       [](Study& s) {
         s.simulate().options.free.divergence_ratio =
             moved(s.simulate().options.free.divergence_ratio);
       }},
      {"simulate.free.initial_altitude_m",
       [](Study& s) {
         s.simulate().options.free.initial_altitude_m =
             moved(s.simulate().options.free.initial_altitude_m);
       }},
      {"trim.freq_hz", [](Study& s) { s.trim.initial.freq_hz = moved(s.trim.initial.freq_hz); }},
      {"trim.method",
       [](Study& s) {
         s.trim.method =
             s.trim.method == TrimMethod::kPeriodic ? TrimMethod::kTwoStage : TrimMethod::kPeriodic;
       }},
      {"trim.unknowns", [](Study& s) { s.trim.unknowns.pop_back(); }},
      {"trim.initial.theta_mean_deg",
       [](Study& s) { s.trim.initial.theta_rad = moved(s.trim.initial.theta_rad); }},
      {"trim.initial.speed_mps",
       [](Study& s) { s.trim.initial.speed_mps = moved(s.trim.initial.speed_mps); }},
      {"trim.initial.tail_angle_deg",
       [](Study& s) { s.trim.initial.tail_angle_rad = moved(s.trim.initial.tail_angle_rad); }},
      {"trim.bounds.theta_mean_deg", [](Study& s) { s.trim.bounds[0].lower -= 0.1; }},
      {"trim.bounds.speed_mps", [](Study& s) { s.trim.bounds[1].upper += 0.1; }},
      {"trim.bounds.tail_angle_deg", [](Study& s) { s.trim.bounds[2].lower -= 0.1; }},
      {"trim.bounds.freq_hz", [](Study& s) { s.trim.bounds[3].upper += 0.1; }},
      {"trim.max_iterations", [](Study& s) { s.trim.max_iterations += 1; }},
      {"trim.residual_tol", [](Study& s) { s.trim.residual_tol = moved(s.trim.residual_tol); }},
      {"trim.function_tol", [](Study& s) { s.trim.function_tol = moved(s.trim.function_tol); }},
      {"trim.rel_tol",
       [](Study& s) { s.trim.simulation.rel_tol = moved(s.trim.simulation.rel_tol); }},
      {"trim.steady_tol",
       [](Study& s) { s.trim.simulation.steady_tol = moved(s.trim.simulation.steady_tol); }},
      {"trim.max_cycles", [](Study& s) { s.trim.simulation.cycles += 1; }},
      {"trim.derivative_cycles", [](Study& s) { s.trim.derivative_cycles += 1; }},
      {"trim.refine_in_free_flight",
       [](Study& s) { s.trim.refine_in_free_flight = !s.trim.refine_in_free_flight; }},
      {"trim.refine_cycles", [](Study& s) { s.trim.refine_cycles += 1; }},
      {"trim.periodic.control",
       [](Study& s) {
         s.trim.periodic.control = s.trim.periodic.control == PeriodicControl::kFrequency
                                       ? PeriodicControl::kTailAngle
                                       : PeriodicControl::kFrequency;
       }},
      {"trim.periodic.residual_tol",
       [](Study& s) { s.trim.periodic.residual_tol = moved(s.trim.periodic.residual_tol); }},
      {"trim.periodic.rel_tol",
       [](Study& s) { s.trim.periodic.rel_tol = moved(s.trim.periodic.rel_tol); }},
      {"trim.periodic.max_iterations", [](Study& s) { s.trim.periodic.max_iterations += 1; }},
      {"trim.periodic.history_samples", [](Study& s) { s.trim.periodic.history_samples += 1; }},
      {"trim.periodic.floquet",
       [](Study& s) { s.trim.periodic.floquet = !s.trim.periodic.floquet; }},
      {"trim.periodic.multipliers", [](Study& s) { s.trim.periodic.multipliers += 1; }},
      {"trim.periodic.multiplier_check",
       [](Study& s) { s.trim.periodic.multiplier_check = !s.trim.periodic.multiplier_check; }},
  };
  return kChanges;
}

/// Every field of `run` written for one of `studies` is seen to change by its getter when its
/// setting changes; returns the keys checked.
std::vector<std::string> checkChanges(StudyKind run, const std::vector<Study>& studies) {
  std::vector<std::string> checked;
  for (const AnalysisField& f : analysisFields(run)) {
    const std::string key(f.key);
    const auto change = changes().find(key);
    if (change == changes().end()) {
      ADD_FAILURE() << key << ": no change in this test";
      continue;
    }
    for (const Study& base : studies) {
      if (!f.written(base)) continue;
      Study moved_study = base;
      change->second(moved_study);
      EXPECT_FALSE(sameAnalysisValue(f.get(moved_study), f.get(base))) << key;
      EXPECT_TRUE(sameAnalysisValue(f.get(base), f.get(Study(base)))) << key;
      checked.push_back(key);
      break;
    }
  }
  return checked;
}

TEST(AnalysisFields, EveryChangeIsSeen) {
  const std::vector<Study> simulate = {
      loadStudyFile(repo() / "studies" / "paper" / "fig2_rfw_theta20.toml"),
      loadStudyFile(repo() / "studies" / "paper" / "fig6_8_free_flight.toml")};
  const std::vector<Study> trim = {
      loadStudyFile(repo() / "studies" / "examples" / "efw_trim.toml"),
      loadStudyFile(repo() / "studies" / "examples" / "efw_periodic_trim.toml")};
  // Both modes and both methods: every field is written in one of them, so each is checked.
  EXPECT_EQ(checkChanges(StudyKind::kSimulate, simulate).size(),
            analysisFields(StudyKind::kSimulate).size());
  EXPECT_EQ(checkChanges(StudyKind::kTrim, trim).size(), analysisFields(StudyKind::kTrim).size());
}

TEST(AnalysisFields, SignOfZeroIsADifference) {
  // study.resolved.toml writes -0.0 and 0.0 differently, so a sweep must see them as different.
  EXPECT_FALSE(sameAnalysisValue(AnalysisValue(0.0), AnalysisValue(-0.0)));
  EXPECT_FALSE(sameAnalysisValue(AnalysisValue(std::vector<double>{0.0, 1.0}),
                                 AnalysisValue(std::vector<double>{-0.0, 1.0})));
  EXPECT_TRUE(
      sameAnalysisValue(AnalysisValue(std::string("free")), AnalysisValue(std::string("free"))));
}

}  // namespace
}  // namespace orni::studies
