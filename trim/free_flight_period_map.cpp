#include "trim/free_flight_period_map.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/dynamics/flapping.hpp"
#include "core/dynamics/modal_implicit_split.hpp"
#include "core/model/invariant.hpp"

namespace orni {

namespace {

constexpr int kReducedOffset = 2;  // x = y[2 .. powerOffset)

// A FreeFlightModel of `core` that keeps `core` alive (the model holds a reference to it), so a
// system built on it outlives modelAt's next shift.
std::shared_ptr<const FreeFlightModel> modelKeeping(std::shared_ptr<const FlightCoreModel> core) {
  struct Owned {
    explicit Owned(std::shared_ptr<const FlightCoreModel> c)
        : core(std::move(c)), model(*core, core->flexible.get()) {}
    std::shared_ptr<const FlightCoreModel> core;
    FreeFlightModel model;
  };
  auto owned = std::make_shared<const Owned>(std::move(core));
  return std::shared_ptr<const FreeFlightModel>(owned, &owned->model);
}

}  // namespace

FreeFlightPeriodMap::FreeFlightPeriodMap(const FlightCoreModel& model,
                                         const FreeFlightPeriodMapOptions& options)
    : base_(model), options_(options) {
  if (!(options.rel_tol > 0.0 && options.rel_tol <= 1e-2))
    throw std::invalid_argument("free-flight period map: rel_tol must be in (0, 1e-2]");
  if (!(options.friction_speed_mps > 0.0))
    throw std::invalid_argument("free-flight period map: friction speed must be > 0");
  const OperatingPoint& op = options.design_point;
  prepare(parameters(op.freq_hz > 0.0 ? op : OperatingPoint{10.0, 10.0, 0.0, 0.0}).data());
  mode_count_ = sys_->modeCount();
  full_ = sys_->stateCount();
  power_ = sys_->powerOffset();
  n_ = power_ - kReducedOffset;
  // Scales: the free-flight absolute tolerances at relative tolerance 1, lag and separation 0.1.
  std::vector<double> atol;
  sys_->absoluteTolerances(1.0, 0.1, 0.1, &atol);
  scale_.assign(atol.begin() + kReducedOffset, atol.begin() + power_);
  control_.rel_tol = options.rel_tol;
  control_.max_step_fraction = options.max_step_fraction;
  control_.abs_tol.resize(static_cast<std::size_t>(full_));
  for (int i = 0; i < full_; ++i)
    control_.abs_tol[static_cast<std::size_t>(i)] = options.rel_tol * atol[static_cast<std::size_t>(i)];
  y0_.assign(static_cast<std::size_t>(full_), 0.0);
  y1_.assign(static_cast<std::size_t>(full_), 0.0);

  const char* body[4] = {"theta", "U", "W", "Q"};
  const char* body_units[4] = {"rad", "m/s", "m/s", "rad/s"};
  const FloquetStateKind kinds[4] = {FloquetStateKind::kBodyTheta, FloquetStateKind::kBodyU,
                                     FloquetStateKind::kBodyW, FloquetStateKind::kBodyQ};
  for (int i = 0; i < 4; ++i) {
    info_.push_back({body[i], kinds[i], 0});
    units_.emplace_back(body_units[i]);
  }
  for (int k = 1; k <= mode_count_; ++k) {
    info_.push_back({"q" + std::to_string(k), FloquetStateKind::kModal, k});
    units_.emplace_back("m kg^0.5");
  }
  for (int k = 1; k <= mode_count_; ++k) {
    info_.push_back({"q" + std::to_string(k) + "_dot", FloquetStateKind::kModal, k});
    units_.emplace_back("m kg^0.5/s");
  }
  const int per = model.aero_states_per_strip;
  const int strips = static_cast<int>(model.strips.size());
  for (int j = 1; j <= strips; ++j)
    for (int s = 0; s < per; ++s) {
      const bool separation = s == per - 1;
      info_.push_back({std::string(separation ? "sep_f_strip" : "lag_z_strip") + std::to_string(j),
                       FloquetStateKind::kAeroLag, 0});
      units_.emplace_back(separation ? "-" : "rad");
    }
  ORNI_DEMAND(static_cast<int>(info_.size()) == n_,
              "free-flight period map: one state description per state");
}

FreeFlightPeriodMap::~FreeFlightPeriodMap() = default;

FreeFlightPeriodMap::FreeFlightPeriodMap(const FreeFlightPeriodMap& other, CloneTag)
    : base_(other.base_),
      options_(other.options_),
      n_(other.n_),
      mode_count_(other.mode_count_),
      full_(other.full_),
      power_(other.power_),
      scale_(other.scale_),
      info_(other.info_),
      units_(other.units_),
      shifted_(other.shifted_),
      shift_m_(other.shift_m_),
      base_model_(other.base_model_),
      shifted_model_(other.shifted_model_),
      control_(other.control_),
      grid_(other.grid_),
      y0_(other.y0_.size(), 0.0),
      y1_(other.y1_.size(), 0.0) {}

std::unique_ptr<PeriodMap> FreeFlightPeriodMap::clone() const {
  return std::unique_ptr<PeriodMap>(new FreeFlightPeriodMap(*this, CloneTag{}));
}

void FreeFlightPeriodMap::addWorkOf(const PeriodMap& clone) {
  if (const auto* c = dynamic_cast<const FreeFlightPeriodMap*>(&clone))
    rhs_evaluations_ += c->rhs_evaluations_;
}

double FreeFlightPeriodMap::parameterScale(int j) const {
  switch (j) {
    case kPeriodTailAngle: return 0.1;
    case kPeriodFrequency: return 1.0;
    default: return 0.01;
  }
}

double orbitScaleSpeed_mps(const OperatingPoint& design_point) {
  return design_point.speed_mps > 0.0 ? design_point.speed_mps : 10.0;
}

std::vector<double> FreeFlightPeriodMap::parameters(const OperatingPoint& point, double cg_shift_m) {
  return {point.tail_angle_rad, point.freq_hz, cg_shift_m};
}

void FreeFlightPeriodMap::setFrictionSpeed(double speed_mps) {
  if (!(speed_mps > 0.0))
    throw std::invalid_argument("free-flight period map: friction speed must be > 0");
  options_.friction_speed_mps = speed_mps;
  prepared_ = false;
}

std::string FreeFlightPeriodMap::methodName() const { return rk_->methodName(); }

const FlightCoreModel& FreeFlightPeriodMap::modelAt(const double* p) {
  const double shift = p[kPeriodCgShift];
  if (shift == 0.0) return base_;
  if (!shifted_ || shift != shift_m_) {
    VehicleModel v = base_.vehicle;
    v.flapping.hinge_x_B_m -= shift;
    v.tail.arm_m += shift;
    // The shift moves the hinge and the tail, not the wing: the base's modal wing serves.
    if (!shifted_wings_ && base_.flexible) {
      shifted_wings_ = std::make_shared<ModalWingCache>(1);
      shifted_wings_->insert(base_.vehicle, base_.flexible->modal);
    }
    shifted_ = std::make_shared<const FlightCoreModel>(v, FlightCoreModel::Checks::kRequired,
                                                       shifted_wings_.get());
    shifted_model_.reset();  // of the previous shift
    shift_m_ = shift;
  }
  return *shifted_;
}

std::shared_ptr<const FreeFlightModel> FreeFlightPeriodMap::freeFlightModelAt(const double* p) {
  const FlightCoreModel& model = modelAt(p);
  if (&model == &base_) {
    if (!base_model_)
      base_model_ = std::make_shared<const FreeFlightModel>(base_, base_.flexible.get());
    return base_model_;
  }
  if (!shifted_model_) shifted_model_ = modelKeeping(shifted_);
  return shifted_model_;
}

void FreeFlightPeriodMap::prepare(const double* p) {
  if (prepared_ && std::equal(p, p + kPeriodParameterCount, p_)) return;
  if (!(p[kPeriodFrequency] > 0.0) || !std::isfinite(p[kPeriodFrequency]))
    throw std::invalid_argument("free-flight period map: frequency must be > 0");
  rk_.reset();
  sys_.reset();
  sys_ = std::make_unique<FreeFlightSystem>(
      freeFlightModelAt(p), ControlInput{p[kPeriodFrequency], p[kPeriodTailAngle]},
      orbitScaleSpeed_mps(options_.design_point));
  sys_->setFrictionSpeed(options_.friction_speed_mps);
  using Imex = ModalImex<FreeFlightSystem>;
  if (sys_->hasModes())
    rk_ = std::make_unique<GridRungeKutta>(sys_->stateCount(), &Imex::explicitRhs, Imex::part(sys_->nonlinearWing()),
                                           sys_.get());
  else
    rk_ = std::make_unique<GridRungeKutta>(sys_->stateCount(), &FreeFlightSystem::rhsCallback,
                                           sys_.get());
  std::copy(p, p + kPeriodParameterCount, p_);
  prepared_ = true;
}

void FreeFlightPeriodMap::fullState(const double* x, double* y) const {
  y[0] = 0.0;  // x_I
  y[1] = 0.0;  // h
  std::copy(x, x + n_, y + kReducedOffset);
  y[power_] = 0.0;
}

std::vector<double> FreeFlightPeriodMap::reducedState(const BodyState& body,
                                                      const std::vector<double>& wing) const {
  if (static_cast<int>(wing.size()) != n_ - 4)
    throw std::invalid_argument("free-flight period map: wing state of another layout");
  std::vector<double> x{body.theta_rad, body.U_mps, body.W_mps, body.Q_radps};
  x.insert(x.end(), wing.begin(), wing.end());
  return x;
}

bool FreeFlightPeriodMap::refreshDiscretisation(const double* x, const double* p,
                                                std::string* why) {
  prepare(p);
  fullState(x, y0_.data());
  const long before = rk_->rhsEvaluations();
  const bool ok = rk_->integrateAdaptive(0.0, period_s(p), y0_.data(), control_, &grid_, y1_.data());
  rhs_evaluations_ += rk_->rhsEvaluations() - before;
  if (!ok && why) *why = rk_->lastError();
  return ok;
}

bool FreeFlightPeriodMap::flow(const double* x, const double* p, double* x_T, double* g,
                               std::string* why) {
  if (grid_.empty() && !refreshDiscretisation(x, p, why)) return false;
  prepare(p);
  fullState(x, y0_.data());
  const long before = rk_->rhsEvaluations();
  const bool ok = rk_->integrateOnGrid(0.0, period_s(p), grid_, y0_.data(), y1_.data());
  rhs_evaluations_ += rk_->rhsEvaluations() - before;
  if (!ok) {
    if (why) *why = rk_->lastError();
    return false;
  }
  std::copy(y1_.begin() + kReducedOffset, y1_.begin() + power_, x_T);
  if (g) g[kPeriodAltitudeGain] = y1_[1] - y0_[1];
  last_power_W_ = y1_[static_cast<std::size_t>(power_)] * p[kPeriodFrequency];
  return true;
}

namespace {

struct SampleContext {
  FreeFlightSystem* sys;
  const std::vector<char>* is_sample;
  OrbitHistory* out;
  int power;
  double amplitude_rad, freq_hz;
};

void observeSample(int node, double t_s, const double* y, void* data) {
  auto* c = static_cast<SampleContext*>(data);
  if (!(*c->is_sample)[static_cast<std::size_t>(node)]) return;
  OrbitHistory& h = *c->out;
  h.t_s.push_back(t_s);
  h.delta_M_rad.push_back(flapStateAt(c->amplitude_rad, c->freq_hz, t_s).delta_rad);
  h.body.push_back(BodyState{y[0], y[1], y[2], y[3], y[4], y[5]});
  FreeFlightSample s;
  c->sys->sample(t_s, y, &s, false);
  h.samples.push_back(s);
  h.power_integral_J.push_back(y[c->power]);
}

}  // namespace

bool FreeFlightPeriodMap::sampleOrbit(const double* x, const double* p, int samples,
                                      OrbitHistory* out, std::string* why) {
  if (samples < 1) throw std::invalid_argument("sampleOrbit: samples must be >= 1");
  if (grid_.empty() && !refreshDiscretisation(x, p, why)) return false;
  prepare(p);
  // The grid merged with the sample phases k / samples (nodes closer than 1e-9 merged).
  std::vector<double> nodes = grid_;
  for (int k = 1; k < samples; ++k) nodes.push_back(static_cast<double>(k) / samples);
  std::sort(nodes.begin(), nodes.end());
  std::vector<double> merged;
  std::vector<char> is_sample;
  for (double v : nodes)
    if (merged.empty() || v - merged.back() > 1e-9) merged.push_back(v);
  merged.back() = 1.0;
  for (double v : merged) {
    const double k = v * samples;
    is_sample.push_back(std::abs(k - std::round(k)) < 1e-9 * samples ? 1 : 0);
  }
  *out = OrbitHistory{};
  SampleContext ctx{sys_.get(), &is_sample, out, power_, modelAt(p).vehicle.flapping.amplitude_rad,
                    p[kPeriodFrequency]};
  fullState(x, y0_.data());
  const bool ok = rk_->integrateOnGrid(0.0, period_s(p), merged, y0_.data(), y1_.data(),
                                       &observeSample, &ctx);
  if (!ok && why) *why = rk_->lastError();
  return ok;
}

}  // namespace orni
