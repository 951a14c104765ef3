// CalculiX .dat displacement reader (docs/theory.md 2.7). See calculix_results.hpp.
#include "core/structure/calculix_results.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace orni::structure {
namespace {

constexpr double kMPerMm = 1e-3;

// " displacements (vx,vy,vz) for set NPRINT and time  0.1000000E+01"
bool parseHeader(const std::string& line, CalculixDisplacementTable* table) {
  const std::string tag = "displacements (vx,vy,vz) for set ";
  const std::size_t start = line.find(tag);
  if (start == std::string::npos) return false;
  std::istringstream in(line.substr(start + tag.size()));
  std::string set, and_word, time_word;
  double time = 0.0;
  if (!(in >> set >> and_word >> time_word >> time) || and_word != "and" || time_word != "time")
    throw std::runtime_error("CalculiX .dat: cannot read the table header '" + line + "'");
  table->set = set;
  table->time = time;
  return true;
}

bool blank(const std::string& line) {
  return line.find_first_not_of(" \t\r") == std::string::npos;
}

}  // namespace

std::vector<CalculixDisplacementTable> readCalculixDisplacements(std::istream& dat) {
  std::vector<CalculixDisplacementTable> tables;
  std::string line;
  bool in_table = false, seen_row = false;
  while (std::getline(dat, line)) {
    CalculixDisplacementTable header;
    if (parseHeader(line, &header)) {
      tables.push_back(std::move(header));
      in_table = true;
      seen_row = false;
      continue;
    }
    if (!in_table) continue;
    if (blank(line)) {
      // One blank line between the header and the rows; a blank line after rows ends the table.
      if (seen_row) in_table = false;
      continue;
    }
    std::istringstream in(line);
    int id = 0;
    double vx = 0.0, vy = 0.0, vz = 0.0;
    if (!(in >> id)) {  // another table's header (e.g. stresses): the displacements ended
      in_table = false;
      continue;
    }
    if (!(in >> vx >> vy >> vz))
      throw std::runtime_error("CalculiX .dat: cannot read the displacement line '" + line + "'");
    tables.back().displacement_mm[id] = Eigen::Vector3d(vx, vy, vz);
    seen_row = true;
  }
  return tables;
}

std::vector<CalculixDisplacementTable> readCalculixDisplacementFile(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("CalculiX .dat: cannot open '" + path + "'");
  return readCalculixDisplacements(in);
}

const CalculixDisplacementTable* calculixTableAt(const std::vector<CalculixDisplacementTable>& tables,
                                                 double time) {
  const CalculixDisplacementTable* found = nullptr;
  for (const CalculixDisplacementTable& t : tables)
    if (std::abs(t.time - time) <= 1e-6 * std::max(1.0, std::abs(time))) found = &t;
  return found;
}

Eigen::Matrix3Xd meshDisplacements(const CalculixDisplacementTable& table, int mesh_node_count) {
  Eigen::Matrix3Xd u = Eigen::Matrix3Xd::Constant(3, mesh_node_count,
                                                  std::numeric_limits<double>::quiet_NaN());
  for (const auto& [id, v] : table.displacement_mm)
    if (id >= 1 && id <= mesh_node_count) u.col(id - 1) = kMPerMm * v;
  return u;
}

}  // namespace orni::structure
