// Cross-code reference (docs/theory.md 2.7): the "mini-wing" plate with a leading-edge rod, against
// CalculiX 2.20 (S8R skin + B32R rod).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/structure/dof_partition.hpp"
#include "core/structure/fe_assembly.hpp"
#include "core/structure/modal_solver.hpp"
#include "tests/unit/structure/fe_test_meshes.hpp"

namespace orni::structure {
namespace {

// Different elements (DKT/CST + Euler-Bernoulli vs S8R + B32R expanded to solids, both without
// beam offset): measured -0.8 % ... +0.05 % on the first six modes with 20 x 20 x 2 facets.
constexpr double kCrossCodeTol = 0.015;

TEST(StructureFeCrossCode, MiniWingMatchesCalculixS8R) {
  // 100 x 100 mm plate, t = 0.04 mm, skin material (E 100 GPa, nu 0.31, rho 500), clamped along
  // x = 0; the LE1 rod (d 2 mm) along the free edge y = 0 from the clamp to x = 100 mm.
  constexpr int n = 20;
  WingMesh mesh = fe_test::plateGridMesh(0.1, 0.1, n, n);
  for (int i = 0; i < n; ++i)
    mesh.beams.push_back({{fe_test::gridNode(i, 0, n), fe_test::gridNode(i + 1, 0, n)}, 0});
  VehicleModel v = fe_test::skinVehicle(4e-5, 100e9, 0.31, 500.0);
  v.materials.push_back(fe_test::makeMaterial("LE1", 250e9, 0.31, 1800.0));
  v.wing.members.push_back(fe_test::makeMember("LE1", "LE1", 2e-3));
  const WingFeModel fe = assembleWingFe(v, mesh);
  std::vector<int> clamp;
  for (int j = 0; j <= n; ++j)
    for (int d = 0; d < kDofsPerNode; ++d)
      clamp.push_back(globalDof(fe_test::gridNode(0, j, n), d));
  const DofPartition part = makeDofPartition(fe.active, clamp);
  const EigenSolution sol =
      lowestEigenpairs(extractBlock(fe.stiffness, part.interior, part.interior),
                       extractBlock(fe.mass, part.interior, part.interior), 6);
  ASSERT_TRUE(sol.success) << sol.message;
  const double ccx_hz[6] = {18.99, 65.50, 73.09, 131.0, 172.0, 180.2};
  double worst = 0.0;
  for (int k = 0; k < 6; ++k) {
    const double f = std::sqrt(sol.eigenvalues(k)) / (2 * fe_test::kTestPi);
    worst = std::max(worst, std::abs(f / ccx_hz[k] - 1));
    EXPECT_NEAR(f / ccx_hz[k], 1.0, kCrossCodeTol) << "mode " << k + 1 << ": " << f << " Hz";
  }
  fe_test::recordError("ccx_s8r_max_rel_diff", worst);
}

}  // namespace
}  // namespace orni::structure
