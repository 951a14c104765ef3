// Study files (TOML, docs/design.md section 5) -> Study.
//
// This is the header the rest of the program includes: no toml++ here. Errors are InputError
// (input_error.hpp) naming file, line and key; main maps them to exit status 2.
//
// Top-level keys of a study file:
//   kind     (required) "simulate" | "modes" | "aeromap" | "trim" | "optimize" | "sweep" |
//            "calibrate" ([calibrate]: config/calibrate_section.hpp) | "sensitivity"
//            ([sensitivity] and [trim]: config/sensitivity_study.hpp) | "continuation"
//            ([continuation] and [trim], the periodic trim it starts from:
//            config/continuation_section.hpp)
//   name     (optional) run name, [A-Za-z0-9_.-]+; default: the file stem
//   vehicle  (required) path of the vehicle file relative to the study's folder, or an inline
//            [vehicle] table (as written into study.resolved.toml)
//   vehicle_source (optional, only with an inline [vehicle]) where that vehicle came from
//   [override] (optional) any vehicle key with the vehicle file's names and units, e.g.
//            `tail.arm_m = 0.12` or `[override.wing] semispan_m = 0.3`; tables are merged key by
//            key, scalars and arrays are replaced. Errors in overridden values name the study file,
//            its line and the key as 'override.tail.arm_m'.
//   [simulate] (optional, kind = "simulate" only) mode "tethered"|"free", speed_mps, freq_hz,
//            theta_deg, tail_angle_deg (default: the vehicle's operating point), cycles, rel_tol,
//            abs_tol, separation_abs_tol, steady_tol, samples_per_cycle (default:
//            SimulationOptions), history_every (>= 1, default 1: histories.csv keeps every n-th
//            of the samples_per_cycle samples; an output option, the summary, spectra, the
//            constrained flight test and the limit-cycle metrics use every sample).
//   [simulate.free] (optional, only with mode = "free": rejected for a tethered [simulate], where
//            it would be silently ignored) the free-flight settings (FreeFlightOptions):
//              bound_speed_mps, bound_W_mps, bound_theta_deg, bound_h_m and
//              bound_Q_degps (0 = automatic 2 pi f bound_theta): the bounds R_i of the
//                bounded-norm criterion (paper Eq. 5) on the deviations of U, W, theta, Q, h;
//              transient_fraction (share of the cycles before the verdict),
//              divergence_ratio (stop as diverged above this scaled norm),
//              initial_altitude_m (ground contact at h = 0).
//            Every key's range: the field table (`ornithopter keys simulate`).
//            Defaults: FreeFlightOptions (simulation_options.hpp).
//   [aeromap] (required for kind = "aeromap", rejected otherwise) the grid of an aero map (paper
//            Fig. 5). Axes speed_mps, freq_hz, theta_deg (required) and tail_angle_deg (optional,
//            default: the vehicle's operating-point tail angle), each given as
//              - a grid spec string "A:B:N": N evenly spaced values from A to B inclusive
//                (N >= 1; N = 1 needs A == B), e.g. speed_mps = "10:20:6", or
//              - an array of values, e.g. theta_deg = [0, 5, 12.5], or a single number.
//            (A three-number array is a list of three values, never a spec: "A:B:N" is a string
//            so that the two cannot be confused.) Options: cycles (the maximum per point,
//            default 40), steady_tol, rel_tol, abs_tol, separation_abs_tol (default:
//            SimulationOptions). Every point stops at its periodic steady state.
//   [trim]   (optional, kind = "trim" only; in a sweep or sensitivity study the settings of every
//            point's trim) freq_hz, unknowns = ["theta_mean_deg", "speed_mps",
//            "tail_angle_deg"] (any 1-3 of these and "freq_hz"), initial = { theta_mean_deg,
//            speed_mps, tail_angle_deg } (default: the vehicle's operating point), bounds =
//            { <unknown> = [lower, upper] }, max_iterations, residual_tol, function_tol, rel_tol,
//            steady_tol, max_cycles, derivative_cycles, refine_in_free_flight, refine_cycles,
//            method ("two_stage" | "periodic": the periodic orbit and its Floquet multipliers,
//            kind = "trim" only) and [trim.periodic]; see config/trim_section.hpp for ranges and
//            defaults. A trim study needs a vehicle with a [body] (its mass sets the weight).
//   [sweep]  (required for kind = "sweep", rejected otherwise) a parameter study: another kind run
//            at every point of a grid of vehicle or analysis values, one table row per point
//            (docs/design.md 5). Keys:
//              run  (required) the kind run at every point: "trim" or "simulate" (tethered or
//                   free, as its [simulate] says);
//              axes (required) an array of 1-16 tables { key = "...", values = ... }, written
//                   inline (axes = [{ key = "tail.arm_m", values = [0.10, 0.12] }, ...]) or as
//                   [[sweep.axes]] tables. An array, not a table of key -> values, because the
//                   axes' order matters and a TOML table has none (toml++ iterates it
//                   alphabetically): the points are the full factorial, the FIRST axis
//                   outermost and the last varying fastest (core/grid/sweep_grid.hpp), the row
//                   order of sweep.csv.
//              key    a vehicle key exactly as in [override] ("tail.arm_m", "body.mass_kg",
//                     "operating_point.freq_hz") or a key of the run's analysis section prefixed
//                     with its name ("trim.freq_hz", "trim.initial.speed_mps",
//                     "simulate.speed_mps", "simulate.free.bound_theta_deg"); distinct per axis.
//              values a grid spec "A:B:N", an array of numbers or one number, exactly like an
//                     [aeromap] axis (file units of the key). A whole number is given to the key
//                     as a TOML integer (so integer keys such as "wing.strips" can be swept; float
//                     keys take integers anyway), any other value as a float.
//            The run's section ([trim] or [simulate]; the other one is rejected) holds the base
//            settings of every point. A point is the study you get by writing its axis values
//            into the file: vehicle keys into [override] (after the file's own overrides), analysis
//            keys into the run's section, replacing what is there; defaults that follow other keys
//            follow the swept values (e.g. a [trim] without freq_hz trims at each point's
//            operating_point.freq_hz). The study without the axes must itself be valid, and so
//            must every point: an invalid value is an error at that axis ('sweep.axes[1].values'),
//            an invalid combination an error at 'sweep.axes' naming the point.
//   [optimize] (required for kind = "optimize", rejected otherwise) the design optimisation:
//            algorithm, objective, max_evaluations, starts, seed, freq_hz, variables, and the
//            tables [optimize.constraints], [optimize.weights], [optimize.trim]; see
//            config/optimize_section.hpp. Needs a vehicle with a [body].
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "core/dynamics/simulation_options.hpp"
#include "core/grid/grid_spec.hpp"
#include "core/model/vehicle_model.hpp"
#include "optimize/design_options.hpp"
#include "optimize/design_space.hpp"
#include "optimize/optimizer_options.hpp"
#include "studies/runner/config/input_error.hpp"
#include "trim/aero_map_options.hpp"
#include "trim/calibration_options.hpp"
#include "trim/trim_continuation.hpp"
#include "trim/trim_options.hpp"

