// The [trim] section of a study file (docs/design.md 5) <-> orni::TrimOptions.
//
// Private to orni_studies (includes toml++ through toml_access.hpp). Keys (all optional; file
// units in the suffixes, converted to SI here; each valid range is the key's entry in the field
// table, core/model/field_table.cpp, `ornithopter keys trim`, copied here for reading):
//
//   freq_hz           flapping frequency [0.01, 200]: fixed, or the initial guess when "freq_hz" is an
//                     unknown; default the vehicle's operating point
//   unknowns          array of 1-3 distinct names from "theta_mean_deg", "speed_mps",
//                     "tail_angle_deg", "freq_hz"; default the first three (3 = square solve,
//                     fewer = least squares)
//   initial           table { theta_mean_deg, speed_mps, tail_angle_deg }: initial guess of the
//                     unknowns and the fixed value of the others; each defaults to the vehicle's
//                     operating point
//   bounds            table { <unknown name> = [lower, upper] } with lower < upper, per unknown;
//                     defaults theta_mean_deg [-10, 40], speed_mps [2, 30], tail_angle_deg
//                     [-30, 45], freq_hz [1, 40]; inside the ranges of the unknowns
//   max_iterations    Ceres iterations [1, 1000], default 50
//   residual_tol      equilibrium tolerance [1e-12, 0.1] as a fraction of the weight: max(|FV - W|,
//                     |FH|, |M| / c_mean) <= residual_tol * W, default 1e-4
//   function_tol      Ceres function tolerance [1e-20, 1), default 1e-12
//   rel_tol           integrator relative tolerance of every periodic run [1e-12, 0.01], default 1e-6
//   steady_tol        periodic steady-state tolerance of the residual runs [1e-12, 0.1], default 1e-5
//   max_cycles        cycle limit of a residual run [1, 100000], default 40
//   derivative_cycles cycles of each finite-difference run [1, 1000], default 3
//   refine_in_free_flight  refine the Eq. (4) trim to level settled free flight (default true;
//                     trim/free_flight_trim.hpp)
//   refine_cycles     cycles of each settled free flight [6, 10000], default 120 (last third averaged)
//   method            "two_stage" (default: Eq. 4, then the free-flight refinement) or "periodic"
//                     (the periodic orbit of free flight and its Floquet multipliers,
//                     trim/periodic_trim.hpp; kind = "trim" only). With "periodic" the keys above
//                     set the Eq. (4) start of Newton's iteration and three defaults are looser
//                     (residual_tol 1e-3, rel_tol 1e-4, steady_tol 1e-3: usePeriodicMethod);
//                     refine_in_free_flight and refine_cycles belong to "two_stage" and are errors.
//   [trim.periodic]   (method = "periodic" only) control ("tail_angle_deg" default, "freq_hz",
//                     "cg_shift_m": the control made free for level flight), residual_tol (0, 1e-4]
//                     default 1e-8, rel_tol (0, 1e-3] default 1e-5, max_iterations [1, 1000]
//                     default 40, history_samples [8, 100000] default 200, floquet (bool, default
//                     true), multipliers [0, 100] default 8 (leading multipliers by Arnoldi; 0 =
//                     all, from the full monodromy matrix); see trim/periodic_trim_options.hpp.
//
// Every error is an InputError naming file, line and key ('trim.bounds.speed_mps', ...).
#pragma once

#include <string>
#include <vector>

#include "core/model/vehicle_model.hpp"
#include "studies/runner/config/toml_access.hpp"
#include "trim/trim_options.hpp"

namespace orni::studies {

/// The keys a [trim] table may have.
std::vector<std::string> trimSectionKeys();

/// Throws InputError at 'trim.method' when `trim` asks for the periodic method, which `where`
/// (e.g. "a sweep") cannot run yet.
void rejectPeriodicMethod(TableReader& trim, const std::string& where);

/// Reads a [trim] table; `design_point` (the vehicle file's [operating_point]) supplies the
/// defaults of the initial guess and the frequency, and TrimOptions::design_point. Calls
/// trim.finish(). Throws InputError.
orni::TrimOptions readTrimSection(TableReader& trim, const orni::OperatingPoint& design_point);

/// Writes [trim] (or the table `prefix`, e.g. {"optimize", "trim"}) with every key (initial and
/// bounds as sub-tables), so that readTrimSection reproduces `options`; freq_hz only when
/// `with_freq` (an optimisation keeps it in [optimize]).
void writeTrimSection(const orni::TrimOptions& options, TomlWriter& out,
                      const std::vector<std::string>& prefix = {"trim"}, bool with_freq = true);

}  // namespace orni::studies
