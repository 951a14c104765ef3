#include "vehicle_object.hpp"

#include <utility>

#include "studies/runner/config/input_error.hpp"
#include "studies/runner/config/toml_access.hpp"
#include "studies/runner/config/vehicle_file.hpp"
#include "toml_python.hpp"

namespace py = pybind11;

namespace orni::python {

namespace {

/// The file named in messages about values set from Python (they have no file and no line).
constexpr const char* kPythonSource = "<python>";

}  // namespace

VehicleObject VehicleObject::load(const std::string& path) {
  VehicleObject v;
  v.source_ = studies::displayPath(path);
  v.adopt(studies::loadVehicleFile(path));
  return v;
}

VehicleObject VehicleObject::fromTable(const toml::table& table, const std::string& source) {
  studies::ReadContext context;
  context.file = kPythonSource;
  VehicleObject v;
  v.source_ = source;
  v.adopt(studies::parseVehicleTable(table, context, std::string()));
  return v;
}

VehicleObject VehicleObject::fromDict(const py::dict& d, const std::string& source) {
  return fromTable(toTomlTable(d, "vehicle"), source);
}

VehicleObject VehicleObject::fromToml(const std::string& text, const std::string& source) {
  return fromTable(studies::parseTomlText(text, kPythonSource), source);
}

VehicleObject VehicleObject::clone() const {
  VehicleObject v;
  v.definition_ = definition_;
  v.document_ = document_;
  v.keys_ = keys_;
  v.source_ = source_;
  const std::lock_guard<std::mutex> lock(*core_mutex_);
  v.core_ = core_;  // immutable: shared until either vehicle changes
  return v;
}

py::dict VehicleObject::toDict() const { return toPython(document_).cast<py::dict>(); }

py::list VehicleObject::items() const {
  py::list out;
  for (const std::string& k : keys_) out.append(py::make_tuple(k, get(k)));
  return out;
}

std::string VehicleObject::repr() const {
  std::string out = "<ornithopter.Vehicle '" + definition_.model.name + "'";
  if (!source_.empty()) out += " from '" + source_ + "'";
  return out + ", " + std::to_string(keys_.size()) + " keys>";
}

void VehicleObject::adopt(VehicleDefinition definition) {
  definition_ = std::move(definition);
  // The resolved document: writeVehicleToml writes numbers that read back exactly, so the model
  // re-read from it after a set is this one with only that value changed.
  document_ = studies::parseTomlText(studies::vehicleToToml(definition_), kPythonSource);
  keys_ = leafKeys(document_);
  const std::lock_guard<std::mutex> lock(*core_mutex_);
  core_.reset();
}

py::object VehicleObject::get(const std::string& key) const {
  const toml::node* n = findNode(document_, parseDottedKey(key));
  if (!n) throw py::key_error("no vehicle key '" + key + "' (see Vehicle.keys())");
  return toPython(*n);
}

bool VehicleObject::contains(const std::string& key) const {
  return findNode(document_, parseDottedKey(key)) != nullptr;
}

void VehicleObject::set(const std::string& key, const py::handle& value) {
  toml::table changed = document_;
  setNode(changed, parseDottedKey(key), key, value);
  studies::ReadContext context;
  context.file = kPythonSource;
  // The file reader, exactly: the field table's type and range, the cross-checks, unknown keys.
  VehicleDefinition definition = studies::parseVehicleTable(changed, context, std::string());
  document_ = std::move(changed);
  keys_ = leafKeys(document_);
  const std::lock_guard<std::mutex> lock(*core_mutex_);  // coreModel() reads definition_ without the GIL
  definition_ = std::move(definition);
  core_.reset();
}

std::string VehicleObject::toToml() const { return studies::vehicleToToml(definition_); }

std::shared_ptr<const FlightCoreModel> VehicleObject::coreModel() const {
  const std::lock_guard<std::mutex> lock(*core_mutex_);
  if (!core_) core_ = std::make_shared<const FlightCoreModel>(definition_.model);
  return core_;
}

}  // namespace orni::python
