// VehicleModel: the immutable description of an ornithopter (or a wind-tunnel rig) in SI units.
//
// Built once from a vehicle file (studies/runner/config) and never changed by an algorithm
// (docs/design.md 7.1). Every field states its unit; its valid range is its entry in the field
// table (core/model/field_table.cpp, `ornithopter keys vehicle`), checked by core
// (core/model/vehicle_validation.hpp) and by the readers, which name file, line and key.
//
// Frames (core/model/frames.hpp): B body at P1 (x forward, y right, z down), W right wing at P2
// (x_W forward along the root chord, y_W outboard, z_W down when the flap angle is zero).
#pragma once

#include <string>
#include <vector>

namespace orni {

/// Ambient air and gravity.
struct AirModel {
  double density_kgpm3 = 1.225;               ///< rho
  double kinematic_viscosity_m2ps = 1.5e-5;   ///< nu
  double gravity_mps2 = 9.81;                 ///< g
};

/// Isotropic linear-elastic material (paper Table 1).
struct Material {
  std::string name;
  double youngs_modulus_pa = 0.0;  ///< E
  double poisson_ratio = 0.3;      ///< nu
  double density_kgpm3 = 0.0;      ///< rho
};

/// A straight wing member (spar, diagonal, stiffener): solid circular rod between two points of
/// the wing plane, coordinates (x_W, y_W) in metres (x_W <= 0 aft of the leading edge).
struct WingMember {
  std::string name;
  std::string material;     ///< key into VehicleModel::materials
  double diameter_m = 0.0;  ///< rod diameter
  double start_x_W_m = 0.0;
  double start_y_W_m = 0.0;
  double end_x_W_m = 0.0;
  double end_y_W_m = 0.0;
};

/// Wing skin: a shell of uniform thickness over the whole planform.
struct WingSkin {
  std::string material;      ///< key into VehicleModel::materials
  double thickness_m = 0.0;  ///< skin thickness
  /// Isotropic membrane pretension N0 (N/m) of the skin as built (a shrunk film), reacted by the
  /// frame; adds its geometric stiffness to the wing (docs/theory.md 4.6, 4.7). 0 = slack.
  double pretension_N_per_m = 0.0;
};

enum class Planform { kRectangular, kQuarterEllipse };
enum class StructureLevel { kRigid, kFlexible };

/// The joint that attaches the wing at P3 to the fuselage (docs/theory.md 2.6; the paper does not
/// say which rotations it holds).
/// Translations are always held; the rotations held at P3 in the wing frame W are:
enum class P3Joint {
  kUniversal,  ///< the rotation about the cross axis n_u (p3_cross_axis_normal): the paper's
               ///< "universal joint"; the stiffener roots pivot about the other in-plane axis
  kSpherical,  ///< none (a ball joint)
  kRevoluteX,  ///< about y_W and z_W: a pin along the flapping axis x_W only
  kClamped,    ///< all three: the stiffener roots bonded to a root block that flaps with W
};

/// Stiffness of the inertial loads on the flexible wing's modes (docs/theory.md 4.6).
enum class InertialStiffness {
  kBoth,           ///< spin softening K_w and geometric (stress) stiffening K_G: the physics
  kSofteningOnly,  ///< K_w only: a linear flexible body with the I9 invariant (earlier versions)
  kNone,           ///< neither: a linear flexible body without I9 (sensitivity test of docs/theory.md 4.6)
};

/// At most this many wing.fe.static_shapes_pa (each a full nonlinear static solve at the build).
inline constexpr int kMaxStaticShapesOfAWing = 8;

/// Finite-element and modal settings of the flexible wing (docs/theory.md 2.5, 2.6, 3.4, 3.5, 4.6).
struct WingFeSettings {
  double element_size_m = 0.005;  ///< target element edge h, <= semispan
  int max_modes = 12;             ///< fixed-interface modes kept (at most; file key "modes")
  double cutoff_hz = 0.0;         ///< keep only modes below this frequency; 0 = no cut-off
  double damping_ratio = 0.015;   ///< modal damping zeta of every mode
  bool p3_cross_axis_normal = true;  ///< universal-joint cross axis n_u = z_W (true) or y_W
  P3Joint p3_joint = P3Joint::kUniversal;  ///< the joint at P3
  /// Every node of the root chord (y_W = 0: the skin's root edge, on the flapping axis) held in
  /// translation, as a membrane taped to the fuselage along the hinge line; false = the wing is
  /// attached at P2 and P3 only (the paper).
  bool root_edge_pinned = false;
  InertialStiffness inertial_stiffness = InertialStiffness::kBoth;  ///< docs/theory.md 4.6
  /// Geometric nonlinearity of the skin and members (von Karman strains, the membrane condensed
  /// into the modal coordinates: core/structure/membrane_rom.hpp, docs/theory.md 4.7); false = the
  /// linear wing. Off by default: its reduced model is validated (within 5 % of the full
  /// nonlinear FE solution) only where the slack skin's static answer is unique and with 48
  /// modes (docs/theory.md 4.7), and flapping it costs about 35 times the linear wing
  /// (docs/speed.md: the condensed membrane's P x P products). Its free flights need rel_tol 1e-5
  /// (kNonlinearWingFreeFlightRelTol).
  bool nonlinear = false;
  /// Uniform lift pressures (Pa) whose full nonlinear static shapes join the modal basis of the
  /// nonlinear wing (structure/static_shapes.hpp, docs/theory.md 4.7); empty = the modes alone.
  std::vector<double> static_shapes_pa;
};

/// Geometry and structure of the right wing; the left wing is its mirror image.
struct WingModel {
  Planform planform = Planform::kRectangular;
  double semispan_m = 0.0;      ///< s: hinge P2 to tip along y_W
  double root_chord_m = 0.0;    ///< c0; chord c(y) = c0 (rectangular) or c0 sqrt(1-(y/s)^2)
  double incidence_rad = 0.0;   ///< built-in chord incidence relative to the hinge axis, nose-up +
  int strip_count = 27;         ///< aerodynamic strips per half wing
  StructureLevel structure = StructureLevel::kRigid;
  double p3_aft_of_le_m = 0.0;  ///< P3 (universal joint) on the root chord, <= c0
  WingSkin skin;
  std::vector<WingMember> members;
  /// Factor on every member diameter (spar details the paper leaves open: a calibration value,
  /// see studies/paper/calibrate_magpie.toml); 1 = the diameters as listed.
  double member_diameter_scale = 1.0;
  WingFeSettings fe;

