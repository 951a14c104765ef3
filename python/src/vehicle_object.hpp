// ornithopter.Vehicle: a vehicle as the file reader made it, its fields read and set by their file
// keys (v["tail.arm_m"] = 0.14). Every set re-reads the whole document with the file reader
// (parseVehicleTable), so a value is checked exactly as in a file (field table, cross-checks);
// a rejected value leaves the vehicle unchanged and raises ornithopter.InputError.
#pragma once

#include <pybind11/pybind11.h>
#include <toml++/toml.h>

#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "core/dynamics/flight_core.hpp"
#include "core/model/vehicle_model.hpp"

namespace orni::python {

class VehicleObject {
 public:
  /// Reads a vehicle file (loadVehicleFile: the CLI's reader). Throws InputError.
  static VehicleObject load(const std::string& path);

  /// A vehicle from a vehicle document: a dict in the file's key names and units
  /// (Vehicle.to_dict()'s form), checked by the file reader. Throws InputError ("<python>").
  static VehicleObject fromDict(const pybind11::dict& d, const std::string& source);
  /// A vehicle from vehicle-file text (pickle's state). Throws InputError.
  static VehicleObject fromToml(const std::string& text, const std::string& source);

  /// An independent copy (its own cache lock; the immutable core model is shared until a set).
  VehicleObject clone() const;

  /// The resolved vehicle document as nested dicts and lists (file key names and units).
  pybind11::dict toDict() const;
  /// (key, value) for every leaf key, in document order.
  pybind11::list items() const;
  std::size_t size() const { return keys_.size(); }
  std::string repr() const;

  pybind11::object get(const std::string& key) const;
  void set(const std::string& key, const pybind11::handle& value);
  std::vector<std::string> keys() const { return keys_; }
  bool contains(const std::string& key) const;
  /// The complete vehicle document (every default filled in) as TOML text, file units.
  std::string toToml() const;

  const VehicleModel& model() const { return definition_.model; }
  /// The vehicle as a TOML table (a study's inline [vehicle]).
  const toml::table& document() const { return document_; }
  const std::string& source() const { return source_; }
  /// The core model of this vehicle, built once per vehicle state (simulate reuses it); safe to
  /// call without the GIL from several threads.
  std::shared_ptr<const FlightCoreModel> coreModel() const;

 private:
  /// A vehicle from a vehicle document, read by the file reader (errors name "<python>").
  static VehicleObject fromTable(const toml::table& table, const std::string& source);
  void adopt(VehicleDefinition definition);

  VehicleDefinition definition_;  ///< the vehicle and its design point ([operating_point])
  toml::table document_;  ///< the resolved vehicle in file units and key names
  std::vector<std::string> keys_;
  std::string source_;    ///< the file it was read from
  mutable std::shared_ptr<const FlightCoreModel> core_;  ///< guarded by core_mutex_
  std::shared_ptr<std::mutex> core_mutex_ = std::make_shared<std::mutex>();
};

}  // namespace orni::python
