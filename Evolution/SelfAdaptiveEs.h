#pragma once
/// @file SelfAdaptiveEs.h
/// @brief A simple baseline strategy: the (mu/mu, lambda) evolution strategy with
/// self-adapted step size.

#include <Evolution/Strategy.h>
#include <Tools/MTRandom.h>

#include <cstdint>
#include <vector>

namespace thyrix {

/// The (mu/mu_I, lambda)-sigmaSA-ES (H.-G. Beyer and H.-P. Schwefel, "Evolution strategies: a
/// comprehensive introduction", 2002): each offspring k draws its own step size
/// `sigma_k = sigma * exp(tau * N(0, 1))` with `tau = 1 / sqrt(2 n)` and is placed at
/// `m + sigma_k * z_k`, z_k standard normal; the mu best become the new centre and step size
/// (their means). One isotropic step size, no covariance: a baseline for CMA-ES, and an
/// example of a Strategy. Fitness is maximized.
class SelfAdaptiveEs final : public Strategy {
 public:
  /// @param mean the initial centre (its size is the dimension, at least 1)
  /// @param sigma the initial step size (positive, finite)
  /// @param population lambda, at least 2
  /// @param parents mu, in [1, lambda); 0 picks `lambda / 4` (at least 1)
  /// @param seed the random stream's seed
  /// @throws InvalidArgument naming "SelfAdaptiveEs.mean", ".sigma", ".population" or
  ///         ".parents"
  SelfAdaptiveEs(std::vector<double> mean, double sigma, std::size_t population,
                 std::size_t parents = 0, std::uint32_t seed = 1);

  [[nodiscard]] std::size_t dimension() const override { return mean_.size(); }
  [[nodiscard]] std::size_t populationSize() const override { return lambda_; }
  [[nodiscard]] std::uint64_t generation() const override { return generation_; }
  [[nodiscard]] std::span<const double> mean() const override { return mean_; }
  std::span<const std::vector<double>> ask() override;
  void tell(std::span<const double> fitnesses) override;
  void save(std::ostream& out) const override;
  void restore(std::istream& in) override;

  /// The current step size.
  [[nodiscard]] double sigma() const { return sigma_; }

 private:
  std::size_t lambda_;
  std::size_t mu_;
  double tau_;
  std::vector<double> mean_;
  double sigma_;
  std::uint64_t generation_ = 0;
  bool asked_ = false;
  std::vector<double> sigmas_;                   // the asked points' step sizes
  std::vector<std::vector<double>> population_;  // the asked points
  MTRandom random_;
};

}  // namespace thyrix
