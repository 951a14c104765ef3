#include "optimize/optimizer.hpp"

#include <nlopt.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <limits>
#include <map>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <thread>
#include <utility>

#include "core/model/cancellation.hpp"
#include "core/model/invariant.hpp"

namespace orni::opt {

const char* toString(EvaluationStatus s) {
  return s == EvaluationStatus::kOk ? "ok" : "failed";
}

const char* toString(Stage s) {
  switch (s) {
    case Stage::kLocal: return "local";
    case Stage::kGlobal: return "global";
    case Stage::kPolish: return "polish";
  }
  return "local";
}

bool VariableBox::IsValid(std::string* why) const {
  auto fail = [why](const std::string& m) {
    if (why) *why = m;
    return false;
  };
  if (lower.empty()) return fail("no variables");
  if (upper.size() != lower.size() || initial.size() != lower.size())
    return fail("lower, upper and initial differ in size");
  for (std::size_t i = 0; i < lower.size(); ++i) {
    const std::string at = " (variable " + std::to_string(i) + ")";
    if (!(std::isfinite(lower[i]) && std::isfinite(upper[i]) && lower[i] < upper[i]))
      return fail("bounds must be finite with lower < upper" + at);
    if (!(initial[i] >= lower[i] && initial[i] <= upper[i]))
      return fail("initial value outside the bounds" + at);
  }
  return true;
}

namespace {

// Radical inverse of k in base b (Halton coordinate), in (0, 1) for k >= 1.
double radicalInverse(int k, int base) {
  double f = 1.0, r = 0.0;
  while (k > 0) {
    f /= base;
    r += f * (k % base);
    k /= base;
  }
  return r;
}

int nthPrime(int i) {
  static const int kPrimes[] = {2,  3,  5,  7,  11, 13, 17, 19, 23, 29, 31, 37, 41, 43, 47, 53,
                                59, 61, 67, 71, 73, 79, 83, 89, 97, 101, 103, 107, 109, 113};
  constexpr int kCount = static_cast<int>(sizeof kPrimes / sizeof kPrimes[0]);
  if (i < kCount) return kPrimes[i];
  int p = kPrimes[kCount - 1], found = kCount - 1;
  while (found < i) {
    p += 2;
    bool prime = true;
    for (int d = 3; d * d <= p; d += 2)
      if (p % d == 0) prime = false;
    if (prime) ++found;
  }
  return p;
}

bool converged(nlopt_result r) {
  return r == NLOPT_SUCCESS || r == NLOPT_STOPVAL_REACHED || r == NLOPT_FTOL_REACHED ||
         r == NLOPT_XTOL_REACHED;
}

std::string terminationText(nlopt_result r) {
  switch (r) {
    case NLOPT_SUCCESS: return "success";
    case NLOPT_STOPVAL_REACHED: return "objective target reached";
    case NLOPT_FTOL_REACHED: return "ftol reached (objective change below ftol_rel)";
    case NLOPT_XTOL_REACHED: return "xtol reached (step below xtol)";
    case NLOPT_MAXEVAL_REACHED: return "evaluation budget reached (max_evaluations)";
    case NLOPT_MAXTIME_REACHED: return "time limit reached";
    case NLOPT_FAILURE: return "NLopt failure";
    case NLOPT_INVALID_ARGS: return "NLopt: invalid arguments";
    case NLOPT_OUT_OF_MEMORY: return "NLopt: out of memory";
    case NLOPT_ROUNDOFF_LIMITED: return "NLopt: progress limited by roundoff";
    case NLOPT_FORCED_STOP: return "stopped";
    default: break;
  }
  return "NLopt result " + std::to_string(static_cast<int>(r));
}

/// Owner of an nlopt_opt.
struct NloptHandle {
  explicit NloptHandle(nlopt_algorithm a, unsigned n) : opt(nlopt_create(a, n)) {
    if (!opt) throw std::runtime_error("nlopt_create failed");
  }
  ~NloptHandle() { nlopt_destroy(opt); }
  NloptHandle(const NloptHandle&) = delete;
  NloptHandle& operator=(const NloptHandle&) = delete;
  nlopt_opt opt;
};

void check(nlopt_result r, const char* what) {
  if (r < 0) throw std::runtime_error(std::string("NLopt: ") + what + " failed");
}

/// Better of two records: feasible before infeasible; then objective (feasible) or violation
/// (infeasible, objective breaking ties). Strict: equal records keep the earlier one.
bool better(const EvaluationRecord& a, const EvaluationRecord& b) {
  if (a.feasible != b.feasible) return a.feasible;
  if (a.feasible) return a.result.objective < b.result.objective;
  if (a.violation != b.violation) return a.violation < b.violation;
  return a.result.objective < b.result.objective;
}

/// One start: its NLopt runs, its cache, its workspace and its records.
class StartRun {
 public:
  StartRun(const Problem& problem, const VariableBox& box, const OptimizerOptions& options,
           const OptimizerHooks& hooks, int start, std::atomic<bool>* abort)
      : problem_(problem), box_(box), o_(options), hooks_(hooks), start_(start), abort_(abort),
        workspace_(problem.makeWorkspace()) {
    summary_.start = start;
    summary_.x0 = startPoint(box, start);
  }

