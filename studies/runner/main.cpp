// ornithopter: the command-line front end (architecture.md 3). Only main catches everything and
// maps it to the exit code: 0 finished (whatever the physics verdict), 1 failed, 2 bad input.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstdlib>
#include <cmath>
#include <filesystem>
#include <stdexcept>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "core/model/field_table.hpp"
#include "core/model/frames.hpp"
#include "core/model/invalid_model_error.hpp"
#include "studies/runner/commands/aeromap_command.hpp"
#include "studies/runner/commands/calibrate_command.hpp"
#include "studies/runner/commands/keys_command.hpp"
#include "studies/runner/commands/modes_command.hpp"
#include "studies/runner/commands/optimize_command.hpp"
#include "studies/runner/commands/periodic_trim_command.hpp"
#include "studies/runner/commands/run_info.hpp"
#include "studies/runner/commands/run_study.hpp"
#include "studies/runner/commands/sensitivity_command.hpp"
#include "studies/runner/commands/simulate_command.hpp"
#include "studies/runner/commands/sweep_command.hpp"
#include "studies/runner/commands/trim_command.hpp"
#include "studies/runner/config/input_error.hpp"
#include "studies/runner/config/study_file.hpp"
#include "studies/runner/config/toml_access.hpp"
#include "studies/runner/distributed/point_farm.hpp"
#include "studies/runner/output/atomic_file.hpp"
#include "studies/runner/output/folder_lock.hpp"
#include "studies/runner/plotting/gnuplot.hpp"
#include "trim/grid_spec.hpp"

#ifdef ORNI_HAVE_MPI
#include "studies/runner/mpi/mpi_farm.hpp"
#endif

namespace fs = std::filesystem;
using namespace orni;
using namespace orni::studies;

namespace {

constexpr int kExitOk = 0;
constexpr int kExitFailed = 1;
constexpr int kExitBadInput = 2;

// A bad command-line value: reported like a file error, with "command line" as the file.
struct CliError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// "command line: option --freq: expected E (key simulate.freq_hz), got G".
CliError optionError(const std::string& flag, std::string_view key, const std::string& expected,
                     const std::string& got) {
  return CliError("command line: option " + flag + ": expected " + expected + " (key " +
                  std::string(key) + "), got " + got);
}

/// The value of a command-line option that sets the field-table key `key` (file units): the
/// whole text a number (kNumber) or an integer (kInteger) inside the key's range, the same range
/// as in the files. Messages quote the text as given.
double optionValue(const std::string& flag, std::string_view key, const std::string& text) {
  const FieldSpec& f = field(key);
  const std::string got = "'" + text + "'";
  if (f.type == FieldType::kInteger) {
    long long v = 0;
    const char* end = text.data() + text.size();
    const auto res = std::from_chars(text.data(), end, v);
    if (text.empty() || res.ec != std::errc() || res.ptr != end)
      throw optionError(flag, key, f.expected(), got);
    if (!f.range.contains(static_cast<double>(v))) throw optionError(flag, key, f.expected(), got);
    return static_cast<double>(v);
  }
  char* end = nullptr;
  const double v = text.empty() || std::isspace(static_cast<unsigned char>(text[0]))
                       ? std::nan("")
                       : std::strtod(text.c_str(), &end);
  if (end == nullptr || *end != '\0') throw optionError(flag, key, f.expected(), got);
  if (!f.range.contains(v)) throw optionError(flag, key, f.expected(), got);
  return v;
}

/// A grid axis from a command-line spec "A:B:N" for the [aeromap] key `key`, every value inside
/// its range.
GridAxis axisOption(const std::string& flag, std::string_view key, const std::string& text) {
  const FieldSpec& f = field(key);
  const std::string expected = std::string("A:B:N (") + trim::kGridSpecMeaning + "), " +
                               f.range.describe("each value");
  trim::GridSpec spec;
  std::string reason;
  if (!trim::tryParseGridSpec(text, &spec, &reason))
    throw optionError(flag, key, expected, "'" + text + "' (" + reason + ")");
  GridAxis axis = gridAxis(spec);
  for (const double v : axis.values)
    if (!f.range.contains(v))
      throw optionError(flag, key, expected, "'" + text + "' (value " + displayNumber(v) + ")");
  return axis;
}

/// -j N: the "jobs" entry of the field table; 1 when not given.
int jobsOption(const std::optional<std::string>& text) {
  return text ? static_cast<int>(optionValue("-j", "jobs", *text)) : 1;
}

/// -o, --export-ccx and RUN_DIR: a name, never "" (which would silently mean the default).
const CLI::Validator kNonEmptyPath(
    [](std::string& text) {
      return text.empty() ? std::string("expected a path, got an empty string") : std::string();
    },
    "PATH", "NonEmptyPath");

std::vector<std::string> subcommandNames(CLI::App& app) {
  std::vector<std::string> names;
  for (const CLI::App* sub : app.get_subcommands({})) names.push_back(sub->get_name());
  return names;
}

fs::path outputFolder(const std::optional<std::string>& out_opt, const Study& study,
                      bool several) {
  if (!out_opt) return fs::path("results") / study.name;
  return several ? fs::path(*out_opt) / study.name : fs::path(*out_opt);
}

/// A vehicle without [body] cannot fly free: bad input, before any work.
void requireBodyForFreeFlight(const Study& study) {
  if (study.simulate.mode == FlightMode::kFree && !study.vehicle.body.present)
    throw InputError::missingKey(inputFileOf(study), 0, "body",
                                 "a [body] table: free flight needs the vehicle's mass and pitch "
                                 "inertia");
}

}  // namespace

