// The periodic-flight core: wing strips, rigid-wing inertia and tail assembled into the loads that
// the wings and tail apply to the fuselage at P1 (docs/theory.md 4.4, docs/theory.md 5.5, paper Eq. 2).
//
// Model vs data (docs/design.md 7.1): FlightCoreModel is built once from a VehicleModel and never
// changed; FlightCoreData is the per-thread workspace, sized once. evaluateLoads() does not
// allocate.
#pragma once

#include <array>
#include <memory>
#include <vector>

#include "core/aero/mst_strip.hpp"
#include "core/aero/mst_td_batch.hpp"
#include "core/dynamics/flapping.hpp"
#include "core/dynamics/load_sample.hpp"
#include "core/model/frames.hpp"
#include "core/model/vehicle_model.hpp"
#include "core/model/wing_geometry.hpp"
#include "core/model/wing_inertia.hpp"

namespace orni {

/// Motion of the fuselage (B components). In tethered mode U, W, theta are held and Q = 0.
struct BodyMotion {
  Vec3 v_P1_B = Vec3::Zero();     ///< inertial velocity of P1 (U, 0, W)
  Vec3 a_P1_B = Vec3::Zero();     ///< inertial acceleration of P1
  double theta_rad = 0.0;         ///< pitch attitude (for the flight-path angle)
  double Q_radps = 0.0;           ///< pitch rate
  double Qdot_radps2 = 0.0;       ///< pitch acceleration
};

struct FlexibleWingModel;
class ModalWingCache;

struct FlightCoreModel {
  VehicleModel vehicle;
  std::vector<Strip> strips;
  std::vector<aero::StripGeometry> strip_geometry;
  aero::StripContext aero_context;
  int aero_states_per_strip = 0;
  WingMassBreakdown wing_mass;     ///< one wing
  Vec3 p_P1P2_B = Vec3::Zero();    ///< hinge position
  Vec3 p_P1P4_B = Vec3::Zero();    ///< tail aerodynamic centre
  Vec3 e_c_W = Vec3::UnitX();      ///< chord direction TE->LE in W (incidence applied)
  Vec3 n_W = -Vec3::UnitZ();       ///< upper-surface normal in W
  double wing_area_both_m2 = 0.0;  ///< S of the pair (strip areas summed)
  double mean_chord_m = 0.0;       ///< S / b

  /// The flexible wing (structure = "flexible"): modes, strip modal data; null for rigid.
  std::shared_ptr<const FlexibleWingModel> flexible;

  /// Whether the constructor runs core's model checks (core/model/vehicle_validation.hpp).
  enum class Checks {
    kRequired,  ///< every vehicle of the program: InvalidModelError outside the field table's
                ///< ranges and rules
    kSkippedForLimitTests,  ///< analytic-limit tests only (a wing 1000 times stiffer than any
                            ///< material, massless wings, no air): vehicles outside the physical
                            ///< ranges on purpose
  };
  /// A flexible wing's modal wing comes from `modal_wings` (owned by the caller, kept here for
  /// models derived from this one) or, when null, is built for this model alone.
  explicit FlightCoreModel(const VehicleModel& v, Checks checks = Checks::kRequired,
                           ModalWingCache* modal_wings = nullptr);
  ModalWingCache* modal_wing_cache = nullptr;  ///< the cache it was built with (not owned)
  int aeroStateCount() const {
    return aero_states_per_strip * static_cast<int>(strips.size());
  }
};

/// Per-thread workspace.
struct FlightCoreData {
  explicit FlightCoreData(const FlightCoreModel& model);
  std::vector<double> separation_f;  ///< last f per strip (diagnostic)
  std::vector<double> friction_cd;   ///< M11 Cd_f per strip at friction_speed_mps
  double friction_speed_mps = -1.0;  ///< flight speed the friction cache belongs to
  aero::StripBatch batch;            ///< structure-of-arrays workspace of the vectorised kernel
  Eigen::ArrayXd y_strip_m;          ///< strip mid-stations (batch layout)
};

/// Everything that sets the operating condition besides the body motion.
struct ControlInput {
  double freq_hz = 0.0;
  double tail_angle_rad = 0.0;
};

/// Loads on the fuselage at time t. `aero_states` holds FlightCoreModel::aeroStateCount() values;
/// their derivatives go to `aero_state_derivatives` (null = not needed). Gravity is not included
/// (a tared load cell; the free-flight equations add it). No allocation.
void evaluateLoads(const FlightCoreModel& model, FlightCoreData& data, const BodyMotion& body,
                   const ControlInput& control, double t_s, const double* aero_states,
                   double* aero_state_derivatives, LoadSample* out);

/// Quasi-steady initial aero states at time t (docs/theory.md 5.7: no start-up transient).
void initialAeroStates(const FlightCoreModel& model, const BodyMotion& body,
                       const ControlInput& control, double t_s, double* aero_states);

/// Scales of the quadrature channels at flight speed U: q S for FV and FH, q S c_mean for M,
/// q S U for the powers (q = rho U^2 / 2). Used for tolerances and the steady-state test.
std::array<double, kQuadratureChannels> quadratureScales(const FlightCoreModel& model,
                                                         double speed_mps);

/// Tail loads about P1 (paper Eq. 3 with the incidence of docs/theory.md 7) into the tail fields of
/// `out`, the fuselage parasite drag into FH_body_N, then the totals FV, FH, M from the wing, tail
/// and body fields. Shared by the rigid and the flexible wing and by free flight.
void addTailAndTotals(const FlightCoreModel& model, const BodyMotion& body,
                      const ControlInput& control, LoadSample* out);

/// Body motion of the tethered (wind-tunnel / constrained) mode: level flight path at speed U with
/// the body pitched by theta; U_B = U cos(theta), W_B = U sin(theta), Q = 0.
BodyMotion tetheredBodyMotion(double speed_mps, double theta_rad);

}  // namespace orni
