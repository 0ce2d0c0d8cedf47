#pragma once
/// @file MTRandom.h
/// @brief The Mersenne Twister as a Thyrix random stream.

#include <Tools/Random.h>

#include <cstdint>
#include <random>

namespace thyrix {

/// A Mersenne Twister (MT19937) stream, seeded explicitly.
///
/// `std::mt19937` is specified bit for bit by the standard, so a seed reproduces the same
/// stream everywhere. Each simulator or controller owns its own stream: there is no global one.
class MTRandom final : public Random {
 public:
  /// A stream started from @p seed.
  explicit MTRandom(std::uint32_t seed = 5489u);

  /// Restarts the stream from @p seed.
  void seed(std::uint32_t seed);

  std::uint32_t nextUint32() override;

 private:
  std::mt19937 engine_;
};

}  // namespace thyrix