  void run() {
    nlopt_srand(static_cast<unsigned long>(o_.seed + start_));
    const std::vector<double> u0 = toUnit(summary_.x0);
    nlopt_result r = NLOPT_FAILURE;
    switch (o_.algorithm) {
      case Algorithm::kCobyla:
        r = runLocal(NLOPT_LN_COBYLA, Stage::kLocal, u0, o_.initial_step, o_.max_evaluations);
        break;
      case Algorithm::kBobyqa:
        r = runAuglagBobyqa(u0);
        break;
      case Algorithm::kIsres: {
        const int polish = o_.polishEvaluations();
        runIsres(u0, o_.max_evaluations - polish);
        if (abort_->load() || records_.empty()) break;
        const int best = bestIndex();
        r = runLocal(NLOPT_LN_COBYLA, Stage::kPolish, toUnit(records_[best].x),
                     0.25 * o_.initial_step, polish);
        break;
      }
    }
    summary_.nlopt_result = static_cast<int>(r);
    summary_.termination = error_ ? "stopped by an error" : terminationText(r);
    summary_.converged = converged(r);
    summary_.evaluations = static_cast<int>(records_.size());
    summary_.best = bestIndex();
  }

  std::vector<EvaluationRecord>& records() { return records_; }
  const StartSummary& summary() const { return summary_; }
  std::exception_ptr error() const { return error_; }

  static double objectiveCallback(unsigned n, const double* u, double* grad, void* data) {
    auto* self = static_cast<StartRun*>(data);
    if (grad) std::fill(grad, grad + n, 0.0);
    return self->at(u).result.objective;
  }

  static void constraintCallback(unsigned m, double* result, unsigned n, const double* u,
                                 double* grad, void* data) {
    auto* self = static_cast<StartRun*>(data);
    if (grad) std::fill(grad, grad + static_cast<std::size_t>(m) * n, 0.0);
    const EvaluationRecord& rec = self->at(u);
    for (unsigned i = 0; i < m; ++i) result[i] = rec.result.constraints[i];
  }

 private:
  std::vector<double> toUnit(const std::vector<double>& x) const {
    std::vector<double> u(x.size());
    for (std::size_t i = 0; i < x.size(); ++i)
      u[i] = std::clamp((x[i] - box_.lower[i]) / (box_.upper[i] - box_.lower[i]), 0.0, 1.0);
    return u;
  }

  std::vector<double> toPhysical(const double* u) const {
    std::vector<double> x(box_.lower.size());
    for (std::size_t i = 0; i < x.size(); ++i) {
      const double v = box_.lower[i] + std::clamp(u[i], 0.0, 1.0) * (box_.upper[i] - box_.lower[i]);
      x[i] = std::clamp(v, box_.lower[i], box_.upper[i]);
    }
    return x;
  }

  int bestIndex() const {
    int best = -1;
    for (std::size_t i = 0; i < records_.size(); ++i)
      if (best < 0 || better(records_[i], records_[static_cast<std::size_t>(best)]))
        best = static_cast<int>(i);
    return best;
  }

