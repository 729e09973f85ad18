// Counter-based random numbers for the truth: a sample's numbers depend only on its pixel
// and sample index, so results do not depend on thread scheduling.
#pragma once

#include <cstdint>

namespace shadows {

// lowbias32 (C. Wellons).
inline std::uint32_t hash32(std::uint32_t x) {
  x ^= x >> 16;
  x *= 0x7feb352dU;
  x ^= x >> 15;
  x *= 0x846ca68bU;
  x ^= x >> 16;
  return x;
}

// [0, 1) from the hash's top 24 bits.
inline float unitFloat(std::uint32_t h) {
  return static_cast<float>(h >> 8) * 0x1p-24f;
}

}  // namespace shadows
