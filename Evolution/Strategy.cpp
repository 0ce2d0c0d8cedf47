#include "Strategy.h"

#include <ThyrixLite/InvalidArgument.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

namespace thyrix {

std::vector<std::size_t> rankByFitness(std::string_view strategy, std::span<const double> fitnesses,
                                       std::size_t expected) {
  const std::string field = std::string(strategy) + ".fitnesses";
  if (fitnesses.size() != expected)
    throw InvalidArgument(field, "must hold " + std::to_string(expected) +
                                     " values, one per point (got " +
                                     std::to_string(fitnesses.size()) + ")");
  for (double f : fitnesses)
    if (!std::isfinite(f)) throw InvalidArgument(field, "must be finite");
  std::vector<std::size_t> order(expected);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return fitnesses[a] > fitnesses[b]; });
  return order;
}

}  // namespace thyrix
