#pragma once
/// @file CmaEs.h
/// @brief CMA-ES, the covariance matrix adaptation evolution strategy (Hansen's tutorial).

#include <Evolution/Strategy.h>
#include <Tools/MTRandom.h>

#include <cstdint>
#include <vector>

namespace thyrix {

/// The (mu/mu_w, lambda)-CMA-ES of N. Hansen, "The CMA Evolution Strategy: A Tutorial" (2016),
/// with the tutorial's default parameters (its table 1, positive weights only): weighted
/// recombination of the best half, cumulative step-size adaptation (CSA), the rank-one and
/// rank-mu covariance updates with the h_sigma stall, and the eigendecomposition of C
/// (symmetricEigen) redone every `lambda / (c1 + cmu) / n / 10` generations, as the
/// tutorial's code does, so that large dimensions stay cheap. Sampling is
/// `x_k = m + sigma * B * D * z_k` with z_k standard normal. Fitness is maximized.
class CmaEs final : public Strategy {
 public:
  /// @param mean the initial centre m (its size is the dimension n, at least 1)
  /// @param sigma the initial step size (positive, finite): the optimum should lie within
  ///        about `mean +- 2 sigma` in every coordinate
  /// @param population lambda, at least 2; 0 picks the default `4 + floor(3 ln n)`
  /// @param seed the random stream's seed
  /// @throws InvalidArgument naming "CmaEs.mean" (empty or not finite), "CmaEs.sigma" or
  ///         "CmaEs.population"
  CmaEs(std::vector<double> mean, double sigma, std::size_t population = 0, std::uint32_t seed = 1);

  [[nodiscard]] std::size_t dimension() const override { return n_; }
  [[nodiscard]] std::size_t populationSize() const override { return lambda_; }
  [[nodiscard]] std::uint64_t generation() const override { return generation_; }
  [[nodiscard]] std::span<const double> mean() const override { return mean_; }
  std::span<const std::vector<double>> ask() override;
  void tell(std::span<const double> fitnesses) override;
  void save(std::ostream& out) const override;
  void restore(std::istream& in) override;

  /// The current step size sigma.
  [[nodiscard]] double sigma() const { return sigma_; }
  /// The number of parents mu (the best half of the population).
  [[nodiscard]] std::size_t parentCount() const { return mu_; }
  /// The variance-effective selection mass mu_eff.
  [[nodiscard]] double effectiveParents() const { return muEff_; }
  /// The covariance matrix C, row-major n x n.
  [[nodiscard]] std::span<const double> covariance() const { return c_; }

 private:
  void decompose();

  // Settings, fixed by n and lambda.
  std::size_t n_;
  std::size_t lambda_;
  std::size_t mu_;
  std::vector<double> weights_;
  double muEff_;
  double cSigma_, dSigma_, cC_, c1_, cMu_, chiN_;
  std::uint64_t eigenEvery_;  // generations between eigendecompositions
  // State.
  std::vector<double> mean_;
  double sigma_;
  std::vector<double> c_;       // C, row-major
  std::vector<double> b_;       // B transposed: eigenvector k of C is row k (contiguous)
  std::vector<double> d_;       // D: the square roots of C's eigenvalues
  std::vector<double> pSigma_;  // the conjugate evolution path
  std::vector<double> pC_;      // the evolution path
  std::uint64_t generation_ = 0;
  std::uint64_t eigenGeneration_ = 0;  // the generation of the last eigendecomposition
  bool asked_ = false;
  std::vector<std::vector<double>> y_;           // (x_k - m) / sigma of the asked points
  std::vector<std::vector<double>> population_;  // the asked points
  MTRandom random_;
};

}  // namespace thyrix
