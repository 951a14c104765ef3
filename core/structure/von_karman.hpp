// Geometric nonlinearity of the wing's finite-element model: von Karman (moderate-rotation)
// strains of the skin's membrane and the members' axial stretch (docs/theory.md 4.7).
//
//   skin facet:  eps = B_m d + eta(w),  eta = 1/2 (w_x^2, w_y^2, 2 w_x w_y),
//   member:      eps = x'.du / L + 1/2 |P du|^2 / L^2   (du = u_2 - u_1, P = I - x' x'^T),
//
// with the facet-normal displacement w interpolated linearly over the facet (its gradient is
// constant per facet, as in the membrane-stress geometric stiffness of docs/theory.md 4.6) and the
// member's transverse displacement linearly along the element (chord slope). The linear parts are
// the assembled K (CST membrane, DKT plate, Euler-Bernoulli beams): this file adds only what is
// nonlinear in the displacements,
//   Pi_NL(u) = sum_facets A [(B_m d)^T C eta + 1/2 eta^T C eta] + sum_members EA L [eps0 eta + 1/2 eta^T eta],
// C = E t / (1 - nu^2) [1 nu 0; nu 1 0; 0 0 (1 - nu)/2], so that the full internal force is
// K u + grad Pi_NL(u) and the tangent K + hess Pi_NL(u). A skin pretension is not here: it is a
// constant membrane stress whose geometric stiffness is part of K (modal_wing.cpp).
//
// Why von Karman and not a full large-rotation (co-rotational or total Lagrangian) shell: the
// wing rotates rigidly with the floating frame W (docs/theory.md 4.1), so the elastic rotations are
// moderate (the stiffened chord's slopes are of order 0.1), where von Karman's strain is the
// consistent second-order approximation; it separates the flat wing's in-plane and out-of-plane
// unknowns, which makes the exact static condensation of the membrane in the modal model possible
// (membrane_rom.hpp). Checked against CalculiX with NLGEOM (a full large-rotation solution). Where
// parts of the wing rotate by more than ~10 deg it errs by the rotations' higher powers (2.8 % at
// 14 deg, 10.5 % at 26 deg on a cantilever): the co-rotational wing (corotational.hpp) is the
// static reference there.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/structure/dof_partition.hpp"
#include "core/structure/fe_assembly.hpp"
#include "core/structure/fe_types.hpp"
#include "core/structure/static_nonlinearity.hpp"
#include "core/structure/tension_field.hpp"
#include "core/structure/wing_mesh.hpp"
#include "core/structure/wing_structure.hpp"

namespace orni::structure {

/// Which transverse displacement of a member enters its quadratic strain 1/2 |P du|^2 / L^2.
enum class MemberStretch {
  /// Both transverse components (P = I - x' x'^T): a member's in-plane rotation stretches it at
  /// second order as its out-of-plane one does. The default: what a large-rotation code (CalculiX
  /// NLGEOM) has, and it matters on the EFW (below).
  kBothTransverse,
  /// The out-of-plane component only (P = n n^T, n the normal of the flat wing, z_W): von
  /// Karman's ordering, in which in-plane rotations are second order and their squares dropped,
  /// as they are for the skin's facets. The modal condensation (membrane_rom.hpp) is exact for
  /// this model, not for the default. Measured on the literal EFW under 53 Pa of lift: mid-span
  /// trailing edge 36.2 mm with it against 29.3 mm with the default, tip 19.1 against 17.3 mm:
  /// the in-plane relaxation turns the stiff members in the plane (slopes of 1-6 %), which the
  /// default charges at E A and this ordering does not.
  kOutOfPlaneOnly,
};

/// The skin's membrane law.
enum class SkinMembrane {
  /// Linear elastic in the von Karman strain, compression included: the membrane of a plate
  /// that does not buckle. The modal condensation (membrane_rom.hpp) is exact for it.
  kElastic,
  /// Tension field (tension_field.hpp): the relaxed energy of a film that wrinkles instead of
  /// carrying compression, with a residual fraction kappa of the elastic energy.
  kTensionField,
};

/// The per-element data of the nonlinear strain terms, built once from a mesh.
class VonKarmanTerms final : public StaticNonlinearity {
 public:
  /// `film` is the tension field's law (kappa, compression cap; ignored for kElastic). Throws
  /// std::invalid_argument for a tension field with a skin pretension (a film shrunk onto the
  /// frame, skin_pretension.hpp: its strain is not measured from the flat mesh, not built yet)
  /// or an invalid law (FilmLaw::IsValid).
  VonKarmanTerms(const WingStructure& wing_structure, const WingMesh& mesh,
                 MemberStretch member_stretch = MemberStretch::kBothTransverse,
                 SkinMembrane skin_membrane = SkinMembrane::kElastic,
                 const FilmLaw& film = {});

  int dofCount() const override { return dof_count_; }