  /// The diameter the physics uses for member m: member_diameter_scale * m.diameter_m.
  double memberDiameter(const WingMember& m) const { return member_diameter_scale * m.diameter_m; }
};

enum class AeroModelKind { kMstTd, kDeLaurier1993 };
enum class CirculationLag { kScherer1, kJones2 };  ///< docs/theory.md 5.7 options A and B

/// Strip-aerodynamics parameters (docs/theory.md section 5; DeLaurier sign conventions).
struct AeroParameters {
  AeroModelKind model = AeroModelKind::kMstTd;
  CirculationLag lag = CirculationLag::kScherer1;
  double aspect_ratio = 0.0;            ///< AR = b^2/S of the wing pair; 0 = from the planform
  double zero_lift_angle_rad = 0.0;     ///< alpha0, positive for positive camber
  double moment_coefficient_ac = 0.0;   ///< C_mac, nose-up positive
  double suction_efficiency = 0.98;     ///< eta_s
  double crossflow_drag_coefficient = 1.98;  ///< Cd_cf
  bool skin_friction = true;            ///< M11 turbulent flat-plate friction on/off
  double stall_angle_max_rad = 0.2268928;    ///< alpha_stall_max, 13 deg
  double stall_angle_min_rad = -0.2268928;   ///< alpha_stall_min, -13 deg
  double stall_width_rad = 0.0349066;   ///< delta_s of the tanh separation function (2 deg);
                                        ///< 0 = DeLaurier's hard switch
  double separation_lag_tf0 = 6.0;      ///< T_f0 (semichord times); 0 = no lag
  double min_speed_mps = 0.5;           ///< V_min floor of the reference speed
};

/// Prescribed flapping motion delta_M(t) = A sin(2 pi f t) about the hinge axis at P2.
struct FlappingKinematics {
  double amplitude_rad = 0.0;  ///< A
  double hinge_x_B_m = 0.0;    ///< P2 relative to P1 (the moment reference, the CG), body x
  double hinge_z_B_m = 0.0;    ///< P2 relative to P1, body z (down +)
};

/// Fuselage/vehicle mass properties (free flight, trim).
struct BodyModel {
  bool present = false;          ///< false for a wind-tunnel rig without flight data
  double mass_kg = 0.0;          ///< total vehicle mass including wings and tail
  double pitch_inertia_kgm2 = 0.0;  ///< I_YB of the whole vehicle about P1
  double drag_area_m2 = 0.0;     ///< fuselage parasite drag C_D S (acts at P1 against the flight
                                 ///< velocity); 0 = none (the paper's Eq. 4 has none)
};

/// Horizontal tail, paper Eq. (3) with the incidence of docs/theory.md section 7.
struct TailModel {
  bool present = false;
  double area_m2 = 0.0;            ///< S_T
  double aspect_ratio = 0.0;       ///< AR_T
  double zero_lift_drag_coefficient = 0.0;  ///< C_D0,T
  double oswald_efficiency = 0.9;  ///< e
  double arm_m = 0.0;              ///< P1 to P4 (tail aerodynamic centre) along -x_B
  double height_m = 0.0;           ///< P4 above the body x axis (along -z_B)
  double mass_kg = 0.0;            ///< point mass at P4 (part of BodyModel::mass_kg), < it
  double downwash_factor = 0.0;    ///< d eps_w / d theta_mean; 0 = no wing downwash
};

/// A flight or wind-tunnel operating point: what a run flies at. Every simulation takes its point
/// as an argument; the vehicle file's [operating_point] is its design point (VehicleDefinition),
/// the default of a study's point, never read by core.
struct OperatingPoint {
  double speed_mps = 0.0;       ///< U, flight or tunnel speed
  double freq_hz = 0.0;         ///< f, flapping frequency
  double theta_rad = 0.0;       ///< mean pitch attitude of the body
  double tail_angle_rad = 0.0;  ///< delta_T, tail elevation angle (paper sign)
};

struct VehicleModel {
  std::string name;
  std::string description;
  AirModel air;
  WingModel wing;
  AeroParameters aero;
  FlappingKinematics flapping;
  BodyModel body;
  TailModel tail;
  std::vector<Material> materials;

  /// The main wing alone, as the paper's Fig. 5 and its load cells see it: the same vehicle
  /// without the tail and without fuselage parasite drag (mass properties unchanged).
  VehicleModel mainWingAlone() const {
    VehicleModel v = *this;
    v.tail.present = false;
    v.body.drag_area_m2 = 0.0;
    return v;
  }

  /// The material of that name, or nullptr.
  const Material* findMaterial(const std::string& material_name) const {
    for (const Material& m : materials)
      if (m.name == material_name) return &m;
    return nullptr;
  }
};

/// What a vehicle file holds: the vehicle and its design operating point ([operating_point]: the
/// default point of a study's run, the trim's first guess, the periodic-orbit map's scale speed).
/// The point is kept apart from the VehicleModel (docs/design.md 7.1) so that core, which takes
/// every run's point as an argument, cannot read a second, stale one.
struct VehicleDefinition {
  VehicleModel model;
  OperatingPoint design_point;
};

}  // namespace orni
