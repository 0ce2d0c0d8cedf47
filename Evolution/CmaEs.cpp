#include "CmaEs.h"

#include <Evolution/StateText.h>
#include <Evolution/SymmetricEigen.h>
#include <ThyrixLite/InvalidArgument.h>

#include <algorithm>
#include <cmath>
#include <istream>
#include <numeric>
#include <string>

namespace thyrix {

namespace {

std::size_t defaultPopulation(std::size_t n) {
  return 4 + static_cast<std::size_t>(std::floor(3 * std::log(static_cast<double>(n))));
}

}  // namespace

CmaEs::CmaEs(std::vector<double> mean, double sigma, std::size_t population, std::uint32_t seed)
    : n_(mean.size()),
      lambda_(population == 0 ? defaultPopulation(std::max<std::size_t>(mean.size(), 1))
                              : population),
      mu_(lambda_ / 2),
      mean_(std::move(mean)),
      sigma_(sigma),
      random_(seed) {
  if (n_ == 0) throw InvalidArgument("CmaEs.mean", "must have at least one coordinate");
  for (double x : mean_)
    if (!std::isfinite(x)) throw InvalidArgument("CmaEs.mean", "must be finite");
  if (!(sigma > 0) || !std::isfinite(sigma))
    throw InvalidArgument("CmaEs.sigma",
                          "must be positive and finite (got " + std::to_string(sigma) + ")");
  if (lambda_ < 2)
    throw InvalidArgument("CmaEs.population",
                          "must be at least 2 (got " + std::to_string(lambda_) + ")");
  const double n = static_cast<double>(n_);
  // Tutorial, table 1: w'_i = ln((lambda + 1) / 2) - ln i for the mu best, normalized to sum 1.
  weights_.resize(mu_);
  for (std::size_t i = 0; i < mu_; ++i)
    weights_[i] =
        std::log((static_cast<double>(lambda_) + 1) / 2) - std::log(static_cast<double>(i + 1));
  const double sum = std::accumulate(weights_.begin(), weights_.end(), 0.0);
  double squares = 0;
  for (double& w : weights_) {
    w /= sum;
    squares += w * w;
  }
  muEff_ = 1 / squares;
  cSigma_ = (muEff_ + 2) / (n + muEff_ + 5);
  dSigma_ = 1 + 2 * std::max(0.0, std::sqrt((muEff_ - 1) / (n + 1)) - 1) + cSigma_;
  cC_ = (4 + muEff_ / n) / (n + 4 + 2 * muEff_ / n);
  c1_ = 2 / ((n + 1.3) * (n + 1.3) + muEff_);
  cMu_ = std::min(1 - c1_, 2 * (muEff_ - 2 + 1 / muEff_) / ((n + 2) * (n + 2) + muEff_));
  chiN_ = std::sqrt(n) * (1 - 1 / (4 * n) + 1 / (21 * n * n));
  eigenEvery_ = static_cast<std::uint64_t>(
      std::max(1.0, std::floor(static_cast<double>(lambda_) / (c1_ + cMu_) / n / 10)));

  c_.assign(n_ * n_, 0.0);
  b_.assign(n_ * n_, 0.0);
  for (std::size_t i = 0; i < n_; ++i) c_[i * n_ + i] = b_[i * n_ + i] = 1;
  d_.assign(n_, 1.0);
  pSigma_.assign(n_, 0.0);
  pC_.assign(n_, 0.0);
  y_.assign(lambda_, std::vector<double>(n_));
  population_.assign(lambda_, std::vector<double>(n_));
}

std::span<const std::vector<double>> CmaEs::ask() {
  if (asked_) return population_;
  std::vector<double> z(n_);
  for (std::size_t k = 0; k < lambda_; ++k) {
    std::vector<double>& y = y_[k];
    if (eigenGeneration_ == 0) {  // B = I and D = 1 until the first eigendecomposition
      for (std::size_t i = 0; i < n_; ++i) y[i] = random_.normal();
      continue;
    }
    for (std::size_t i = 0; i < n_; ++i) z[i] = d_[i] * random_.normal();
    // y = B D z as a sum of B's columns (rows of b_), which the compiler vectorizes.
    std::fill(y.begin(), y.end(), 0.0);
    for (std::size_t j = 0; j < n_; ++j) {
      const double zj = z[j];
      const double* column = &b_[j * n_];
      for (std::size_t i = 0; i < n_; ++i) y[i] += column[i] * zj;
    }
  }
  for (std::size_t k = 0; k < lambda_; ++k)
    for (std::size_t i = 0; i < n_; ++i) population_[k][i] = mean_[i] + sigma_ * y_[k][i];
  asked_ = true;
  return population_;
}

void CmaEs::tell(std::span<const double> fitnesses) {
  if (!asked_) throw InvalidArgument("CmaEs.fitnesses", "given before ask()");
  // The best first; ties keep the population's order, so the ranking is deterministic.
  const std::vector<std::size_t> order = rankByFitness("CmaEs", fitnesses, lambda_);

  // Recombination (tutorial eq. 41, c_m = 1): m += sigma * <y>_w.
  std::vector<double> yw(n_, 0.0);
  for (std::size_t i = 0; i < mu_; ++i)
    for (std::size_t j = 0; j < n_; ++j) yw[j] += weights_[i] * y_[order[i]][j];
  for (std::size_t j = 0; j < n_; ++j) mean_[j] += sigma_ * yw[j];

  // Step-size path (eq. 43): C^(-1/2) <y>_w = B D^-1 B^T <y>_w.
  std::vector<double> whitened(n_, 0.0);
  for (std::size_t k = 0; k < n_; ++k) {
    const double* column = &b_[k * n_];
    double t = 0;
    for (std::size_t j = 0; j < n_; ++j) t += column[j] * yw[j];
    t /= d_[k];
    for (std::size_t i = 0; i < n_; ++i) whitened[i] += column[i] * t;
  }
  const double sigmaRate = std::sqrt(cSigma_ * (2 - cSigma_) * muEff_);
  double pSigmaNorm2 = 0;
  for (std::size_t i = 0; i < n_; ++i) {
    pSigma_[i] = (1 - cSigma_) * pSigma_[i] + sigmaRate * whitened[i];
    pSigmaNorm2 += pSigma_[i] * pSigma_[i];
  }
  const double pSigmaNorm = std::sqrt(pSigmaNorm2);

  // h_sigma stalls the rank-one path while the step size grows fast (after eq. 45).
  const double n = static_cast<double>(n_);
  const double correction =
      std::sqrt(1 - std::pow(1 - cSigma_, 2 * static_cast<double>(generation_ + 1)));
  const bool hSigma = pSigmaNorm / correction < (1.4 + 2 / (n + 1)) * chiN_;

  // Covariance path (eq. 45) and covariance update (eq. 47).
  const double cRate = std::sqrt(cC_ * (2 - cC_) * muEff_);
  for (std::size_t i = 0; i < n_; ++i) pC_[i] = (1 - cC_) * pC_[i] + (hSigma ? cRate * yw[i] : 0.0);
  // On the upper triangle, row by row (contiguous, vectorized), then mirrored.
  const double keep = 1 - c1_ - cMu_ + (hSigma ? 0.0 : c1_ * cC_ * (2 - cC_));
  for (std::size_t i = 0; i < n_; ++i) {
    double* row = &c_[i * n_];
    const double a = c1_ * pC_[i];
    for (std::size_t j = i; j < n_; ++j) row[j] = keep * row[j] + a * pC_[j];
  }
  for (std::size_t k = 0; k < mu_; ++k) {
    const std::vector<double>& y = y_[order[k]];
    const double wk = cMu_ * weights_[k];
    for (std::size_t i = 0; i < n_; ++i) {
      double* row = &c_[i * n_];
      const double a = wk * y[i];
      for (std::size_t j = i; j < n_; ++j) row[j] += a * y[j];
    }
  }
  for (std::size_t i = 0; i < n_; ++i)
    for (std::size_t j = i + 1; j < n_; ++j) c_[j * n_ + i] = c_[i * n_ + j];

  // Step size (eq. 44).
  sigma_ *= std::exp(cSigma_ / dSigma_ * (pSigmaNorm / chiN_ - 1));

  ++generation_;
  asked_ = false;
  if (generation_ - eigenGeneration_ >= eigenEvery_) decompose();
}

void CmaEs::decompose() {
  std::vector<double> values(n_), vectors(n_ * n_);
  symmetricEigen(n_, c_, values, vectors);
  for (std::size_t i = 0; i < n_; ++i)
    for (std::size_t k = 0; k < n_; ++k) b_[k * n_ + i] = vectors[i * n_ + k];
  // A round-off eigenvalue at or below 0 would stop the search along its axis.
  const double largest = std::max(values.back(), 1e-300);
  for (std::size_t i = 0; i < n_; ++i) d_[i] = std::sqrt(std::max(values[i], largest * 1e-28));
  eigenGeneration_ = generation_;
}

void CmaEs::save(std::ostream& out) const {
  StateWriter w(out);
  w.word("strategy", "cma-es-1");
  w.integer("dimension", n_);
  w.integer("population", lambda_);
  w.integer("generation", generation_);
  w.integer("eigen-generation", eigenGeneration_);
  w.doubles("sigma", {&sigma_, 1});
  w.doubles("mean", mean_);
  w.doubles("covariance", c_);
  w.doubles("eigenvectors", b_);
  w.doubles("axes", d_);
  w.doubles("sigma-path", pSigma_);
  w.doubles("covariance-path", pC_);
  w.integer("asked", asked_ ? 1 : 0);
  if (asked_)
    for (const std::vector<double>& y : y_) w.doubles("y", y);
  random_.saveState().write(out);
}

void CmaEs::restore(std::istream& in) {
  StateReader r(in, "CMA-ES state");
  if (const std::string kind = r.word("strategy"); kind != "cma-es-1")
    r.fail("is a state of '" + kind + "', not of CMA-ES ('cma-es-1')");
  if (const auto n = r.integer("dimension"); n != n_)
    r.fail("has dimension " + std::to_string(n) + ", this CMA-ES " + std::to_string(n_));
  if (const auto lambda = r.integer("population"); lambda != lambda_)
    r.fail("has population " + std::to_string(lambda) + ", this CMA-ES " + std::to_string(lambda_));
  CmaEs s = *this;
  s.generation_ = r.integer("generation");
  s.eigenGeneration_ = r.integer("eigen-generation", s.generation_);
  s.sigma_ = r.doubles("sigma", 1)[0];
  if (!(s.sigma_ > 0)) r.fail("'sigma' must be positive");
  s.mean_ = r.doubles("mean", n_);
  s.c_ = r.doubles("covariance", n_ * n_);
  s.b_ = r.doubles("eigenvectors", n_ * n_);
  s.d_ = r.doubles("axes", n_);
  for (double d : s.d_)
    if (!(d > 0)) r.fail("'axes' must be positive");
  s.pSigma_ = r.doubles("sigma-path", n_);
  s.pC_ = r.doubles("covariance-path", n_);
  s.asked_ = r.integer("asked", 1) == 1;
  if (s.asked_) {
    for (std::vector<double>& y : s.y_) y = r.doubles("y", n_);
    for (std::size_t k = 0; k < lambda_; ++k)
      for (std::size_t i = 0; i < n_; ++i) s.population_[k][i] = s.mean_[i] + s.sigma_ * s.y_[k][i];
  }
  s.random_.restoreState(r.randomStream());
  *this = std::move(s);
}

}  // namespace thyrix
