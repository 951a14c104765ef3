// `ornithopter trim VEHICLE --freq F [--theta] [--speed] [--tail] [--unknowns] [--method] [-o]`.
#include <memory>
#include <optional>
#include <sstream>
#include <string>

#include "core/model/frames.hpp"
#include "studies/runner/cli/cli_options.hpp"
#include "studies/runner/cli/subcommands.hpp"
#include "studies/runner/commands/run_study.hpp"
#include "trim/trim_options.hpp"
#include "trim/trim_unknowns.hpp"

namespace orni::studies::cli {

namespace {

struct TrimArgs {
  std::string vehicle, unknowns;
  std::optional<std::string> out;
  std::string freq;
  std::optional<std::string> theta, speed, tail;
  std::string method = "two_stage";
  std::optional<std::string> jobs;
};

int runTrim(const TrimArgs& a) {
  Study study = studyFromVehicle(a.vehicle, StudyKind::kTrim);
  study.name += "_trim";
  TrimOptions& o = study.trim;
  o.initial.freq_hz = optionValue("--freq", "trim.freq_hz", a.freq);
  if (a.theta)
    o.initial.theta_rad =
        optionValue("--theta", "trim.initial.theta_mean_deg", *a.theta) * kDegToRad;
  if (a.speed) o.initial.speed_mps = optionValue("--speed", "trim.initial.speed_mps", *a.speed);
  if (a.tail)
    o.initial.tail_angle_rad =
        optionValue("--tail", "trim.initial.tail_angle_deg", *a.tail) * kDegToRad;
  if (!a.unknowns.empty()) {
    o.unknowns.clear();
    std::stringstream list(a.unknowns);
    for (std::string item; std::getline(list, item, ',');) {
      const std::optional<TrimUnknown> u = parseTrimUnknown(item);
      if (!u)
        throw CliError(
            "command line: option --unknowns: expected a comma-separated list of "
            "theta, speed, tail, freq, got '" +
            item + "'");
      o.unknowns.push_back(*u);
    }
  }
  if (a.method == "periodic") usePeriodicMethod(&o);
  std::string why;
  if (!o.IsValid(&why)) throw CliError("command line: trim options: " + why);
  return runStudyLocked(study, outputFolder(a.out, study, false), jobsOption(a.jobs));
}

}  // namespace

Subcommand addTrimSubcommand(CLI::App& app) {
  auto a = std::make_shared<TrimArgs>();
  auto* trim = app.add_subcommand(
      "trim",
      "Solve the trim of a vehicle (paper Eq. 4: mean FV = weight, mean FH = 0, mean M "
      "about the CG = 0) with Ceres; initial guess = the vehicle's operating point");
  trim->add_option("VEHICLE", a->vehicle, "Vehicle file (TOML) with a [body] section")->required();
  addFieldOption(trim, "--freq", "trim.freq_hz", a->freq,
                 "Flapping frequency f (Hz): fixed, or the initial guess when freq is an unknown")
      ->required();
  addFieldOption(trim, "--theta", "trim.initial.theta_mean_deg", a->theta,
                 "Initial guess of the mean pitch attitude (deg)");
  addFieldOption(trim, "--speed", "trim.initial.speed_mps", a->speed,
                 "Initial guess of the flight speed U (m/s)");
  addFieldOption(trim, "--tail", "trim.initial.tail_angle_deg", a->tail,
                 "Initial guess of the tail angle delta_T (deg)");
  trim->add_option("--unknowns", a->unknowns,
                   "Comma-separated unknowns from theta, speed, tail, freq (default "
                   "theta,speed,tail; fewer than 3 = least squares); the others are held");
  trim->add_option("-o,--output", a->out, "Output folder (default results/<vehicle name>_trim)")
      ->check(nonEmptyPath());
  trim->add_option("--method", a->method,
                   "two_stage (default: Eq. 4, then level settled free flight) or periodic (the "
                   "periodic orbit of free flight by shooting, with its Floquet multipliers)")
      ->check(CLI::IsMember({"two_stage", "periodic"}));
  addFieldOption(trim, "-j,--jobs", "jobs", a->jobs,
                 "Threads for the runs of each Jacobian (Eq. 4's finite differences, the periodic "
                 "orbit's columns); the results are the same for any count");
  return {trim, [a] { return runTrim(*a); }, false};
}

}  // namespace orni::studies::cli
