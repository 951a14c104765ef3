// The period map of free longitudinal flight (core/dynamics/free_flight_system.hpp) for the
// periodic-orbit trim and its Floquet analysis (core/analysis/periodic_shooting.hpp, floquet.hpp).
//
// State x (the free-flight state without the ignorable ones): [theta, U, W, Q, q (M), q' (M),
// MST-TD states z, f per strip]. Horizontal position x_I and altitude h enter no equation: they are
// left out, and the altitude gained over the period is the map's condition (level flight: zero).
// The aerodynamic power integral rides along for the cycle-mean power. Parameters: the tail angle
// (rad), the flapping frequency (Hz; the period is 1/f) and a forward shift of the CG from the
// vehicle file's position (m: the hinge moves aft and the tail arm grows by the shift, mass and
// pitch inertia held). Each period starts at flap phase 0.
//
// Integration: GridRungeKutta (core/integrate/grid_runge_kutta.hpp) with the free-flight
// integrator's methods (IMEX ARK4(3)7L[2]SA with the modal stiffness implicit for the flexible
// wing, Dormand-Prince 5(4) for the rigid one) and its tolerance conventions; the step grid is
// chosen adaptively at refreshDiscretisation() and then fixed, so that flow() is smooth in (x, p).
// Scales (the scaled residual's units, the Floquet eigenvectors'): the free-flight absolute
// tolerances over the relative one: theta 0.1 rad, U and W 1 m/s, Q 1 rad/s, q 1e-3 m sqrt(kg),
// q' 0.1 m sqrt(kg)/s, lag angle and separation fraction 0.1; altitude gain 0.1 m; tail angle
// 0.1 rad, frequency 1 Hz, CG shift 0.01 m.
//
// The skin friction of every strip is frozen at `friction_speed_mps` (free flight freezes it at the
// release speed; here it must not depend on the unknowns). No allocation in the right-hand side.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "core/analysis/floquet.hpp"
#include "core/analysis/period_map.hpp"
#include "core/dynamics/flight_core.hpp"
#include "core/dynamics/modal_wing_cache.hpp"
#include "core/dynamics/free_flight_system.hpp"
#include "core/integrate/grid_runge_kutta.hpp"

namespace orni {

/// Parameter indices of FreeFlightPeriodMap.
enum FreeFlightPeriodParameter : int {
  kPeriodTailAngle = 0,  ///< tail angle delta_T (rad)
  kPeriodFrequency = 1,  ///< flapping frequency f (Hz)
  kPeriodCgShift = 2,    ///< CG shift forward of the vehicle file's CG (m)
  kPeriodParameterCount = 3,
};
/// Condition index: altitude gained over the period (m).
constexpr int kPeriodAltitudeGain = 0;

/// The speed that scales a periodic orbit's state and power tolerances (FreeFlightSystem's
/// reference speed): the vehicle's design speed (its file's [operating_point],
/// VehicleDefinition::design_point), 10 m/s when it has none. Fixed for a map's lifetime, so that
/// the scales do not move with the friction speed while a continuation walks a branch.
double orbitScaleSpeed_mps(const OperatingPoint& design_point);

struct FreeFlightPeriodMapOptions {
  double rel_tol = 1e-6;               ///< step control of the grid, (0, 1e-2]
  double friction_speed_mps = 10.0;    ///< skin friction frozen at this speed, > 0
  double max_step_fraction = 0.125;    ///< largest step, fraction of the period (free flight: T/8)
  /// The vehicle file's design point (TrimOptions::design_point): its speed scales the tolerances
  /// (orbitScaleSpeed_mps); the map is first prepared at it (at 10 m/s and 10 Hz when it is
  /// zero, i.e. none).
  OperatingPoint design_point;
};

/// One period of the orbit, sampled uniformly (histories, cycle means).
struct OrbitHistory {
  std::vector<double> t_s, delta_M_rad;
  std::vector<BodyState> body;           ///< x_I and h from 0 at t = 0
  std::vector<FreeFlightSample> samples;  ///< accelerations and loads
  std::vector<double> power_integral_J;   ///< aerodynamic energy since t = 0
};

class FreeFlightPeriodMap final : public PeriodMap {
 public:
  /// `model` must outlive the map. Throws std::invalid_argument like FreeFlightSystem.
  FreeFlightPeriodMap(const FlightCoreModel& model, const FreeFlightPeriodMapOptions& options);
  ~FreeFlightPeriodMap() override;

