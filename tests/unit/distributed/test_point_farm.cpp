// The transport-free parts of distributed runs (studies/runner/distributed/): the message bytes
// round-trip and reject truncated or padded messages; the master's schedule hands out every
// position exactly once in ascending chunks (guided sizes, at least `threads`), holds the hand-out
// when the ordered window is full, delivers in order when asked and rejects a duplicate result;
// without a backend nothing is distributed.
#include <gtest/gtest.h>

#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "studies/runner/distributed/farm_messages.hpp"
#include "studies/runner/distributed/farm_schedule.hpp"
#include "studies/runner/distributed/point_farm.hpp"

namespace orni::studies {
namespace {

TEST(FarmMessages, RoundTripIncludingEmptyAndBinaryItems) {
  const FarmItems items = {{0, ""}, {7, "abc\n"}, {123456789012ULL, std::string("a\0b", 3)}};
  const std::string bytes = encodeFarmItems(items);
  EXPECT_EQ(decodeFarmItems(bytes.data(), bytes.size()), items);
  const std::string none = encodeFarmItems({});
  EXPECT_EQ(none.size(), 8u);
  EXPECT_TRUE(decodeFarmItems(none.data(), none.size()).empty());
}

TEST(FarmMessages, RejectsTruncatedOrPaddedMessages) {
  const std::string bytes = encodeFarmItems({{1, "hello"}, {2, "world"}});
  for (std::size_t cut = 0; cut < bytes.size(); ++cut)
    EXPECT_THROW(decodeFarmItems(bytes.data(), cut), std::runtime_error) << cut;
  const std::string padded = bytes + "x";
  EXPECT_THROW(decodeFarmItems(padded.data(), padded.size()), std::runtime_error);
}

/// Hands out everything (results delivered right after each chunk); the chunks in order.
std::vector<std::vector<std::size_t>> drain(FarmSchedule* s, std::vector<std::size_t>* delivered) {
  std::vector<std::vector<std::size_t>> chunks;
  for (std::vector<std::size_t> c = s->nextChunk(); !c.empty(); c = s->nextChunk()) {
    chunks.push_back(c);
    for (const std::size_t pos : c)
      s->received(pos, std::to_string(pos),
                  [&](std::size_t p, std::string r) {
                    EXPECT_EQ(r, std::to_string(p));
                    delivered->push_back(p);
                  });
  }
  return chunks;
}

TEST(FarmSchedule, EveryPositionOnceInGuidedChunks) {
  FarmSchedule s(180, 2, 1, false, 0);
  std::vector<std::size_t> delivered;
  const auto chunks = drain(&s, &delivered);
  EXPECT_TRUE(s.allHandedOut());
  EXPECT_TRUE(s.allDelivered());
  std::vector<std::size_t> all;
  for (const auto& c : chunks) all.insert(all.end(), c.begin(), c.end());
  ASSERT_EQ(all.size(), 180u);
  for (std::size_t i = 0; i < all.size(); ++i) EXPECT_EQ(all[i], i);
  // Guided: the first chunk is remaining / (4 workers' worth) capped at 16 per thread, the last
  // ones are single points.
  EXPECT_EQ(chunks.front().size(), 16u);
  EXPECT_EQ(chunks.back().size(), 1u);
  for (std::size_t k = 1; k < chunks.size(); ++k)
    EXPECT_LE(chunks[k].size(), chunks[k - 1].size());
}

TEST(FarmSchedule, ChunksKeepEveryThreadBusy) {
  FarmSchedule s(10, 4, 3, false, 0);
  const std::vector<std::size_t> c = s.nextChunk();
  EXPECT_EQ(c.size(), 3u);
}

TEST(FarmSchedule, OrderedWindowHoldsTheHandOutAndDeliversInOrder) {
  FarmSchedule s(10, 2, 1, true, 4);
  std::vector<std::size_t> got;
  auto deliver = [&](std::size_t p, std::string) { got.push_back(p); };
  std::vector<std::size_t> out;
  for (std::vector<std::size_t> c = s.nextChunk(); !c.empty(); c = s.nextChunk())
    out.insert(out.end(), c.begin(), c.end());
  EXPECT_EQ(out, (std::vector<std::size_t>{0, 1, 2, 3}));  // the window is full
  EXPECT_FALSE(s.allHandedOut());
  s.received(2, "", deliver);
  s.received(1, "", deliver);
  EXPECT_TRUE(got.empty());  // waiting for position 0
  EXPECT_TRUE(s.nextChunk().empty());
  s.received(0, "", deliver);
  EXPECT_EQ(got, (std::vector<std::size_t>{0, 1, 2}));
  EXPECT_FALSE(s.nextChunk().empty());  // the window moved on
  EXPECT_THROW(s.received(1, "", deliver), std::logic_error);  // twice
  EXPECT_THROW(s.received(9, "", deliver), std::logic_error);  // never handed out
}

TEST(FarmSchedule, RejectsNoWorkersOrThreads) {
  EXPECT_THROW(FarmSchedule(5, 0, 1, false, 0), std::invalid_argument);
  EXPECT_THROW(FarmSchedule(5, 1, 0, false, 0), std::invalid_argument);
}

TEST(PointFarm, WithoutABackendNothingIsDistributed) {
  EXPECT_FALSE(farmDistributed());
  EXPECT_TRUE(farmWriter());
  EXPECT_EQ(farmRank(), 0);
  EXPECT_EQ(farmRanks(), 1);
  EXPECT_THROW(runFarm(FarmJob{}), std::logic_error);
}

}  // namespace
}  // namespace orni::studies