/// The command line of one process (every rank of a distributed run parses and loads the same).
int runCommandLine(int argc, char** argv) {
  CLI::App app{"ornithopter: flexible flapping-wing flight simulation, aero maps, trim and design"};
  app.require_subcommand(1);
  app.add_flag_callback(
      "--version",
      [] {
        std::cout << "ornithopter " << versionString() << "\n";
        throw CLI::Success();
      },
      "Print the version and git revision");

  // simulate
  auto* sim = app.add_subcommand("simulate", "Simulate a vehicle file (tethered or free flight)");
  std::string sim_vehicle, sim_mode;
  std::optional<std::string> sim_out;
  // Values as text: checked against the field table (optionValue), quoted as given in messages.
  std::optional<std::string> sim_speed, sim_freq, sim_theta, sim_tail, sim_cycles;
  sim->add_option("VEHICLE", sim_vehicle, "Vehicle file (TOML)")->required();
  sim->add_option("--mode", sim_mode, "tethered | free (default tethered)")
      ->check(CLI::IsMember({"tethered", "free"}));
  sim->add_option("--speed", sim_speed, "Flight / tunnel speed U (m/s)");
  sim->add_option("--freq", sim_freq, "Flapping frequency f (Hz)");
  sim->add_option("--theta", sim_theta, "Mean pitch attitude (deg)");
  sim->add_option("--tail", sim_tail, "Tail elevation angle delta_T (deg)");
  sim->add_option("--cycles", sim_cycles, "Flapping cycles to simulate");
  sim->add_option("-o,--output", sim_out, "Output folder (default results/<vehicle name>)")
      ->check(kNonEmptyPath);

  // run
  auto* run = app.add_subcommand("run", "Run one or more study files (kind given inside)");
  std::vector<std::string> run_files;
  std::optional<std::string> run_out;
  std::optional<std::string> run_jobs;
  run->add_option("STUDY", run_files, "Study files (TOML)")->required();
  run->add_option("-o,--output", run_out,
                  "Output folder (default results/<study name>); with several studies each goes "
                  "into DIR/<study name>")
      ->check(kNonEmptyPath);
  run->add_option("-j,--jobs", run_jobs, "Worker threads");

  // plot
  auto* plot = app.add_subcommand("plot", "(Re)draw the figures of a finished run");
  std::string plot_dir;
  plot->add_option("RUN_DIR", plot_dir, "Run output folder")->required()->check(kNonEmptyPath);

  // modes
  auto* modes = app.add_subcommand("modes", "Wing FE model: natural frequencies, effective masses, "
                                            "mode shapes; optional CalculiX deck");
  std::string modes_vehicle, modes_ccx;
  std::optional<std::string> modes_out;
  modes->add_option("VEHICLE", modes_vehicle, "Vehicle file (TOML)")->required();
  modes->add_option("-o,--output", modes_out, "Output folder (default results/<vehicle name>)")
      ->check(kNonEmptyPath);
  modes->add_option("--export-ccx", modes_ccx, "Also write the FE model as a CalculiX deck (.inp)")
      ->check(kNonEmptyPath);

  // aeromap
  auto* am = app.add_subcommand(
      "aeromap", "Aero map: cycle-mean tethered loads over a grid of speed, frequency, pitch and "
                 "tail angle (paper Fig. 5); resumable");
  std::string am_vehicle, am_speed, am_freq, am_theta, am_tail;
  std::optional<std::string> am_out;
  std::optional<std::string> am_cycles, am_jobs;
  am->add_option("VEHICLE", am_vehicle, "Vehicle file (TOML)")->required();
  am->add_option("--speed", am_speed, "Speeds U (m/s) A:B:N: N values from A to B inclusive")
      ->required();
  am->add_option("--freq", am_freq, "Flapping frequencies f (Hz) A:B:N")->required();
  am->add_option("--theta", am_theta, "Mean pitch attitudes (deg) A:B:N")->required();
  am->add_option("--tail", am_tail,
                 "Tail elevation angles delta_T (deg) A:B:N (default: the vehicle's "
                 "operating-point tail angle)");
  am->add_option("--cycles", am_cycles, "Maximum flapping cycles per point (default 40)");
  am->add_option("-j,--jobs", am_jobs, "Worker threads");
  am->add_option("-o,--output", am_out,
                 "Output folder (default results/<vehicle name>_aeromap); an interrupted run "
                 "resumes from the journal there")
      ->check(kNonEmptyPath);

  // trim
  auto* trim = app.add_subcommand(
      "trim", "Solve the trim of a vehicle (paper Eq. 4: mean FV = weight, mean FH = 0, mean M "
              "about the CG = 0) with Ceres; initial guess = the vehicle's operating point");
  std::string trim_vehicle, trim_unknowns;
  std::optional<std::string> trim_out;
  std::string trim_freq;
  std::optional<std::string> trim_theta, trim_speed, trim_tail;
  trim->add_option("VEHICLE", trim_vehicle, "Vehicle file (TOML) with a [body] section")
      ->required();
  trim->add_option("--freq", trim_freq,
                   "Flapping frequency f (Hz): fixed, or the initial guess when freq is an unknown")
      ->required();
  trim->add_option("--theta", trim_theta, "Initial guess of the mean pitch attitude (deg)");
  trim->add_option("--speed", trim_speed, "Initial guess of the flight speed U (m/s)");
  trim->add_option("--tail", trim_tail, "Initial guess of the tail angle delta_T (deg)");
  trim->add_option("--unknowns", trim_unknowns,
                   "Comma-separated unknowns from theta, speed, tail, freq (default "
                   "theta,speed,tail; fewer than 3 = least squares); the others are held");
  trim->add_option("-o,--output", trim_out,
                   "Output folder (default results/<vehicle name>_trim)")
      ->check(kNonEmptyPath);
  std::string trim_method = "two_stage";
  trim->add_option("--method", trim_method,
                   "two_stage (default: Eq. 4, then level settled free flight) or periodic (the "
                   "periodic orbit of free flight by shooting, with its Floquet multipliers)")
      ->check(CLI::IsMember({"two_stage", "periodic"}));

  // stability
  auto* stab = app.add_subcommand(
      "stability", "Floquet stability of trimmed flight: the periodic-orbit trim, the monodromy "
                   "matrix of the orbit and all its multipliers, sorted and labelled");
  std::string stab_vehicle;
  std::optional<std::string> stab_out;
  std::optional<std::string> stab_freq;
  stab->add_option("VEHICLE", stab_vehicle, "Vehicle file (TOML) with a [body] section")
      ->required();
  stab->add_option("--freq", stab_freq,
                   "Flapping frequency f (Hz) (default: the vehicle's operating point)");
  stab->add_option("-o,--output", stab_out,
                   "Output folder (default results/<vehicle name>_stability)")
      ->check(kNonEmptyPath);

  // optimize
  auto* opt = app.add_subcommand(
      "optimize", "Design optimisation with NLopt (kind = \"optimize\" study): design variables "
                  "(member sections and layout, tail area, aspect ratio and arm) sized so that "
                  "the vehicle trims, flies bounded and needs the least flapping power; resumable");
  std::string opt_study;
  std::optional<std::string> opt_out;
  std::optional<std::string> opt_jobs;
  opt->add_option("STUDY", opt_study, "Study file (TOML) of kind \"optimize\"")->required();
  opt->add_option("-o,--output", opt_out,
                  "Output folder (default results/<study name>); an interrupted run resumes from "
                  "the journal there")
      ->check(kNonEmptyPath);
  opt->add_option("-j,--jobs", opt_jobs, "Worker threads (over the starts of a multi-start run)");

  // keys
  auto* keys = app.add_subcommand(
      "keys", "Print every input key (vehicle files, study files, command line): unit, valid "
              "range, default and meaning, from the one table every reader checks");
  std::string keys_group;
  bool keys_markdown = false;
  keys->add_option("GROUP", keys_group,
                   "vehicle | study | simulate | aeromap | trim | optimize | calibrate | sweep | "
                   "sensitivity | continuation | cli (default: every group)");
  keys->add_flag("--markdown", keys_markdown, "Markdown tables (the README's key reference)");

  // A mistyped subcommand: name the nearest one, as a mistyped key does.
  const std::vector<std::string> subcommands = subcommandNames(app);
  if (argc >= 2 && argv[1][0] != '-' &&
      std::find(subcommands.begin(), subcommands.end(), argv[1]) == subcommands.end()) {
    const std::string near = closestMatch(argv[1], subcommands);
    std::cerr << "ornithopter: error: unknown subcommand '" << argv[1] << "'"
              << (near.empty() ? std::string() : " (did you mean '" + near + "'?)")
              << "; run with --help for the list\n";
    return kExitBadInput;
  }

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int rc = app.exit(e);
    return rc == 0 ? kExitOk : kExitBadInput;
  }

  // A worker rank of a distributed run takes part in the commands that spread points (run,
  // aeromap, optimize) and does nothing else (rank 0 runs the rest alone).
  if (!farmWriter() && !run->parsed() && !am->parsed() && !opt->parsed()) return kExitOk;

  try {
    if (sim->parsed()) {
      Study study = studyFromVehicle(sim_vehicle);
      if (!sim_mode.empty())
        study.simulate.mode = sim_mode == "free" ? FlightMode::kFree : FlightMode::kTethered;
      if (sim_speed)
        study.point.speed_mps = optionValue("--speed", "simulate.speed_mps", *sim_speed);
      if (sim_freq) study.point.freq_hz = optionValue("--freq", "simulate.freq_hz", *sim_freq);
      if (sim_theta)
        study.point.theta_rad =
            optionValue("--theta", "simulate.theta_deg", *sim_theta) * kDegToRad;
      if (sim_tail)
        study.point.tail_angle_rad =
            optionValue("--tail", "simulate.tail_angle_deg", *sim_tail) * kDegToRad;
      if (sim_cycles)
        study.simulate.cycles =
            static_cast<int>(optionValue("--cycles", "simulate.cycles", *sim_cycles));
      requireBodyForFreeFlight(study);
      return runStudyLocked(study, outputFolder(sim_out, study, false), 1);
    }
    if (run->parsed()) {
      const int jobs = jobsOption(run_jobs);
      // Load (and validate) every study first, so a typo in the last one fails before any work.
      std::vector<Study> studies;
      for (const std::string& f : run_files) studies.push_back(loadStudyFile(f));
      // One writer per folder: every output folder locked before any work, none shared.
      std::vector<fs::path> outs;
      for (const Study& s : studies) {
        outs.push_back(outputFolder(run_out, s, studies.size() > 1));
        for (std::size_t i = 0; i + 1 < outs.size(); ++i)
          if (outs[i].lexically_normal() == outs.back().lexically_normal())
            throw CliError("command line: studies " + inputFileOf(studies[i]) + " and " +
                           inputFileOf(s) + " both write into " + outs.back().string() +
                           " (give them different names, `name = ...`)");
      }
      std::vector<std::unique_ptr<OutputFolderLock>> locks;  // the writer's (rank 0's) only
      if (farmWriter())
        for (const fs::path& out : outs) locks.push_back(std::make_unique<OutputFolderLock>(out));
      int rc = kExitOk;
      for (std::size_t i = 0; i < studies.size(); ++i) {
        const int r = runStudy(studies[i], outs[i], jobs);
        if (r != kExitOk) rc = r;
      }
      return rc;
    }
    if (am->parsed()) {
      GridAxis speed = axisOption("--speed", "aeromap.speed_mps", am_speed);
      GridAxis freq = axisOption("--freq", "aeromap.freq_hz", am_freq);
      GridAxis theta = axisOption("--theta", "aeromap.theta_deg", am_theta);
      std::optional<GridAxis> tail;
      if (!am_tail.empty()) tail = axisOption("--tail", "aeromap.tail_angle_deg", am_tail);
      std::size_t points = speed.values.size() * freq.values.size() * theta.values.size();
      if (tail) points *= tail->values.size();
      if (points > trim::kMaxAeroMapPoints)
        throw CliError("command line: options --speed, --freq, --theta, --tail: expected a grid of "
                       "at most " + std::to_string(trim::kMaxAeroMapPoints) + " points, got " +
                       std::to_string(points));
      Study study = aeromapStudyFromVehicle(am_vehicle, std::move(speed), std::move(freq),
                                            std::move(theta), std::move(tail));
      if (am_cycles)
        study.aeromap().options.cycles =
            static_cast<int>(optionValue("--cycles", "aeromap.cycles", *am_cycles));
      AeromapRunOptions opts;
      opts.threads = jobsOption(am_jobs);
      const fs::path out = outputFolder(am_out, study, false);
      std::optional<OutputFolderLock> lock;  // the writer's (rank 0's) only
      if (farmWriter()) lock.emplace(out);
      return runAeromapStudy(study, out, opts);
    }
    if (modes->parsed()) {
      const fs::path out =
          modes_out ? fs::path(*modes_out) : fs::path("results") / fs::path(modes_vehicle).stem();
      const OutputFolderLock lock(out);
      return runModesCommand(modes_vehicle, out, modes_ccx);
    }
    if (trim->parsed()) {
      Study study = studyFromVehicle(trim_vehicle, StudyKind::kTrim);
      study.name += "_trim";
      TrimOptions& o = study.trim;
      o.initial.freq_hz = optionValue("--freq", "trim.freq_hz", trim_freq);
      if (trim_theta)
        o.initial.theta_rad =
            optionValue("--theta", "trim.initial.theta_mean_deg", *trim_theta) * kDegToRad;
      if (trim_speed)
        o.initial.speed_mps = optionValue("--speed", "trim.initial.speed_mps", *trim_speed);
      if (trim_tail)
        o.initial.tail_angle_rad =
            optionValue("--tail", "trim.initial.tail_angle_deg", *trim_tail) * kDegToRad;
      if (!trim_unknowns.empty()) {
        o.unknowns.clear();
        std::stringstream list(trim_unknowns);
        for (std::string item; std::getline(list, item, ',');) {
          const std::optional<TrimUnknown> u = parseTrimUnknown(item);
          if (!u)
            throw CliError("command line: option --unknowns: expected a comma-separated list of "
                           "theta, speed, tail, freq, got '" + item + "'");
          o.unknowns.push_back(*u);
        }
      }
      if (trim_method == "periodic") usePeriodicMethod(&o);
      std::string why;
      if (!o.IsValid(&why)) throw CliError("command line: trim options: " + why);
      return runStudyLocked(study, outputFolder(trim_out, study, false), 1);
    }
    if (stab->parsed()) {
      Study study = studyFromVehicle(stab_vehicle, StudyKind::kTrim);
      study.name += "_stability";
      TrimOptions& o = study.trim;
      usePeriodicMethod(&o);
      o.periodic.multipliers = 0;      // all of them: the full monodromy matrix
      o.verify_free_flight = false;    // the verdict is Floquet's; `trim` runs the Eq. (5) check
      if (stab_freq) o.initial.freq_hz = optionValue("--freq", "trim.freq_hz", *stab_freq);
      std::string why;
      if (!o.IsValid(&why)) throw CliError("command line: stability options: " + why);
      const fs::path out = outputFolder(stab_out, study, false);
      const OutputFolderLock lock(out);
      try {
        return runPeriodicTrimStudy(study, out, PeriodicRunKind::kStability);
      } catch (const InvalidModelError& e) {
        throw InputError(inputFileOf(study), 0, std::string(),
                         std::string("invalid model: ") + e.what());
      }
    }
    if (opt->parsed()) {
      const Study study = loadStudyFile(opt_study);
      if (study.kind != StudyKind::kOptimize)
        throw CliError("command line: " + opt_study +
                       ": expected a study of kind \"optimize\", got kind \"" +
                       std::string(toString(study.kind)) + "\" (run it with `ornithopter run`)");
      return runStudyLocked(study, outputFolder(opt_out, study, false), jobsOption(opt_jobs));
    }
    if (keys->parsed()) {
      const std::optional<std::string> text = keysText(keys_group, keys_markdown);
      if (!text) {
        std::vector<std::string> groups;
        for (std::string_view g : fieldGroups()) groups.emplace_back(g);
        const std::string near = closestMatch(keys_group, groups);
        std::string list;
        for (const std::string& g : groups) list += (list.empty() ? "" : ", ") + g;
        throw CliError("command line: GROUP: expected one of " + list + ", got '" + keys_group +
                       "'" + (near.empty() ? std::string() : " (did you mean '" + near + "'?)"));
      }
      std::cout << *text;
      return kExitOk;
    }
    if (plot->parsed()) {
      const fs::path dir(plot_dir);
      std::error_code ec;
      if (!fs::is_directory(dir, ec))
        throw CliError("command line: RUN_DIR " + plot_dir + ": " +
                       (fs::exists(dir, ec) ? "not a folder" : "no such folder"));
      if (!fs::is_regular_file(dir / "summary.json", ec))
        throw CliError("command line: RUN_DIR " + plot_dir +
                       ": not a run folder (no summary.json; expected the output folder of an "
                       "ornithopter run)");
      const OutputFolderLock lock(dir);
      const int n = redrawFigures(dir);
      if (n == 0)
        throw CliError("command line: RUN_DIR " + plot_dir +
                       ": no figure scripts (*.gp) to draw (this run drew no figures)");
      std::cout << "redrew " << n << " figure(s) in " << plot_dir << "\n";
      return kExitOk;
    }
    // Every subcommand returns above; CLI11 rejects any other name before this point.
    throw std::logic_error("unhandled subcommand " + app.get_subcommands().front()->get_name());
  } catch (const InputError& e) {
    std::cerr << "ornithopter: error: " << e.what() << "\n";
    return kExitBadInput;
  } catch (const CliError& e) {
    std::cerr << "ornithopter: error: " << e.what() << "\n";
    return kExitBadInput;
  } catch (const FolderBusyError& e) {
    std::cerr << "ornithopter: error: " << e.what() << "\n";
    return kExitBadInput;
  } catch (const InvalidModelError& e) {
    std::cerr << "ornithopter: error: invalid model: " << e.what() << "\n";
    return kExitBadInput;
  } catch (const std::exception& e) {
    std::cerr << "ornithopter: failed: " << e.what() << "\n";
    return kExitFailed;
  }
}

int main(int argc, char** argv) {
#ifdef ORNI_HAVE_MPI
  // Started by mpirun/srun: rank 0 is the master, the others compute (studies/runner/mpi/).
  // Otherwise no MPI function is called: the program runs as a build without MPI.
  if (launchedByMpi()) {
    MpiFarm mpi(&argc, &argv);
    setFarmBackend(&mpi);
    const int rc = runCommandLine(argc, argv);
    setFarmBackend(nullptr);
    return mpi.finish(rc);
  }
#endif
  return runCommandLine(argc, argv);
}
