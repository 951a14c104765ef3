// The design problem (docs/theory.md 12.1): size a vehicle so that it trims (paper Eq. 4), flies
// within the bounded-norm criterion (paper Eq. 5) and needs as little flapping power as possible,
// instead of the paper's heuristic search of tail area, aspect ratio, elevation and the P1-P4 distance.
//
// One evaluation (evaluateDesign): apply the design to a copy of the vehicle (design_space.hpp),
// check it (core's model checks, core/model/vehicle_validation.hpp: the ranges of the field table
// and the rules between fields, the same as the vehicle files'), build the FlightCoreModel (a flexible wing's modal model
// comes from the problem's ModalWingCache, core/dynamics/modal_wing_cache.hpp), solve the trim with Ceres
// (trim/trim_solver.hpp; initial guess: the last converged trim of this start, warm start, else
// the study's initial guess) and, on a converged trim, the free-flight check that solveTrim runs.
//
// Objective (DesignObjective), in its own unit:
//   power            cycle-mean mechanical power at the two hinges at the trim point (W): the
//                    TrimSummary's cycle means (power_hinge_W) of the final periodic run; for a
//                    trim that did not converge, the same at its final iterate (a finite number
//                    the optimiser can follow while the trim constraint is violated);
//   pitch_amplitude  half the peak-to-peak pitch of the free flight after the transient (deg);
//   weighted         w_power * power (W) + w_pitch * pitch amplitude (deg).
// Constraints g_i <= 0, dimensionless:
//   trimmed          -1 for a converged trim; else max(log10(r / residual_tol), 0.01) with r the
//                    max scaled residual of Eq. (4) at the final iterate (how far from trim);
//   bounded          (optional, default on) max(norm_ratio_max - 1, drift - drift_limit) over
//                    the analysed window (both in units of the bounds R_i): <= 0 exactly when
//                    Eq. (5) holds (norm <= 1, secular drift within its limit), at least 0.01
//                    when not; when the flight diverged (the norm passed divergence_ratio)
//                    divergence_ratio (2 - t_div / horizon), so that diverging later is closer to
//                    bounded and any diverged flight is worse than a flown one;
//   pitch_amplitude  (optional) amplitude / limit - 1 (a diverged flight: as for bounded);
//   tip_deflection   (optional, flexible wing) max |tip deflection| over one periodic cycle of the
//                    tethered run at the trim point / limit - 1;
//   structural_mass  (optional) mass of both wings (members + skin) / limit - 1;
//   floquet_max_modulus (optional, periodic trim) largest Floquet multiplier modulus of the
//                    trimmed orbit / limit - 1 (the orbit's stability, docs/theory.md 10.4; a limit < 1
//                    demands a stable orbit with that margin).
// The trim: options.trim.method two-stage (solveTrim) or periodic (solvePeriodicTrim: the orbit
// of free flight, its Floquet multipliers, and the bounded-norm check when verify_free_flight).
// With the periodic trim the power is that of the tethered periodic run at the orbit's cycle-mean
// point (theta, airspeed, tail angle, frequency), with the two-stage trim's default run
// tolerances: the same definition as the two-stage trim's power, at the periodic trim's point.
// Without a converged trim the trim-point quantities do not exist: bounded, pitch_amplitude and
// tip_deflection are then trimmed + 2 divergence_ratio, worse than any flown value and
// following the trim constraint, so that the largest violation (which COBYLA reduces first) still
// measures the distance from trim. A value that cannot be computed otherwise (the free flight or
// the tethered run failed) is NaN, which the driver hands to NLopt as the finite failure penalty.
// An evaluation whose model cannot be built or whose trim throws is kFailed; nothing throws out of
// evaluate().
#pragma once

#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "core/dynamics/modal_wing_cache.hpp"
#include "core/model/vehicle_model.hpp"
#include "optimize/design_options.hpp"
#include "optimize/design_space.hpp"
#include "optimize/optimizer.hpp"
#include "optimize/problem.hpp"
#include "trim/trim_solver.hpp"

