#include "studies/runner/distributed/farm_schedule.hpp"

#include <algorithm>
#include <stdexcept>
#include <utility>

namespace orni::studies {

FarmSchedule::FarmSchedule(std::size_t points, int workers, int threads, bool ordered,
                           std::size_t ahead_limit)
    : points_(points),
      workers_(static_cast<std::size_t>(std::max(workers, 0))),
      threads_(static_cast<std::size_t>(std::max(threads, 0))),
      ordered_(ordered),
      ahead_limit_(ahead_limit),
      got_(points, 0) {
  if (workers < 1) throw std::invalid_argument("FarmSchedule: expected workers >= 1");
  if (threads < 1) throw std::invalid_argument("FarmSchedule: expected threads >= 1");
}

std::vector<std::size_t> FarmSchedule::nextChunk() {
  std::size_t end = points_;
  if (ordered_ && ahead_limit_ > 0) end = std::min(end, delivered_ + ahead_limit_);
  if (next_ >= end) return {};
  const std::size_t remaining = points_ - next_;
  const std::size_t per = kFarmChunksPerWorker * workers_;
  std::size_t size = (remaining + per - 1) / per;
  size = std::max(size, threads_);
  size = std::min(size, kFarmMaxChunkPerThread * threads_);
  size = std::min(size, end - next_);
  std::vector<std::size_t> chunk(size);
  for (std::size_t k = 0; k < size; ++k) chunk[k] = next_ + k;
  next_ += size;
  return chunk;
}

void FarmSchedule::received(
    std::size_t pos, std::string result,
    const std::function<void(std::size_t pos, std::string result)>& deliver) {
  if (pos >= next_ || got_[pos])
    throw std::logic_error("distributed run: result of point position " + std::to_string(pos) +
                           (pos >= next_ ? " that was never handed out" : " received twice"));
  got_[pos] = 1;
  if (!ordered_) {
    ++delivered_;
    deliver(pos, std::move(result));
    return;
  }
  waiting_.emplace(pos, std::move(result));
  for (auto it = waiting_.find(delivered_); it != waiting_.end(); it = waiting_.find(delivered_)) {
    std::string r = std::move(it->second);
    waiting_.erase(it);
    ++delivered_;
    deliver(delivered_ - 1, std::move(r));
  }
}

}  // namespace orni::studies
