#pragma once
// Deterministic integer hashing for procedural content: identical on every platform and run, so frame N of a
// scene is the same everywhere.

#include <cstdint>

namespace photopic {

/// A 32-bit integer hash (Wellons' "lowbias32", 2018): cheap and well mixed.
constexpr std::uint32_t hash32(std::uint32_t x) {
    x ^= x >> 16;
    x *= 0x7feb352dU;
    x ^= x >> 15;
    x *= 0x846ca68bU;
    x ^= x >> 16;
    return x;
}

} // namespace photopic
