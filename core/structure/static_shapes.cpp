#include "core/structure/static_shapes.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

#include <Eigen/Eigenvalues>

#include "core/model/invalid_model_error.hpp"
#include "core/structure/shell_element.hpp"

namespace orni::structure {

Section sectionOf(const WingMesh& mesh, const Eigen::VectorXd& u, std::size_t strip) {
  if (strip >= mesh.strip_nodes.size())
    throw std::invalid_argument("sectionOf: strip " + std::to_string(strip) + " outside the mesh's " +
                                std::to_string(mesh.strip_nodes.size()));
  const StripSampleNodes& s = mesh.strip_nodes[strip];
  const double lead = -u(globalDof(s.leading_edge, kW));
  const double trail = -u(globalDof(s.trailing_edge, kW));
  const double chord = (mesh.nodes_W_m[static_cast<std::size_t>(s.leading_edge)] -
                        mesh.nodes_W_m[static_cast<std::size_t>(s.trailing_edge)])
                           .norm();
  return {lead, trail, -std::atan2(trail - lead, chord) * 180.0 / 3.14159265358979323846};
}

Eigen::VectorXd uniformLiftLoad(const WingMesh& mesh, double pressure_pa) {
  Eigen::VectorXd f = Eigen::VectorXd::Zero(kDofsPerNode * mesh.nodeCount());
  for (const std::array<int, 3>& tri : mesh.triangles) {
    const std::array<Vec3, 3> x = {mesh.nodes_W_m[static_cast<std::size_t>(tri[0])],
                                   mesh.nodes_W_m[static_cast<std::size_t>(tri[1])],
                                   mesh.nodes_W_m[static_cast<std::size_t>(tri[2])]};
    const double per_node_N = pressure_pa * triangleArea(x) / 3.0;
    for (int n : tri) f(globalDof(n, kW)) -= per_node_N;  // upward = -z_W
  }
  return f;
}

Eigen::VectorXd outOfPlanePart(const Eigen::VectorXd& displacement) {
  Eigen::VectorXd w = displacement;
  const Eigen::Index nodes = w.size() / kDofsPerNode;
  for (Eigen::Index n = 0; n < nodes; ++n)
    for (int dof : {kU, kV, kThetaZ}) w(kDofsPerNode * n + dof) = 0.0;
  return w;
}

RitzBasis rayleighRitzBasis(const SparseMatrix& stiffness, const SparseMatrix& mass,
                            const Eigen::MatrixXd& shapes, const Eigen::MatrixXd& extra,
                            double dependence_tol) {
  const Eigen::Index m = shapes.cols();
  // The extra directions, M-orthogonalised against the basis and each other (Gram-Schmidt,
  // twice), and dropped where nothing is left of them.
  Eigen::MatrixXd basis(shapes.rows(), m + extra.cols());
  basis.leftCols(m) = shapes;
  Eigen::Index count = m;
  RitzBasis out;
  for (Eigen::Index c = 0; c < extra.cols(); ++c) {
    Eigen::VectorXd v = extra.col(c);
    const double norm0 = std::sqrt(v.dot(mass * v));
    if (!(norm0 > 0.0)) {
      ++out.dropped;
      continue;
    }
    v /= norm0;
    for (int pass = 0; pass < 2; ++pass) {
      const Eigen::VectorXd mv = mass * v;
      v -= basis.leftCols(count) * (basis.leftCols(count).transpose() * mv);
    }
    const double norm = std::sqrt(v.dot(mass * v));
    if (!(norm > dependence_tol)) {
      ++out.dropped;
      continue;
    }
    basis.col(count++) = v / norm;
  }
  basis.conservativeResize(Eigen::NoChange, count);
  // The basis is M-orthonormal: the Ritz problem is the ordinary eigenproblem of its stiffness.
  Eigen::MatrixXd k_r = basis.transpose() * (stiffness * basis);
  k_r = 0.5 * (k_r + k_r.transpose()).eval();
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(k_r);
  out.omega2 = eig.eigenvalues();
  out.shapes = basis * eig.eigenvectors();
  // A sign convention, so that the shapes do not depend on the eigensolver's: the largest
  // component of each is positive.
  for (Eigen::Index c = 0; c < out.shapes.cols(); ++c) {
    Eigen::Index at = 0;
    out.shapes.col(c).cwiseAbs().maxCoeff(&at);
    if (out.shapes(at, c) < 0.0) out.shapes.col(c) *= -1.0;
  }
  return out;
}

Eigen::MatrixXd nonlinearStaticShapes(const SparseMatrix& stiffness, const VonKarmanTerms& terms,
                                      const DofPartition& part, const WingMesh& mesh,
                                      const std::vector<double>& pressures_pa) {
  Eigen::MatrixXd out(stiffness.rows(), static_cast<Eigen::Index>(pressures_pa.size()));
  NonlinearStaticOptions options;
  options.load_steps = 10;  // measured: the slack EFW at 0.5-3 Pa converges in 120-200 iterations
  for (std::size_t k = 0; k < pressures_pa.size(); ++k) {
    const NonlinearStaticResult r =
        solveNonlinearStatic(stiffness, terms, part, uniformLiftLoad(mesh, pressures_pa[k]), options);
    if (!r.converged) {
      std::ostringstream s;
      s << "wing.fe.static_shapes_pa: the wing's nonlinear static solution under a uniform lift of "
        << pressures_pa[k] << " Pa did not converge (" << r.message
        << "); choose smaller pressures (the slack skin's static answer is unique only for small "
           "loads, docs/theory.md 4.7)";
      throw InvalidModelError(s.str());
    }
    out.col(static_cast<Eigen::Index>(k)) = outOfPlanePart(r.displacement);
  }
  return out;
}

}  // namespace orni::structure
