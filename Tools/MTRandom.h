#pragma once
/// @file MTRandom.h
/// @brief The Mersenne Twister as a Thyrix random stream, with a portable normal distribution
///        and a state that can be saved and restored exactly.

#include <Tools/Random.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <iosfwd>

namespace thyrix {

/// A Mersenne Twister (MT19937) stream, seeded explicitly.
///
/// MT19937 is specified bit for bit (Matsumoto and Nishimura 1998; `std::mt19937` is the same
/// generator), so a seed reproduces the same stream everywhere. It is written out here rather
/// than wrapped so that its state can be saved in a form that every platform reads alike (the
/// standard libraries' text forms of `std::mt19937` differ). Each simulator or controller owns its
/// own stream: there is no global one. normal() is computed from the stream's own uniform draws
/// with basic arithmetic only, so it too gives the same numbers on every platform.
class MTRandom final : public Random {
 public:
  /// Everything that determines the rest of a stream: the generator and the normal draw that
  /// normal() keeps for its next call. Restoring it continues the stream exactly.
  struct State {
    std::array<std::uint32_t, 624> words{};  ///< the generator's state vector
    std::uint32_t index = 624;               ///< the next word to temper (624: twist first)
    bool hasSpare = false;                   ///< whether a normal draw is kept for the next call
    double spare = 0;                        ///< that draw (0 when there is none)

    /// Writes the state as text: a line `mt19937-state 1`, a line with the index then the 624
    /// words in decimal, then a line `spare 0|1 HEXFLOAT`.
    void write(std::ostream& out) const;
    /// Reads what write() wrote, stopping after it (so a state can sit inside a larger file).
    /// @throws std::runtime_error saying what is wrong (another header, a missing or
    ///         out-of-range index or word, a bad spare)
    static State read(std::istream& in);

    /// Same generator state and same kept draw.
    friend bool operator==(const State&, const State&) = default;
  };

  /// A stream started from @p seed.
  explicit MTRandom(std::uint32_t seed = 5489u);

  /// Restarts the stream from @p seed (and forgets any kept normal draw).
  void seed(std::uint32_t seed);

  std::uint32_t nextUint32() override;

  /// A standard normal draw (mean 0, variance 1), by Marsaglia's polar method on pairs of
  /// uniform() draws: each accepted pair gives two draws, the second kept for the next call.
  /// (In double, like uniform(): Tools does not know the simulation's `real`.)
  double normal();
  /// A normal draw of mean @p mean and standard deviation @p sd: `mean + sd * normal()`.
  /// @throws std::invalid_argument unless @p sd is non-negative and finite
  double normal(double mean, double sd);

  /// The state now, to continue the stream later with restoreState().
  [[nodiscard]] State saveState() const { return state_; }
  /// Continues from @p state exactly as the stream that saved it would have.
  /// @throws std::invalid_argument when the index is above 624 or a kept draw is not finite
  void restoreState(const State& state);

 private:
  /// Renews the 624 words (MT19937's recurrence).
  void twist();

  State state_;
};

}  // namespace thyrix