  /// grad Pi_NL at the displacement u (6n): the internal force beyond K u (N, N m).
  Eigen::VectorXd internalForce(const Eigen::VectorXd& u) const override;
  /// Pi_NL(u) (J).
  double energy(const Eigen::VectorXd& u) const override;
  /// hess Pi_NL at u (6n x 6n, symmetric, translational DOFs only): the tangent beyond K.
  SparseMatrix tangent(const Eigen::VectorXd& u) const override;

  /// Membrane force resultants of the skin facets at u, (N_xx, N_yy, N_xy) per facet in its
  /// triad (N/m), the linear part C B_m d included (the relaxed stress of a tension field):
  /// 3 x facets.
  Eigen::Matrix3Xd membraneForces(const Eigen::VectorXd& u) const;
  /// The state of each skin facet's film at u (every facet taut for the elastic law).
  std::vector<FilmState> facetStates(const Eigen::VectorXd& u) const;

  // Element data, read by the modal condensation (membrane_rom.cpp).
  struct Facet {
    std::array<int, 3> nodes{};
    Mat3 triad;                          ///< rows e1, e2, n in W
    Eigen::Matrix<double, 2, 3> grad;    ///< gradients of the linear shape functions (1/m)
    Eigen::Matrix<double, 3, 6> b_m;     ///< CST strain matrix on (u1 v1 u2 v2 u3 v3) local
    double area_m2 = 0.0;
  };
  struct Member {
    std::array<int, 2> nodes{};
    Vec3 axis;                  ///< x' (W)
    Mat3 transverse;            ///< P: the projection on the transverse directions that stretch
    double length_m = 0.0;
    double axial_stiffness_n = 0.0;  ///< EA (N)
  };
  const std::vector<Facet>& facets() const { return facets_; }
  const std::vector<Member>& members() const { return members_; }
  const Mat3& membraneStiffness() const { return c_t_; }  ///< C (N/m)

 private:
  /// The skin's membrane law at the membrane strain eps: energy per area, stress and (with
  /// kWithTangent) tangent.
  RelaxedMembrane skinLaw(const Vec3& strain,
                          FilmOutput output = FilmOutput::kWithTangent) const;

  int dof_count_ = 0;
  std::vector<Facet> facets_;
  std::vector<Member> members_;
  Mat3 c_t_ = Mat3::Zero();
  SkinMembrane skin_membrane_ = SkinMembrane::kElastic;
  double skin_et_n_per_m_ = 0.0;  ///< E t of the skin
  double skin_nu_ = 0.0;
  FilmLaw film_;
};

/// The strain measures of the nonlinear static wing.
enum class StrainKinematics {
  kVonKarman,     ///< moderate rotations (this file): what the modal condensation reduces
  kCoRotational,  ///< large rotations (corotational.hpp): the reference where parts of the
                  ///< wing rotate by more than about 10 deg (FeVonKarmanValidity)
};

struct NonlinearStaticOptions {
  bool nonlinear = true;         ///< false: the linear solution K u = F (for comparison)
  int load_steps = 8;            ///< load increments, geometric from 1 % to the full load
  int max_newton_iterations = 60;  ///< per increment
  double force_tolerance = 1e-8;   ///< converged: |residual| <= tol * |F| on the free DOFs,
  double displacement_tolerance = 1e-10;  ///< or a Newton correction <= tol * |u|
  /// The skin's membrane law; read by solveWingStatic, which builds the terms (solveNonlinearStatic
  /// takes them built).
  SkinMembrane skin_membrane = SkinMembrane::kElastic;
  FilmLaw film;  ///< the tension field's law (with kTensionField)
  /// Read by solveWingStatic: the von Karman terms or the co-rotational wing (whose rotation
  /// DOFs in the result are rotation vectors of the nodes' total rotations).
  StrainKinematics kinematics = StrainKinematics::kVonKarman;
  bool IsValid(std::string* why) const;
};

struct NonlinearStaticResult {
  Eigen::VectorXd displacement;  ///< 6n, zero on the held and inactive DOFs (m, rad)
  bool converged = false;
  int newton_iterations = 0;     ///< over all increments
  double residual_ratio = 0.0;   ///< final |residual| / |F|
  std::string message;           ///< why not converged
};

/// Solves K u + grad Pi_NL(u) = F on the retained DOFs of `part` (interior and free boundary;
/// the clamped DOFs held at zero) by Newton's method with load increments and an Armijo line
/// search on the total potential energy. `stiffness` is the assembled (possibly prestressed) K.
NonlinearStaticResult solveNonlinearStatic(const SparseMatrix& stiffness,
                                           const StaticNonlinearity& terms, const DofPartition& part,
                                           const Eigen::VectorXd& load,
                                           const NonlinearStaticOptions& options = {});

/// The whole static chain for a wing: assembly (with the skin pretension of wing.skin,
/// skin_pretension.hpp), the
/// support of wing.fe, the terms, the solve.
NonlinearStaticResult solveWingStatic(const WingStructure& wing_structure, const WingMesh& mesh,
                                      const WingSupport& support, const Eigen::VectorXd& load,
                                      const NonlinearStaticOptions& options = {});

}  // namespace orni::structure
