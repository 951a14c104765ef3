// The wing's finite-element model with large rotations: a co-rotational (total Lagrangian in the
// membrane) formulation of the same facets and members, for static answers where parts of the
// wing rotate by tens of degrees (docs/theory.md 4.7, "Large rotations").
//
// The von Karman strains (von_karman.hpp) keep the squares of the slopes and drop the higher
// powers of the rotations: on a cantilever they err by 2.8 % at a 14 deg tip rotation and 10.5 %
// at 26 deg (FeVonKarmanValidity), and the literal EFW at the Table-3 load rotates its skin by
// 25-50 deg. Here each element's rigid rotation is taken out exactly and its small local strains
// keep the existing laws:
//
//   skin facet (CST membrane + DKT plate): the membrane strain is Green's, E = 1/2 (G^T G - I)
//     with G (3 x 2) the gradient of the current positions in the facet's initial local
//     coordinates (exact for any rotation; the skin's law, elastic or the wrinkling film,
//     takes E); the facet's current triad is the rotation of the polar decomposition of G, and
//     the DKT's nodal rotations are the tilts of the nodes' directors d_i = R(psi_i) n_0 in it,
//     theta = (-d_y, d_x) asin(|d_xy|) / |d_xy| (no drilling, as in the linear facet);
//   member (Euler-Bernoulli beam): the chord's length change is the axial strain, the current
//     triad is the chord with the mean of the nodes' rotated z' axes (Crisfield's element frame),
//     and the nodal rotations relative to it, log(Lambda R(psi_i) Lambda_0^T), are the local
//     bending and torsion rotations.
//
// Each element's energy is its linear local energy in these deformational quantities, so the
// model equals the linear one to first order (its tangent at u = 0 is the assembled K) and is
// exactly invariant under rigid motions of any size. A node's rotation DOFs (theta_x, theta_y,
// theta_z) are read as the rotation vector psi of its total rotation, R = exp([psi]x): exact
// for the dead loads of a static solve, singular only at 180 deg. The gradient of every element
// energy is exact (forward-mode dual numbers, dual_number.hpp); the tangent is exact in the
// membrane and the bending's first-order part, or, on request, the central difference of the
// gradient (FacetTangent): Newton's convergence rate, not its answer, depends on it.
// A skin pretension is not built here (its prestressed K is the linear wing's).
#pragma once

#include <array>
#include <vector>

#include <Eigen/Core>

#include "core/structure/static_nonlinearity.hpp"
#include "core/structure/tension_field.hpp"
#include "core/structure/von_karman.hpp"
#include "core/structure/wing_mesh.hpp"
#include "core/structure/wing_structure.hpp"

namespace orni::structure {

/// How the skin facets' part of the tangent is formed (the members' is always differenced).
enum class FacetTangent {
  /// Exact in the membrane (the law's tangent and the membrane stresses' geometric stiffness,
  /// analytic) and in the bending's first-order part J_b^T K_b J_b; without the bending moments'
  /// own geometric term (the moments times the second derivatives of the nodal rotations, of the
  /// order of the local rotations against the bending stiffness: a thin skin's is far below its
  /// membrane's). One dual-number pass per facet. Newton's rate, not its answer, depends on it.
  kMembraneExact,
  /// Central differences of the exact gradient: every term, 36 passes per facet.
  kDifferences,
};

class CoRotationalTerms final : public StaticNonlinearity {
 public:
  /// `linear_stiffness` is the assembled K of the same wing (assembleWingFe, no pretension): the
  /// solver adds K u, this returns the rest. Throws std::invalid_argument for a skin pretension,
  /// an invalid film law or a K of another size.
  CoRotationalTerms(const WingStructure& wing_structure, const WingMesh& mesh,
                    const SparseMatrix& linear_stiffness,
                    SkinMembrane skin_membrane = SkinMembrane::kElastic, const FilmLaw& film = {},
                    FacetTangent facet_tangent = FacetTangent::kMembraneExact);

  int dofCount() const override { return dof_count_; }
  Eigen::VectorXd internalForce(const Eigen::VectorXd& u) const override;  ///< f(u) - K u
  double energy(const Eigen::VectorXd& u) const override;                 ///< U(u) - 1/2 u^T K u
  SparseMatrix tangent(const Eigen::VectorXd& u) const override;          ///< dF/du - K

  /// The whole strain energy U(u) (J), its gradient f(u) and tangent (FacetTangent).
  double strainEnergy(const Eigen::VectorXd& u) const;
  Eigen::VectorXd strainForce(const Eigen::VectorXd& u) const;
  SparseMatrix strainTangent(const Eigen::VectorXd& u) const;

  /// The state of each skin facet's film at u (its law at the facet's Green strain; every facet
  /// taut for the elastic law).
  std::vector<FilmState> facetStates(const Eigen::VectorXd& u) const;
  /// The largest rotation of a facet's plane from its initial one (rad): the measure of how far
  /// the wing is from von Karman's range (FeVonKarmanValidity).
  double largestFacetTilt(const Eigen::VectorXd& u) const;

  struct Facet {
    std::array<int, 3> nodes{};
    Vec3 normal0;                        ///< n_0, the initial facet normal (W)
    Eigen::Matrix<double, 2, 3> grad;    ///< dN_i / d(xi, eta), initial local coordinates (1/m)
    Eigen::Matrix<double, 6, 6> bending; ///< the DKT stiffness over (theta_x, theta_y) per node
    double area_m2 = 0.0;
    double size_m = 0.0;                 ///< the longest edge (finite-difference steps)
  };
  struct Member {
    std::array<int, 2> nodes{};
    Mat3 triad0;                        ///< Lambda_0, rows x', y', z' (W)
    double length_m = 0.0;
    /// The local stiffness over (theta_1 (3), elongation, theta_2 (3)).
    Eigen::Matrix<double, 7, 7> stiffness;
  };

 private:
  int dof_count_ = 0;
  std::vector<Vec3> x0_;  ///< the nodes' initial positions (W)
  std::vector<Facet> facets_;
  std::vector<Member> members_;
  SparseMatrix linear_stiffness_;
  SkinMembrane skin_membrane_ = SkinMembrane::kElastic;
  Mat3 membrane_c_ = Mat3::Zero();  ///< C = E t / (1 - nu^2) [...] (N/m)
  double skin_et_n_per_m_ = 0.0;
  double skin_nu_ = 0.0;
  FilmLaw film_;
  FacetTangent facet_tangent_ = FacetTangent::kMembraneExact;
};

}  // namespace orni::structure
