#pragma once
/// @file SeedDerivation.h
/// @brief The seed of one evaluation, derived from (run seed, generation, individual, trial).

#include <cstdint>

namespace thyrix {

/// SplitMix64's finalizer (Steele, Lea and Flood, 2014): a bijection of 64-bit words whose
/// outputs for neighbouring inputs look independent.
[[nodiscard]] constexpr std::uint64_t splitMix64(std::uint64_t x) noexcept {
  x += 0x9E3779B97F4A7C15ull;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
  return x ^ (x >> 31);
}

/// The seed of trial @p trial of individual @p individual in generation @p generation of the
/// run seeded by @p runSeed: a splitmix64 chain,
/// `h = splitMix64(runSeed); h = splitMix64(h ^ generation); h = splitMix64(h ^ individual);
/// h = splitMix64(h ^ trial)`. It depends on these four numbers alone (not on threads or on
/// the order of evaluation), so a run is reproduced from its seed.
[[nodiscard]] constexpr std::uint64_t deriveSeed(std::uint64_t runSeed, std::uint64_t generation,
                                                 std::uint64_t individual,
                                                 std::uint64_t trial) noexcept {
  std::uint64_t h = splitMix64(runSeed);
  h = splitMix64(h ^ generation);
  h = splitMix64(h ^ individual);
  return splitMix64(h ^ trial);
}

}  // namespace thyrix
