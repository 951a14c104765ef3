// The accessors of the vehicle's numbers (core/model/vehicle_fields.hpp): every number, integer
// and pair of the field table's vehicle group has one (a new key cannot be forgotten), each reads
// and writes the member its key names (set through the accessor, written by the resolved writer,
// read back at the key) and no other, and concrete keys resolve to their member or material.
#include <gtest/gtest.h>

#include <toml++/toml.h>

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "core/model/field_table.hpp"
#include "core/model/vehicle_fields.hpp"
#include "studies/runner/config/vehicle_file.hpp"

namespace orni {
namespace {

VehicleModel magpie() {
  return studies::loadVehicleFile(std::string(ORNI_SOURCE_DIR) +
                                  "/studies/vehicles/efw_magpie.toml").model;
}

/// A number of the vehicle file's [operating_point]: the design point, not the VehicleModel's.
bool designPointNumber(const FieldSpec& f) { return f.key.substr(0, 16) == "operating_point."; }

bool vehicleNumber(const FieldSpec& f) {
  return f.group() == "vehicle" && !designPointNumber(f) &&
         (f.type == FieldType::kNumber || f.type == FieldType::kInteger ||
          f.type == FieldType::kPair);
}

TEST(ModelVehicleFields, EveryVehicleNumberOfTheFieldTableHasAnAccessor) {
  int checked = 0;
  for (const FieldSpec& f : fieldTable()) {
    if (!vehicleNumber(f)) continue;
    SCOPED_TRACE(std::string(f.key));
    if (f.type == FieldType::kPair) {
      EXPECT_NE(findVehicleNumber(f.key, 0), nullptr) << "no accessor of the pair's x";
      EXPECT_NE(findVehicleNumber(f.key, 1), nullptr) << "no accessor of the pair's y";
      EXPECT_EQ(findVehicleNumber(f.key), nullptr);
    } else {
      EXPECT_NE(findVehicleNumber(f.key), nullptr) << "a vehicle number without an accessor";
    }
    ++checked;
  }
  EXPECT_GE(checked, 44);  // as many as the table has today, at least
}

TEST(ModelVehicleFields, TheDesignPointsNumbersHaveTheirOwnAccessors) {
  std::vector<std::string_view> keys;
  for (const FieldSpec& f : fieldTable())
    if (f.group() == "vehicle" && designPointNumber(f)) keys.push_back(f.key);
  ASSERT_EQ(keys.size(), 4u);
  const std::vector<DesignPointNumber>& numbers = designPointNumbers();
  ASSERT_EQ(numbers.size(), keys.size());
  const VehicleDefinition base = studies::loadVehicleFile(std::string(ORNI_SOURCE_DIR) +
                                                          "/studies/vehicles/efw_magpie.toml");
  for (std::size_t i = 0; i < keys.size(); ++i) {
    const DesignPointNumber& n = numbers[i];
    SCOPED_TRACE(std::string(n.key));
    EXPECT_EQ(n.key, keys[i]);  // the field table's order
    EXPECT_EQ(findVehicleNumber(n.key), nullptr);  // not a number of the VehicleModel
    // Setting one changes it alone, and the writer writes it at its key.
    VehicleDefinition v = base;
    const double si = 0.37 * n.spec().range.hi * n.spec().si_per_unit;
    ASSERT_NE(n.get(base.design_point), si);
    n.set(v.design_point, si);
    for (const DesignPointNumber& other : numbers)
      EXPECT_EQ(other.get(v.design_point), &other == &n ? si : other.get(base.design_point));
    const std::string written = studies::vehicleToToml(v);
    const toml::table root = toml::parse(std::string_view(written), std::string("written.toml"));
    EXPECT_DOUBLE_EQ(root.at_path(n.key).value<double>().value_or(0.0) * n.spec().si_per_unit, si);
  }
}

TEST(ModelVehicleFields, EveryAccessorIsAVehicleNumberInTheOrderOfTheFieldTable) {
  std::size_t last = 0;
  for (const VehicleNumber& n : vehicleNumbers()) {
    SCOPED_TRACE(std::string(n.key) + " " + std::to_string(n.component));
    const FieldSpec* f = findField(n.key);
    ASSERT_NE(f, nullptr);
    EXPECT_EQ(f->key, n.key);  // the table's spelling, "[]" and "*" included
    EXPECT_TRUE(vehicleNumber(*f));
    EXPECT_EQ(n.component >= 0, f->type == FieldType::kPair);
    EXPECT_EQ(findVehicleNumber(n.key, n.component), &n);  // one accessor per key and component
    const std::size_t at = static_cast<std::size_t>(f - fieldTable().data());
    EXPECT_GE(at, last) << "not in the order of the field table (the resolved writer's)";
    last = at;
    const bool member = n.key.substr(0, 13) == "wing.members[";
    const bool material = n.key.substr(0, 10) == "materials.";
    EXPECT_EQ(n.element, member     ? VehicleElement::kMember
                         : material ? VehicleElement::kMaterial
                                    : VehicleElement::kNone);
  }
}

/// The value at a concrete key of a written vehicle, in file units; NaN when absent.
double readBack(const toml::table& root, const VehicleNumber& n, const VehicleModel& v,
                std::size_t index) {
  std::string key(n.key);
  const toml::node* node = nullptr;
  if (n.element == VehicleElement::kMember) {
    const toml::array* members = root["wing"]["members"].as_array();
    if (!members || index >= members->size()) return std::nan("");
    node = members->get(index)->as_table()->get(key.substr(key.rfind('.') + 1));
  } else if (n.element == VehicleElement::kMaterial) {
    node = root["materials"][v.materials.at(index).name][key.substr(key.rfind('.') + 1)].node();
  } else {
    node = root.at_path(key).node();
  }
  if (node && n.component >= 0) {
    const toml::array* pair = node->as_array();
    node = pair && pair->size() == 2 ? pair->get(static_cast<std::size_t>(n.component)) : nullptr;
  }
  if (!node) return std::nan("");
  if (const auto i = node->value<std::int64_t>(); i && node->is_integer())
    return static_cast<double>(*i);
  return node->value<double>().value_or(std::nan(""));
}

TEST(ModelVehicleFields, EachAccessorReadsAndWritesTheFieldItsKeyNames) {
  const VehicleModel base = magpie();
  ASSERT_TRUE(base.body.present && base.tail.present);
  ASSERT_GE(base.wing.members.size(), 2u);
  ASSERT_GE(base.materials.size(), 2u);
  for (const VehicleNumber& n : vehicleNumbers()) {
    const FieldSpec& spec = n.spec();
    const std::size_t count = n.count(base);
    ASSERT_GE(count, 1u);
    for (const std::size_t index : {std::size_t{0}, count - 1}) {
      SCOPED_TRACE(std::string(n.key) + " component " + std::to_string(n.component) +
                   " element " + std::to_string(index));
      // A value inside the key's range (file units) that the vehicle does not have yet.
      double file = 0.0;
      for (const double fraction : {0.37, 0.61}) {
        file = spec.range.lo + fraction * (spec.range.hi - spec.range.lo);
        if (spec.type == FieldType::kInteger) file = std::round(file);
        if (n.get(base, index) != file * spec.si_per_unit) break;
      }
      const double si = file * spec.si_per_unit;
      ASSERT_NE(n.get(base, index), si);
      VehicleModel v = base;
      n.set(v, index, si);
      EXPECT_EQ(n.get(v, index), si);
      // No other number changed.
      for (const VehicleNumber& other : vehicleNumbers()) {
        for (std::size_t e = 0; e < other.count(base); ++e) {
          if (&other == &n && e == index) continue;
          EXPECT_EQ(other.get(v, e), other.get(base, e))
              << std::string(other.key) << " element " << e << " changed too";
        }
      }
      // The resolved writer writes it at the key.
      const std::string written = studies::vehicleToToml({v, OperatingPoint{}});
      const toml::table root = toml::parse(std::string_view(written), std::string("written.toml"));
      EXPECT_DOUBLE_EQ(readBack(root, n, v, index) * spec.si_per_unit, si);
    }
  }
}

TEST(ModelVehicleFields, ConcreteKeysResolveToTheirMemberOrMaterial) {
  const VehicleModel v = magpie();
  const auto end_y = resolveVehicleNumber(v, "wing.members[2].end_xy_m", 1);
  ASSERT_TRUE(end_y);
  EXPECT_EQ(v.wing.members[2].name, "DIAG1");
  EXPECT_EQ(end_y->get(v), v.wing.members[2].end_y_W_m);
  const std::string name = v.materials.back().name;
  const auto rho = resolveVehicleNumber(v, "materials." + name + ".density_kgpm3");
  ASSERT_TRUE(rho);
  EXPECT_EQ(rho->index, v.materials.size() - 1);
  EXPECT_EQ(rho->get(v), v.materials.back().density_kgpm3);
  const auto arm = resolveVehicleNumber(v, "tail.arm_m");
  ASSERT_TRUE(arm);
  EXPECT_EQ(arm->get(v), v.tail.arm_m);
  const auto strips = resolveVehicleNumber(v, "wing.strips");
  ASSERT_TRUE(strips);
  VehicleModel w = v;
  strips->set(w, 31.4);  // integers are rounded
  EXPECT_EQ(w.wing.strip_count, 31);

  EXPECT_FALSE(resolveVehicleNumber(v, "wing.members[99].diameter_m"));
  EXPECT_FALSE(resolveVehicleNumber(v, "wing.members[].diameter_m"));
  EXPECT_FALSE(resolveVehicleNumber(v, "materials.NOPE.density_kgpm3"));
  EXPECT_FALSE(resolveVehicleNumber(v, "wing.members[0].end_xy_m"));  // a pair needs a component
  EXPECT_FALSE(resolveVehicleNumber(v, "wing.planform"));             // not a number
  EXPECT_FALSE(resolveVehicleNumber(v, "tail.span_m"));               // no such key
}

}  // namespace
}  // namespace orni
