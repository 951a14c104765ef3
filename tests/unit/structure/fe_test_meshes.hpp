// Small meshes and vehicles built by hand for the structural FE tests (independent of the
// station-sweep mesher): a straight beam chain, a rectangular plate triangulated in a grid, and a
// mini-wing (plate + leading-edge rod + diagonal rod).
#pragma once

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/model/vehicle_model.hpp"
#include "core/structure/fe_types.hpp"
#include "core/structure/wing_mesh.hpp"

namespace orni::structure::fe_test {

constexpr double kTestPi = 3.14159265358979323846;

/// Records a measured error in the test's XML output (--gtest_output=xml) for reports.
inline void recordError(const char* name, double value) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3e", value);
  ::testing::Test::RecordProperty(name, buf);
}

inline Material makeMaterial(const char* name, double e, double nu, double rho) {
  Material m;
  m.name = name;
  m.youngs_modulus_pa = e;
  m.poisson_ratio = nu;
  m.density_kgpm3 = rho;
  return m;
}

inline WingMember makeMember(const char* name, const char* material, double d,
                             const Vec3& a = Vec3::Zero(), const Vec3& b = Vec3::Zero()) {
  WingMember m;
  m.name = name;
  m.material = material;
  m.diameter_m = d;
  m.start_x_W_m = a.x();
  m.start_y_W_m = a.y();
  m.end_x_W_m = b.x();
  m.end_y_W_m = b.y();
  return m;
}

/// Vehicle with the paper's LE1 rod (member 0: E 250 GPa, nu 0.31, rho 1800, d 2 mm).
inline VehicleModel le1RodVehicle() {
  VehicleModel v;
  v.materials.push_back(makeMaterial("LE1", 250e9, 0.31, 1800.0));
  v.wing.members.push_back(makeMember("LE1", "LE1", 2e-3));
  return v;
}

/// Straight chain of `elements` beam elements from the origin along `direction`, member 0;
/// P2 = node 0 (the clamp), no P3.
inline WingMesh beamChainMesh(int elements, double length_m,
                              const Vec3& direction = Vec3::UnitY()) {
  WingMesh mesh;
  const Vec3 e = direction.normalized();
  for (int i = 0; i <= elements; ++i)
    mesh.nodes_W_m.push_back((length_m * i / elements) * e);
  for (int i = 0; i < elements; ++i) mesh.beams.push_back({{i, i + 1}, 0});
  mesh.p2_node = 0;
  return mesh;
}

/// Node id of grid point (i, j) of a plate grid with nx x ny cells.
inline int gridNode(int i, int j, int nx) { return j * (nx + 1) + i; }

/// Rectangle [x0, x0 + a] x [y0, y0 + b] in the (x_W, y_W) plane, nx x ny cells, each cell split
/// into two counter-clockwise triangles (alternating diagonals if `alternate`).
inline WingMesh plateGridMesh(double a, double b, int nx, int ny, double x0 = 0.0,
                              double y0 = 0.0, bool alternate = false) {
  WingMesh mesh;
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i)
      mesh.nodes_W_m.emplace_back(x0 + a * i / nx, y0 + b * j / ny, 0.0);
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int n00 = gridNode(i, j, nx), n10 = gridNode(i + 1, j, nx);
      const int n01 = gridNode(i, j + 1, nx), n11 = gridNode(i + 1, j + 1, nx);
      if (alternate && (i + j) % 2 == 1) {
        mesh.triangles.push_back({n00, n10, n01});
        mesh.triangles.push_back({n10, n11, n01});
      } else {
        mesh.triangles.push_back({n00, n10, n11});
        mesh.triangles.push_back({n00, n11, n01});
      }
    }
  return mesh;
}

/// Vehicle with only a skin (for plate tests).
inline VehicleModel skinVehicle(double thickness_m, double e, double nu, double rho) {
  VehicleModel v;
  v.materials.push_back(makeMaterial("SKIN", e, nu, rho));
  v.wing.skin.material = "SKIN";
  v.wing.skin.thickness_m = thickness_m;
  return v;
}

/// Mini-wing in the EFW materials: a chord x span = c x s plate, x_W in [-c, 0] (leading edge at
/// x_W = 0), y_W in [0, s], nx x ny cells; member 0 = LE1 rod along the leading edge, member 1 a
/// 0.4 mm rod on the grid diagonal from the root-chord node P3 (x = -c/2) outboard; P2 at the
/// root leading edge. nx must be even.
struct MiniWing {
  VehicleModel vehicle;
  WingMesh mesh;
};

inline MiniWing miniWing(int nx = 4, int ny = 8, double c = 0.04, double s = 0.08) {
  MiniWing w;
  VehicleModel& v = w.vehicle;
  v.materials.push_back(makeMaterial("LE1", 250e9, 0.31, 1800.0));
  v.materials.push_back(makeMaterial("ROD", 175e9, 0.31, 500.0));
  v.materials.push_back(makeMaterial("SKIN", 100e9, 0.31, 500.0));
  v.wing.skin.material = "SKIN";
  v.wing.skin.thickness_m = 4e-5;
  v.wing.members.push_back(makeMember("LE1", "LE1", 2e-3, Vec3(0, 0, 0), Vec3(0, s, 0)));
  v.wing.members.push_back(makeMember("STIF", "ROD", 4e-4));
  w.mesh = plateGridMesh(c, s, nx, ny, -c, 0.0);
  for (int j = 0; j < ny; ++j)
    w.mesh.beams.push_back({{gridNode(nx, j, nx), gridNode(nx, j + 1, nx)}, 0});
  // Diagonal stiffener from P3 = (nx/2, 0) towards the trailing edge; the grid diagonals of
  // plateGridMesh (non-alternating) run from (i, j) to (i + 1, j + 1), i.e. towards the LE, so
  // use them from P3 to the leading edge.
  const int p3 = gridNode(nx / 2, 0, nx);
  for (int k = 0; k < nx / 2; ++k)
    w.mesh.beams.push_back({{gridNode(nx / 2 + k, k, nx), gridNode(nx / 2 + k + 1, k + 1, nx)}, 1});
  v.wing.members[1].start_x_W_m = -c / 2;
  v.wing.members[1].end_x_W_m = 0.0;
  v.wing.members[1].end_y_W_m = s * (nx / 2) / ny;
  w.mesh.p2_node = gridNode(nx, 0, nx);
  w.mesh.p3_node = p3;
  return w;
}

}  // namespace orni::structure::fe_test