namespace orni::opt {

/// The physical outcome of one design evaluation.
struct DesignEvaluation {
  bool trim_attempted = false;  ///< the model was built and the trim ran
  std::string message;          ///< failure reason, or the trim / free-flight verdict
  /// Valid when trim_attempted. With the periodic trim: status, message, solution (the orbit's
  /// cycle means), free_flight from the periodic trim; scaled_residual_max = its periodic
  /// residual (or the Eq. (4) start's when that did not converge); evaluations = period maps;
  /// mean = the tethered periodic run at the solution (the hinge power, as the two-stage trim's).
  TrimSummary trim;
  /// The tolerance trim.scaled_residual_max is measured against (the constraint "trimmed"):
  /// Eq. (4)'s residual_tol, or the periodic residual_tol once the Eq. (4) start converged.
  double residual_tol = 0.0;
  bool periodic = false;        ///< the periodic trim ran (options.trim.method)
  bool floquet_valid = false;   ///< the periodic orbit's Floquet analysis exists
  double floquet_max_modulus = std::numeric_limits<double>::quiet_NaN();
  double periodic_residual = std::numeric_limits<double>::quiet_NaN();  ///< scaled states
  OperatingPoint equation4;     ///< the periodic trim's Eq. (4) start (its final iterate)
  double pitch_amplitude_rad = std::numeric_limits<double>::quiet_NaN();
  double tip_deflection_m = std::numeric_limits<double>::quiet_NaN();
  double structural_mass_kg = std::numeric_limits<double>::quiet_NaN();  ///< both wings
};

/// Evaluate the (already designed) vehicle: build, trim from `initial_guess` (its unknowns; the
/// other fields come from options.trim.initial) and check free flight. Never throws for a design
/// that cannot be evaluated: trim_attempted is false and message says why.
DesignEvaluation evaluateDesign(const VehicleModel& vehicle, const DesignProblemOptions& options,
                                const OperatingPoint& initial_guess,
                                ModalWingCache* modal_wings = nullptr);

/// Name, unit and scale of one reported value (Evaluation::values, SI): value_in_unit =
/// value_si / si_per_unit.
struct DesignValueInfo {
  const char* name;
  const char* unit;
  double si_per_unit;
};

/// Indices of Evaluation::values of the design problem: kDesignValueCount of them, and with the
/// periodic trim six more (kFloquetMaxModulus .. kEquation4TailAngle).
enum DesignValue : int {
  kTrimConverged = 0,  ///< 1 / 0
  kTrimTheta,          ///< rad
  kTrimSpeed,          ///< m/s
  kTrimTailAngle,      ///< rad
  kTrimFreq,           ///< Hz
  kTrimResidual,       ///< max scaled residual of Eq. (4)
  kPowerHinge,         ///< W
  kPowerAero,          ///< W
  kBounded,            ///< 1 / 0 (NaN: no free flight)
  kNormRatioMax,       ///< -
  kFlownTime,          ///< s flown freely before the horizon or the divergence
  kDrift,              ///< secular drift over the window, in units of the state's bound
  kPitchAmplitude,     ///< rad
  kTipDeflection,      ///< m
  kStructuralMass,     ///< kg, both wings
  kPeriodicRuns,       ///< periodic runs of the trim (two-stage) or period maps (periodic)
  kDesignValueCount,
  kFloquetMaxModulus = kDesignValueCount,  ///< largest |mu| of the orbit (periodic trim only)
  kFloquetStable,      ///< 1 / 0 (NaN: no Floquet analysis)
  kPeriodicResidual,   ///< max |x(T) - x(0)| in state scales
  kEquation4Theta,     ///< rad: the Eq. (4) start of the periodic trim (its warm start)
  kEquation4Speed,     ///< m/s
  kEquation4TailAngle, ///< rad
  kPeriodicDesignValueCount
};

class DesignProblem final : public Problem {
 public:
  /// Throws std::invalid_argument for invalid options, an empty or inconsistent space, or a
  /// tip-deflection limit on a rigid wing.
  DesignProblem(VehicleModel base, DesignSpace space, DesignProblemOptions options);

  int variableCount() const override { return space_.size(); }
  int constraintCount() const override { return static_cast<int>(constraint_names_.size()); }
  int valueCount() const override { return static_cast<int>(value_info_.size()); }
  std::unique_ptr<ProblemWorkspace> makeWorkspace() const override;
  Evaluation evaluate(const std::vector<double>& x, ProblemWorkspace& workspace) const override;
  void observe(const std::vector<double>& x, const Evaluation& result,
               ProblemWorkspace& workspace) const override;

  /// Names of the constraints in order: "trimmed", then the enabled ones of "bounded",
  /// "pitch_amplitude", "tip_deflection", "structural_mass", "floquet_max_modulus".
  const std::vector<std::string>& constraintNames() const { return constraint_names_; }
  /// The reported values (Evaluation::values), in DesignValue order: the two-stage trim's, and
  /// with the periodic trim the Floquet ones after them.
  const std::vector<DesignValueInfo>& valueInfo() const { return value_info_; }

  const VehicleModel& baseVehicle() const { return base_; }
  const DesignSpace& space() const { return space_; }
  const DesignProblemOptions& options() const { return options_; }
  /// The variables' bounds and initial values.
  VariableBox box() const;
  /// The designed vehicle of x with the trim point of `result` as its design point (when the trim
  /// converged; otherwise the trim options' design point): the vehicle file of a design.
  VehicleDefinition designVehicle(const std::vector<double>& x, const Evaluation& result) const;

 private:
  VehicleModel base_;
  DesignSpace space_;
  DesignProblemOptions options_;
  std::vector<std::string> constraint_names_;
  std::vector<DesignValueInfo> value_info_;
  /// The modal wings of the designs evaluated (one per stiffener design; every design of a
  /// tail-only space shares the base's). Shared by the workspaces' threads.
  std::shared_ptr<ModalWingCache> modal_wings_ = std::make_shared<ModalWingCache>();
};

}  // namespace orni::opt
