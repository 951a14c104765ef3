#include "studies/runner/mpi/mpi_farm.hpp"

// The C API only: the MPI C++ bindings (deprecated, a library of their own) stay out.
#define OMPI_SKIP_MPICXX 1
#define MPICH_SKIP_MPICXX 1
#include <mpi.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "core/grid/point_pool.hpp"
#include "studies/runner/distributed/farm_messages.hpp"
#include "studies/runner/distributed/farm_schedule.hpp"

// Open MPI's handles are macros with C casts (MPI_COMM_WORLD, MPI_BYTE, ...).
#pragma GCC diagnostic ignored "-Wold-style-cast"

namespace orni::studies {

namespace {

constexpr int kTagResult = 1;  // worker -> master: finished chunk (and request for more)
constexpr int kTagTask = 2;    // master -> worker: next chunk, or empty = released

void check(int rc, const char* what) {
  if (rc != MPI_SUCCESS) throw std::runtime_error(std::string("MPI: ") + what + " failed");
}

void pollSleep(long* sleep_us) {
  const timespec t{0, *sleep_us * 1000L};
  nanosleep(&t, nullptr);
  *sleep_us = std::min(*sleep_us * 2, kMpiPollSleepMaxUs);
}

/// The next message with `tag` from `source` (MPI_ANY_SOURCE allowed), polling; *from = sender.
std::string receive(int source, int tag, int* from) {
  MPI_Status status;
  int flag = 0;
  long sleep_us = 1;
  for (;;) {
    check(MPI_Iprobe(source, tag, MPI_COMM_WORLD, &flag, &status), "MPI_Iprobe");
    if (flag) break;
    pollSleep(&sleep_us);
  }
  int count = 0;
  check(MPI_Get_count(&status, MPI_BYTE, &count), "MPI_Get_count");
  std::string bytes(static_cast<std::size_t>(count), '\0');
  check(MPI_Recv(bytes.data(), count, MPI_BYTE, status.MPI_SOURCE, tag, MPI_COMM_WORLD,
                 MPI_STATUS_IGNORE),
        "MPI_Recv");
  if (from) *from = status.MPI_SOURCE;
  return bytes;
}

void send(const std::string& bytes, int dest, int tag) {
  if (bytes.size() > static_cast<std::size_t>(INT32_MAX))
    throw std::runtime_error("MPI: message of " + std::to_string(bytes.size()) +
                             " bytes exceeds 2 GiB");
  check(MPI_Send(bytes.data(), static_cast<int>(bytes.size()), MPI_BYTE, dest, tag,
                 MPI_COMM_WORLD),
        "MPI_Send");
}

}  // namespace

bool launchedByMpi() {
  for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK", "PMI_RANK",
                        "MPI_LOCALNRANKS", "HYDRA_CONTROL_FD"})
    if (std::getenv(v) != nullptr) return true;
  return false;
}

MpiFarm::MpiFarm(int* argc, char*** argv) {
  int provided = 0;
  check(MPI_Init_thread(argc, argv, MPI_THREAD_FUNNELED, &provided), "MPI_Init_thread");
  if (provided < MPI_THREAD_FUNNELED) {
    std::fprintf(stderr, "ornithopter: error: the MPI library does not support threads "
                         "(MPI_THREAD_FUNNELED)\n");
    MPI_Abort(MPI_COMM_WORLD, 1);
  }
  check(MPI_Comm_rank(MPI_COMM_WORLD, &rank_), "MPI_Comm_rank");
  check(MPI_Comm_size(MPI_COMM_WORLD, &ranks_), "MPI_Comm_size");
}

MpiFarm::~MpiFarm() { MPI_Finalize(); }

int MpiFarm::finish(int exit_status) {
  if (exit_status != 0 && ranks_ > 1) {
    std::fflush(stdout);
    std::fflush(stderr);
    MPI_Abort(MPI_COMM_WORLD, exit_status);
  }
  // A polite barrier: MPI_Finalize may spin while the master still works on a sequential study.
  MPI_Request request;
  check(MPI_Ibarrier(MPI_COMM_WORLD, &request), "MPI_Ibarrier");
  long sleep_us = 1;
  for (int done = 0;;) {
    check(MPI_Test(&request, &done, MPI_STATUS_IGNORE), "MPI_Test");
    if (done) break;
    pollSleep(&sleep_us);
  }
  return exit_status;
}