  /// Finite values, the right sizes, feasibility and violation.
  void finish(EvaluationRecord* rec) const {
    Evaluation& e = rec->result;
    const std::size_t m = static_cast<std::size_t>(problem_.constraintCount());
    const bool failed = e.status == EvaluationStatus::kFailed;
    if (e.constraints.size() != m) {
      if (!failed) {
        e.status = EvaluationStatus::kFailed;
        e.message = "the problem returned " + std::to_string(e.constraints.size()) +
                    " constraint values, expected " + std::to_string(m);
      }
      e.constraints.assign(m, o_.failure_constraint);
    }
    if (e.status == EvaluationStatus::kFailed || !std::isfinite(e.objective))
      e.objective = o_.failure_objective;
    for (double& g : e.constraints)
      if (e.status == EvaluationStatus::kFailed || !std::isfinite(g)) g = o_.failure_constraint;
    e.values.resize(static_cast<std::size_t>(problem_.valueCount()),
                    std::numeric_limits<double>::quiet_NaN());
    double v = 0.0;
    for (const double g : e.constraints) v = std::max(v, g);
    rec->violation = e.status == EvaluationStatus::kFailed ? std::max(v, o_.failure_constraint) : v;
    rec->feasible = e.status != EvaluationStatus::kFailed && v <= o_.constraint_tol;
  }

  /// The record at scaled point u: the last one when u repeats it (NLopt asks for the objective
  /// and then the constraints), else a new evaluation.
  const EvaluationRecord& at(const double* u) {
    const std::size_t n = box_.lower.size();
    if (!records_.empty() && std::equal(u, u + n, last_u_.begin())) return records_.back();
    last_u_.assign(u, u + n);
    EvaluationRecord rec;
    rec.start = start_;
    rec.index = static_cast<int>(records_.size());
    rec.stage = stage_;
    rec.x = toPhysical(u);
    // A failed record for a point left unevaluated, and NLopt asked to stop.
    auto stopped = [&](const char* message) -> const EvaluationRecord& {
      rec.result = Evaluation{};
      rec.result.status = EvaluationStatus::kFailed;
      rec.result.message = message;
      finish(&rec);
      if (current_) nlopt_force_stop(current_);
      records_.push_back(std::move(rec));
      return records_.back();
    };
    if (abort_->load()) return stopped("run stopped");  // another start failed: stop quickly
    const auto seen = cache_.find(rec.x);
    std::optional<Evaluation> replayed;
    if (seen != cache_.end()) {
      rec.result = records_[static_cast<std::size_t>(seen->second)].result;
      rec.repeat_of = seen->second;
      rec.source = EvaluationSource::kCached;
    } else if (hooks_.replay && (replayed = hooks_.replay(start_, rec.index, rec.x))) {
      rec.result = std::move(*replayed);
      rec.source = EvaluationSource::kReplayed;
    } else {
      try {
        throwIfCancelled();  // a cancellation point per evaluation (core/model/cancellation.hpp)
        rec.result = problem_.evaluate(rec.x, *workspace_);
      } catch (const Cancelled&) {
        // Like a kill: nothing journaled for this point; the run rethrows it after NLopt returns.
        if (!error_) error_ = std::current_exception();
        abort_->store(true);
        return stopped("run cancelled");
      } catch (const std::exception& e) {
        if (isProgrammingError(e)) {  // core/model/invariant.hpp: the run fails, loudly
          if (!error_) error_ = std::current_exception();
          abort_->store(true);
          return stopped("run failed on a programming error (rethrown)");
        }
        rec.result = Evaluation{};
        rec.result.status = EvaluationStatus::kFailed;
        rec.result.message = e.what();
      } catch (...) {  // not a std::exception: nothing this code throws, so not an outcome
        if (!error_) error_ = std::current_exception();
        abort_->store(true);
        return stopped("run failed on an unknown exception (rethrown)");
      }
      rec.source = EvaluationSource::kComputed;
    }
    finish(&rec);
    if (seen == cache_.end()) cache_.emplace(rec.x, rec.index);
    try {
      problem_.observe(rec.x, rec.result, *workspace_);
      if (hooks_.on_evaluation) hooks_.on_evaluation(rec);
    } catch (...) {
      if (!error_) error_ = std::current_exception();
      abort_->store(true);
      if (current_) nlopt_force_stop(current_);
    }
    records_.push_back(std::move(rec));
    return records_.back();
  }

  void setCommon(nlopt_opt opt, int max_evaluations) {
    const unsigned n = static_cast<unsigned>(box_.lower.size());
    const std::vector<double> zero(n, 0.0), one(n, 1.0);
    check(nlopt_set_lower_bounds(opt, zero.data()), "set_lower_bounds");
    check(nlopt_set_upper_bounds(opt, one.data()), "set_upper_bounds");
    check(nlopt_set_maxeval(opt, max_evaluations), "set_maxeval");
  }

