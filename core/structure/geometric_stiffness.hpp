// Geometric (stress) stiffness of the wing under its own inertial loads (docs/theory.md 4.6, the
// "cheap fix" after Wallrapp & Schwertassek 1991 / SID): for each parameter p_i of the inertial
// body-force field in W, the static stresses of the unit field and their modal geometric
// stiffness K^_G,i = Phi^T K_G(sigma_i) Phi, so that at run time K_G(p) = sum_i p_i K^_G,i.
//
// The body force per unit mass at a point x (from P2, W components) of a wing whose frame W has
// origin acceleration a_O, angular velocity w and angular acceleration alpha, in gravity g_W, is
//   b(x) = -[(a_O - g_W) + alpha x x + w x (w x x)],
// linear in the 12 parameters p = ((a_O - g_W)_x,y,z, alpha_x,y,z, w_x^2, w_y^2, w_z^2, w_x w_y,
// w_x w_z, w_y w_z). The nodal load of parameter i is F_i = -M a_i with the consistent mass M and
// the nodal acceleration field a_i of the unit parameter (translations; the rotational slots carry
// alpha, the angular acceleration of every node's rotary inertia, as in the invariants L, H and
// S_kl of docs/theory.md 3.6).
//
// Stresses: beam axial force N = EA/L x'.(u_2 - u_1) (tension positive, constant per element);
// skin membrane force N = t C B_m u (CST, constant per facet). Geometric stiffness: the beam matrix
// of docs/theory.md 2.2 in both bending planes plus the Wagner torsion term N I_p / (A L); the
// skin's membrane-stress plate matrix A grad(N_w)^T [[Nxx, Nxy], [Nxy, Nyy]] grad(N_w) on the
// facet's normal displacement with linear interpolation (docs/theory.md 4.6).
#pragma once

#include <array>
#include <vector>

#include "core/structure/wing_structure.hpp"
#include "core/structure/dof_partition.hpp"
#include "core/structure/fe_assembly.hpp"
#include "core/structure/fe_types.hpp"
#include "core/structure/wing_mesh.hpp"

