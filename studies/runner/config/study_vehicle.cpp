// The vehicle of a study file: `vehicle` (a path relative to the study's folder, or an inline
// [vehicle] table as study.resolved.toml writes it), vehicle_source and [override]
// (study_file.hpp documents the keys).
#include <filesystem>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

#include "studies/runner/config/study_sections.hpp"
#include "studies/runner/config/vehicle_file.hpp"

namespace orni::studies {

namespace fs = std::filesystem;

namespace {

/// Merges `from` into `into`: tables are merged key by key, everything else is replaced. Nodes are
/// moved, so they keep their source (file and line) for messages.
void mergeOverride(toml::table& into, toml::table& from) {
  for (auto&& [key, node] : from) {
    const std::string k(key.str());
    toml::table* from_table = node.as_table();
    toml::node* target = into.get(k);
    if (from_table && target && target->is_table()) {
      mergeOverride(*target->as_table(), *from_table);
    } else {
      into.insert_or_assign(k, std::move(node));
    }
  }
}

/// The vehicle file a study names (`vehicle` = "PATH"): its table and read context, in which the
/// errors of an overridden value name the study's [override].
struct VehicleFileInput {
  toml::table table;
  ReadContext context;
};

VehicleFileInput readNamedVehicleFile(const TableReader& top, const toml::node& vehicle_node,
                                      const fs::path& given, const fs::path& study_file,
                                      const std::string& study_name) {
  const fs::path resolved = study_file.parent_path() / given;
  const std::string expected =
      "the path of an existing vehicle file, relative to the study's folder";
  // An error at 'vehicle': `what` says what the named file is instead.
  auto wrongFile = [&](const std::string& also_expected, const std::string& what) {
    return top.valueError("vehicle", expected + also_expected,
                          describeNode(vehicle_node) + " (" + what + ")");
  };
  const std::string unreadable = given.empty() ? "no such file" : notARegularFile(resolved);
  if (!unreadable.empty())
    throw wrongFile("", TomlWriter::stringText(displayPath(resolved)) + ": " + unreadable);
  std::error_code ec;
  if (fs::equivalent(resolved, study_file, ec))
    throw wrongFile(", not the study itself", "this study file");
  VehicleFileInput in{parseTomlFile(resolved), {}};
  if (in.table.contains("kind"))
    throw wrongFile(", not a study", TomlWriter::stringText(displayPath(resolved)) +
                                         " is a study file: it has a top-level 'kind' key");
  in.context.file = displayPath(resolved);
  in.context.foreign_file = study_name;
  in.context.foreign_prefix = "override.";
  return in;
}

}  // namespace

void readStudyVehicle(StudyDocument doc, const fs::path& study_file, Study& study) {
  TableReader& top = doc.top;
  const std::string study_name = doc.context->file;
  VehicleFileInput vehicle;
  std::string vehicle_root_path;
  const std::string vehicle_expected =
      "a vehicle file path relative to the study's folder, or a [vehicle] table";
  const toml::node* vehicle_node = top.take("vehicle");
  const toml::node* source_node = top.take("vehicle_source");
  if (!vehicle_node) throw top.missingError("vehicle", vehicle_expected);
  if (const auto* s = vehicle_node->as_string()) {
    if (source_node)
      throw InputError::unknownKey(top.fileOf("vehicle_source"), top.lineOf("vehicle_source"),
                                   "vehicle_source", "only allowed with an inline [vehicle] table");
    const fs::path given = s->get();
    vehicle = readNamedVehicleFile(top, *vehicle_node, given, study_file, study_name);
    study.vehicle_path = given;
  } else if (toml::table* t = doc.root.get("vehicle")->as_table()) {
    vehicle.table = std::move(*t);
    vehicle.context.file = study_name;
    vehicle_root_path = "vehicle";
    if (source_node) study.vehicle_path = top.requiredString("vehicle_source");
  } else {
    throw top.valueError("vehicle", vehicle_expected, describeNode(*vehicle_node));
  }

  if (const toml::node* o = top.take("override")) {
    toml::table* ot = doc.root.get("override")->as_table();
    if (!ot)
      throw top.valueError("override", "a table [override] of vehicle keys", describeNode(*o));
    mergeOverride(vehicle.table, *ot);
  }
  orni::VehicleDefinition definition =
      parseVehicleTable(vehicle.table, vehicle.context, vehicle_root_path);
  study.vehicle = std::move(definition.model);
  study.design_point = definition.design_point;
  study.point = study.design_point;
}

std::string inputFileOf(const Study& study) {
  const fs::path& p = study.study_path.empty() ? study.vehicle_path : study.study_path;
  return p.empty() ? std::string("vehicle") : displayPath(p);
}

InputError vehicleKeyError(const Study& study, const std::string& key,
                           const std::string& expected, const std::string& got) {
  std::vector<std::string> path;  // the key's tables and name
  for (std::size_t start = 0, dot;; start = dot + 1) {
    dot = key.find('.', start);
    path.push_back(key.substr(start, dot == std::string::npos ? std::string::npos : dot - start));
    if (dot == std::string::npos) break;
  }
  auto lineIn = [](const fs::path& file, const std::vector<std::string>& parts) -> int {
    try {
      const toml::table root = parseTomlFile(file);
      const toml::node* node = &root;
      for (const std::string& part : parts) {
        const toml::table* t = node->as_table();
        node = t != nullptr ? t->get(part) : nullptr;
        if (node == nullptr) return -1;
      }
      return static_cast<int>(node->source().begin.line);
    } catch (const InputError&) {
      return -1;
    }
  };
  if (!study.study_path.empty()) {
    std::vector<std::string> in_override = {"override"};
    in_override.insert(in_override.end(), path.begin(), path.end());
    const int line = lineIn(study.study_path, in_override);
    if (line >= 0)
      return InputError::wrongValue(displayPath(study.study_path), line, "override." + key,
                                    expected, got);
  }
  if (!study.vehicle_path.empty()) {
    const fs::path vehicle = study.study_path.empty()
                                 ? study.vehicle_path
                                 : study.study_path.parent_path() / study.vehicle_path;
    const int line = lineIn(vehicle, path);
    if (line >= 0) return InputError::wrongValue(displayPath(vehicle), line, key, expected, got);
  }
  return InputError::wrongValue(inputFileOf(study), 0, key, expected, got);
}

}  // namespace orni::studies