  void setTolerances(nlopt_opt opt) {
    if (o_.xtol > 0.0) check(nlopt_set_xtol_abs1(opt, o_.xtol), "set_xtol_abs");
    if (o_.ftol_rel > 0.0) check(nlopt_set_ftol_rel(opt, o_.ftol_rel), "set_ftol_rel");
  }

  void addConstraints(nlopt_opt opt) {
    const unsigned m = static_cast<unsigned>(problem_.constraintCount());
    if (m == 0) return;
    const std::vector<double> tol(m, 0.0);
    check(nlopt_add_inequality_mconstraint(opt, m, &StartRun::constraintCallback, this,
                                           tol.data()),
          "add_inequality_mconstraint");
  }

  nlopt_result optimize(nlopt_opt opt, std::vector<double> u) {
    check(nlopt_set_min_objective(opt, &StartRun::objectiveCallback, this), "set_min_objective");
    double f = 0.0;
    current_ = opt;
    const nlopt_result r = nlopt_optimize(opt, u.data(), &f);
    current_ = nullptr;
    return r;
  }

  nlopt_result runLocal(nlopt_algorithm algorithm, Stage stage, const std::vector<double>& u0,
                        double step, int max_evaluations) {
    stage_ = stage;
    NloptHandle h(algorithm, static_cast<unsigned>(u0.size()));
    setCommon(h.opt, max_evaluations);
    setTolerances(h.opt);
    check(nlopt_set_initial_step1(h.opt, step), "set_initial_step");
    addConstraints(h.opt);
    return optimize(h.opt, u0);
  }

  nlopt_result runAuglagBobyqa(const std::vector<double>& u0) {
    stage_ = Stage::kLocal;
    const unsigned n = static_cast<unsigned>(u0.size());
    NloptHandle outer(NLOPT_AUGLAG, n);
    NloptHandle inner(NLOPT_LN_BOBYQA, n);
    setCommon(outer.opt, o_.max_evaluations);
    setTolerances(outer.opt);
    setTolerances(inner.opt);
    check(nlopt_set_initial_step1(inner.opt, o_.initial_step), "set_initial_step");
    check(nlopt_set_local_optimizer(outer.opt, inner.opt), "set_local_optimizer");
    addConstraints(outer.opt);
    return optimize(outer.opt, u0);
  }

  nlopt_result runIsres(const std::vector<double>& u0, int max_evaluations) {
    stage_ = Stage::kGlobal;
    NloptHandle h(NLOPT_GN_ISRES, static_cast<unsigned>(u0.size()));
    setCommon(h.opt, max_evaluations);
    if (o_.population > 0)
      check(nlopt_set_population(h.opt, static_cast<unsigned>(o_.population)), "set_population");
    addConstraints(h.opt);
    return optimize(h.opt, u0);
  }