namespace orni::studies {

enum class StudyKind {
  kSimulate,
  kModes,
  kAeromap,
  kTrim,
  kOptimize,
  kSweep,
  kCalibrate,
  kSensitivity,
  kContinuation
};

/// "simulate", "modes", "aeromap", "trim", "optimize", "sweep", "calibrate", "sensitivity",
/// "continuation".
std::string_view toString(StudyKind kind);
/// The kind of that spelling, or nullopt.
std::optional<StudyKind> parseStudyKind(std::string_view text);

/// One axis of an aero map in file units (m/s, Hz, deg): a grid spec "A:B:N" or a list.
struct GridAxis {
  std::optional<orni::GridSpec> spec;  ///< set when the axis was given as "A:B:N"
  std::vector<double> values;          ///< the values (gridValues(spec), or as listed)
};

/// The [aeromap] section (kind "aeromap").
struct AeromapSettings {
  GridAxis speed_mps, freq_hz, theta_deg, tail_angle_deg;
  /// The main wing alone (VehicleModel::mainWingAlone: no tail, no fuselage drag), the quantity
  /// of paper Fig. 5; false = the whole vehicle (wings, tail at the tail angle, fuselage drag).
  bool wing_only = false;
  /// Per-point options; cycles is the maximum (default 40), stop_when_steady is always on.
  orni::SimulationOptions options = orni::AeroMapOptions::defaultSimulation();
};

/// The [simulate] section (kind "simulate") beyond the operating point (Study::point): what only
/// a simulation uses.
struct SimulateSettings {
  orni::SimulationOptions options;  ///< mode, cycles, tolerances, samples, [simulate.free]
  bool wing_only = false;           ///< wing_only (tethered): the main wing alone
  /// at_trim: fly at the vehicle's trim point at point.freq_hz (Eq. 4 refined in free flight,
  /// trim/trim_solver.hpp) instead of the given theta, speed and tail angle, which are then the
  /// trim's initial guess.
  bool at_trim = false;
  int history_every = 1;  ///< histories.csv keeps every n-th sample (output only; the analysis
                          ///< uses all)
  bool rel_tol_given = false;  ///< the study set rel_tol (else a nonlinear wing's free flight
                               ///< takes kNonlinearWingFreeFlightRelTol: applyWingTolerance)
};

/// One axis of a sweep: a key and its values in the key's file units.
struct SweepAxis {
  std::string key;  ///< "tail.arm_m" (a vehicle key) or "trim.freq_hz" (an analysis key)
  GridAxis values;  ///< "A:B:N" spec or list, file units
};

struct Study;

/// The [sweep] section (kind "sweep").
struct SweepSettings {
  StudyKind run = StudyKind::kTrim;  ///< kTrim or kSimulate
  std::vector<SweepAxis> axes;       ///< in file order; the first is the outermost
  /// One resolved study of kind `run` per point, in point order (core/grid/sweep_grid.hpp).
  std::vector<Study> points;
  /// Keys of the base study's resolved sections whose value differs between points although no
  /// axis sets them (defaults that follow a swept key, e.g. "trim.freq_hz" when the axis is
  /// "operating_point.freq_hz"): study.resolved.toml leaves them out so that it re-runs the same
  /// points. Full dotted paths ("trim.freq_hz", "vehicle.wing.p3_aft_of_le_m").
  std::vector<std::string> derived_keys;
  /// The base study's [simulate] settings (run = kSimulate; defaults for a trim sweep): the
  /// sweep's own settings are this alternative, so the base's are kept here for the resolved
  /// study and the result columns (tethered or free).
  SimulateSettings base_simulate;
};

/// One parameter of a sensitivity study: a vehicle value the paper does not give, moved over its
/// plausible range (config/sensitivity_study.hpp).
struct SensitivityParameter {
  std::string key;    ///< a vehicle key as in [override], e.g. "body.pitch_inertia_kgm2"
  double low = 0.0;   ///< lower end of the plausible range, file units of the key
  double high = 0.0;  ///< upper end, > low
  /// The base vehicle's value in file units (from its resolved form); NaN when the resolved
  /// vehicle does not write the key.
  double base = 0.0;
};

/// The [sensitivity] section (kind "sensitivity").
struct SensitivitySettings {
  std::vector<SensitivityParameter> parameters;  ///< in file order
  /// The free flight flown at every trim (the pitch swing and altitude oscillations): cycles and
  /// the bounded-norm settings ([sensitivity.free], the keys of [simulate.free]).
  int free_flight_cycles = 60;
  orni::FreeFlightOptions free;
  /// One resolved study of kind trim per point: [0] the base vehicle, then for parameter i the
  /// vehicle with that key at low [1 + 2 i] and at high [2 + 2 i].
  std::vector<Study> points;
};

/// The [optimize] section (kind "optimize"; config/optimize_section.hpp).
struct OptimizeSettings {
  orni::opt::OptimizerOptions optimizer;  ///< threads: set by the command line (-j)
  orni::opt::DesignSpace space;           ///< the design variables, resolved against the vehicle
  orni::opt::DesignProblemOptions problem;  ///< objective, constraints, the trim of every design
};

/// The settings of a study's kind beyond the shared ones (Study::settings).
using KindSettings = std::variant<std::monostate, SimulateSettings, AeromapSettings,
                                  orni::CalibrationOptions, SweepSettings, OptimizeSettings,
                                  SensitivitySettings, orni::TrimContinuationOptions>;

struct Study {
  StudyKind kind = StudyKind::kSimulate;
  std::string name;                    ///< run name (output folder results/<name>/)
  std::filesystem::path study_path;    ///< the study file; empty for studyFromVehicle
  std::filesystem::path vehicle_path;  ///< the vehicle path as written in the study (relative
                                       ///< to study_path's folder), or as given to
                                       ///< studyFromVehicle; empty for an inline vehicle
                                       ///< without vehicle_source
  orni::VehicleModel vehicle;          ///< resolved, overrides applied, SI
  /// The vehicle file's design point ([operating_point], overrides applied, SI): the default of
  /// `point` and of the trim's initial guess; not part of `vehicle` (VehicleDefinition).
  orni::OperatingPoint design_point;
  /// The design point with [simulate] applied for kind simulate (the simulation's point; the
  /// other kinds' runs do not read it, their defaults come from the design point).
  orni::OperatingPoint point;
  /// [output] figures: draw the run's figures (true) or write only their scripts (false).
  bool figures = true;
  orni::TrimOptions trim;              ///< [trim] options (kinds trim and continuation, the
                                       ///< base of a trim sweep, sensitivity points; SI)
  /// The settings only one kind has: SimulateSettings (simulate), AeromapSettings (aeromap),
  /// CalibrationOptions (calibrate), SweepSettings (sweep), OptimizeSettings (optimize),
  /// SensitivitySettings (sensitivity), TrimContinuationOptions (continuation); monostate for
  /// modes (the vehicle alone) and trim, whose settings are the shared `trim` above: a trim
  /// study's [trim] is also the base of a trim sweep's points, of every sensitivity point and of
  /// a continuation's branch, so it stays a shared field rather than one kind's alternative. A
  /// sweep's or sensitivity study's vehicle, point and trim hold its base study (a simulate
  /// sweep's [simulate]: SweepSettings::base_simulate); a continuation's trim the periodic trim
  /// its branch starts from. Read it with the accessors below.
  KindSettings settings;

