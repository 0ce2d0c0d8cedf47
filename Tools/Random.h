#pragma once
/// @file Random.h
/// @brief The interface of a seeded random stream, with platform-independent distributions.

#include <cstdint>

namespace thyrix {

/// A stream of random numbers.
///
/// Only raw 32-bit draws are virtual; every distribution is computed here from them with
/// fixed arithmetic, so a seed gives the same numbers on every compiler and standard library
/// (the distributions of `<random>` are implementation-defined and would not).
class Random {
 public:
  virtual ~Random() = default;

  /// The next raw draw, uniform over all 32-bit values.
  virtual std::uint32_t nextUint32() = 0;

  /// Uniform in [0, 1), with 53 random bits.
  double uniform() {
    const std::uint64_t high = nextUint32() >> 5;  // 27 bits
    const std::uint64_t low = nextUint32() >> 6;   // 26 bits
    return static_cast<double>((high << 26) | low) * 0x1.0p-53;
  }

  /// Uniform in [low, high).
  double uniform(double low, double high) { return low + (high - low) * uniform(); }

  /// Uniform integer in [0, n) for n > 0, without modulo bias (rejection sampling).
  std::uint32_t integer(std::uint32_t n) {
    const std::uint32_t limit = static_cast<std::uint32_t>(-n) % n;  // 2^32 mod n
    std::uint32_t draw = nextUint32();
    while (draw < limit) draw = nextUint32();
    return draw % n;
  }

  /// Uniform integer in [low, high], both included; requires low <= high.
  std::int32_t integer(std::int32_t low, std::int32_t high) {
    const auto span = static_cast<std::uint32_t>(static_cast<std::int64_t>(high) - low + 1);
    // The full range [INT32_MIN, INT32_MAX] has 2^32 values: span wraps to 0 and any draw fits.
    const std::uint32_t offset = span == 0 ? nextUint32() : integer(span);
    return static_cast<std::int32_t>(low + static_cast<std::int64_t>(offset));
  }

  /// True with probability p.
  bool bernoulli(double p) { return uniform() < p; }
};

}  // namespace thyrix