  const Problem& problem_;
  const VariableBox& box_;
  const OptimizerOptions& o_;
  const OptimizerHooks& hooks_;
  int start_;
  std::atomic<bool>* abort_;
  std::unique_ptr<ProblemWorkspace> workspace_;
  std::vector<EvaluationRecord> records_;
  std::map<std::vector<double>, int> cache_;  // exact x -> first index
  std::vector<double> last_u_;
  Stage stage_ = Stage::kLocal;
  nlopt_opt current_ = nullptr;
  StartSummary summary_;
  std::exception_ptr error_;
};

std::string shortNumber(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

}  // namespace

std::vector<double> startPoint(const VariableBox& box, int start) {
  if (start == 0) return box.initial;
  std::vector<double> x(box.lower.size());
  for (std::size_t i = 0; i < x.size(); ++i)
    x[i] = box.lower[i] +
           radicalInverse(start, nthPrime(static_cast<int>(i))) * (box.upper[i] - box.lower[i]);
  return x;
}

std::string OptimizerSummary::BriefReport() const {
  const EvaluationRecord* b = bestRecord();
  std::string s = converged ? "converged" : "not converged";
  if (b)
    s += std::string(feasible ? ", best feasible objective " : ", no feasible point; best ") +
         shortNumber(b->result.objective) + " (start " + std::to_string(b->start) +
         ", evaluation " + std::to_string(b->index) + ")";
  s += ", " + std::to_string(history.size()) + " evaluations (" + std::to_string(computed) +
       " computed, " + std::to_string(cached) + " repeated, " + std::to_string(replayed) +
       " replayed, " + std::to_string(failed) + " failed) in " + std::to_string(starts.size()) +
       " start(s), " + shortNumber(wall_time_s) + " s";
  return s;
}

namespace {

void checkInputs(const Problem& problem, const VariableBox& box, const OptimizerOptions& options) {
  std::string why;
  if (!options.IsValid(&why)) throw std::invalid_argument("optimizer options: " + why);
  if (!box.IsValid(&why)) throw std::invalid_argument("variable box: " + why);
  if (problem.variableCount() != box.size())
    throw std::invalid_argument("the problem has " + std::to_string(problem.variableCount()) +
                                " variables, the box " + std::to_string(box.size()));
  if (problem.constraintCount() < 0) throw std::invalid_argument("negative constraint count");
  if (options.algorithm == Algorithm::kBobyqa && box.size() < 2)
    throw std::invalid_argument("bobyqa needs at least 2 variables");
}

}  // namespace

std::vector<EvaluationRecord> runStart(const Problem& problem, const VariableBox& box,
                                       const OptimizerOptions& options,
                                       const OptimizerHooks& hooks, int start) {
  checkInputs(problem, box, options);
  if (start < 0 || start >= options.starts)
    throw std::invalid_argument("runStart: expected a start in [0, " +
                                std::to_string(options.starts) + "), got " +
                                std::to_string(start));
  std::atomic<bool> abort{false};
  StartRun run(problem, box, options, hooks, start, &abort);
  run.run();
  if (run.error()) std::rethrow_exception(run.error());
  return std::move(run.records());
}

OptimizerSummary minimize(const Problem& problem, const VariableBox& box,
                          const OptimizerOptions& options, const OptimizerHooks& hooks) {
  const auto t0 = std::chrono::steady_clock::now();
  checkInputs(problem, box, options);

  const int starts = options.starts;
  std::vector<std::unique_ptr<StartRun>> runs(static_cast<std::size_t>(starts));
  std::atomic<bool> abort{false};
  std::atomic<int> next{0};
  std::mutex error_mutex;
  std::exception_ptr error;
  auto worker = [&] {
    for (int k = next.fetch_add(1); k < starts && !abort.load(); k = next.fetch_add(1)) {
      try {
        auto run = std::make_unique<StartRun>(problem, box, options, hooks, k, &abort);
        run->run();
        if (run->error()) {
          std::lock_guard<std::mutex> lock(error_mutex);
          if (!error) error = run->error();
        }
        runs[static_cast<std::size_t>(k)] = std::move(run);
      } catch (...) {
        std::lock_guard<std::mutex> lock(error_mutex);
        if (!error) error = std::current_exception();
        abort.store(true);
      }
    }
  };
  const int threads = std::min(options.threads, starts);
  if (threads <= 1) {
    worker();
  } else {
    std::vector<std::thread> pool;
    for (int t = 0; t < threads; ++t) pool.emplace_back(worker);
    for (std::thread& t : pool) t.join();
  }
  if (error) std::rethrow_exception(error);

  OptimizerSummary s;
  for (auto& run : runs) {
    s.starts.push_back(run->summary());
    for (EvaluationRecord& r : run->records()) {
      switch (r.source) {
        case EvaluationSource::kComputed: ++s.computed; break;
        case EvaluationSource::kCached: ++s.cached; break;
        case EvaluationSource::kReplayed: ++s.replayed; break;
      }
      if (r.result.status == EvaluationStatus::kFailed) ++s.failed;
      s.history.push_back(std::move(r));
    }
  }
  for (std::size_t i = 0; i < s.history.size(); ++i)
    if (s.best < 0 || better(s.history[i], s.history[static_cast<std::size_t>(s.best)]))
      s.best = static_cast<int>(i);
  const EvaluationRecord* b = s.bestRecord();
  s.feasible = b && b->feasible;
  s.converged = s.feasible && s.starts[static_cast<std::size_t>(b->start)].converged;
  if (!b) {
    s.message = "no evaluation";
  } else if (s.feasible) {
    s.message = "best feasible objective " + shortNumber(b->result.objective) + " at start " +
                std::to_string(b->start) + ", evaluation " + std::to_string(b->index) + "; start " +
                std::to_string(b->start) + ": " +
                s.starts[static_cast<std::size_t>(b->start)].termination;
  } else {
    s.message = "no feasible point in " + std::to_string(s.history.size()) +
                " evaluations; least violation " + shortNumber(b->violation) + " at start " +
                std::to_string(b->start) + ", evaluation " + std::to_string(b->index) + " (" +
                b->result.message + ")";
  }
  s.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return s;
}

}  // namespace orni::opt
