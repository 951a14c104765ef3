// Design spaces and the design problem (optimize/design_space.hpp, design_problem.hpp): field
// names and groups resolve against a vehicle, a design is applied to a copy, and an evaluation of
// efw_magpie maps its trim and free flight to the objective and constraints: a converged trim is
// trimmed (g = -1) with the hinge power as the objective, a trim without equilibrium is a finite
// violation (how far from trim), a design that is not a valid vehicle is a failed evaluation
// (never an exception), and the warm start follows the last converged trim of the start. With the
// periodic trim: the Floquet constraint and values are the orbit's (docs/theory.md 10.3).
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "tests/support/magpie_vehicle.hpp"
#include "core/model/frames.hpp"
#include "core/dynamics/flight_core.hpp"
#include "core/dynamics/tethered_simulation.hpp"
#include "optimize/design_problem.hpp"
#include "trim/periodic_trim.hpp"
#include "studies/runner/config/vehicle_file.hpp"

namespace orni::opt {
namespace {

VehicleModel magpie() {
  return studies::loadVehicleFile(std::string(ORNI_SOURCE_DIR) +
                                  "/studies/vehicles/efw_magpie.toml").model;
}

// The design-problem machinery on a frozen rigid-wing fixture (the magpie of commit 70ab58e, before
// the honest vehicle, Table 1's wing; tests/data/sensitivity/magpie_rigid_fixture.toml): a contract
// test that must not move with the paper vehicle's physics. At 12 Hz its Eq. (4) trim exists (theta
// 5.44 deg, U 12.25 m/s, tail 10.2 deg; no free-flight refinement here), at 6 Hz it does not.
VehicleModel rigidMagpie() {
  VehicleModel v = studies::loadVehicleFile(std::string(ORNI_SOURCE_DIR) +
                                            "/tests/data/sensitivity/magpie_rigid_fixture.toml")
                       .model;
  EXPECT_EQ(v.wing.structure, StructureLevel::kRigid);
  return v;
}

std::vector<DesignField> resolve(const std::string& name, const VehicleModel& v) {
  std::vector<DesignField> f;
  std::string why;
  EXPECT_TRUE(resolveDesignField(name, v, &f, &why)) << name << ": " << why;
  return f;
}

TEST(OptimizeDesignSpace, ResolvesFieldsAndGroups) {
  const VehicleModel v = magpie();
  EXPECT_EQ(resolve("tail.area_m2", v).front().ref.number->key, "tail.area_m2");
  EXPECT_EQ(resolve("kinematics.hinge_x_m", v).front().ref.number->key, "kinematics.hinge_x_m");
  EXPECT_EQ(fieldValue(v, resolve("kinematics.hinge_x_m", v).front()), v.flapping.hinge_x_B_m);
  const std::vector<DesignField> stif = resolve("wing.members.STIF*.diameter_m", v);
  ASSERT_EQ(stif.size(), 4u);
  EXPECT_EQ(stif[0].name, "wing.members.STIF1.diameter_m");
  EXPECT_EQ(stif[3].name, "wing.members.STIF4.diameter_m");
  const std::vector<DesignField> end = resolve("wing.members.DIAG1.end_y_m", v);
  ASSERT_EQ(end.size(), 1u);
  EXPECT_EQ(fieldValue(v, end[0]), 0.0945);
  EXPECT_EQ(end[0].ref.index, 2u);  // DIAG1, the third member
  EXPECT_EQ(end[0].ref.number->component, 1);
  EXPECT_EQ(stif[0].spec().key, "wing.members[].diameter_m");
  EXPECT_EQ(end[0].spec().key, "wing.members[].end_xy_m");

  std::vector<DesignField> f;
  std::string why;
  EXPECT_FALSE(resolveDesignField("wing.members.STIF9.diameter_m", v, &f, &why));
  EXPECT_NE(why.find("STIF9"), std::string::npos);
  EXPECT_NE(why.find("LE1"), std::string::npos);  // lists the members
  EXPECT_FALSE(resolveDesignField("wing.members.STIF1.radius_m", v, &f, &why));
  EXPECT_NE(why.find("diameter_m"), std::string::npos);
  EXPECT_FALSE(resolveDesignField("tail.span_m", v, &f, &why));
  EXPECT_NE(why.find("tail.area_m2"), std::string::npos);
  EXPECT_TRUE(f.empty());
}

TEST(OptimizeDesignSpace, ApplyDesignSetsEveryFieldOfAGroupOnACopy) {
  const VehicleModel v = magpie();
  DesignSpace s;
  DesignVariable stif;
  stif.name = "stif";
  stif.fields = resolve("wing.members.STIF*.diameter_m", v);
  DesignVariable arm;
  arm.name = "arm";
  arm.fields = resolve("tail.arm_m", v);
  s.variables = {stif, arm};
  const VehicleModel d = applyDesign(v, s, {6e-4, 0.15});
  for (const WingMember& m : d.wing.members)
    EXPECT_EQ(m.diameter_m, m.name.rfind("STIF", 0) == 0 ? 6e-4 : m.diameter_m);
  EXPECT_EQ(d.wing.members[0].diameter_m, v.wing.members[0].diameter_m);  // LE1 untouched
  EXPECT_EQ(d.wing.members[4].diameter_m, 6e-4);
  EXPECT_EQ(d.tail.arm_m, 0.15);
  EXPECT_EQ(v.tail.arm_m, 0.12);  // the base is not changed
  EXPECT_THROW(applyDesign(v, s, {1.0}), std::invalid_argument);
}

/// Tail area and arm of the rigid magpie, trimmed (Eq. 4 only) at `freq_hz`.
DesignProblem tailProblem(double freq_hz) {
  const VehicleModel v = rigidMagpie();
  DesignSpace s;
  for (const char* name : {"tail.area_m2", "tail.arm_m"}) {
    DesignVariable var;
    var.name = name;
    var.fields = resolve(name, v);
    var.initial = fieldValue(v, var.fields.front());
    var.lower = 0.5 * var.initial;
    var.upper = 2.0 * var.initial;
    s.variables.push_back(var);
  }
  DesignProblemOptions o;
  o.trim = defaultTrimOptions(testing::magpieDesignPoint());
  o.trim.initial.freq_hz = freq_hz;
  o.trim.refine_in_free_flight = false;
  o.trim.initial.theta_rad = 5.4 * kDegToRad;
  o.trim.initial.speed_mps = 12.3;
  o.trim.initial.tail_angle_rad = 10.2 * kDegToRad;
  o.constraints.structural_mass_max_kg = 0.004;
  return DesignProblem(v, s, o);
}

TEST(OptimizeDesignProblem, ConvergedTrimGivesPowerAndTrimmedConstraint) {
  const DesignProblem p = tailProblem(12.0);
  ASSERT_EQ(p.constraintNames(), (std::vector<std::string>{"trimmed", "bounded",
                                                            "structural_mass"}));
  auto ws = p.makeWorkspace();
  const Evaluation e = p.evaluate(p.box().initial, *ws);
  SCOPED_TRACE(e.message);
  ASSERT_EQ(e.status, EvaluationStatus::kOk);
  ASSERT_EQ(e.values.size(), static_cast<std::size_t>(kDesignValueCount));
  EXPECT_EQ(e.values[kTrimConverged], 1.0);
  EXPECT_EQ(e.constraints[0], -1.0);
  EXPECT_EQ(e.objective, e.values[kPowerHinge]);
  EXPECT_GT(e.objective, 5.0);  // about 18 W at 12 Hz, 12.3 m/s
  EXPECT_LT(e.objective, 50.0);
  EXPECT_NEAR(e.values[kTrimTheta] / kDegToRad, 5.44, 0.05);
  EXPECT_NEAR(e.values[kTrimSpeed], 12.25, 0.05);
  EXPECT_TRUE(std::isfinite(e.constraints[1]));  // bounded or not: a finite measure
  const double mass = e.values[kStructuralMass];
  EXPECT_GT(mass, 0.0);
  EXPECT_NEAR(e.constraints[2], mass / 0.004 - 1.0, 1e-15);
  EXPECT_GT(e.values[kPeriodicRuns], 0.0);
}

TEST(OptimizeDesignProblem, TrimWithoutEquilibriumIsAFiniteViolation) {
  const DesignProblem p = tailProblem(6.0);  // the rigid magpie has no equilibrium at 6 Hz
  auto ws = p.makeWorkspace();
  const Evaluation e = p.evaluate(p.box().initial, *ws);
  SCOPED_TRACE(e.message);
  EXPECT_EQ(e.status, EvaluationStatus::kOk);
  EXPECT_EQ(e.values[kTrimConverged], 0.0);
  EXPECT_GT(e.constraints[0], 0.0);
  EXPECT_TRUE(std::isfinite(e.constraints[0]));
  EXPECT_NEAR(e.constraints[0], std::log10(e.values[kTrimResidual] / 1e-4), 1e-12);
  // No free flight: bounded is worse than any flown value (2 divergence_ratio = 10) and follows
  // the trim constraint.
  EXPECT_EQ(e.constraints[1], e.constraints[0] + 10.0);
  EXPECT_TRUE(std::isfinite(e.objective));    // the power at the final iterate
  EXPECT_NE(e.message.find("trim not converged"), std::string::npos);
}

TEST(OptimizeDesignProblem, InvalidDesignIsAFailedEvaluation) {
  const VehicleModel v = magpie();
  DesignSpace s;
  DesignVariable end;  // STIF4's end point moved beyond the trailing edge
  end.name = "stif4_end_x";
  end.fields = resolve("wing.members.STIF4.end_x_m", v);
  end.lower = -0.2;
  end.upper = -0.05;
  end.initial = -0.0624;
  s.variables = {end};
  DesignProblemOptions o;
  o.trim = defaultTrimOptions(testing::magpieDesignPoint());
  const DesignProblem p(v, s, o);
  auto ws = p.makeWorkspace();
  const Evaluation e = p.evaluate({-0.15}, *ws);
  EXPECT_EQ(e.status, EvaluationStatus::kFailed);
  EXPECT_NE(e.message.find("design not evaluated"), std::string::npos);
  EXPECT_NE(e.message.find("members[7]"), std::string::npos) << e.message;
}

TEST(OptimizeDesignProblem, WarmStartFollowsTheLastConvergedTrim) {
  const DesignProblem p = tailProblem(12.0);
  auto ws = p.makeWorkspace();
  const std::vector<double> x0 = p.box().initial;
  const Evaluation first = p.evaluate(x0, *ws);
  ASSERT_EQ(first.values[kTrimConverged], 1.0);
  p.observe(x0, first, *ws);
  // The same design again, warm: the trim starts at its own solution and converges at once.
  const Evaluation again = p.evaluate(x0, *ws);
  EXPECT_EQ(again.values[kTrimConverged], 1.0);
  EXPECT_LT(again.values[kPeriodicRuns], first.values[kPeriodicRuns]);
  EXPECT_NEAR(again.objective, first.objective, 1e-4 * first.objective);
}

TEST(OptimizeDesignProblem, RejectsInconsistentSetups) {
  const VehicleModel v = rigidMagpie();
  DesignProblemOptions o;
  o.trim = defaultTrimOptions(testing::magpieDesignPoint());
  EXPECT_THROW(DesignProblem(v, DesignSpace{}, o), std::invalid_argument);  // no variables
  DesignSpace s;
  DesignVariable d;
  d.name = "stif";
  d.fields = resolve("wing.members.STIF*.diameter_m", v);
  d.lower = 0.0;  // a diameter must stay > 0
  d.upper = 1e-3;
  d.initial = 4e-4;
  s.variables = {d};
  EXPECT_THROW(DesignProblem(v, s, o), std::invalid_argument);
  s.variables[0].lower = 1e-4;
  o.constraints.tip_deflection_max_m = 0.01;  // rigid wing: no tip deflection
  EXPECT_THROW(DesignProblem(v, s, o), std::invalid_argument);
  o.constraints.tip_deflection_max_m = 0.0;
  o.trim.verify_free_flight = false;  // bounded needs the free flight
  EXPECT_THROW(DesignProblem(v, s, o), std::invalid_argument);
  o.trim.verify_free_flight = true;
  o.constraints.floquet_max_modulus = 0.98;  // the multipliers need the periodic trim
  EXPECT_THROW(DesignProblem(v, s, o), std::invalid_argument);
  usePeriodicMethod(&o.trim);
  o.trim.periodic.floquet = false;  // ... with its Floquet analysis on
  EXPECT_THROW(DesignProblem(v, s, o), std::invalid_argument);
  o.trim.periodic.floquet = true;
  o.constraints.floquet_max_modulus = -0.5;
  EXPECT_THROW(DesignProblem(v, s, o), std::invalid_argument);
}

// The periodic trim as the trim of a design evaluation (docs/theory.md 10.3): the flexible magpie at 12 Hz
// with the floquet_max_modulus constraint and no bounded-norm flight. The orbit and multipliers
// are solvePeriodicTrim's (the same code path, so equal to the last bit), the constraint is
// max |mu| / limit - 1, and the objective is the hinge power of the tethered periodic run at the
// orbit's cycle-mean point with the two-stage trim's default run tolerances.
TEST(OptimizeDesignProblem, PeriodicTrimGivesTheFloquetConstraint) {
  const VehicleModel v = magpie();
  DesignSpace s;
  DesignVariable area;
  area.name = "tail.area_m2";
  area.fields = resolve("tail.area_m2", v);
  area.initial = fieldValue(v, area.fields.front());
  area.lower = 0.5 * area.initial;
  area.upper = 2.0 * area.initial;
  s.variables = {area};
  DesignProblemOptions o;
  o.trim = defaultTrimOptions(testing::magpieDesignPoint());
  o.trim.initial.freq_hz = 12.0;
  usePeriodicMethod(&o.trim);
  o.constraints.bounded = false;
  o.constraints.floquet_max_modulus = 0.98;
  const DesignProblem p(v, s, o);
  ASSERT_EQ(p.constraintNames(), (std::vector<std::string>{"trimmed", "floquet_max_modulus"}));
  ASSERT_EQ(p.valueCount(), static_cast<int>(kPeriodicDesignValueCount));
  EXPECT_EQ(p.valueInfo()[kFloquetMaxModulus].name, std::string("floquet_max_modulus"));
  auto ws = p.makeWorkspace();
  const Evaluation e = p.evaluate(p.box().initial, *ws);
  SCOPED_TRACE(e.message);
  ASSERT_EQ(e.status, EvaluationStatus::kOk);
  ASSERT_EQ(e.values.size(), static_cast<std::size_t>(kPeriodicDesignValueCount));
  ASSERT_EQ(e.values[kTrimConverged], 1.0);
  EXPECT_EQ(e.constraints[0], -1.0);

  const FlightCoreModel model(v);
  TrimOptions t = o.trim;
  t.verify_free_flight = false;
  const PeriodicTrimSummary ref = solvePeriodicTrim(model, t);
  ASSERT_TRUE(ref.converged && ref.floquet_valid) << ref.message;
  EXPECT_EQ(e.values[kFloquetMaxModulus], ref.floquet.max_modulus);
  EXPECT_EQ(e.values[kFloquetStable], ref.floquet.max_modulus < 1.0 ? 1.0 : 0.0);
  EXPECT_EQ(e.values[kPeriodicResidual], ref.shooting.residual_max);
  EXPECT_LE(e.values[kPeriodicResidual], o.trim.periodic.residual_tol);
  EXPECT_EQ(e.constraints[1], ref.floquet.max_modulus / 0.98 - 1.0);
  EXPECT_EQ(e.values[kTrimTheta], ref.solution.theta_rad);
  EXPECT_EQ(e.values[kTrimSpeed], ref.solution.speed_mps);
  EXPECT_EQ(e.values[kTrimTailAngle], ref.solution.tail_angle_rad);
  EXPECT_TRUE(std::isnan(e.values[kBounded]));  // no bounded-norm flight was asked for
  EXPECT_NE(e.message.find("Floquet max |mu|"), std::string::npos);

  SimulationOptions run = defaultTrimOptions(testing::magpieDesignPoint()).simulation;
  run.mode = FlightMode::kTethered;
  run.stop_when_steady = true;
  const SimulationSummary tethered = simulateTethered(model, ref.solution, run, nullptr);
  EXPECT_EQ(e.objective, tethered.mean.power_hinge_W);
  EXPECT_EQ(e.values[kPowerAero], tethered.mean.power_aero_W);
  // The power at the orbit's mean point is near the Eq. (4) start's (the points differ by the
  // settling of the free flight: tenths of a degree and of a m/s).
  EXPECT_NEAR(e.objective, ref.stage1.mean.power_hinge_W, 0.05 * ref.stage1.mean.power_hinge_W);
}

}  // namespace
}  // namespace orni::opt
