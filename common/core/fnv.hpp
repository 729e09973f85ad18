// 64-bit FNV-1a: a hash of bytes for cache keys (the truth job's, what a lesson's measurement
// depends on), where a changed byte must change the key and nothing needs to be secret.
#pragma once

#include <cstddef>
#include <cstdint>

namespace shadows {

struct Fnv {
  std::uint64_t h = 0xcbf29ce484222325ull;
  void add(const void* data, std::size_t size) {
    const auto* b = static_cast<const std::uint8_t*>(data);
    for (std::size_t i = 0; i < size; ++i) h = (h ^ b[i]) * 0x100000001b3ull;
  }
  template <typename T>
  void add(const T& value) {
    add(&value, sizeof value);
  }
};

}  // namespace shadows