void MpiFarm::run(const FarmJob& job) {
  if (rank_ == 0)
    runMaster(job);
  else
    runWorker(job);
}

namespace {

/// CPU time of this process (s): the master's own cost, polling included.
double processCpuSeconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

}  // namespace

void MpiFarm::runMaster(const FarmJob& job) {
  const auto t0 = std::chrono::steady_clock::now();
  const double cpu0_s = processCpuSeconds();
  const int workers = ranks_ - 1;
  FarmSchedule schedule(job.todo.size(), workers, job.threads, job.ordered, job.ahead_limit);
  std::vector<int> waiting;  // workers that asked while the ordered window was full
  int released = 0;
  std::size_t messages = 0, bytes = 0, chunks = 0;
  double busy_s = 0.0;  // the master's own work: decode, deliver, encode, send

  auto deliver = [&](std::size_t pos, std::string result) {
    job.on_result(job.todo[pos], std::move(result));
  };
  // Gives worker w its next chunk or releases it; false when it must wait (window full).
  auto serve = [&](int w) {
    const std::vector<std::size_t> chunk = schedule.nextChunk();
    if (chunk.empty() && !schedule.allHandedOut()) return false;
    FarmItems items;
    for (const std::size_t pos : chunk) {
      const std::size_t index = job.todo[pos];
      items.emplace_back(index, job.task_input ? job.task_input(index) : std::string());
    }
    const std::string message = encodeFarmItems(items);
    send(message, w, kTagTask);
    ++messages;
    bytes += message.size();
    if (chunk.empty())
      ++released;
    else
      ++chunks;
    return true;
  };

  while (released < workers) {
    int from = -1;
    const std::string message = receive(MPI_ANY_SOURCE, kTagResult, &from);
    const auto t_busy = std::chrono::steady_clock::now();
    ++messages;
    bytes += message.size();
    for (auto& [index, result] : decodeFarmItems(message.data(), message.size())) {
      const auto it = std::lower_bound(job.todo.begin(), job.todo.end(), index);
      if (it == job.todo.end() || *it != index)
        throw std::runtime_error("distributed run: rank " + std::to_string(from) +
                                 " returned point " + std::to_string(index) +
                                 ", which was not handed out");
      schedule.received(static_cast<std::size_t>(it - job.todo.begin()), std::move(result),
                        deliver);
    }
    waiting.push_back(from);
    waiting.erase(std::remove_if(waiting.begin(), waiting.end(), serve), waiting.end());
    busy_s += std::chrono::duration<double>(std::chrono::steady_clock::now() - t_busy).count();
  }
  if (!schedule.allDelivered())
    throw std::logic_error("distributed run: workers released before every point was delivered");
  const double wall_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const double cpu_s = processCpuSeconds() - cpu0_s;
  const std::size_t n = job.todo.size();
  std::fprintf(stderr,
               "mpi: %zu points on %d worker rank(s) x %d thread(s) in %zu chunks, %.3g s: master "
               "%zu messages, %zu bytes, busy %.3g ms (%.3g us per point), CPU %.3g ms\n",
               n, workers, job.threads, chunks, wall_s, messages, bytes, 1e3 * busy_s,
               n ? 1e6 * busy_s / static_cast<double>(n) : 0.0, 1e3 * cpu_s);
}

void MpiFarm::runWorker(const FarmJob& job) {
  std::string message = encodeFarmItems({});  // the first request
  for (;;) {
    send(message, 0, kTagResult);
    const std::string task = receive(0, kTagTask, nullptr);
    const FarmItems items = decodeFarmItems(task.data(), task.size());
    if (items.empty()) return;  // released
    std::vector<std::string> results(items.size());
    std::vector<std::size_t> slots(items.size());
    for (std::size_t k = 0; k < slots.size(); ++k) slots[k] = k;
    runPoints(slots, job.threads,
              [&](std::size_t k) { results[k] = job.work(items[k].first, items[k].second); });
    FarmItems done;
    done.reserve(items.size());
    for (std::size_t k = 0; k < items.size(); ++k)
      done.emplace_back(items[k].first, std::move(results[k]));
    message = encodeFarmItems(done);
  }
}

}  // namespace orni::studies
