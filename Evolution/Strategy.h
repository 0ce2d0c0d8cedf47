#pragma once
/// @file Strategy.h
/// @brief The ask/tell interface of a search strategy over real vectors (e.g. CMA-ES).

#include <cstddef>
#include <cstdint>
#include <iosfwd>
#include <span>
#include <string_view>
#include <vector>

namespace thyrix {

/// A strategy proposes a population of points (ask), learns their fitnesses (tell) and
/// proposes the next; the caller evaluates the points however it likes (in parallel with
/// evaluate(), on a cluster, by hand). Fitness is maximized: higher is better (to minimize a
/// cost f, tell -f). A strategy's whole state, its random stream included, can be saved and
/// restored, so a run interrupted between any two calls continues bit for bit.
class Strategy {
 public:
  virtual ~Strategy() = default;

  /// The number of coordinates of every point.
  [[nodiscard]] virtual std::size_t dimension() const = 0;
  /// The number of points ask() returns.
  [[nodiscard]] virtual std::size_t populationSize() const = 0;
  /// The number of tell() calls so far.
  [[nodiscard]] virtual std::uint64_t generation() const = 0;
  /// The centre of the search: the strategy's estimate of the best point.
  [[nodiscard]] virtual std::span<const double> mean() const = 0;

  /// The population to evaluate: populationSize() points of dimension() coordinates. Asking
  /// again before tell() returns the same points.
  virtual std::span<const std::vector<double>> ask() = 0;
  /// The fitnesses of the points of the last ask(), in the same order (higher is better);
  /// moves the search on by one generation.
  /// @throws InvalidArgument naming "<strategy>.fitnesses" if there is no asked population,
  ///         the count differs from populationSize() or a value is not finite (the strategy
  ///         is then unchanged)
  virtual void tell(std::span<const double> fitnesses) = 0;

  /// Writes the whole state as text (floating-point values in hexadecimal: exact).
  virtual void save(std::ostream& out) const = 0;
  /// Reads a state written by save() of a strategy of the same kind, dimension and
  /// population size.
  /// @throws std::runtime_error saying what is wrong (corrupt, truncated, another kind or
  ///         size); the strategy is then unchanged
  virtual void restore(std::istream& in) = 0;
};

/// Checks the fitnesses told to a strategy (@p expected values, all finite) and returns the
/// points' indices from the best to the worst, ties in the population's order (so that the
/// ranking is deterministic).
/// @throws InvalidArgument naming "<strategy>.fitnesses", @p strategy being the class's name
std::vector<std::size_t> rankByFitness(std::string_view strategy, std::span<const double> fitnesses,
                                       std::size_t expected);

}  // namespace thyrix
