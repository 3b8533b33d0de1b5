#pragma once
/// \file
/// Hashing for the core's own tables: splitmix64, whose every input bit reaches every output
/// bit. A bare product does not: coordinates on a grid (whole numbers) end in ~40 zero bits,
/// and a table that masks the low bits put a 2M-triangle grid's corners in a few slots.

#include <bit>
#include <cstdint>

#include "meshedit/core/math.h"

namespace meshedit {

/// splitmix64 (Steele, Lea and Flood 2014): the increment, then its finaliser.
constexpr std::uint64_t splitmix64(std::uint64_t x) {
    x += 0x9e3779b97f4a7c15ull;
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
    return x ^ (x >> 31);
}

/// A position's hash from the bits of its coordinates (equal bits, equal hash).
inline std::uint64_t position_hash(const Vec3& p) {
    return splitmix64(std::bit_cast<std::uint64_t>(p.x) ^
                      splitmix64(std::bit_cast<std::uint64_t>(p.y) ^
                                 splitmix64(std::bit_cast<std::uint64_t>(p.z))));
}

}  // namespace meshedit
