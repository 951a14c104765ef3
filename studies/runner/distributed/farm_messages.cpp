#include "studies/runner/distributed/farm_messages.hpp"

#include <cstdint>
#include <cstring>
#include <stdexcept>

namespace orni::studies {

namespace {

void putU64(std::string* out, std::uint64_t v) {
  char b[sizeof v];
  std::memcpy(b, &v, sizeof v);
  out->append(b, sizeof v);
}

std::uint64_t getU64(const char* data, std::size_t size, std::size_t* at) {
  std::uint64_t v = 0;
  if (size - *at < sizeof v)
    throw std::runtime_error("distributed run: truncated message (" + std::to_string(size) +
                             " bytes)");
  std::memcpy(&v, data + *at, sizeof v);
  *at += sizeof v;
  return v;
}

}  // namespace

std::string encodeFarmItems(const FarmItems& items) {
  std::size_t bytes = 8;
  for (const auto& item : items) bytes += 16 + item.second.size();
  std::string out;
  out.reserve(bytes);
  putU64(&out, items.size());
  for (const auto& [index, text] : items) {
    putU64(&out, index);
    putU64(&out, text.size());
    out += text;
  }
  return out;
}

FarmItems decodeFarmItems(const char* data, std::size_t size) {
  std::size_t at = 0;
  const std::uint64_t count = getU64(data, size, &at);
  if (count > size / 16)
    throw std::runtime_error("distributed run: message claims " + std::to_string(count) +
                             " items in " + std::to_string(size) + " bytes");
  FarmItems items;
  items.reserve(count);
  for (std::uint64_t k = 0; k < count; ++k) {
    const std::uint64_t index = getU64(data, size, &at);
    const std::uint64_t length = getU64(data, size, &at);
    if (size - at < length)
      throw std::runtime_error("distributed run: truncated message item (" +
                               std::to_string(length) + " bytes announced)");
    items.emplace_back(index, std::string(data + at, length));
    at += length;
  }
  if (at != size)
    throw std::runtime_error("distributed run: " + std::to_string(size - at) +
                             " stray bytes after the message");
  return items;
}

}  // namespace orni::studies
