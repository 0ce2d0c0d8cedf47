#include "SelfAdaptiveEs.h"

#include <Evolution/StateText.h>
#include <ThyrixLite/InvalidArgument.h>

#include <algorithm>
#include <cmath>
#include <istream>
#include <numeric>
#include <string>

namespace thyrix {

SelfAdaptiveEs::SelfAdaptiveEs(std::vector<double> mean, double sigma, std::size_t population,
                               std::size_t parents, std::uint32_t seed)
    : lambda_(population),
      mu_(parents == 0 ? std::max<std::size_t>(1, population / 4) : parents),
      tau_(mean.empty() ? 0.0 : 1 / std::sqrt(2 * static_cast<double>(mean.size()))),
      mean_(std::move(mean)),
      sigma_(sigma),
      random_(seed) {
  if (mean_.empty()) throw InvalidArgument("SelfAdaptiveEs.mean", "must have a coordinate");
  for (double x : mean_)
    if (!std::isfinite(x)) throw InvalidArgument("SelfAdaptiveEs.mean", "must be finite");
  if (!(sigma > 0) || !std::isfinite(sigma))
    throw InvalidArgument("SelfAdaptiveEs.sigma", "must be positive and finite");
  if (lambda_ < 2)
    throw InvalidArgument("SelfAdaptiveEs.population",
                          "must be at least 2 (got " + std::to_string(lambda_) + ")");
  if (mu_ >= lambda_)
    throw InvalidArgument("SelfAdaptiveEs.parents",
                          "must be less than the population (got " + std::to_string(mu_) + ")");
  sigmas_.assign(lambda_, 0.0);
  population_.assign(lambda_, std::vector<double>(mean_.size()));
}

std::span<const std::vector<double>> SelfAdaptiveEs::ask() {
  if (asked_) return population_;
  for (std::size_t k = 0; k < lambda_; ++k) {
    sigmas_[k] = sigma_ * std::exp(tau_ * random_.normal());
    for (std::size_t i = 0; i < mean_.size(); ++i)
      population_[k][i] = mean_[i] + sigmas_[k] * random_.normal();
  }
  asked_ = true;
  return population_;
}

void SelfAdaptiveEs::tell(std::span<const double> fitnesses) {
  if (!asked_) throw InvalidArgument("SelfAdaptiveEs.fitnesses", "given before ask()");
  const std::vector<std::size_t> order = rankByFitness("SelfAdaptiveEs", fitnesses, lambda_);
  std::fill(mean_.begin(), mean_.end(), 0.0);
  double sigma = 0;
  for (std::size_t k = 0; k < mu_; ++k) {
    for (std::size_t i = 0; i < mean_.size(); ++i) mean_[i] += population_[order[k]][i];
    sigma += sigmas_[order[k]];
  }
  const double mu = static_cast<double>(mu_);
  for (double& x : mean_) x /= mu;
  sigma_ = sigma / mu;
  ++generation_;
  asked_ = false;
}

void SelfAdaptiveEs::save(std::ostream& out) const {
  StateWriter w(out);
  w.word("strategy", "self-adaptive-es-1");
  w.integer("dimension", mean_.size());
  w.integer("population", lambda_);
  w.integer("parents", mu_);
  w.integer("generation", generation_);
  w.doubles("sigma", {&sigma_, 1});
  w.doubles("mean", mean_);
  w.integer("asked", asked_ ? 1 : 0);
  if (asked_) {
    w.doubles("sigmas", sigmas_);
    for (const std::vector<double>& x : population_) w.doubles("x", x);
  }
  random_.saveState().write(out);
}

void SelfAdaptiveEs::restore(std::istream& in) {
  StateReader r(in, "self-adaptive ES state");
  if (const std::string kind = r.word("strategy"); kind != "self-adaptive-es-1")
    r.fail("is a state of '" + kind + "', not of the self-adaptive ES");
  if (r.integer("dimension") != mean_.size()) r.fail("has another dimension");
  if (r.integer("population") != lambda_) r.fail("has another population size");
  if (r.integer("parents") != mu_) r.fail("has another number of parents");
  SelfAdaptiveEs s = *this;
  s.generation_ = r.integer("generation");
  s.sigma_ = r.doubles("sigma", 1)[0];
  if (!(s.sigma_ > 0)) r.fail("'sigma' must be positive");
  s.mean_ = r.doubles("mean", mean_.size());
  s.asked_ = r.integer("asked", 1) == 1;
  if (s.asked_) {
    s.sigmas_ = r.doubles("sigmas", lambda_);
    for (std::vector<double>& x : s.population_) x = r.doubles("x", mean_.size());
  }
  s.random_.restoreState(r.randomStream());
  *this = std::move(s);
}

}  // namespace thyrix
