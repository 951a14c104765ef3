// Reading CalculiX 2.20 results back (docs/theory.md 2.7): the displacement tables that *NODE PRINT
// writes to JOB.dat, mapped to the nodes of our mesh (mesh node i is CalculiX node i + 1; the
// deck's midside nodes follow, calculix_deck.hpp). Units as in the deck: mm.
#pragma once

#include <istream>
#include <map>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace orni::structure {

/// One "displacements (vx,vy,vz) for set NAME and time T" table of a .dat file.
struct CalculixDisplacementTable {
  std::string set;    ///< the NSET of *NODE PRINT, as ccx prints it (upper case)
  double time = 0.0;  ///< ccx's total time at the end of the increment (step k of a
                      ///< calculixDeck load sweep ends at time k)
  std::map<int, Eigen::Vector3d> displacement_mm;  ///< CalculiX node id -> (vx, vy, vz) in mm
};

/// Every displacement table of a .dat text, in file order (ccx writes one per converged increment
/// of a static step). Tables of other quantities (stresses, eigenvalues, ...) are skipped. Throws
/// std::runtime_error on a malformed displacement line.
std::vector<CalculixDisplacementTable> readCalculixDisplacements(std::istream& dat);
/// The same from a file; throws std::runtime_error if it cannot be opened.
std::vector<CalculixDisplacementTable> readCalculixDisplacementFile(const std::string& path);

/// The last table at total time `time` (within 1e-6), or nullptr (the step did not finish).
const CalculixDisplacementTable* calculixTableAt(const std::vector<CalculixDisplacementTable>& tables,
                                                 double time);

/// The translations of our mesh nodes in metres, 3 x mesh_node_count (column i = mesh node i =
/// CalculiX node i + 1); NaN for a node the table does not hold. Midside nodes are dropped.
Eigen::Matrix3Xd meshDisplacements(const CalculixDisplacementTable& table, int mesh_node_count);

}  // namespace orni::structure
