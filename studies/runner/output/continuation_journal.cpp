#include "studies/runner/output/continuation_journal.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace orni::studies {

namespace {

void put(std::string* s, double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, " %.17g", v);
  *s += buf;
}
void putVector(std::string* s, const Eigen::VectorXd& v) {
  put(s, static_cast<double>(v.size()));
  for (Eigen::Index i = 0; i < v.size(); ++i) put(s, v[i]);
}
void putVector(std::string* s, const std::vector<double>& v) {
  putVector(s, Eigen::Map<const Eigen::VectorXd>(v.data(), static_cast<Eigen::Index>(v.size())));
}

class Reader {
 public:
  explicit Reader(std::string_view text) : text_(text) {}
  bool number(double* v) {
    while (pos_ < text_.size() && text_[pos_] == ' ') ++pos_;
    if (pos_ >= text_.size() || text_[pos_] == '|') return false;
    const std::string token(text_.substr(pos_, text_.find(' ', pos_) - pos_));
    char* end = nullptr;
    *v = std::strtod(token.c_str(), &end);
    pos_ += token.size();
    return end && *end == '\0' && !token.empty();
  }
  bool count(std::size_t* n) {
    double v = 0.0;
    if (!number(&v) || !(v >= 0.0 && v <= 1e6) || v != std::floor(v)) return false;
    *n = static_cast<std::size_t>(v);
    return true;
  }
  bool vector(Eigen::VectorXd* out) {
    std::size_t n = 0;
    if (!count(&n)) return false;
    out->resize(static_cast<Eigen::Index>(n));
    for (std::size_t i = 0; i < n; ++i)
      if (!number(&(*out)[static_cast<Eigen::Index>(i)])) return false;
    return true;
  }
  bool vector(std::vector<double>* out) {
    Eigen::VectorXd v;
    if (!vector(&v)) return false;
    out->assign(v.data(), v.data() + v.size());
    return true;
  }
  bool label(std::string* out) {
    const std::size_t bar = text_.find(" |", pos_);
    if (bar == std::string_view::npos) return false;
    for (std::size_t i = pos_; i < bar; ++i)
      if (text_[i] != ' ') return false;
    *out = std::string(text_.substr(bar + 2));
    return true;
  }

 private:
  std::string_view text_;
  std::size_t pos_ = 0;
};

}  // namespace

std::string encodeContinuationPoint(const TrimContinuationPoint& p) {
  const ContinuationPoint& o = p.orbit;
  std::string s = o.event.empty() ? "-" : o.event;
  for (double v : {static_cast<double>(o.index), o.lambda, o.arclength, o.residual_max,
                   static_cast<double>(o.corrector_iterations), o.max_modulus,
                   o.stable ? 1.0 : 0.0, o.tangent_lambda, o.step, o.step_scale,
                   p.friction_speed_mps, p.grid_friction_speed_mps,
                   p.cg_shift_m, p.solution.theta_rad, p.solution.speed_mps,
                   p.solution.tail_angle_rad, p.solution.freq_hz, p.mean.theta_rad,
                   p.mean.airspeed_mps, p.mean.U_mps, p.mean.W_mps, p.mean.Q_radps,
                   p.mean.power_aero_W, p.mean.FV_N, p.mean.FH_N, p.mean.M_Nm,
                   p.mean.theta_min_rad, p.mean.theta_max_rad, p.mean.altitude_p2p_m})
    put(&s, v);
  putVector(&s, o.x);
  putVector(&s, o.p);
  putVector(&s, o.y);
  putVector(&s, o.tangent);
  putVector(&s, o.grid_origin);
  put(&s, static_cast<double>(o.multipliers.size()));
  for (Eigen::Index i = 0; i < o.multipliers.size(); ++i) {
    put(&s, o.multipliers[i].real());
    put(&s, o.multipliers[i].imag());
  }
  return s + " |" + p.leading_label;
}

bool decodeContinuationPoint(std::string_view payload, TrimContinuationPoint* p) {
  const std::size_t space = payload.find(' ');
  if (space == std::string_view::npos) return false;
  ContinuationPoint& o = p->orbit;
  const std::string event(payload.substr(0, space));
  o.event = event == "-" ? std::string() : event;
  Reader r(payload.substr(space));
  double index = 0.0, iterations = 0.0, stable = 0.0;
  double* scalars[] = {&index, &o.lambda, &o.arclength, &o.residual_max, &iterations,
                       &o.max_modulus, &stable, &o.tangent_lambda, &o.step, &o.step_scale,
                       &p->friction_speed_mps, &p->grid_friction_speed_mps, &p->cg_shift_m,
                       &p->solution.theta_rad, &p->solution.speed_mps, &p->solution.tail_angle_rad,
                       &p->solution.freq_hz,
                       &p->mean.theta_rad, &p->mean.airspeed_mps, &p->mean.U_mps, &p->mean.W_mps,
                       &p->mean.Q_radps, &p->mean.power_aero_W, &p->mean.FV_N, &p->mean.FH_N,
                       &p->mean.M_Nm, &p->mean.theta_min_rad, &p->mean.theta_max_rad,
                       &p->mean.altitude_p2p_m};
  for (double* v : scalars)
    if (!r.number(v)) return false;
  o.index = static_cast<int>(index);
  o.corrector_iterations = static_cast<int>(iterations);
  o.stable = stable != 0.0;
  if (!r.vector(&o.x) || !r.vector(&o.p) || !r.vector(&o.y) || !r.vector(&o.tangent) ||
      !r.vector(&o.grid_origin))
    return false;
  std::size_t m = 0;
  if (!r.count(&m)) return false;
  o.multipliers.resize(static_cast<Eigen::Index>(m));
  for (std::size_t i = 0; i < m; ++i) {
    double re = 0.0, im = 0.0;
    if (!r.number(&re) || !r.number(&im)) return false;
    o.multipliers[static_cast<Eigen::Index>(i)] = {re, im};
  }
  const std::size_t N = static_cast<std::size_t>(o.y.size());
  // All n multipliers (the full Jacobian) or the leading ones (Arnoldi), at least one.
  if (o.x.empty() || m == 0 || m > o.x.size() || N < o.x.size() + 1 ||
      static_cast<std::size_t>(o.tangent.size()) != N ||
      static_cast<std::size_t>(o.grid_origin.size()) != N)
    return false;
  o.multipliers_complete = m == o.x.size();
  return r.label(&p->leading_label);
}

}  // namespace orni::studies
