// The field table (field_table.hpp). Ranges are in FILE units; each bound is physical, and the
// comment beside it says why. Every committed vehicle and study, and every test input meant to be
// valid, lies inside them (the ranges only reject values no valid run uses).
#include "core/model/field_table.hpp"

#include <stdexcept>

#include "core/model/frames.hpp"

namespace orni {

namespace {

using R = ValueRange;
using T = FieldType;

constexpr double kDeg = kDegToRad;
constexpr double kGpa = 1e9;

// ---- Shared quantities (a range written once) ------------------------------------------------

/// Flight or tunnel speed U: from 1 mm/s (hover, U = 0, is not modelled: the strip theory needs a
/// free stream, and the integrator's tolerance scales, q S with q = rho U^2 / 2, vanish near it:
/// 1e-160 m/s stopped the run with an internal error) to 100 m/s, Mach 0.3 at sea level, where the
/// incompressible strip theory ends.
constexpr R kSpeed = R::closed(0.001, 100.0);
/// Flapping frequency f: from 0.01 Hz (a 100 s period; large birds and human-powered ornithopters
/// flap at 0.5-3 Hz; 1e-9 Hz failed in the integrator) to 200 Hz (small insects; beyond, strip
/// theory and the wing models do not apply).
constexpr R kFreq = R::closed(0.01, 200.0);
/// Pitch attitude and tail angle: strictly inside a quarter turn (the flight-path frame and the
/// tail's small-angle model turn over at 90 deg).
constexpr R kHalfTurnDeg = R::open(-90.0, 90.0);
/// Lengths of the vehicle: at most 20 m, the largest flapping wing built (the human-powered
/// Snowbird ornithopter, 32 m span) with margin; positions relative to the CG lie within it.
constexpr double kMaxLength_m = 20.0;
constexpr R kPosition = R::closed(-kMaxLength_m, kMaxLength_m);
/// Flapping cycles of a run: at least one, at most 100 000 (hours of computing).
constexpr R kCycles = R::closed(1, 100000);
/// Integrator relative tolerance: 1e-12 is near round-off for the states' scales (2.2e-16 times
/// 1e4), looser than 1e-2 the cycle means are no longer converged.
constexpr R kRelTol = R::closed(1e-12, 1e-2);
/// Absolute tolerances of the lag and separation states (rad, fraction in [0, 1]): same reasoning.
constexpr R kAbsTol = R::closed(1e-14, 1e-2);
/// Periodic steady state: relative cycle-to-cycle change, 1e-12 (round-off) to 0.1.
constexpr R kSteadyTol = R::closed(1e-12, 0.1);

// Default texts of the operating point's keys, used where a key defaults to it.
constexpr std::string_view kFromPoint = "the vehicle's operating point";

constexpr FieldSpec number(std::string_view key, std::string_view unit, double si, R range,
                           std::string_view def, std::string_view meaning,
                           std::string_view cli = {}, std::string_view also = {}) {
  return FieldSpec{key, unit, si, T::kNumber, range, {}, def, meaning, cli, also};
}
constexpr FieldSpec integer(std::string_view key, R range, std::string_view def,
                            std::string_view meaning, std::string_view cli = {},
                            std::string_view also = {}) {
  return FieldSpec{key, "-", 1.0, T::kInteger, range, {}, def, meaning, cli, also};
}
constexpr FieldSpec boolean(std::string_view key, std::string_view def, std::string_view meaning) {
  return FieldSpec{key, "-", 1.0, T::kBoolean, R::any(), {}, def, meaning, {}, {}};
}
constexpr FieldSpec text(std::string_view key, std::string_view def, std::string_view meaning,
                         std::string_view also = {}) {
  return FieldSpec{key, "-", 1.0, T::kString, R::any(), {}, def, meaning, {}, also};
}
constexpr FieldSpec choice(std::string_view key, std::string_view choices, std::string_view def,
                           std::string_view meaning, std::string_view cli = {}) {
  return FieldSpec{key, "-", 1.0, T::kChoice, R::any(), choices, def, meaning, cli, {}};
}
constexpr FieldSpec pair(std::string_view key, std::string_view unit, double si, R range,
                         std::string_view def, std::string_view meaning,
                         std::string_view also = {}) {
  return FieldSpec{key, unit, si, T::kPair, range, {}, def, meaning, {}, also};
}
constexpr FieldSpec numbers(std::string_view key, std::string_view unit, double si, R range,
                            std::string_view def, std::string_view meaning,
                            std::string_view also = {}) {
  return FieldSpec{key, unit, si, T::kNumberList, range, {}, def, meaning, {}, also};
}
constexpr FieldSpec grid(std::string_view key, std::string_view unit, double si, R range,
                         std::string_view def, std::string_view meaning,
                         std::string_view cli = {}) {
  return FieldSpec{key, unit, si, T::kGrid, range, {}, def, meaning, cli, {}};
}
constexpr FieldSpec list(std::string_view key, std::string_view def, std::string_view meaning,
                         std::string_view cli = {}) {
  return FieldSpec{key, "-", 1.0, T::kStringList, R::any(), {}, def, meaning, cli, {}};
}
constexpr FieldSpec table(std::string_view key, std::string_view def, std::string_view meaning) {
  return FieldSpec{key, "-", 1.0, T::kTable, R::any(), {}, def, meaning, {}, {}};
}

std::vector<FieldSpec> makeTable() {
  return {
      // ---- Vehicle: identity --------------------------------------------------------------------
      text("name", "required", "vehicle name (titles, default run names)"),
      text("description", "\"\"", "one line about the vehicle"),

      // ---- [air] --------------------------------------------------------------------------------
      // 0.01: below Mars' surface air (0.02) and Earth's at 30 km (0.018); 10: 8 x sea level.
      number("air.density_kgpm3", "kg/m^3", 1.0, R::closed(0.01, 10.0), "1.225",
             "air density rho"),
      // 1e-6: water; 1e-3: Mars' surface air (air at sea level: 1.5e-5).
      number("air.kinematic_viscosity_m2ps", "m^2/s", 1.0, R::closed(1e-6, 1e-3), "1.5e-5",
             "kinematic viscosity nu (Reynolds number of the skin friction)"),
      // 0: no weight (a tunnel rig); 100: 10 g, beyond any planet's surface (Jupiter 24.8).
      number("air.gravity_mps2", "m/s^2", 1.0, R::closed(0.0, 100.0), "9.81", "gravity g"),

      // ---- [wing] -------------------------------------------------------------------------------
      choice("wing.planform", "rectangular | quarter_ellipse", "required",
             "planform of the half wing"),
      // 5 mm: a RoboBee-size wing (15 mm); 20 m: kMaxLength_m.
      number("wing.semispan_m", "m", 1.0, R::closed(0.005, kMaxLength_m), "required",
             "semispan s: hinge P2 to tip along y_W"),
      // 2 mm to 10 m: an insect's chord to half the largest span.
      number("wing.root_chord_m", "m", 1.0, R::closed(0.002, 10.0), "required",
             "root chord c0; c(y) = c0 or c0 sqrt(1 - (y/s)^2)"),
      // +-45 deg: a built-in incidence beyond it is no longer a small chord twist.
      number("wing.incidence_deg", "deg", kDeg, R::open(-45.0, 45.0), "0",
             "built-in chord incidence to the hinge axis, nose-up +"),
      // 500 strips: a strip narrower than 1/500 of the span adds nothing to strip theory.
      integer("wing.strips", R::closed(1, 500), "required", "aerodynamic strips per half wing"),
      choice("wing.structure", "rigid | flexible", "\"rigid\"",
             "rigid wing, or the finite-element flexible wing"),
      number("wing.p3_aft_of_le_m", "m", 1.0, R::closed(0.0, 10.0), "half the root chord",
             "P3 (the joint to the fuselage) aft of the leading edge on the root chord", {},
             "<= wing.root_chord_m"),
      // 0.01 to 100: a 2 mm spar becomes 20 um or 0.2 m; beyond either the rods are not rods.
      number("wing.member_diameter_scale", "-", 1.0, R::closed(0.01, 100.0), "1",
             "factor on every member diameter"),
      table("wing.skin", "required", "the skin: a shell of uniform thickness over the planform"),
      text("wing.skin.material", "required", "material of the skin", "a [materials.NAME] name"),
      // 1 um: the thinnest polymer films; 5 cm: a solid plate, no longer a skin.
      number("wing.skin.thickness_m", "m", 1.0, R::closed(1e-6, 0.05), "required",
             "skin thickness"),
      // 0 (a slack film) to 2000 N/m: 50 MPa in the 0.04 mm skin, half the yield stress of
      // polyester film (~100 MPa); hand-stretched or heat-shrunk ornithopter films carry
      // 10-200 N/m (1-5 MPa in 20-50 um film). The physical check is the frame's: the film
      // shrunk onto it must not buckle the wing (core/structure/skin_pretension.hpp; the magpie's
      // frame holds up to 41 N/m), checked when the wing is built.
      number("wing.skin.pretension_N_per_m", "N/m", 1.0, R::closed(0.0, 2000.0), "0",
             "isotropic tension of the skin film as laid; shrunk onto the frame it keeps what the frame holds (refused where it buckles the wing)"),
      table("wing.members", "none", "[[wing.members]]: straight solid circular rods"),
      text("wing.members[].name", "required", "member name (unique)"),
      text("wing.members[].material", "required", "material of the rod", "a [materials.NAME] name"),
      // 10 um (a single carbon fibre is 7 um) to 10 cm.
      number("wing.members[].diameter_m", "m", 1.0, R::closed(1e-5, 0.1), "required",
             "rod diameter"),
      pair("wing.members[].start_xy_m", "m", 1.0, kPosition, "required",
           "start point [x_W, y_W] in the wing plane", "inside the planform"),
      pair("wing.members[].end_xy_m", "m", 1.0, kPosition, "required",
           "end point [x_W, y_W] in the wing plane", "inside the planform, != start_xy_m"),

      // ---- [wing.fe] ----------------------------------------------------------------------------
      // 1 mm: 48 000 mesh nodes on the magpie's 0.022 m^2 wing already (the paper used 1857
      // elements); finer meshes run for minutes and GBs (measured: 0.6 mm, 50 s, 950 MB).
      number("wing.fe.element_size_m", "m", 1.0, R::closed(0.001, kMaxLength_m),
             "min(0.005, semispan)", "target finite-element edge length h", {},
             "<= wing.semispan_m; a flexible wing's mesh at most 50000 nodes"),
      integer("wing.fe.modes", R::closed(1, 200), "12", "fixed-interface modes kept (at most)"),
      // 0 = no cut-off; 1e5 Hz: far above every harmonic of the 200 Hz flapping limit.
      number("wing.fe.cutoff_hz", "Hz", 1.0, R::closed(0.0, 1e5), "0",
             "keep only modes below this frequency; 0 = no cut-off"),
      number("wing.fe.damping_ratio", "-", 1.0, R::closedOpen(0.0, 1.0), "0.015",
             "modal damping ratio zeta of every mode (below critical); the nonlinear wing's "
             "membrane strains get Kelvin-Voigt damping with the first mode's ratio"),
      choice("wing.fe.p3_cross_axis", "normal | span", "\"normal\"",
             "cross axis n_u of the universal joint at P3: z_W or y_W"),
      choice("wing.fe.p3_joint", "universal | spherical | revolute_x | clamped", "\"universal\"",
             "the joint at P3 (rotations it holds)"),
      choice("wing.fe.root_edge", "free | pinned", "\"free\"",
             "root chord held in translation (pinned) or free"),
      choice("wing.fe.inertial_stiffness", "both | softening_only | none", "\"both\"",
             "spin softening and geometric stiffening of the inertial loads"),
      boolean("wing.fe.nonlinear", "false",
              "geometrically nonlinear wing: skin membrane stretching and member stretch"),
      // 1000 Pa: 20 times the rigid magpie's lift per area; at most 8 (each a full nonlinear
      // static solve at the build, 10-30 s on the magpie's 5 mm mesh).
      numbers("wing.fe.static_shapes_pa", "Pa", 1.0, R::openClosed(0.0, 1000.0), "[]",
              "uniform lift pressures whose full nonlinear static shapes join the nonlinear "
              "wing's modes (Rayleigh-Ritz; docs/theory.md 4.7); [] = the modes alone",
              "at most 8; needs wing.fe.nonlinear = true"),

      // ---- [materials.NAME] ---------------------------------------------------------------------
      table("materials", "required", "[materials.NAME]: isotropic materials, any names"),
      // 1e-4 GPa = 100 kPa: softer than any membrane (silicone rubber ~1 MPa); 1200: diamond.
      number("materials.*.youngs_modulus_gpa", "GPa", kGpa, R::closed(1e-4, 1200.0), "required",
             "Young's modulus E"),
      number("materials.*.poisson_ratio", "-", 1.0, R::open(-1.0, 0.5), "required",
             "Poisson's ratio nu (thermodynamic limits)"),
      // 1 kg/m^3: aerogels; 25 000: above osmium (22 590), the densest element.
      number("materials.*.density_kgpm3", "kg/m^3", 1.0, R::closed(1.0, 25000.0), "required",
             "density"),

      // ---- [aero] -------------------------------------------------------------------------------
      choice("aero.model", "mst-td | delaurier1993", "\"mst-td\"", "strip aerodynamics model"),
      choice("aero.circulation_lag", "scherer | jones", "\"scherer\"",
             "circulation lag (docs/theory.md 5.7 options A, B)"),
      // 0.1: a disc-like planform; 100: beyond any wing (sailplanes reach 50).
      number("aero.aspect_ratio", "-", 1.0, R::closed(0.1, 100.0), "from the planform (b^2/S)",
             "aspect ratio of the wing pair for the aerodynamic constants"),
      // 0.2 rad (11.45 deg): a strongly cambered section.
      number("aero.zero_lift_angle_deg", "deg", kDeg, R::closed(-11.45, 11.45), "0",
             "zero-lift angle alpha0, positive for positive camber"),
      number("aero.moment_coefficient_ac", "-", 1.0, R::closed(-0.5, 0.5), "0",
             "section moment coefficient about the aerodynamic centre, nose-up +"),
      number("aero.suction_efficiency", "-", 1.0, R::closed(0.0, 1.0), "0.98",
             "leading-edge suction efficiency eta_s"),
      // 3: twice a flat plate's 1.98 (Hoerner).
      number("aero.crossflow_drag_coefficient", "-", 1.0, R::closed(0.0, 3.0), "1.98",
             "crossflow drag coefficient of the separated section"),
      boolean("aero.skin_friction", "true", "turbulent flat-plate skin friction (M11) on"),
      number("aero.stall_angle_max_deg", "deg", kDeg, R::open(0.0, 90.0), "13",
             "positive stall angle"),
      number("aero.stall_angle_min_deg", "deg", kDeg, R::open(-90.0, 0.0), "-13",
             "negative stall angle"),
      number("aero.stall_width_deg", "deg", kDeg, R::closed(0.0, 11.45), "2",
             "width of the smooth separation function; 0 = hard switch"),
      number("aero.separation_lag_tf0", "-", 1.0, R::closed(0.0, 50.0), "6",
             "separation lag T_f0 in semichord times; 0 = none"),
      // 0.01 m/s to 10 m/s: a floor of the reference speed, below any flight speed that matters.
      number("aero.min_speed_mps", "m/s", 1.0, R::closed(0.01, 10.0), "0.5",
             "floor of the aerodynamic reference speed"),

      // ---- [kinematics] -------------------------------------------------------------------------
      number("kinematics.amplitude_deg", "deg", kDeg, R::open(0.0, 90.0), "required",
             "flapping amplitude A of delta_M = A sin(2 pi f t)"),
      number("kinematics.hinge_x_m", "m", 1.0, kPosition, "0",
             "hinge P2 ahead of the CG P1 (body x)"),
      number("kinematics.hinge_z_m", "m", 1.0, kPosition, "0",
             "hinge P2 below the CG P1 (body z, down +)"),

      // ---- [body] (free flight, trim) -----------------------------------------------------------
      // 10 mg (RoboBee 80 mg) to 1000 kg (the Snowbird with its pilot is ~ 130 kg).
      number("body.mass_kg", "kg", 1.0, R::closed(1e-5, 1000.0), "required with [body]",
             "total vehicle mass, wings and tail included"),
      // 1e-12: 10 mg at a 0.3 mm radius of gyration; 1e4: 1000 kg at 3 m.
      number("body.pitch_inertia_kgm2", "kg m^2", 1.0, R::closed(1e-12, 1e4),
             "required with [body]", "pitch inertia of the whole vehicle about P1"),
      // 10 m^2: C_D A of a car-sized blunt body.
      number("body.drag_area_m2", "m^2", 1.0, R::closed(0.0, 10.0), "0",
             "fuselage parasite drag area C_D S; 0 = none"),

      // ---- [tail] -------------------------------------------------------------------------------
      // 1 mm^2 to 100 m^2 (the Snowbird's whole wing is ~ 30 m^2).
      number("tail.area_m2", "m^2", 1.0, R::closed(1e-6, 100.0), "required with [tail]",
             "tail area S_T"),
      number("tail.aspect_ratio", "-", 1.0, R::closed(0.1, 100.0), "required with [tail]",
             "tail aspect ratio AR_T"),
      number("tail.zero_lift_drag_coefficient", "-", 1.0, R::closed(0.0, 1.0),
             "required with [tail]", "tail zero-lift drag coefficient C_D0,T"),
      number("tail.oswald_efficiency", "-", 1.0, R::openClosed(0.0, 1.0), "0.9",
             "tail Oswald efficiency e"),
      number("tail.arm_m", "m", 1.0, R::openClosed(0.0, kMaxLength_m), "required with [tail]",
             "CG P1 to the tail's aerodynamic centre P4, along -x_B"),
      number("tail.height_m", "m", 1.0, kPosition, "0", "P4 above the body x axis"),
      number("tail.mass_kg", "kg", 1.0, R::closedOpen(0.0, 1000.0), "0",
             "tail point mass at P4 (part of body.mass_kg)", {}, "< body.mass_kg"),
      number("tail.downwash_factor", "-", 1.0, R::closedOpen(0.0, 1.0), "0",
             "d eps_w / d theta_mean; 0 = no wing downwash"),

      // ---- [operating_point] --------------------------------------------------------------------
      number("operating_point.speed_mps", "m/s", 1.0, kSpeed, "required",
             "flight or tunnel speed U of the default run point"),
      number("operating_point.freq_hz", "Hz", 1.0, kFreq, "required", "flapping frequency f"),
      number("operating_point.theta_deg", "deg", kDeg, kHalfTurnDeg, "required",
             "mean pitch attitude of the body"),
      number("operating_point.tail_angle_deg", "deg", kDeg, kHalfTurnDeg, "0",
             "tail elevation angle delta_T (paper sign)"),

      // ---- Study files: top level ---------------------------------------------------------------
      choice("kind",
             "simulate | modes | aeromap | trim | optimize | sweep | calibrate | sensitivity | "
             "continuation",
             "required", "what the study runs"),
      text("study.name", "the file stem",
           "a study's top-level `name`: the run name ([A-Za-z0-9_.-], output folder)"),
      text("vehicle", "required", "vehicle file relative to the study, or an inline [vehicle]"),
      text("vehicle_source", "none", "with an inline [vehicle]: where it came from"),
      table("override", "none", "vehicle keys replacing the vehicle file's (same names, units)"),
      boolean("output.figures", "true",
              "draw the figures (PNG and SVG, gnuplot); false writes only their scripts "
              "(`ornithopter plot DIR` draws them later; --no-figures does the same)"),

      // ---- [simulate] ---------------------------------------------------------------------------
      choice("simulate.mode", "tethered | free", "\"tethered\"",
             "body held at (theta, U), or free flight", "simulate --mode"),
      number("simulate.speed_mps", "m/s", 1.0, kSpeed, kFromPoint, "speed U", "simulate --speed"),
      number("simulate.freq_hz", "Hz", 1.0, kFreq, kFromPoint, "flapping frequency f",
             "simulate --freq"),
      number("simulate.theta_deg", "deg", kDeg, kHalfTurnDeg, kFromPoint, "mean pitch attitude",
             "simulate --theta"),
      number("simulate.tail_angle_deg", "deg", kDeg, kHalfTurnDeg, kFromPoint, "tail angle",
             "simulate --tail"),
      integer("simulate.cycles", kCycles, "10", "flapping cycles to simulate", "simulate --cycles"),
      number("simulate.rel_tol", "-", 1.0, kRelTol, "1e-4",
             "integrator relative tolerance (free flight of a nonlinear wing: 1e-5 unless given; "
             "its verdicts are not converged at 1e-4)"),
      number("simulate.abs_tol", "rad", 1.0, kAbsTol, "1e-5",
             "absolute tolerance of the circulation-lag states"),
      number("simulate.separation_abs_tol", "-", 1.0, kAbsTol, "1e-5",
             "absolute tolerance of the separation fractions"),
      number("simulate.steady_tol", "-", 1.0, kSteadyTol, "1e-3",
             "periodic steady state: relative cycle-to-cycle change"),
      // 8 samples resolve the fourth harmonic; 100 000 per cycle fill memory, not the spectra.
      integer("simulate.samples_per_cycle", R::closed(8, 100000), "100",
              "time-history samples per cycle"),
      choice("simulate.sampled_loads", "evaluated | interpolated", "\"interpolated\"",
             "flexible wing: a history sample's loads evaluated at the sampled state, or "
             "interpolated from the integrator's dense output (tethered: about a third of the "
             "cost; free flight of the nonlinear wing: the accelerations; as accurate as the "
             "tolerance on the linear wing, far more so on the nonlinear one; docs/theory.md "
             "9.4)"),
      integer("simulate.history_every", R::closed(1, 1000000), "1",
              "histories.csv keeps every n-th sample (output only)"),
      boolean("simulate.wing_only", "false",
              "tethered: the main wing alone (no tail, no body drag)"),
      boolean("simulate.at_trim", "false", "fly at the vehicle's trim at freq_hz"),
      // Free flight ([simulate.free]; [sensitivity.free] has the same keys and ranges).
      number("simulate.free.bound_speed_mps", "m/s", 1.0, kSpeed, "2",
             "R_U: bound on the speed deviation (paper Eq. 5)"),
      number("simulate.free.bound_W_mps", "m/s", 1.0, kSpeed, "2",
             "R_W: bound on the vertical-speed deviation"),
      number("simulate.free.bound_theta_deg", "deg", kDeg, R::openClosed(0.0, 90.0), "40",
             "R_theta: bound on the pitch deviation"),
      // 1e6 deg/s: ten times the largest automatic bound, 2 pi 200 Hz 90 deg = 1.1e5 deg/s.
      number("simulate.free.bound_Q_degps", "deg/s", kDeg, R::closed(0.0, 1e6), "0",
             "R_Q: bound on the pitch rate; 0 = 2 pi f R_theta"),
      // 10 km: the ceiling of any flapping flight.
      number("simulate.free.bound_h_m", "m", 1.0, R::openClosed(0.0, 1e4), "1",
             "R_h: bound on the altitude change"),
      number("simulate.free.transient_fraction", "-", 1.0, R::closed(0.0, 0.9), "0.2",
             "share of the cycles before the verdict"),
      // 1e6: the free-flight trim's settling runs use 1e6 to switch the test off
      // (trim/free_flight_trim.cpp); any ratio above ~10 is long past divergence.
      number("simulate.free.divergence_ratio", "-", 1.0, R::openClosed(1.0, 1e6), "5",
             "stop as diverged above this scaled norm"),
      number("simulate.free.initial_altitude_m", "m", 1.0, R::openClosed(0.0, 1e4), "10",
             "start altitude (ground contact at h = 0)"),

      // ---- [aeromap] ----------------------------------------------------------------------------
      grid("aeromap.speed_mps", "m/s", 1.0, kSpeed, "required", "speed axis", "aeromap --speed"),
      grid("aeromap.freq_hz", "Hz", 1.0, kFreq, "required", "frequency axis", "aeromap --freq"),
      grid("aeromap.theta_deg", "deg", kDeg, kHalfTurnDeg, "required", "pitch axis",
           "aeromap --theta"),
      grid("aeromap.tail_angle_deg", "deg", kDeg, kHalfTurnDeg, kFromPoint, "tail-angle axis",
           "aeromap --tail"),
      boolean("aeromap.wing_only", "false", "the main wing alone (paper Fig. 5)"),
      integer("aeromap.cycles", kCycles, "40", "maximum cycles per point (each stops when steady)",
              "aeromap --cycles"),
      number("aeromap.rel_tol", "-", 1.0, kRelTol, "1e-4", "integrator relative tolerance"),
      number("aeromap.abs_tol", "rad", 1.0, kAbsTol, "1e-5", "absolute tolerance, lag states"),
      number("aeromap.separation_abs_tol", "-", 1.0, kAbsTol, "1e-5",
             "absolute tolerance, separation fractions"),
      number("aeromap.steady_tol", "-", 1.0, kSteadyTol, "1e-3", "periodic steady state tolerance"),

      // ---- [trim] (also [optimize.trim], without freq_hz) ---------------------------------------
      number("trim.freq_hz", "Hz", 1.0, kFreq, kFromPoint,
             "flapping frequency: fixed, or the initial guess when an unknown",
             "trim --freq, stability --freq"),
      choice("trim.method", "two_stage | periodic", "\"two_stage\"",
             "Eq. (4) then level settled free flight, or the periodic orbit of free flight",
             "trim --method"),
      list("trim.unknowns", "theta_mean_deg, speed_mps, tail_angle_deg",
           "1-3 of theta_mean_deg, speed_mps, tail_angle_deg, freq_hz", "trim --unknowns"),
      number("trim.initial.theta_mean_deg", "deg", kDeg, kHalfTurnDeg, kFromPoint,
             "initial guess (or fixed value) of theta_mean", "trim --theta"),
      number("trim.initial.speed_mps", "m/s", 1.0, kSpeed, kFromPoint,
             "initial guess (or fixed value) of U", "trim --speed"),
      number("trim.initial.tail_angle_deg", "deg", kDeg, kHalfTurnDeg, kFromPoint,
             "initial guess (or fixed value) of delta_T", "trim --tail"),
      pair("trim.bounds.theta_mean_deg", "deg", kDeg, kHalfTurnDeg, "[-10, 40]",
           "[lower, upper] of theta_mean", "lower < upper, 4 steps wide, around the initial value"),
      pair("trim.bounds.speed_mps", "m/s", 1.0, kSpeed, "[2, 30]", "[lower, upper] of U",
           "lower < upper, 4 steps wide, around the initial value"),
      pair("trim.bounds.tail_angle_deg", "deg", kDeg, kHalfTurnDeg, "[-30, 45]",
           "[lower, upper] of delta_T", "lower < upper, 4 steps wide, around the initial value"),
      pair("trim.bounds.freq_hz", "Hz", 1.0, kFreq, "[1, 40]", "[lower, upper] of f",
           "lower < upper, 4 steps wide, around the initial value"),
      integer("trim.max_iterations", R::closed(1, 1000), "50", "Ceres iterations"),
      number("trim.residual_tol", "-", 1.0, R::closed(1e-12, 0.1), "1e-4",
             "equilibrium tolerance as a fraction of the weight"),
      number("trim.function_tol", "-", 1.0, R::closedOpen(1e-20, 1.0), "1e-12",
             "Ceres function tolerance"),
      number("trim.rel_tol", "-", 1.0, kRelTol, "1e-6", "integrator relative tolerance"),
      number("trim.steady_tol", "-", 1.0, kSteadyTol, "1e-5", "periodic steady state tolerance"),
      integer("trim.max_cycles", kCycles, "40", "cycle limit of a residual run"),
      integer("trim.derivative_cycles", R::closed(1, 1000), "3",
              "cycles of each finite-difference run"),
      boolean("trim.refine_in_free_flight", "true", "refine the trim to level settled free flight"),
      integer("trim.refine_cycles", R::closed(6, 10000), "120",
              "cycles of each settled free flight"),
      // [trim.periodic] (method = "periodic", trim/periodic_trim_options.hpp).
      choice("trim.periodic.control", "tail_angle_deg | freq_hz | cg_shift_m",
             "\"tail_angle_deg\"", "the control the periodic trim solves for"),
      // 1e-14: round-off of the scaled states; 1e-4: looser is not a periodic orbit.
      number("trim.periodic.residual_tol", "-", 1.0, R::closed(1e-14, 1e-4), "1e-8",
             "converged when every state returns within this many of its scales"),
      // kRelTol's round-off bound; at most 1e-3, looser grids move the orbit visibly.
      number("trim.periodic.rel_tol", "-", 1.0, R::closed(1e-12, 1e-3), "1e-5",
             "step control of the period map's integration grid"),
      integer("trim.periodic.max_iterations", R::closed(1, 1000), "40", "Newton iterations"),
      integer("trim.periodic.history_samples", R::closed(8, 100000), "200",
              "samples of the orbit's histories (one period)"),
      boolean("trim.periodic.floquet", "true", "the monodromy at the orbit and its multipliers"),
      integer("trim.periodic.multipliers", R::closed(0, 100), "8",
              "leading multipliers by Arnoldi; 0 = all, from the full monodromy"),
      boolean("trim.periodic.multiplier_check", "false",
              "check each multiplier against a monodromy on a 10 times finer grid (resolved or "
              "not); `stability` turns it on"),

      // ---- [optimize] ---------------------------------------------------------------------------
      choice("optimize.algorithm", "cobyla | bobyqa | isres", "\"cobyla\"", "NLopt algorithm"),
      choice("optimize.objective", "power | pitch_amplitude | weighted", "\"power\"",
             "what is minimised"),
      integer("optimize.max_evaluations", R::closed(2, 1000000), "100", "evaluations per start"),
      integer("optimize.starts", R::closed(1, 1000), "1", "starts (multi-start)"),
      integer("optimize.seed", R::closed(0, 1000000000), "1", "seed of the start points"),
      number("optimize.freq_hz", "Hz", 1.0, kFreq, kFromPoint, "flapping frequency of the trim"),
      number("optimize.initial_step", "-", 1.0, R::openClosed(0.0, 1.0), "0.1",
             "first step as a fraction of each variable's range"),
      number("optimize.xtol", "-", 1.0, R::closedOpen(0.0, 1.0), "1e-4",
             "stop at this step (fraction of each range); 0 = off"),
      number("optimize.ftol_rel", "-", 1.0, R::closedOpen(0.0, 1.0), "0",
             "stop at this relative objective change; 0 = off"),
      number("optimize.constraint_tol", "-", 1.0, R::closedOpen(0.0, 1.0), "1e-6",
             "constraint tolerance"),
      boolean("optimize.warm_start", "true", "start each trim from the last converged one"),
      integer("optimize.polish_evaluations", R::closed(0, 999999), "0",
              "isres: local polish evaluations; 0 = max_evaluations / 4", {},
              "< optimize.max_evaluations"),
      integer("optimize.population", R::closed(0, 100000), "0",
              "isres: population; 0 = automatic", {}, "not 1"),
      table("optimize.variables", "required", "[[optimize.variables]]: the design variables"),
      text("optimize.variables[].name", "required", "variable name; also its field by default"),
      list("optimize.variables[].fields", "[name]",
           "design fields: tail.area_m2, tail.aspect_ratio, tail.arm_m, tail.height_m, "
           "kinematics.hinge_x_m, kinematics.hinge_z_m, wing.skin.thickness_m, "
           "wing.members.NAME.diameter_m | start_x_m | start_y_m | end_x_m | end_y_m"),
      number("optimize.variables[].lower", "field", 1.0, R::any(), "required",
             "lower bound, inside the range of every field", {}, "the range of each field"),
      number("optimize.variables[].upper", "field", 1.0, R::any(), "required",
             "upper bound, inside the range of every field", {},
             "the range of each field, > lower"),
      number("optimize.variables[].initial", "field", 1.0, R::any(), "the vehicle's value",
             "initial value", {}, "in [lower, upper]"),
      boolean("optimize.constraints.bounded", "true", "free flight bounded (paper Eq. 5)"),
      number("optimize.constraints.pitch_amplitude_max_deg", "deg", kDeg, R::closedOpen(0.0, 90.0),
             "0", "limit of the pitch amplitude; 0 = off"),
      number("optimize.constraints.tip_deflection_max_m", "m", 1.0, R::closed(0.0, kMaxLength_m),
             "0", "limit of the tip deflection (flexible wing); 0 = off"),
      number("optimize.constraints.structural_mass_max_kg", "kg", 1.0, R::closed(0.0, 1000.0), "0",
             "limit of the mass of both wings; 0 = off"),
      // Moduli above 10 mean an orbit that grows tenfold per flapping period: no design limit.
      number("optimize.constraints.floquet_max_modulus", "-", 1.0, R::closed(0.0, 10.0), "0",
             "limit of the largest Floquet multiplier modulus of the trimmed orbit (trim method "
             "\"periodic\"; < 1 = stable); 0 = off"),
      // 1e6 per unit: weights beyond it only rescale the objective.
      number("optimize.weights.power_per_W", "1/W", 1.0, R::closed(0.0, 1e6), "1",
             "weight of the power (objective \"weighted\")"),
      number("optimize.weights.pitch_amplitude_per_deg", "1/deg", 1.0, R::closed(0.0, 1e6), "0",
             "weight of the pitch amplitude (objective \"weighted\")"),
      table("optimize.trim", "the [trim] defaults",
            "the trim of every design: [trim] keys but freq_hz"),

      // ---- [calibrate] --------------------------------------------------------------------------
      number("calibrate.theta_mean_deg", "deg", kDeg, kHalfTurnDeg, kFromPoint,
             "target mean pitch attitude"),
      number("calibrate.speed_mps", "m/s", 1.0, kSpeed, kFromPoint, "target speed"),
      number("calibrate.tail_angle_deg", "deg", kDeg, kHalfTurnDeg, kFromPoint,
             "target tail angle"),
      number("calibrate.freq_hz", "Hz", 1.0, kFreq, kFromPoint, "flapping frequency"),
      integer("calibrate.settled_cycles", R::closed(6, 10000), "120",
              "cycles of each settled free flight"),
      integer("calibrate.window_cycles", R::closed(1, 9999), "settled_cycles / 3",
              "averaged last cycles", {}, "< calibrate.settled_cycles"),
      // 10 deg or 10 m/s: a calibration looser than that says nothing.
      number("calibrate.tolerance", "deg, 0.1 m/s", 1.0, R::openClosed(0.0, 10.0), "0.01",
             "converged when the theta and climb angle errors (deg) and the U error (in 0.1 m/s: "
             "0.01 holds U to 1 mm/s) are within it"),
      integer("calibrate.max_iterations", R::closed(1, 200), "20", "solver iterations"),
      boolean("calibrate.tethered_first", "true",
              "first fit Eq. (4)'s tethered means at the target, then the settled free flight "
              "from there"),
      table("calibrate.variables", "required", "[[calibrate.variables]]: 1 to 4 vehicle values"),
      text("calibrate.variables[].key", "required",
           "wing.member_diameter_scale, body.drag_area_m2, kinematics.hinge_x_m, "
           "kinematics.hinge_z_m, tail.arm_m, body.pitch_inertia_kgm2, wing.p3_aft_of_le_m, "
           "aero.suction_efficiency or wing.skin.pretension_N_per_m"),
      text("calibrate.variables[].source", "none",
           "where the range [lower, upper] comes from; reported beside the fitted value"),
      number("calibrate.variables[].lower", "key", 1.0, R::any(), "required",
             "lower bound, inside the key's range", {}, "the range of the key"),
      number("calibrate.variables[].upper", "key", 1.0, R::any(), "required",
             "upper bound, inside the key's range", {}, "the range of the key, > lower"),
      number("calibrate.variables[].initial", "key", 1.0, R::any(), "the vehicle's value",
             "initial value", {}, "in [lower, upper]"),

      // ---- [sweep] ------------------------------------------------------------------------------
      choice("sweep.run", "trim | simulate", "required", "the kind run at every point"),
      table("sweep.axes", "required", "1-16 axes { key, values }; the first is outermost"),
      text("sweep.axes[].key", "required",
           "a vehicle key as in [override], or a key of the run's section (\"trim.freq_hz\")"),
      grid("sweep.axes[].values", "key", 1.0, R::any(), "required",
           "\"A:B:N\", an array or a number, in the key's units", {}),

      // ---- [sensitivity] ------------------------------------------------------------------------
      table("sensitivity.parameters", "required", "1-16 parameters { key, low, high }"),
      text("sensitivity.parameters[].key", "required", "a vehicle key as in [override]"),
      number("sensitivity.parameters[].low", "key", 1.0, R::any(), "required",
             "low end of the plausible range, inside the key's range", {},
             "the range of the key"),
      number("sensitivity.parameters[].high", "key", 1.0, R::any(), "required",
             "high end, inside the key's range", {}, "the range of the key, > low"),
      integer("sensitivity.free_flight_cycles", kCycles, "60",
              "cycles of the free flight at every trim"),
      table("sensitivity.free", "the [simulate.free] defaults",
            "the bounded-norm settings: the keys of [simulate.free]"),

      // ---- [continuation] (kind continuation, trim/trim_continuation.hpp) -------------------------
      choice("continuation.parameter", "freq_hz | tail_angle_deg | cg_shift_m", "required",
             "the parameter the trim branch is followed over (not the [trim.periodic] control)"),
      number("continuation.to", "key", 1.0, R::any(), "required",
             "the end of the branch, in the parameter's units", {},
             "the range of trim.freq_hz, of trim.initial.tail_angle_deg, or [-0.1, 0.1] m"),
      number("continuation.step", "key", 1.0, R::any(), "0.2 Hz, 0.5 deg or 0.002 m",
             "first step in the parameter; the arclength steps adapt from there", {},
             "> 0 and at most the width of the parameter's range"),
      integer("continuation.max_points", R::closed(1, 10000), "30",
              "regular points after the start"),
      boolean("continuation.locate_events", "true",
              "folds and stability changes located by bisection"),

      // ---- Command line only --------------------------------------------------------------------
      // 1024 threads: far beyond any machine this runs on; each owns a workspace.
      integer("jobs", R::closed(1, 1024), "1", "worker threads", "run/aeromap/optimize/trim -j"),
  };
}

constexpr std::string_view kVehicleSections[] = {"air",        "wing", "materials",
                                                 "aero",       "kinematics", "body",
                                                 "tail",       "operating_point", "name",
                                                 "description"};
constexpr std::string_view kStudySections[] = {"simulate",  "aeromap", "trim",
                                               "optimize",  "calibrate", "sweep",
                                               "sensitivity", "continuation"};

std::string_view firstPart(std::string_view key) { return key.substr(0, key.find('.')); }

/// "wing.members[3].x" -> "wing.members[].x"; "materials.LE1.x" -> "materials.*.x";
/// "vehicle." / "override." dropped; "[sensitivity.free]" and "[optimize.trim]" share the keys of
/// [simulate.free] and [trim].
std::string normalise(std::string_view key) {
  std::string k(key);
  for (std::string_view prefix : {"override.", "vehicle."})
    if (k.compare(0, prefix.size(), prefix) == 0) k.erase(0, prefix.size());
  const std::pair<std::string_view, std::string_view> aliases[] = {
      {"sensitivity.free.", "simulate.free."}, {"optimize.trim.", "trim."}};
  for (const auto& [from, to] : aliases)
    if (k.compare(0, from.size(), from) == 0) k = std::string(to) + k.substr(from.size());
  // Array indices.
  for (std::size_t open = k.find('['); open != std::string::npos; open = k.find('[', open + 1)) {
    const std::size_t close = k.find(']', open);
    if (close == std::string::npos) break;
    k.erase(open + 1, close - open - 1);
  }
  // Material names.
  const std::string materials = "materials.";
  if (k.compare(0, materials.size(), materials) == 0) {
    const std::size_t dot = k.find('.', materials.size());
    if (dot != std::string::npos) k = materials + "*" + k.substr(dot);
  }
  return k;
}

}  // namespace

const char* toString(FieldType type) {
  switch (type) {
    case FieldType::kNumber: return "number";
    case FieldType::kInteger: return "integer";
    case FieldType::kBoolean: return "boolean";
    case FieldType::kString: return "string";
    case FieldType::kChoice: return "choice";
    case FieldType::kPair: return "pair";
    case FieldType::kNumberList: return "number list";
    case FieldType::kGrid: return "grid";
    case FieldType::kStringList: return "string list";
    case FieldType::kTable: return "table";
  }
  return "number";
}

std::string_view FieldSpec::group() const {
  const std::string_view first = firstPart(key);
  for (std::string_view s : kVehicleSections)
    if (first == s) return "vehicle";
  for (std::string_view s : kStudySections)
    if (first == s) return s;
  if (first == "jobs") return "cli";
  return "study";
}

std::string FieldSpec::expected() const {
  auto quotedChoices = [this] {
    std::string out;
    std::string_view rest = choices;
    std::vector<std::string> names;
    while (!rest.empty()) {
      const std::size_t bar = rest.find(" | ");
      names.emplace_back(rest.substr(0, bar));
      if (bar == std::string_view::npos) break;
      rest.remove_prefix(bar + 3);
    }
    for (std::size_t i = 0; i < names.size(); ++i) {
      if (i) out += (i + 1 == names.size()) ? " or " : ", ";
      out += "\"" + names[i] + "\"";
    }
    return out;
  };
  switch (type) {
    case FieldType::kNumber: return range.describe("a number");
    case FieldType::kInteger: return range.describe("an integer");
    case FieldType::kBoolean: return "a boolean (true or false)";
    case FieldType::kString: return "a non-empty string";
    case FieldType::kChoice: return "one of " + quotedChoices();
    case FieldType::kPair: return "an array of 2 numbers (each " + range.describe() + ")";
    case FieldType::kNumberList: return "an array of numbers (each " + range.describe() + ")";
    case FieldType::kGrid:
      return "a grid \"A:B:N\", an array of numbers or a number (each " + range.describe() + ")";
    case FieldType::kStringList: return "an array of strings";
    case FieldType::kTable: return "a table";
  }
  return std::string();
}

const std::vector<FieldSpec>& fieldTable() {
  static const std::vector<FieldSpec> table = makeTable();
  return table;
}

const FieldSpec* findField(std::string_view key) {
  const std::string k = normalise(key);
  for (const FieldSpec& f : fieldTable())
    if (f.key == k) return &f;
  // The study's own name key is listed as "study.name" (a vehicle has "name" too).
  return nullptr;
}

const FieldSpec& field(std::string_view key) {
  if (const FieldSpec* f = findField(key)) return *f;
  throw std::logic_error("field table: no entry for key '" + std::string(key) + "'");
}

const std::vector<std::string_view>& fieldGroups() {
  static const std::vector<std::string_view> groups = {
      "vehicle", "study", "simulate", "aeromap", "trim", "optimize", "calibrate", "sweep",
      "sensitivity", "continuation", "cli"};
  return groups;
}

}  // namespace orni
