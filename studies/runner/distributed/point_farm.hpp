// Independent points spread over the ranks of a distributed run (docs/design.md 6: `mpirun -n N
// ornithopter run STUDY`): aero-map points, sweep and sensitivity points, optimisation starts.
//
// One interface, two worlds. Without a distributed backend (MPI absent, or one rank) nothing here
// is used and every command runs exactly as before. With one (studies/runner/mpi/, linked into the
// executable only), rank 0 is the master: it alone opens the journal, writes outputs and draws
// progress; it hands out the indices of `todo` in ascending order, in chunks, to whichever worker
// asks (dynamic load balancing: a stalled trim does not hold up the others), and receives each
// point's result as bytes. The other ranks are workers: they compute the points they are given
// (each chunk on `threads` threads, core/grid/point_pool.hpp) and write nothing.
//
// The result bytes are the point's journal payload (the exact, shortest round-trip serialisation
// that a resumed run reads back bit-identically), so the master builds its outputs the way a
// resumed run does from a complete journal: the bytes equal a `-j 1` run by construction, and a
// journal written under MPI resumes without it and the other way round.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace orni::studies {

/// One batch of independent points.
struct FarmJob {
  /// Master: the indices to compute, ascending (the resumed ones left out).
  std::vector<std::size_t> todo;
  /// Threads per rank (`-j M`): each chunk a worker gets runs on that many threads.
  int threads = 1;
  /// Master: when true, on_result is called in `todo` order (finished points wait for earlier
  /// ones) and no index is handed out more than `ahead_limit` positions of `todo` beyond the first
  /// point not yet delivered (bounded memory, like trim/aero_map_stream.hpp's lookahead).
  bool ordered = false;
  std::size_t ahead_limit = 0;  ///< 0: unlimited
  /// Master, optional: bytes sent with index i to its worker (e.g. journaled evaluations to
  /// replay); empty when not set.
  std::function<std::string(std::size_t index)> task_input;
  /// Workers: computes point `index` and returns its result bytes. Called concurrently for
  /// different indices (like PointWork); a numerical failure must be part of the result (a
  /// status), an escaping exception aborts the whole run.
  std::function<std::string(std::size_t index, const std::string& input)> work;
  /// Master: the result bytes of point `index`, on the master's thread, one call at a time.
  std::function<void(std::size_t index, std::string result)> on_result;
};

/// A way of running FarmJobs over several processes (the MPI one: studies/runner/mpi/).
class FarmBackend {
 public:
  virtual ~FarmBackend() = default;
  /// This process's rank, 0 .. ranks() - 1.
  virtual int rank() const = 0;
  /// Number of processes (>= 1).
  virtual int ranks() const = 0;
  /// Master: hands out job.todo and delivers every result; returns when all are delivered and
  /// every worker is released for the next job. Worker: serves the master until released.
  virtual void run(const FarmJob& job) = 0;
};

/// Installs the backend (main() of an MPI build, before any command; nullptr removes it). The
/// backend must outlive every call below.
void setFarmBackend(FarmBackend* backend);

/// True in a run over at least two processes: the commands that spread points use runFarm().
bool farmDistributed();
/// True on the process that writes files and prints: rank 0, or the only process.
bool farmWriter();
/// This process's rank (0 without a backend).
int farmRank();
/// Number of processes (1 without a backend).
int farmRanks();

/// Runs `job` over the ranks (see FarmBackend::run). std::logic_error when !farmDistributed().
void runFarm(const FarmJob& job);

}  // namespace orni::studies