  int stateCount() const override { return n_; }
  int parameterCount() const override { return kPeriodParameterCount; }
  int conditionCount() const override { return 1; }
  double stateScale(int i) const override { return scale_[static_cast<std::size_t>(i)]; }
  double parameterScale(int j) const override;
  double conditionScale(int) const override { return 0.1; }
  double period_s(const double* p) const override { return 1.0 / p[kPeriodFrequency]; }
  bool flow(const double* x, const double* p, double* x_T, double* g, std::string* why) override;
  bool refreshDiscretisation(const double* x, const double* p, std::string* why) override;
  /// A copy with this map's step grid, friction speed, CG-shifted vehicle and free-flight models
  /// (shared, read only); its system is built at its first flow. Thread-compatible with this map.
  std::unique_ptr<PeriodMap> clone() const override;
  /// Adds the clone's right-hand-side evaluations to rhsEvaluations().
  void addWorkOf(const PeriodMap& clone) override;

  /// Names and kinds of the states (Floquet labels, CSV columns) and their units.
  const std::vector<FloquetStateInfo>& stateInfo() const { return info_; }
  const std::vector<std::string>& stateUnits() const { return units_; }
  int modeCount() const { return mode_count_; }

  /// x from the body state (theta, U, W, Q) and the wing state [q, q', aero states] (the layout of
  /// SimulationSummary::final_wing_state).
  std::vector<double> reducedState(const BodyState& body, const std::vector<double>& wing) const;

  /// Parameters [tail, f, CG shift] of an operating point with a CG shift.
  static std::vector<double> parameters(const OperatingPoint& point, double cg_shift_m = 0.0);

  /// One period from (x, p) sampled at `samples` uniform phases plus the end (samples + 1 rows),
  /// on the current grid merged with the sample phases. False with the reason on failure.
  bool sampleOrbit(const double* x, const double* p, int samples, OrbitHistory* out,
                   std::string* why);

  /// Freeze the skin friction at another speed (the step grid is kept).
  void setFrictionSpeed(double speed_mps);
  double frictionSpeed_mps() const { return options_.friction_speed_mps; }
  /// Mean aerodynamic power of both wings over the last flow() (W).
  double lastMeanPower_W() const { return last_power_W_; }
  /// The vehicle at parameters p (the CG shift applied); valid until the next call with another
  /// shift.
  const FlightCoreModel& modelAt(const double* p);
  int gridSteps() const { return grid_.empty() ? 0 : static_cast<int>(grid_.size()) - 1; }
  long rhsEvaluations() const { return rhs_evaluations_; }
  std::string methodName() const;

 private:
  struct CloneTag {};
  FreeFlightPeriodMap(const FreeFlightPeriodMap& other, CloneTag);
  // Build the system and integrator for p when p changed; the system's immutable part from
  // freeFlightModelAt (shared: only the per-run workspace is new).
  void prepare(const double* p);
  // The free-flight model of modelAt(p): one per underlying FlightCoreModel (the base's, the
  // CG-shifted one's), built at its first use and shared with clones (immutable).
  std::shared_ptr<const FreeFlightModel> freeFlightModelAt(const double* p);
  void fullState(const double* x, double* y) const;

  const FlightCoreModel& base_;
  FreeFlightPeriodMapOptions options_;
  int n_ = 0, mode_count_ = 0, full_ = 0, power_ = 0;
  std::vector<double> scale_;
  std::vector<FloquetStateInfo> info_;
  std::vector<std::string> units_;
  std::shared_ptr<const FlightCoreModel> shifted_;  // CG-shifted vehicle (null: base_)
  std::shared_ptr<ModalWingCache> shifted_wings_;    // holds base_'s modal wing (flexible)
  double shift_m_ = 0.0;
  std::shared_ptr<const FreeFlightModel> base_model_;     // of base_ (null: not built yet)
  std::shared_ptr<const FreeFlightModel> shifted_model_;  // of *shifted_, keeps it alive
  std::unique_ptr<FreeFlightSystem> sys_;
  std::unique_ptr<GridRungeKutta> rk_;
  double p_[kPeriodParameterCount] = {0.0, 0.0, 0.0};
  bool prepared_ = false;
  GridStepControl control_;
  std::vector<double> grid_;
  std::vector<double> y0_, y1_;
  double last_power_W_ = 0.0;
  long rhs_evaluations_ = 0;
};

}  // namespace orni
