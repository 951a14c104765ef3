// The MPI backend of distributed runs (studies/runner/distributed/point_farm.hpp), compiled into
// the executable only and only when CMake finds MPI (ORNI_MPI, top-level CMakeLists.txt): the
// library orni_studies, the Python module and the installed package never link MPI.
//
// MPI is initialised only when the process was started by an MPI launcher (mpirun/mpiexec of Open
// MPI or MPICH, srun under Slurm: their environment variables are checked); a plain
// `ornithopter ...` calls no MPI function at all and runs exactly as a build without MPI.
//
// Transport. Rank 0 is the master, the others are workers (FarmSchedule decides the chunks). A
// worker sends a result message (its finished chunk, empty at first) that is also its request for
// more; the master answers with a task message (the next chunk, or an empty list that releases
// the worker). Two messages per chunk. Every wait polls (MPI_Iprobe / MPI_Test) with a sleep of at
// most kMpiPollSleepMaxUs in between rather than blocking in MPI: Open MPI's blocking calls spin
// and would take a core from the workers on a machine with as many ranks as cores.
//
// Failures. A worker's numerical failure is its point's status (the commands' work functions);
// an exception on any rank, or a non-zero exit status of any rank, ends the job with MPI_Abort;
// a lost rank ends it through the launcher. Only rank 0 writes the journal, one whole line per
// write, so it stays valid and a rerun (with or without mpirun) resumes from it.
#pragma once

#include <cstddef>

#include "studies/runner/distributed/point_farm.hpp"

namespace orni::studies {

/// Longest sleep between two polls of a waiting rank (microseconds).
constexpr long kMpiPollSleepMaxUs = 200;

/// True when the environment says an MPI launcher started this process.
bool launchedByMpi();

class MpiFarm : public FarmBackend {
 public:
  /// MPI_Init_thread (funnelled: only the main thread calls MPI). Call only when launchedByMpi().
  MpiFarm(int* argc, char*** argv);
  /// MPI_Finalize (after finish()).
  ~MpiFarm() override;
  MpiFarm(const MpiFarm&) = delete;
  MpiFarm& operator=(const MpiFarm&) = delete;

  int rank() const override { return rank_; }
  int ranks() const override { return ranks_; }
  void run(const FarmJob& job) override;

  /// The end of main(): with exit status 0 every rank waits (politely) for the others and
  /// returns 0; any other status aborts the whole job (MPI_Abort) with that status, so that no
  /// rank waits forever for one that gave up.
  int finish(int exit_status);

 private:
  void runMaster(const FarmJob& job);
  void runWorker(const FarmJob& job);
  int rank_ = 0, ranks_ = 1;
};

}  // namespace orni::studies
