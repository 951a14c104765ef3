// Core's checks of a VehicleModel (the validation lives in the model, so every front end
// gets it; docs/design.md 7.6).
//
// Every field is checked in SI against the range of its entry in the field table
// (core/model/field_table.hpp, scaled to SI), and the rules that tie fields together are checked
// here and nowhere else: P3 on the root chord, the element size within the semispan and the
// flexible wing's mesh within kMaxWingMeshNodes, members inside the planform with known
// materials, the tail lighter than the vehicle, a flat flexible wing. A library user gets the
// same checks as the command line: FlightCoreModel's constructor calls requireValidVehicle
// (InvalidModelError, exit status 2 at the command line); the file readers call vehicleProblems
// and report each problem at the file, line and key it came from.
#pragma once

#include <string>
#include <vector>

#include "core/model/vehicle_model.hpp"

namespace orni {

/// Largest finite-element mesh of a wing (estimated nodes, estimatedMeshNodes): 25 times the
/// paper's mesh (1857 elements, ~1900 nodes on the magpie at h = 5 mm); 0.6 mm on the magpie
/// (135 000 nodes) took 50 s and 950 MB to build, smaller sizes run out of memory.
constexpr double kMaxWingMeshNodes = 50000.0;

/// Estimated node count of the wing's mesh at its element size: 2.2 nodes per h^2 of planform
/// (the station-sweep mesher: 1859 nodes on 882 h^2 for the magpie at h = 5 mm), within tens of
/// percent of the real count.
double estimatedMeshNodes(const WingModel& wing);

/// One violated rule: the file key of the field at fault (with indices and names:
/// "wing.members[2].end_xy_m", "materials.LE1.youngs_modulus_gpa"), what it must be and the value
/// found, both in file units.
struct ModelProblem {
  std::string key;
  std::string expected;
  std::string got;
  /// "key 'KEY': expected EXPECTED, got GOT".
  std::string message() const;
};

/// Every problem of `vehicle`, in the order of a vehicle file (empty = valid).
std::vector<ModelProblem> vehicleProblems(const VehicleModel& vehicle);

/// Every problem of a vehicle file's design point ([operating_point]; core never reads it).
std::vector<ModelProblem> designPointProblems(const OperatingPoint& design_point);

/// Every problem of a vehicle file's content: the vehicle's, then its design point's.
std::vector<ModelProblem> definitionProblems(const VehicleDefinition& definition);

/// Throws InvalidModelError("invalid vehicle: key '...': expected ..., got ...") for the first
/// problem of `vehicle`.
void requireValidVehicle(const VehicleModel& vehicle);

}  // namespace orni
