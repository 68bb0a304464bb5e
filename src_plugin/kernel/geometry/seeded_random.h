// Counter-based random numbers: a value is a pure function of (seed, key, stream), so a
// particle's shape and orientation depend on its atom tag and the deck's seeds only, never on
// the number of MPI ranks, the order atoms are created in, or the standard library (std::
// distributions differ between implementations; these do not).
#pragma once

#include <cstdint>

namespace tri {

// SplitMix64 finaliser (Steele, Lea, Flood 2014): a bijective 64-bit mix with full avalanche.
constexpr std::uint64_t mix64(std::uint64_t z) {
  z += 0x9e3779b97f4a7c15ULL;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

constexpr std::uint64_t seeded_bits(std::uint64_t seed, std::uint64_t key, std::uint64_t stream) {
  return mix64(mix64(mix64(seed) ^ key) ^ stream);
}

// Uniform in [0, 1), 53 random bits.
constexpr double seeded_uniform(std::uint64_t seed, std::uint64_t key, std::uint64_t stream) {
  return static_cast<double>(seeded_bits(seed, key, stream) >> 11) * 0x1.0p-53;
}

// Uniform integer in [0, n), n > 0 (multiply-shift: no modulo bias worth speaking of for
// the small n of a shape list).
constexpr int seeded_index(std::uint64_t seed, std::uint64_t key, int n) {
  return static_cast<int>(
      (static_cast<unsigned __int128>(seeded_bits(seed, key, 0)) * static_cast<unsigned>(n)) >> 64);
}

} // namespace tri
