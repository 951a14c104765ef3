// The defaults are written twice: as text in the field table (core/model/field_table.cpp, what
// `ornithopter keys` and docs/keys.md show) and as the readers' fallbacks (the option structs'
// initial values). This test holds them together: for every key whose table default is a plain
// number, the resolved study of a minimal study (every default filled in by the readers) holds
// that number, for the study's sections and for every vehicle key the vehicle file leaves out.
#include <gtest/gtest.h>

#include <toml++/toml.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include "core/model/field_table.hpp"
#include "studies/runner/config/study_file.hpp"
#include "studies/runner/config/toml_access.hpp"

namespace orni::studies {
namespace {

namespace fs = std::filesystem;

/// The table's default as a number, when the whole text is one.
bool numericDefault(const FieldSpec& f, double* value) {
  const std::string text(f.default_text);
  if (text.empty()) return false;
  char* end = nullptr;
  *value = std::strtod(text.c_str(), &end);
  return end == text.c_str() + text.size() && std::isfinite(*value);
}

/// The node at dotted `key` in `root` ("simulate.free.bound_speed_mps"), or null.
const toml::node* at(const toml::table& root, const std::string& key) {
  const toml::table* t = &root;
  std::size_t begin = 0;
  for (;;) {
    const std::size_t dot = key.find('.', begin);
    const std::string part = key.substr(begin, dot == std::string::npos ? dot : dot - begin);
    const toml::node* n = t->get(part);
    if (!n || dot == std::string::npos) return n;
    t = n->as_table();
    if (!t) return nullptr;
    begin = dot + 1;
  }
}

struct Checked {
  int compared = 0;
  std::vector<std::string> mismatches;
};

/// Compares every numeric default of the keys under `prefix` ("simulate.", "" for the vehicle's
/// keys, which the resolved study writes under [vehicle]) with the resolved document.
void compare(const toml::table& resolved, const std::string& prefix, const std::string& doc_prefix,
             const toml::table* given, Checked* out) {
  for (const FieldSpec& f : fieldTable()) {
    const std::string key(f.key);
    if (f.type != FieldType::kNumber && f.type != FieldType::kInteger) continue;
    if (key.find('*') != std::string::npos || key.find("[]") != std::string::npos) continue;
    if (key.compare(0, prefix.size(), prefix) != 0) continue;
    if (prefix.empty() && f.group() != "vehicle") continue;
    double expected = 0.0;
    if (!numericDefault(f, &expected)) continue;
    if (given && at(*given, key)) continue;  // the vehicle file sets it
    const toml::node* n = at(resolved, doc_prefix + key);
    if (!n) continue;  // not written (a section the study does not have)
    const std::optional<double> got = n->value<double>();
    ++out->compared;
    if (!got || std::abs(*got - expected) > 1e-12 * std::max(1.0, std::abs(expected)))
      out->mismatches.push_back(key + ": table " + std::string(f.default_text) + ", reader " +
                                (got ? std::to_string(*got) : std::string("not a number")));
  }
}

fs::path writeStudy(const std::string& name, const std::string& text) {
  const fs::path dir = fs::temp_directory_path() / "orni_field_defaults";
  fs::create_directories(dir);
  std::ofstream(dir / name) << text;
  return dir / name;
}

TEST(FieldDefaults, TheReadersFallBackToTheTablesDefaults) {
  Checked checked;
  for (const char* name : {"efw_magpie.toml", "rfw_tunnel.toml"}) {
    const fs::path vehicle = fs::path(ORNI_SOURCE_DIR) / "studies" / "vehicles" / name;
    const toml::table given = parseTomlText(readTomlFileText(vehicle), vehicle);
    const std::string v = "vehicle = \"" + vehicle.string() + "\"\n";
    const bool has_body = given.contains("body");  // free flight and trim need the mass
    const std::vector<std::pair<std::string, std::string>> studies = {
        {"simulate.", "kind = \"simulate\"\n" + v},
        {"simulate.", "kind = \"simulate\"\n" + v + "[simulate]\nmode = \"free\"\n"},
        {"trim.", "kind = \"trim\"\n" + v}};
    for (std::size_t i = 0; i < studies.size(); ++i) {
      const auto& [prefix, text] = studies[i];
      if (i > 0 && !has_body) continue;
      const fs::path f = writeStudy("study.toml", text);
      const toml::table resolved = parseTomlText(resolvedStudyToml(loadStudyFile(f)), f);
      compare(resolved, prefix, "", nullptr, &checked);
      compare(resolved, "", "vehicle.", &given, &checked);
    }
  }
  for (const std::string& m : checked.mismatches) ADD_FAILURE() << m;
  EXPECT_GT(checked.compared, 30) << "the comparison must reach the sections' keys";
  std::cout << "compared " << checked.compared << " defaults\n";
}

}  // namespace
}  // namespace orni::studies
