#include "studies/runner/distributed/point_farm.hpp"

#include <stdexcept>

namespace orni::studies {

namespace {
FarmBackend* g_backend = nullptr;  // set once by main() before any command
}  // namespace

void setFarmBackend(FarmBackend* backend) { g_backend = backend; }

bool farmDistributed() { return g_backend != nullptr && g_backend->ranks() > 1; }

bool farmWriter() { return g_backend == nullptr || g_backend->rank() == 0; }

int farmRank() { return g_backend ? g_backend->rank() : 0; }

int farmRanks() { return g_backend ? g_backend->ranks() : 1; }

void runFarm(const FarmJob& job) {
  if (!farmDistributed()) throw std::logic_error("runFarm: not a distributed run");
  g_backend->run(job);
}

}  // namespace orni::studies
