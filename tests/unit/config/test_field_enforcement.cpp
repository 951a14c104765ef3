// Every numeric entry of the field table (core/model/field_table.hpp) is enforced by the readers
// (issue 14 defect 5, issue 15): for each key, a valid document gets the value just outside each
// bound written at that key, and the reader must reject it with an InputError that names the key
// and the range of the entry. A key the readers do not read, or read with another range, fails
// here. The same value one step inside the bound is accepted (the bound is the one checked).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "core/model/field_table.hpp"
#include "studies/runner/config/input_error.hpp"
#include "studies/runner/config/study_file.hpp"
#include "studies/runner/config/study_reader.hpp"
#include "studies/runner/config/vehicle_file.hpp"

namespace orni::studies {
namespace {

namespace fs = std::filesystem;

fs::path magpie() {
  return fs::path(ORNI_SOURCE_DIR) / "studies" / "vehicles" / "efw_magpie.toml";
}

/// A valid document in which the key of each group is set: the magpie for vehicle keys, a study
/// of the key's kind for analysis keys.
std::string baseText(std::string_view group, std::string_view key = {}) {
  const std::string vehicle = "vehicle = \"" + magpie().generic_string() + "\"\n";
  if (group == "simulate")
    return "kind = \"simulate\"\n" + vehicle + "[simulate]\nmode = \"free\"\n";
  if (group == "aeromap")
    return "kind = \"aeromap\"\n" + vehicle +
           "[aeromap]\nspeed_mps = 10.0\nfreq_hz = 12.0\ntheta_deg = 5.0\n";
  if (group == "trim" && key.rfind("trim.periodic.", 0) == 0)
    return "kind = \"trim\"\n" + vehicle + "[trim]\nmethod = \"periodic\"\n";
  if (group == "trim") return "kind = \"trim\"\n" + vehicle + "[trim]\n";
  if (group == "optimize")
    return "kind = \"optimize\"\n" + vehicle +
           "[optimize]\nalgorithm = \"isres\"\nobjective = \"weighted\"\n"
           "[[optimize.variables]]\nname = \"tail.area_m2\"\nlower = 0.004\nupper = 0.02\n";
  if (group == "calibrate")
    return "kind = \"calibrate\"\n" + vehicle +
           "[calibrate]\n[[calibrate.variables]]\nkey = \"tail.arm_m\"\nlower = 0.1\nupper = 0.14\n";
  if (group == "continuation")
    return "kind = \"continuation\"\n" + vehicle +
           "[continuation]\nparameter = \"freq_hz\"\nto = 12.5\n";
  if (group == "sensitivity")
    return "kind = \"sensitivity\"\n" + vehicle +
           "[sensitivity]\nparameters = [{ key = \"tail.arm_m\", low = 0.1, high = 0.14 }]\n";
  std::ifstream in(magpie());
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

/// The key with the first array element and the first material filled in
/// ("wing.members[].diameter_m" -> "wing.members[0].diameter_m", "materials.*.x" ->
/// "materials.LE1.x"), as a reader names it.
std::string concreteKey(std::string_view key) {
  std::string k(key);
  for (std::size_t at = k.find("[]"); at != std::string::npos; at = k.find("[]"))
    k.replace(at, 2, "[0]");
  const std::size_t star = k.find(".*.");
  if (star != std::string::npos) k.replace(star + 1, 1, "LE1");
  return k;
}

/// Writes `value` at the dotted (concrete) key of `root`, creating tables; "[0]" parts address the
/// first table of an array of tables.
void setValue(toml::table& root, const std::string& key, toml::node&& value) {
  toml::table* t = &root;
  std::size_t start = 0;
  for (;;) {
    const std::size_t dot = key.find('.', start);
    std::string part = key.substr(start, dot == std::string::npos ? dot : dot - start);
    if (dot == std::string::npos) {
      value.visit([&](auto&& v) { t->insert_or_assign(part, std::move(v)); });
      return;
    }
    const std::size_t bracket = part.find('[');
    if (bracket != std::string::npos) {
      part = part.substr(0, bracket);
      t = t->get(part)->as_array()->get(0)->as_table();
    } else {
      if (!t->get(part)) t->insert_or_assign(part, toml::table{});
      t = t->get(part)->as_table();
    }
    start = dot + 1;
  }
}

/// Reads the document of `group` (a vehicle, or a study of that kind) from the parsed `root`.
void read(std::string_view group, toml::table& root, const std::string& text) {
  const fs::path file = "enforce.toml";
  if (group == "vehicle") {
    (void)parseVehicleTable(root, file);
  } else if (group == "sensitivity") {
    (void)loadSensitivityStudy(root, text, file, false);
  } else {
    (void)readStudyRoot(root, file);
  }
}

/// The InputError of the document with `value` at the key, or "" when it is accepted.
std::string errorWith(const FieldSpec& f, toml::node&& value, std::string* key_named) {
  const std::string text = baseText(f.group(), f.key);
  toml::table root = toml::parse(text, std::string("enforce.toml"));
  setValue(root, concreteKey(f.key), std::move(value));
  try {
    read(f.group(), root, text);
  } catch (const InputError& e) {
    *key_named = e.key();
    return e.what();
  }
  return std::string();
}

/// The TOML node of a number of the entry's type (a pair's or grid's value in the right place).
toml::node* makeValue(const FieldSpec& f, double v, bool at_upper,
                      std::unique_ptr<toml::node>* own) {
  if (f.type == FieldType::kInteger) {
    own->reset(new toml::value<int64_t>(static_cast<int64_t>(v)));
  } else if (f.type == FieldType::kPair) {
    // The other element inside the range, on the other side so that [lower, upper] is ordered.
    const double inside = at_upper ? f.range.lo + (f.range.hi - f.range.lo) * 0.25
                                   : f.range.lo + (f.range.hi - f.range.lo) * 0.75;
    auto* a = new toml::array();
    if (f.key.find("xy_m") != std::string_view::npos) {
      a->push_back(v);
      a->push_back(0.0);
    } else if (at_upper) {
      a->push_back(inside);
      a->push_back(v);
    } else {
      a->push_back(v);
      a->push_back(inside);
    }
    own->reset(a);
  } else if (f.type == FieldType::kNumberList) {
    // A valid element first, so that the bad one is found at its index.
    auto* a = new toml::array();
    a->push_back(f.range.lo + (f.range.hi - f.range.lo) * 0.5);
    a->push_back(v);
    own->reset(a);
  } else {
    own->reset(new toml::value<double>(v));
  }
  return own->get();
}

struct Bound {
  double outside;
  bool upper;
};

std::vector<Bound> outsideValues(const FieldSpec& f) {
  const double inf = std::numeric_limits<double>::infinity();
  if (f.type == FieldType::kInteger) return {{f.range.lo - 1, false}, {f.range.hi + 1, true}};
  return {{f.range.lo_open ? f.range.lo : std::nextafter(f.range.lo, -inf), false},
          {f.range.hi_open ? f.range.hi : std::nextafter(f.range.hi, inf), true}};
}

bool checkedByValue(const FieldSpec& f) {
  const bool typed = f.type == FieldType::kNumber || f.type == FieldType::kInteger ||
                     f.type == FieldType::kPair || f.type == FieldType::kGrid ||
                     f.type == FieldType::kNumberList;
  return typed && !f.rangeOfAnotherKey() && f.group() != "cli";
}

TEST(ConfigFieldEnforcement, EveryBoundOfEveryKeyIsCheckedByTheReaders) {
  int checked = 0;
  for (const FieldSpec& f : fieldTable()) {
    if (!checkedByValue(f)) continue;
    for (const Bound& b : outsideValues(f)) {
      SCOPED_TRACE(std::string(f.key) + (b.upper ? " above " : " below ") +
                   displayNumber(b.upper ? f.range.hi : f.range.lo));
      std::unique_ptr<toml::node> value;
      makeValue(f, b.outside, b.upper, &value);
      std::string key;
      const std::string what = errorWith(f, std::move(*value), &key);
      ASSERT_FALSE(what.empty()) << "accepted " << displayNumber(b.outside);
      EXPECT_EQ(key, concreteKey(f.key)) << what;
      EXPECT_NE(what.find(f.range.interval()), std::string::npos) << what;
      ++checked;
    }
  }
  EXPECT_GE(checked, 200);  // about 110 keys, two bounds each
}

TEST(ConfigFieldEnforcement, ValuesOnTheClosedBoundsAreAccepted) {
  // Keys whose bounds are reachable alone (no rule ties them to another key at the bound).
  for (const char* k : {"air.density_kgpm3", "air.gravity_mps2", "wing.strips",
                        "wing.fe.damping_ratio", "materials.*.youngs_modulus_gpa",
                        "aero.suction_efficiency", "body.drag_area_m2", "simulate.cycles",
                        "simulate.free.transient_fraction", "trim.max_iterations",
                        "optimize.starts"}) {
    const FieldSpec& f = field(k);
    for (const double v : {f.range.lo, f.range.hi}) {
      if ((v == f.range.lo && f.range.lo_open) || (v == f.range.hi && f.range.hi_open)) continue;
      SCOPED_TRACE(std::string(k) + " = " + displayNumber(v));
      std::unique_ptr<toml::node> value;
      makeValue(f, v, v == f.range.hi, &value);
      std::string key;
      EXPECT_EQ(errorWith(f, std::move(*value), &key), "");
    }
  }
}

/// True when a `kind = ...` line comes before the first table header (a study, not a vehicle).
bool isStudy(const fs::path& file) {
  std::ifstream in(file);
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("[", 0) == 0) return false;
    if (line.rfind("kind", 0) == 0) return true;
  }
  return false;
}

TEST(ConfigFieldEnforcement, CommittedInputsAreInsideTheRanges) {
  // Every committed vehicle and study, every valid test input and every committed resolved study
  // loads: the ranges change no valid run (issue 14 defect 5).
  const fs::path root(ORNI_SOURCE_DIR);
  int loaded = 0;
  for (const char* dir : {"studies", "tests/data", "results"}) {
    for (const auto& entry : fs::recursive_directory_iterator(root / dir)) {
      const fs::path& p = entry.path();
      if (p.extension() != ".toml" || p.string().find("/tests/data/bad/") != std::string::npos)
        continue;
      if (std::string(dir) == "results" && p.filename() != "study.resolved.toml") continue;
      SCOPED_TRACE(p.string());
      try {
        if (isStudy(p))
          (void)loadStudyFile(p);
        else
          (void)loadVehicleFile(p);
        ++loaded;
      } catch (const InputError& e) {
        ADD_FAILURE() << e.what();
      }
    }
  }
  EXPECT_GE(loaded, 20);
}

}  // namespace
}  // namespace orni::studies
