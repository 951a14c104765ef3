// Spin softening plus geometric stiffening on the modes (docs/theory.md 3.6, 4.6).
#include "core/structure/inertial_stiffness.hpp"

#include <algorithm>
#include <stdexcept>

namespace orni::structure {

ModalInertialStiffness modalInertialStiffness(const InertiaInvariants& invariants,
                                              const ModalGeometricStiffness& kg,
                                              InertialStiffness model) {
  const Eigen::Index m = invariants.modeCount();
  const bool softening = model != InertialStiffness::kNone;
  const bool stiffening = model == InertialStiffness::kBoth;
  if (stiffening && kg.empty())
    throw std::invalid_argument(
        "inertial stiffness: geometric stiffening asked for, but the modal wing has no K_G");
  if (stiffening)
    for (const Eigen::MatrixXd& k : kg.per_load)
      if (k.rows() != m || k.cols() != m)
        throw std::invalid_argument("inertial stiffness: K_G and invariants differ in mode count");
  ModalInertialStiffness out;
  for (int k = 0; k < 3; ++k)
    for (int l = 0; l < 3; ++l) {
      Eigen::MatrixXd& s = out.spin[static_cast<std::size_t>(3 * k + l)];
      s.setZero(m, m);
      if (softening) {  // K_w = sum_kl w_k w_l P_kl - |w|^2 sum_j P_jj
        s = invariants.P(k, l);
        if (k == l) s -= invariants.P(0, 0) + invariants.P(1, 1) + invariants.P(2, 2);
      }
      if (stiffening) s += (k == l ? 1.0 : 0.5) * kg[spinLoad(k, l)];
    }
  if (!stiffening || m == 0) return out;
  double largest = 0.0;
  for (const Eigen::MatrixXd& k : kg.per_load) largest = std::max(largest, k.cwiseAbs().maxCoeff());
  for (int i = kLoadAccelX; i <= kLoadAlphaZ; ++i) {
    const auto load = static_cast<InertialLoad>(i);
    if (kg[load].cwiseAbs().maxCoeff() > 1e-12 * largest) out.linear_loads.push_back(load);
  }
  out.linear_stack.resize(static_cast<Eigen::Index>(out.linear_loads.size()) * m, m);
  for (std::size_t j = 0; j < out.linear_loads.size(); ++j)
    out.linear_stack.middleRows(static_cast<Eigen::Index>(j) * m, m) = kg[out.linear_loads[j]];
  return out;
}

}  // namespace orni::structure