  /// The kind's settings; std::logic_error naming the kind when `settings` holds another kind's.
  const SimulateSettings& simulate() const;
  SimulateSettings& simulate();
  const AeromapSettings& aeromap() const;
  AeromapSettings& aeromap();
  const orni::CalibrationOptions& calibrate() const;
  orni::CalibrationOptions& calibrate();
  const SweepSettings& sweep() const;
  SweepSettings& sweep();
  const OptimizeSettings& optimize() const;
  OptimizeSettings& optimize();
  const SensitivitySettings& sensitivity() const;
  SensitivitySettings& sensitivity();
  const orni::TrimContinuationOptions& continuation() const;
  orni::TrimContinuationOptions& continuation();
};

/// True for an axis key of the run's analysis section ("trim.*" in a trim sweep), false for a
/// vehicle key.
bool isAnalysisKey(const std::string& key, StudyKind run);

/// The unit of a key from its suffix ("tail.arm_m" -> "m", "trim.freq_hz" -> "Hz",
/// "body.pitch_inertia_kgm2" -> "kg m^2"); "-" when the suffix names no unit.
std::string keyUnit(const std::string& key);

/// The axis of a grid spec (values = gridValues(spec)).
GridAxis gridAxis(const orni::GridSpec& spec);

/// Reads and validates a study file and the vehicle it names. Throws InputError.
Study loadStudyFile(const std::filesystem::path& study_file);

/// The study behind `ornithopter simulate VEHICLE.toml` (and `trim VEHICLE.toml` with kind trim):
/// name = the vehicle file stem, point = the vehicle file's design point, default options (for trim:
/// defaultTrimOptions, not yet validated against the bounds; the caller applies its flags and
/// checks TrimOptions::IsValid). Throws InputError (also for a trim of a vehicle without [body]).
Study studyFromVehicle(const std::filesystem::path& vehicle_file,
                       StudyKind kind = StudyKind::kSimulate);

/// The study behind `ornithopter aeromap VEHICLE.toml --speed .. --freq .. --theta .. [--tail ..]`:
/// kind aeromap, name "<vehicle stem>_aeromap", the given axes (file units, values already checked
/// by the caller), the vehicle's operating-point tail angle when `tail_angle_deg` is empty,
/// default options. Throws InputError for a bad vehicle file.
Study aeromapStudyFromVehicle(const std::filesystem::path& vehicle_file, GridAxis speed_mps,
                              GridAxis freq_hz, GridAxis theta_deg,
                              std::optional<GridAxis> tail_angle_deg);

/// study.resolved.toml: a complete TOML document with every default filled in (for a sweep: every
/// default that is the same at every point; SweepSettings::derived_keys), kind, name,
/// vehicle_source (the vehicle path as given), [simulate] with all options (kind simulate; in free
/// mode also [simulate.free] with every free-flight option), [aeromap] with its axes (specs as
/// "A:B:N", lists as arrays) and options (kind aeromap), [trim] with all options (kind trim),
/// [calibrate] (kind calibrate) or [optimize] with all options, sub-tables and variables (kind
/// optimize), and the resolved vehicle as a [vehicle] table in file units and key names; a sweep
/// writes [sweep] with run and its axes as [[sweep.axes]] tables, then its base study's section
/// and vehicle; a sensitivity study writes [sensitivity] with free_flight_cycles, its parameters
/// as [[sensitivity.parameters]] tables and [sensitivity.free], then [trim] and the base vehicle.
/// loadStudyFile reads it back into the same Study (apart from study_path); a sweep's or
/// sensitivity study's points are the same (loadStudyFile checks this when it loads one).
std::string resolvedStudyToml(const Study& study);

/// The file a study came from, for messages: the study file, or the vehicle file it was made of
/// ("vehicle" for a study built in memory).
std::string inputFileOf(const Study& study);

/// The error for vehicle key `key` (e.g. "wing.fe.element_size_m") of `study` that only a later
/// stage can judge (the mesh a value gives, say), at the line where the value was written: the
/// study's [override] ("override." + key), else the vehicle file; the study's file at line 0 when
/// neither holds it (a default).
InputError vehicleKeyError(const Study& study, const std::string& key,
                           const std::string& expected, const std::string& got);

}  // namespace orni::studies
