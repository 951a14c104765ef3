// `ornithopter simulate VEHICLE [--mode] [--speed] [--freq] [--theta] [--tail] [--cycles] [-o]`.
#include <memory>
#include <optional>
#include <string>

#include "core/model/frames.hpp"
#include "studies/runner/cli/cli_options.hpp"
#include "studies/runner/cli/subcommands.hpp"
#include "studies/runner/commands/run_study.hpp"
#include "studies/runner/config/study_sections.hpp"

namespace orni::studies::cli {

namespace {

struct SimulateArgs {
  std::string vehicle, mode;
  std::optional<std::string> out;
  // Values as text: checked against the field table (optionValue), quoted as given in messages.
  std::optional<std::string> speed, freq, theta, tail, cycles;
};

int runSimulate(const SimulateArgs& a) {
  Study study = studyFromVehicle(a.vehicle);
  if (!a.mode.empty())
    study.simulate().options.mode = a.mode == "free" ? FlightMode::kFree : FlightMode::kTethered;
  applyWingTolerance(study);  // a nonlinear wing's free flight: 1e-5 (no rel_tol on the CLI)
  if (a.speed) study.point.speed_mps = optionValue("--speed", "simulate.speed_mps", *a.speed);
  if (a.freq) study.point.freq_hz = optionValue("--freq", "simulate.freq_hz", *a.freq);
  if (a.theta)
    study.point.theta_rad = optionValue("--theta", "simulate.theta_deg", *a.theta) * kDegToRad;
  if (a.tail)
    study.point.tail_angle_rad =
        optionValue("--tail", "simulate.tail_angle_deg", *a.tail) * kDegToRad;
  if (a.tail && !study.vehicle.tail.present && study.point.tail_angle_rad != 0.0)
    throw CliError("command line: option --tail: expected 0 or no tail angle (key "
                   "simulate.tail_angle_deg): the vehicle has no [tail], got '" +
                   *a.tail + "'");
  if (a.cycles)
    study.simulate().options.cycles =
        static_cast<int>(optionValue("--cycles", "simulate.cycles", *a.cycles));
  requireBodyForFreeFlight(study);
  return runStudyLocked(study, outputFolder(a.out, study, false), 1);
}

}  // namespace

Subcommand addSimulateSubcommand(CLI::App& app) {
  auto a = std::make_shared<SimulateArgs>();
  auto* sim = app.add_subcommand("simulate", "Simulate a vehicle file (tethered or free flight)");
  sim->add_option("VEHICLE", a->vehicle, "Vehicle file (TOML)")->required();
  sim->add_option("--mode", a->mode, "tethered | free (default tethered)")
      ->check(CLI::IsMember({"tethered", "free"}));
  addFieldOption(sim, "--speed", "simulate.speed_mps", a->speed, "Flight / tunnel speed U (m/s)");
  addFieldOption(sim, "--freq", "simulate.freq_hz", a->freq, "Flapping frequency f (Hz)");
  addFieldOption(sim, "--theta", "simulate.theta_deg", a->theta, "Mean pitch attitude (deg)");
  addFieldOption(sim, "--tail", "simulate.tail_angle_deg", a->tail,
                 "Tail elevation angle delta_T (deg)");
  addFieldOption(sim, "--cycles", "simulate.cycles", a->cycles, "Flapping cycles to simulate");
  sim->add_option("-o,--output", a->out, "Output folder (default results/<vehicle name>)")
      ->check(nonEmptyPath());
  return {sim, [a] { return runSimulate(*a); }, false};
}

}  // namespace orni::studies::cli
