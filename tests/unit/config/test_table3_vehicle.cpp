// The calibrated vehicle (studies/vehicles/efw_magpie_table3.toml) is the honest vehicle
// (efw_magpie.toml) with the nonlinear wing and the values the calibration study
// (studies/paper/calibrate_table3.toml) fits, nothing else: "a fit is a fit". Every fitted value
// lies inside the range the study declares.
#include <gtest/gtest.h>
#include <toml++/toml.h>

#include <filesystem>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "core/model/vehicle_fields.hpp"
#include "studies/runner/config/vehicle_file.hpp"
#include "trim/calibration_options.hpp"

namespace orni::studies {
namespace {

namespace fs = std::filesystem;

fs::path sourcePath(const std::string& relative) { return fs::path(ORNI_SOURCE_DIR) / relative; }

// Removes a dotted key ("wing.fe.nonlinear") from a parsed file; false when it is absent.
bool erase(toml::table& t, const std::string& dotted) {
  toml::table* parent = &t;
  std::string rest = dotted;
  for (std::size_t dot; (dot = rest.find('.')) != std::string::npos;) {
    parent = parent->get_as<toml::table>(rest.substr(0, dot));
    if (!parent) return false;
    rest = rest.substr(dot + 1);
  }
  return parent->erase(rest) == 1;
}

// The leaves of a table as dotted keys ("wing.fe.nonlinear"): TOML's dotted keys are nested tables.
void flatten(const toml::table& t, const std::string& prefix,
             std::vector<std::pair<std::string, const toml::node*>>* out) {
  for (const auto& [key, node] : t) {
    const std::string k = prefix + std::string(key.str());
    if (const toml::table* sub = node.as_table())
      flatten(*sub, k + ".", out);
    else
      out->emplace_back(k, &node);
  }
}

struct Fit {
  std::string key;
  double lower, upper, initial;
};

std::vector<Fit> fittedKeys() {
  const toml::table study =
      toml::parse_file(sourcePath("studies/paper/calibrate_table3.toml").string());
  std::vector<Fit> fits;
  for (const toml::node& n : *study["calibrate"]["variables"].as_array()) {
    const toml::table& v = *n.as_table();
    fits.push_back({v["key"].value<std::string>().value(), v["lower"].value<double>().value(),
                    v["upper"].value<double>().value(), v["initial"].value<double>().value()});
  }
  return fits;
}

TEST(Table3Vehicle, IsTheHonestVehicleWithTheNonlinearWingAndTheFittedValuesOnly) {
  toml::table honest = toml::parse_file(sourcePath("studies/vehicles/efw_magpie.toml").string());
  toml::table fitted =
      toml::parse_file(sourcePath("studies/vehicles/efw_magpie_table3.toml").string());
  EXPECT_EQ(fitted["wing"]["fe"]["nonlinear"].value<bool>(), std::optional<bool>(true));
  const std::vector<Fit> fits = fittedKeys();
  // The study's [override] keys (the nonlinear wing, and a value fitted by an earlier stage and
  // held, each declared there): the calibrated vehicle carries exactly those values.
  const toml::table study =
      toml::parse_file(sourcePath("studies/paper/calibrate_table3.toml").string());
  const toml::table* overrides = study["override"].as_table();
  ASSERT_NE(overrides, nullptr);
  ASSERT_GE(fits.size(), 1u);
  // The limit: at most four values differ from the honest vehicle's (the fitted ones and
  // those held by the study's overrides, beside the nonlinear wing).
  std::vector<std::pair<std::string, const toml::node*>> leaves;
  flatten(*overrides, "", &leaves);
  EXPECT_LE(fits.size() + leaves.size() - 1, 4u);
  for (const auto& [k, value] : leaves) {
    if (k == "wing.fe.nonlinear") continue;
    const auto want = value->value<double>();
    ASSERT_TRUE(want.has_value()) << k;
    EXPECT_EQ(fitted.at_path(k).value<double>(), want) << k << ": not the study's value";
    EXPECT_TRUE(erase(fitted, k)) << k;
    erase(honest, k);
  }
  for (const char* k : {"name", "description", "wing.fe.nonlinear"}) {
    erase(honest, k);
    erase(fitted, k);
  }
  for (const Fit& f : fits) {
    EXPECT_TRUE(erase(fitted, f.key)) << f.key << " missing from the calibrated vehicle";
    erase(honest, f.key);  // absent when the honest vehicle takes the default
  }
  EXPECT_TRUE(honest == fitted)
      << "efw_magpie_table3.toml differs from efw_magpie.toml in more than its fitted values";
}

TEST(Table3Vehicle, FittedValuesLieInsideTheirDeclaredRanges) {
  const VehicleModel fitted =
      loadVehicleFile(sourcePath("studies/vehicles/efw_magpie_table3.toml")).model;
  for (const Fit& f : fittedKeys()) {
    const CalibrationParameter p = calibrationParameter(f.key);
    const double x = valueOf(fitted, p);
    EXPECT_GE(x, f.lower) << f.key;
    EXPECT_LE(x, f.upper) << f.key;
  }
}

}  // namespace
}  // namespace orni::studies
