// The field table (core/model/field_table.hpp) itself: one entry per key, every numeric entry
// with a finite lower AND upper bound, integer ranges closed on whole numbers, a unit, a default
// and a meaning; key normalisation; and core's model checks (vehicle_validation.hpp) on a model
// built in code, with the same ranges the readers use.
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <string>

#include "core/dynamics/flight_core.hpp"
#include "core/model/field_table.hpp"
#include "core/model/frames.hpp"
#include "core/model/invalid_model_error.hpp"
#include "core/model/vehicle_validation.hpp"
#include "tests/support/test_vehicles.hpp"

namespace orni {
namespace {

bool numeric(const FieldSpec& f) {
  return f.type == FieldType::kNumber || f.type == FieldType::kInteger ||
         f.type == FieldType::kPair || f.type == FieldType::kGrid ||
         f.type == FieldType::kNumberList;
}

TEST(ModelFieldTable, EveryKeyOnceWithUnitDefaultAndMeaning) {
  std::set<std::string_view> keys;
  for (const FieldSpec& f : fieldTable()) {
    SCOPED_TRACE(std::string(f.key));
    EXPECT_TRUE(keys.insert(f.key).second) << "listed twice";
    EXPECT_FALSE(f.unit.empty());
    EXPECT_FALSE(f.default_text.empty());
    EXPECT_FALSE(f.meaning.empty());
    EXPECT_GT(f.si_per_unit, 0.0);
    EXPECT_EQ(findField(f.key), &f);
  }
  EXPECT_GE(keys.size(), 150u);
}

TEST(ModelFieldTable, EveryNumberHasALowerAndAnUpperBound) {
  for (const FieldSpec& f : fieldTable()) {
    if (!numeric(f) || f.rangeOfAnotherKey()) continue;
    SCOPED_TRACE(std::string(f.key));
    EXPECT_TRUE(std::isfinite(f.range.lo));
    EXPECT_TRUE(std::isfinite(f.range.hi));
    EXPECT_LT(f.range.lo, f.range.hi);
    if (f.type == FieldType::kInteger) {
      EXPECT_FALSE(f.range.lo_open || f.range.hi_open);
      EXPECT_EQ(std::floor(f.range.lo), f.range.lo);
      EXPECT_EQ(std::floor(f.range.hi), f.range.hi);
      // Integer keys never report the int32 range.
      EXPECT_LT(f.range.hi, 2147483647.0);
    }
  }
}

TEST(ModelFieldTable, ChoicesAndGroups) {
  for (const FieldSpec& f : fieldTable()) {
    SCOPED_TRACE(std::string(f.key));
    EXPECT_EQ(f.type == FieldType::kChoice, !f.choices.empty());
    bool known = false;
    for (std::string_view g : fieldGroups()) known = known || g == f.group();
    EXPECT_TRUE(known) << f.group();
  }
  EXPECT_EQ(field("wing.planform").expected(),
            "one of \"rectangular\" or \"quarter_ellipse\"");
  EXPECT_EQ(field("wing.strips").expected(), "an integer in [1, 500]");
  EXPECT_EQ(field("operating_point.freq_hz").expected(), "a number in [0.01, 200]");
}

TEST(ModelFieldTable, KeysAreNormalised) {
  EXPECT_EQ(findField("wing.members[3].diameter_m")->key, "wing.members[].diameter_m");
  EXPECT_EQ(findField("materials.CFRP_ROD.density_kgpm3")->key, "materials.*.density_kgpm3");
  EXPECT_EQ(findField("override.tail.arm_m")->key, "tail.arm_m");
  EXPECT_EQ(findField("vehicle.tail.arm_m")->key, "tail.arm_m");
  EXPECT_EQ(findField("sensitivity.free.bound_h_m")->key, "simulate.free.bound_h_m");
  EXPECT_EQ(findField("optimize.trim.max_cycles")->key, "trim.max_cycles");
  EXPECT_EQ(findField("tail.arm"), nullptr);
  EXPECT_THROW(field("tail.arm"), std::logic_error);
}

TEST(ModelFieldTable, OneQuantityOneRange) {
  // The speed, frequency and angles of a run have the same range wherever they are set.
  for (const char* k : {"simulate.speed_mps", "aeromap.speed_mps", "trim.initial.speed_mps",
                        "trim.bounds.speed_mps", "calibrate.speed_mps"}) {
    const ValueRange& a = field(k).range;
    const ValueRange& b = field("operating_point.speed_mps").range;
    EXPECT_TRUE(a.lo == b.lo && a.hi == b.hi && a.lo_open == b.lo_open && a.hi_open == b.hi_open)
        << k;
  }
  for (const char* k : {"simulate.freq_hz", "aeromap.freq_hz", "trim.freq_hz",
                        "trim.bounds.freq_hz", "optimize.freq_hz", "calibrate.freq_hz"})
    EXPECT_EQ(field(k).range.interval(), "[0.01, 200]") << k;
}

TEST(ModelDisplayNumber, AsAUserWritesIt) {
  EXPECT_EQ(displayNumber(6e-4), "6e-4");
  EXPECT_EQ(displayNumber(0.005), "0.005");
  EXPECT_EQ(displayNumber(6e-7), "6e-7");
  EXPECT_EQ(displayNumber(1e308), "1e308");
  EXPECT_EQ(displayNumber(200.0), "200");
  EXPECT_EQ(displayNumber(0.0), "0");
  EXPECT_EQ(displayNumber(1e5), "100000");
  EXPECT_EQ(displayNumber(1e16), "1e16");
  EXPECT_EQ(displayNumber(-1.5e-12), "-1.5e-12");
}

TEST(ModelVehicleValidation, TheRigIsValid) {
  EXPECT_TRUE(vehicleProblems(testing::rfwRig()).empty());
}

TEST(ModelVehicleValidation, RangesAndRulesInSi) {
  struct Case {
    void (*edit)(VehicleModel&);
    const char* key;
    const char* says;
  };
  const Case cases[] = {
      {[](VehicleModel& v) { v.wing.semispan_m = 1e308; }, "wing.semispan_m",
       "expected a number in [0.005, 20], got 1e308"},
      {[](VehicleModel& v) { v.materials[0].youngs_modulus_pa = 2e12; },
       "materials.RIPSTOP.youngs_modulus_gpa", "expected a number in [1e-4, 1200], got 2000"},
      {[](VehicleModel& v) { v.flapping.amplitude_rad = 90.0 * kDegToRad; },
       "kinematics.amplitude_deg", "expected a number in (0, 90), got 90"},
      {[](VehicleModel& v) { v.wing.p3_aft_of_le_m = 0.2; }, "wing.p3_aft_of_le_m",
       "(on the root chord)"},
      {[](VehicleModel& v) { v.wing.fe.element_size_m = 0.3; }, "wing.fe.element_size_m",
       "(at most wing.semispan_m)"},
      {[](VehicleModel& v) {
         v.wing.structure = StructureLevel::kFlexible;
         v.wing.fe.element_size_m = 0.001;  // ~ 57 000 nodes on the 0.026 m^2 rig wing
       },
       "wing.fe.element_size_m", "at most 50000 mesh nodes"},
      {[](VehicleModel& v) { v.wing.members[0].end_y_W_m = 0.3; }, "wing.members[0].end_xy_m",
       "inside the planform"},
      {[](VehicleModel& v) { v.wing.members[0].material = "FOIL"; }, "wing.members[0].material",
       "unknown material \"FOIL\""},
      {[](VehicleModel& v) {
         v.body.present = true;
         v.body.mass_kg = 0.1;
         v.body.pitch_inertia_kgm2 = 1e-4;
         v.tail.present = true;
         v.tail.area_m2 = 0.01;
         v.tail.aspect_ratio = 2.0;
         v.tail.arm_m = 0.1;
         v.tail.mass_kg = 0.2;
       },
       "tail.mass_kg", "a number < body.mass_kg = 0.1"},
      {[](VehicleModel& v) {
         v.wing.structure = StructureLevel::kFlexible;
         v.wing.incidence_rad = 0.1;
       },
       "wing.incidence_deg", "0 for a flexible wing"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.key);
    VehicleModel v = testing::rfwRig();
    c.edit(v);
    const std::vector<ModelProblem> p = vehicleProblems(v);
    ASSERT_FALSE(p.empty());
    EXPECT_EQ(p.front().key, c.key);
    EXPECT_NE(p.front().message().find(c.says), std::string::npos) << p.front().message();
    // A library user gets the same check from the model's constructor.
    try {
      const FlightCoreModel model(v);
      ADD_FAILURE() << "FlightCoreModel accepted the vehicle";
    } catch (const InvalidModelError& e) {
      EXPECT_NE(std::string(e.what()).find(p.front().message()), std::string::npos) << e.what();
    }
  }
}

// The vehicle file's design point is checked beside the model, not in it (issue 15 item 7):
// the reader reports it at its key; core's model checks never see it.
TEST(ModelVehicleValidation, TheDesignPointIsCheckedBesideTheModel) {
  EXPECT_TRUE(designPointProblems(testing::rfwRigPoint()).empty());
  OperatingPoint p = testing::rfwRigPoint();
  p.speed_mps = 1e6;
  const std::vector<ModelProblem> problems = designPointProblems(p);
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_EQ(problems.front().key, "operating_point.speed_mps");
  EXPECT_NE(problems.front().message().find("expected a number in [0.001, 100], got 1000000"),
            std::string::npos)
      << problems.front().message();
  // definitionProblems: the model's problems first, then the point's.
  VehicleDefinition d{testing::rfwRig(), p};
  d.model.wing.semispan_m = -1.0;
  const std::vector<ModelProblem> both = definitionProblems(d);
  ASSERT_GE(both.size(), 2u);
  EXPECT_EQ(both.front().key, "wing.semispan_m");
  EXPECT_EQ(both.back().key, "operating_point.speed_mps");
}

}  // namespace
}  // namespace orni
