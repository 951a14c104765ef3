// The master's bookkeeping of a distributed run (point_farm.hpp), apart from any transport so that
// it is tested without MPI: which positions of `todo` the next chunk holds, and the delivery of
// results (in order when asked, holding back the hand-out when too far ahead).
//
// Chunks are guided: a chunk is ceil(remaining / (kFarmChunksPerWorker * workers)) points, at least
// `threads` (every thread of the worker busy) and at most kFarmMaxChunkPerThread * threads, so the
// first chunks are large (few messages for cheap points) and the last ones small (no worker left
// with a long tail while the others idle).
#pragma once

#include <cstddef>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace orni::studies {

/// Chunks aimed at per worker over the remaining points (guided self-scheduling).
constexpr std::size_t kFarmChunksPerWorker = 4;
/// Largest chunk, per thread of a worker.
constexpr std::size_t kFarmMaxChunkPerThread = 16;

class FarmSchedule {
 public:
  /// `points` positions to hand out to `workers` workers of `threads` threads each. ordered /
  /// ahead_limit as in FarmJob. std::invalid_argument when workers or threads < 1.
  FarmSchedule(std::size_t points, int workers, int threads, bool ordered,
               std::size_t ahead_limit);

  /// Positions of the next chunk (ascending, consecutive); empty when nothing may be handed out
  /// now (everything handed out, or the ordered window is full).
  std::vector<std::size_t> nextChunk();
  /// True when every position has been handed out.
  bool allHandedOut() const { return next_ == points_; }
  /// True when every position has been delivered.
  bool allDelivered() const { return delivered_ == points_; }

  /// Result of position `pos`: passed to `deliver` at once (unordered) or once every earlier
  /// position is delivered (ordered). std::logic_error for a position not handed out or twice.
  void received(std::size_t pos, std::string result,
                const std::function<void(std::size_t pos, std::string result)>& deliver);

 private:
  std::size_t points_, workers_, threads_;
  bool ordered_;
  std::size_t ahead_limit_;
  std::size_t next_ = 0;       // first position not handed out
  std::size_t delivered_ = 0;  // positions delivered (ordered: all below this one)
  std::vector<char> got_;      // per position: result received
  std::map<std::size_t, std::string> waiting_;  // ordered: received, waiting for an earlier one
};

}  // namespace orni::studies
