#include "core/dynamics/modal_implicit_split.hpp"

#include <stdexcept>

#include <Eigen/Cholesky>

namespace orni {

ModalImplicitSplit::ModalImplicitSplit(const FlexibleWingModel& flex, int q_offset,
                                       int state_count)
    : mode_count_(flex.mode_count),
      off_(q_offset),
      n_(state_count),

      K_(Eigen::MatrixXd(flex.stiffness.asDiagonal()) + flex.membrane_reference_stiffness),
      D_(flex.damping),
      S_(flex.mode_count, flex.mode_count),
      S_chol_(flex.mode_count),
      w_(flex.mode_count),
      r_(flex.mode_count) {
  if (mode_count_ < 1 || q_offset < 0 || q_offset + 2 * mode_count_ > state_count)
    throw std::invalid_argument("ModalImplicitSplit: modal rows outside the state");
  // A0 = M_qq + A(f = 1) (lower triangle from addApparentModalMass, then mirrored).
  Eigen::MatrixXd lower = flex.M_qq;
  Eigen::VectorXd packed(static_cast<Eigen::Index>(mode_count_) * (mode_count_ + 1) / 2);
  const Eigen::ArrayXd attached = Eigen::ArrayXd::Ones(flex.stacked.ns);
  addApparentModalMass(flex.stacked, attached, 1.0, &packed, lower);
  A0_ = lower.selfadjointView<Eigen::Lower>();
  const Eigen::LLT<Eigen::MatrixXd> llt(A0_);
  if (llt.info() != Eigen::Success)
    throw std::runtime_error("ModalImplicitSplit: reference modal mass is not positive definite");
  GH_.resize(mode_count_, 2 * mode_count_);
  GH_.leftCols(mode_count_) = llt.solve(K_);
  GH_.rightCols(mode_count_) = llt.solve(Eigen::MatrixXd(D_.asDiagonal()));
}

void ModalImplicitSplit::stiffAcceleration(const double* y) {
  w_.noalias() = GH_ * Eigen::Map<const Eigen::VectorXd>(y + off_, 2 * mode_count_);
}

void ModalImplicitSplit::apply(const double* y, double* ydot) {
  for (int i = 0; i < n_; ++i) ydot[i] = 0.0;
  stiffAcceleration(y);
  for (int i = 0; i < mode_count_; ++i) {
    ydot[off_ + i] = y[off_ + mode_count_ + i];
    ydot[off_ + mode_count_ + i] = -w_[i];
  }
}

void ModalImplicitSplit::removeFrom(const double* y, double* ydot) {
  stiffAcceleration(y);
  for (int i = 0; i < mode_count_; ++i) {
    ydot[off_ + i] -= y[off_ + mode_count_ + i];
    ydot[off_ + mode_count_ + i] += w_[i];
  }
}

void ModalImplicitSplit::solve(double gamma, const double* b, double* x) {
  if (gamma != gamma_) {
    S_ = A0_;
    S_.diagonal() += gamma * D_;
    S_ += (gamma * gamma) * K_;
    if (!S_chol_.factor(S_))
      throw std::runtime_error("ModalImplicitSplit: stage matrix is not positive definite");
    gamma_ = gamma;
  }
  for (int i = 0; i < n_; ++i) x[i] = b[i];
  const Eigen::Map<const Eigen::VectorXd> bq(b + off_, mode_count_),
      bqd(b + off_ + mode_count_, mode_count_);
  r_.noalias() = A0_ * bqd;
  r_.noalias() -= gamma * (K_ * bq);
  S_chol_.solveInPlace(r_);
  w_ = r_;
  for (int i = 0; i < mode_count_; ++i) {
    x[off_ + mode_count_ + i] = w_[i];
    x[off_ + i] = bq[i] + gamma * w_[i];
  }
}

void modalAbsoluteTolerances(double rel_tol, int mode_count, int offset,
                             std::vector<double>* atol) {
  for (int i = 0; i < mode_count; ++i) {
    (*atol)[static_cast<std::size_t>(offset + i)] = 1e-3 * rel_tol;
    (*atol)[static_cast<std::size_t>(offset + mode_count + i)] = 1e-1 * rel_tol;
  }
}

}  // namespace orni
