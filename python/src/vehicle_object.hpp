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
  void adopt(VehicleDefinition definition);

  VehicleDefinition definition_;  ///< the vehicle and its design point ([operating_point])
  toml::table document_;  ///< the resolved vehicle in file units and key names
  std::vector<std::string> keys_;
  std::string source_;    ///< the file it was read from
  mutable std::shared_ptr<const FlightCoreModel> core_;  ///< guarded by core_mutex_
  std::shared_ptr<std::mutex> core_mutex_ = std::make_shared<std::mutex>();
};

}  // namespace orni::python
