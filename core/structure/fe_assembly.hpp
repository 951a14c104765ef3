// Assembly of the wing finite-element model from (WingStructure, WingMesh) (docs/theory.md 2.6):
// sparse K and M over 6 DOF per node, the DOF activity mask (docs/theory.md 2.4) and the boundary
// DOF set of the fixed-interface problem (docs/theory.md 2.6).
#pragma once

#include <vector>

#include "core/structure/wing_structure.hpp"
#include "core/structure/beam_element.hpp"
#include "core/structure/fe_types.hpp"
#include "core/structure/shell_element.hpp"
#include "core/structure/wing_mesh.hpp"

namespace orni::structure {

struct FeAssemblyOptions {
  MassLumping mass = MassLumping::kConsistent;
  /// Beam orientation vector n (local z' axis): the wing normal z_W for in-plane members.
  Vec3 beam_orientation_W = Vec3::UnitZ();
};

/// The assembled model. K and M are full symmetric (both triangles stored), 6n x 6n, W components.
struct WingFeModel {
  int node_count = 0;
  SparseMatrix stiffness;       ///< K (N/m, N, N m)
  SparseMatrix mass;            ///< M (kg, kg m, kg m^2)
  std::vector<bool> active;     ///< per global DOF: false for drilling DOFs of skin-only nodes
                                ///< and for every DOF of a node no element touches
  double member_mass_kg = 0.0;  ///< sum of rho A L over beam elements
  double skin_mass_kg = 0.0;    ///< sum of rho t A over facets

  int dofCount() const { return kDofsPerNode * node_count; }
  double totalMass_kg() const { return member_mass_kg + skin_mass_kg; }
};

/// Section and material of every member (index = member), solid rods of wing.memberDiameter.
/// Throws std::invalid_argument for a material not in [materials].
std::vector<BeamProperties> memberBeamProperties(const WingStructure& wing_structure);

/// The skin's shell properties. Throws std::invalid_argument for a missing material or a
/// thickness <= 0.
ShellProperties skinShellProperties(const WingStructure& wing_structure);

/// Assembles K and M by triplets. Throws std::invalid_argument for a missing material, a bad
/// member index, a node index out of range or a non-positive skin thickness when facets exist.
WingFeModel assembleWingFe(const WingStructure& wing_structure, const WingMesh& mesh,
                           const FeAssemblyOptions& options = {});

/// Activity mask (docs/theory.md 2.4): theta_z inactive at nodes no beam touches; all six DOF
/// inactive at nodes no element touches.
std::vector<bool> dofActivityMask(const WingMesh& mesh);

/// Cross axis n_u of the universal joint at P3 (docs/theory.md 2.6).
enum class UniversalJointCrossAxis {
  kZW,  ///< default: rotation about z_W (theta_z at P3) constrained
  kYW,  ///< alternative: rotation about y_W (theta_y at P3) constrained
};

/// How the wing is held besides the clamped hinge node P2 (docs/theory.md 2.6).
struct WingSupport {
  P3Joint p3_joint = P3Joint::kUniversal;
  UniversalJointCrossAxis p3_cross_axis = UniversalJointCrossAxis::kZW;  ///< universal joint only
  bool root_edge_pinned = false;  ///< every root-chord node (y_W = 0) held in translation
  /// The support a vehicle's wing.fe settings describe.
  static WingSupport of(const WingFeSettings& fe);
};

/// Boundary DOFs of the fixed-interface problem, ascending global ids: P2 all six, P3 u, v, w and
/// the rotations its joint holds (docs/theory.md 2.6; the universal joint: the one about n_u), and
/// with root_edge_pinned u, v, w of every node on y_W = 0. A node index < 0 is skipped (test
/// meshes).
std::vector<int> wingBoundaryDofs(const WingMesh& mesh, const WingSupport& support = {});

/// The rotation DOFs (kThetaX, kThetaY, kThetaZ) the joint at P3 holds.
std::vector<int> p3HeldRotations(const WingSupport& support);

/// Mesh nodes on the root chord (y_W = 0), ascending.
std::vector<int> rootChordNodes(const WingMesh& mesh);

/// Lumped nodal mass: translational mass per node (kg) and the rotational 3 x 3 block per node
/// (kg m^2, W components), identical to the lumped assembled M (which is block diagonal).
struct LumpedNodalMass {
  Eigen::VectorXd mass_kg;
  std::vector<Mat3> rotary_W_kgm2;
};
LumpedNodalMass lumpedNodalMass(const WingStructure& wing_structure, const WingMesh& mesh,
                                const Vec3& beam_orientation_W = Vec3::UnitZ());

}  // namespace orni::structure