namespace orni::structure {

/// The parameters p_i of the inertial body-force field (docs/theory.md 4.6), in this order.
enum InertialLoad : int {
  kLoadAccelX = 0,  ///< (a_O - g_W)_x, m/s^2
  kLoadAccelY,      ///< (a_O - g_W)_y
  kLoadAccelZ,      ///< (a_O - g_W)_z
  kLoadAlphaX,      ///< alpha_x, rad/s^2
  kLoadAlphaY,      ///< alpha_y
  kLoadAlphaZ,      ///< alpha_z
  kLoadSpinXX,      ///< w_x^2, (rad/s)^2
  kLoadSpinYY,      ///< w_y^2
  kLoadSpinZZ,      ///< w_z^2
  kLoadSpinXY,      ///< w_x w_y
  kLoadSpinXZ,      ///< w_x w_z
  kLoadSpinYZ,      ///< w_y w_z
};
constexpr int kInertialLoadCount = 12;

/// The spin parameter of the product w_k w_l (k, l in 0..2, either order).
InertialLoad spinLoad(int k, int l);

/// Nodal acceleration fields of the unit parameters (6n x 12, column i = a_i, W components):
/// translational slots (a_O - g_W) = e_k, alpha x x = e_k x x, w x (w x x) for the unit product
/// (e_k x_k - x for w_k^2; e_k x_l + e_l x_k for w_k w_l, k != l); rotational slots e_k for
/// alpha_k, else zero. x is taken from `origin_W_m` (P2).
Eigen::MatrixXd unitInertialAccelerations(const std::vector<Vec3>& nodes_W_m,
                                          const Vec3& origin_W_m);

/// Static solutions of the unit inertial loads with the fixed-interface boundary conditions.
struct UnitInertialLoadSolution {
  Eigen::MatrixXd loads;          ///< 6n x 12: F_i = -M a_i (N, N m per unit parameter)
  Eigen::MatrixXd displacements;  ///< 6n x 12: K u_i = F_i on the free DOFs (interior and b_f),
                                  ///< zero on the clamped and inactive DOFs (m, rad); zero for
                                  ///< the loads not solved (see `solved`)
  bool flat = false;              ///< every node in the plane z_W = z_W(P2)
  std::array<bool, kInertialLoadCount> solved{};  ///< load i solved (all unless flat)
};

/// True for the loads whose field lies in the plane of a flat wing: (a_O - g_W)_x, _y, alpha_z,
/// w_x^2, w_y^2, w_z^2, w_x w_y.
bool isInPlaneLoad(InertialLoad load);

/// Solves K u_i = F_i for the unit loads with the clamped DOFs of `part` held (one sparse
/// L D L^T over the free DOFs). For a flat wing (every node at z_W = z_W(P2)) K and M do not
/// couple the in-plane DOFs (u, v, theta_z) with the others, and the out-of-plane loads bend the
/// wing without membrane stress: only the in-plane block is factored, for the seven in-plane
/// loads (about a third of the DOFs; the other loads' displacements stay zero). Throws
/// std::runtime_error if K is singular there.
UnitInertialLoadSolution solveUnitInertialLoads(const WingFeModel& fe, const DofPartition& part,
                                                const std::vector<Vec3>& nodes_W_m,
                                                const Vec3& origin_W_m);

/// Element stress resultants of displacement fields (one column per field).
struct ElementStresses {
  Eigen::MatrixXd beam_axial_force_N;       ///< (beams) x fields, tension positive
  Eigen::MatrixXd skin_membrane_force_Npm;  ///< (3 facets) x fields: rows 3f .. 3f + 2 =
                                            ///< (N_xx, N_yy, N_xy) of facet f in its triad, N/m
};

/// Recovers beam axial forces and skin membrane forces from displacement fields (6n x fields).
ElementStresses recoverElementStresses(const WingStructure& wing_structure, const WingMesh& mesh,
                                       const Eigen::MatrixXd& displacements);

/// Membrane-stress plate geometric stiffness of a facet (18 x 18, W components) for the membrane
/// forces (N_xx, N_yy, N_xy) in the facet triad (N/m): A G^T [[N_xx, N_xy], [N_xy, N_yy]] G on
/// the facet-normal displacements, G the gradients of the linear shape functions.
Mat18 shellMembraneGeometricStiffness(const std::array<Vec3, 3>& x_W_m,
                                      const Vec3& membrane_force_Npm);

/// Global geometric stiffness (6n x 6n, full symmetric) of one stress state: column `field` of
/// `stresses`. The reference assembly (tests); the modal wing uses the projected form below.
SparseMatrix assembleGeometricStiffness(const WingStructure& wing_structure, const WingMesh& mesh,
                                        const ElementStresses& stresses, int field,
                                        const FeAssemblyOptions& options = {});

/// K^_G,i = Phi^T K_G,i Phi (M x M, symmetric) for the 12 unit inertial loads.
struct ModalGeometricStiffness {
  std::array<Eigen::MatrixXd, kInertialLoadCount> per_load;

  bool empty() const { return per_load[0].size() == 0; }
  const Eigen::MatrixXd& operator[](InertialLoad i) const {
    return per_load[static_cast<std::size_t>(i)];
  }
};

/// Projects the geometric stiffness of every column of `stresses` on `shapes` (6n x M) without
/// assembling it: per beam element Phi_e^T K_G,e(N = 1) Phi_e weighted by N, per facet the modal
/// gradients of the normal displacement weighted by the membrane forces.
std::vector<Eigen::MatrixXd> projectGeometricStiffness(const WingStructure& wing_structure,
                                                       const WingMesh& mesh,
                                                       const ElementStresses& stresses,
                                                       const Eigen::MatrixXd& shapes,
                                                       const FeAssemblyOptions& options = {});

/// The whole chain: unit loads, static solutions, stresses, projection on `shapes` (6n x M).
ModalGeometricStiffness modalGeometricStiffness(const WingStructure& wing_structure, const WingMesh& mesh,
                                                const WingFeModel& fe, const DofPartition& part,
                                                const Eigen::MatrixXd& shapes,
                                                const FeAssemblyOptions& options = {});

}  // namespace orni::structure
