// The bytes a distributed run's master and workers exchange (point_farm.hpp): a list of
// (index, bytes) items. A task message carries the indices of a chunk with their inputs (an empty
// list releases the worker), a result message the indices of the finished chunk with their
// result bytes. Layout, little-endian as the machine is (every rank runs the same binary):
//   u64 count, then per item: u64 index, u64 length, `length` bytes.
#pragma once

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace orni::studies {

using FarmItems = std::vector<std::pair<std::size_t, std::string>>;

/// The message bytes of `items`.
std::string encodeFarmItems(const FarmItems& items);
/// The items of a message; std::runtime_error when the bytes are not a whole message.
FarmItems decodeFarmItems(const char* data, std::size_t size);

}  // namespace orni::studies
