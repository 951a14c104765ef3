#include "tethered_run.hpp"

#include <pybind11/numpy.h>

#include <chrono>
#include <memory>
#include <optional>
#include <vector>

#include "core/dynamics/tethered_simulation.hpp"
#include "studies/runner/commands/simulate_command.hpp"

namespace py = pybind11;

namespace orni::python {

namespace {

/// Thrown out of the run (through simulateTethered) when Python has a pending signal (Ctrl-C);
/// the KeyboardInterrupt stays set in the thread state and is raised once the GIL is back.
struct Interrupted {};

/// Rows straight into the buffer that becomes the NumPy array; a Python signal check per cycle.
class HistoryBuffer : public TetheredRunObserver {
 public:
  HistoryBuffer(std::vector<double>* rows, bool keep) : rows_(rows), keep_(keep) {}
  void onSample(double t_s, double delta_M_rad, const LoadSample& loads) override {
    if (!keep_) return;
    const std::size_t at = rows_->size();
    rows_->resize(at + studies::kHistoryColumns);  // capacity reserved: no reallocation
    studies::historyRow(t_s, delta_M_rad, loads, rows_->data() + at);
  }
  void onCycle(int, const CycleMeans&) override {
    py::gil_scoped_acquire gil;
    if (PyErr_CheckSignals() != 0) throw Interrupted{};
  }

 private:
  std::vector<double>* rows_;
  bool keep_;
};

}  // namespace

py::tuple simulateTetheredStudy(const VehicleObject& vehicle, const studies::Study& study,
                                bool histories) {
  auto rows = std::make_unique<std::vector<double>>();
  std::string summary_text;
  {
    py::gil_scoped_release release;
    try {
      const auto t0 = std::chrono::steady_clock::now();
      const std::shared_ptr<const FlightCoreModel> whole = vehicle.coreModel();
      std::optional<FlightCoreModel> wing_alone;
      if (study.simulate().wing_only) wing_alone.emplace(study.vehicle.mainWingAlone());
      const FlightCoreModel& model = wing_alone ? *wing_alone : *whole;
      // Without histories the run samples nothing (as BM_TetheredRfw10Cycles): the summary then
      // lacks the last-cycle harmonics and the constrained flight test, which need the samples.
      SimulationOptions opts = study.simulate().options;
      opts.record_history = histories;
      const std::size_t samples =
          static_cast<std::size_t>(opts.cycles) * static_cast<std::size_t>(opts.samples_per_cycle) +
          1;
      if (histories) rows->reserve(samples * studies::kHistoryColumns);
      HistoryBuffer buffer(rows.get(), histories);
      TimeHistory history;
      const SimulationSummary s =
          simulateTethered(model, study.point, opts, histories ? &history : nullptr, &buffer);
      const double wall_s =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      std::optional<ConstrainedFlightTest> cft;
      if (histories && s.status != SimulationStatus::kFailed)
        cft = lastCycleConstrainedFlightTest(model, study.point, history, opts.samples_per_cycle);
      summary_text =
          studies::tetheredSummary(study, model, s, opts, history, cft, wall_s, nullptr).toString();
    } catch (const Interrupted&) {
      // fall through: the GIL is re-acquired below and the pending KeyboardInterrupt raised
      summary_text.clear();
      rows.reset();
    }
  }
  if (!rows) throw py::error_already_set();
  if (!histories) return py::make_tuple(py::str(summary_text), py::none());
  // The array owns the vector (a capsule frees it): no copy of the samples.
  const py::ssize_t n = static_cast<py::ssize_t>(rows->size() / studies::kHistoryColumns);
  std::vector<double>* raw = rows.release();
  py::capsule owner(raw, [](void* p) { delete static_cast<std::vector<double>*>(p); });
  py::array_t<double> array({n, static_cast<py::ssize_t>(studies::kHistoryColumns)},
                            raw->data(), owner);
  return py::make_tuple(py::str(summary_text), array);
}

}  // namespace orni::python
