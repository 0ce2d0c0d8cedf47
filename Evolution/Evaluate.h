#pragma once
/// @file Evaluate.h
/// @brief The task concept and the parallel evaluation of a population.

#include <Evolution/SeedDerivation.h>
#include <Evolution/ThreadPool.h>
#include <ThyrixLite/InvalidArgument.h>

#include <concepts>
#include <cstddef>
#include <cstdint>
#include <ranges>
#include <span>
#include <string>
#include <vector>

namespace thyrix {

/// What an experiment scores, for genomes of type @p Genome: `task.makeWorld(genome, seed)`
/// builds a fresh world (any pointer-like owner, e.g. `std::unique_ptr<SpherusSimulator>`)
/// whose agents are driven by @p genome and whose layout comes from @p seed;
/// `task.steps()` is the episode's length in steps; `task.fitness(world)` reads the score
/// from the world after the episode (higher is better). The calls are `const` and must not
/// share mutable state, because evaluations run in parallel threads.
template <class T, class Genome>
concept Task = requires(const T& task, const Genome& genome, std::uint64_t seed) {
  { task.steps() } -> std::convertible_to<long>;
  {task.makeWorld(genome, seed)->advanceTime()};
  { task.fitness(*task.makeWorld(genome, seed)) } -> std::convertible_to<double>;
};

/// How evaluate() runs.
struct EvaluationOptions {
  std::size_t threads = 1;       ///< threads (the caller's included); ignored with a pool
  std::size_t trials = 1;        ///< episodes per genome; the fitness is their mean
  std::uint64_t seed = 1;        ///< the run's seed
  std::uint64_t generation = 0;  ///< the generation, for the episodes' seeds
};

/// Runs episodes `first` to `first + episodes.size() - 1` of evaluate() on @p pool, writing
/// the fitness of episode `first + k` to `episodes[k]` (episode `i * options.trials + t` is trial
/// t of genome i, seeded by `deriveSeed(options.seed, options.generation, i, t)`). evaluate()
/// and the evaluation over MPI ranks (MpiEvaluation.h) both run their episodes here, so their
/// results agree bit for bit however the episodes are split.
template <class T, std::ranges::random_access_range Genomes>
requires Task<T, std::ranges::range_value_t<Genomes>>
void evaluateEpisodes(const T& task, const Genomes& genomes, const EvaluationOptions& options,
                      std::size_t first, std::span<double> episodes, ThreadPool& pool) {
  const std::size_t trials = options.trials;
  const long steps = task.steps();
  pool.forEach(episodes.size(), [&](std::size_t k) {
    const std::size_t episode = first + k;
    const std::size_t individual = episode / trials;
    const std::size_t trial = episode % trials;
    auto world =
        task.makeWorld(std::ranges::begin(genomes)[static_cast<std::ptrdiff_t>(individual)],
                       deriveSeed(options.seed, options.generation, individual, trial));
    for (long step = 0; step < steps; ++step) world->advanceTime();
    episodes[k] = static_cast<double>(task.fitness(*world));
  });
}

/// The fitness of each genome from its episodes' fitnesses (genome i's trials at
/// `[i * trials, (i + 1) * trials)`): their mean, summed in trial order.
[[nodiscard]] inline std::vector<double> meanOverTrials(std::span<const double> episodes,
                                                        std::size_t trials) {
  const std::size_t count = episodes.size() / trials;
  std::vector<double> fitness(count);
  for (std::size_t i = 0; i < count; ++i) {
    double sum = 0;
    for (std::size_t t = 0; t < trials; ++t) sum += episodes[i * trials + t];
    fitness[i] = sum / static_cast<double>(trials);
  }
  return fitness;
}

/// One fitness per genome of @p genomes (a random-access range, e.g. a vector or a span): the mean
/// over `options.trials` episodes of `task.fitness` after `task.steps()` steps of
/// `task.makeWorld(genomes[i], seed)`, where episode t of genome i has `seed =
/// deriveSeed(options.seed, options.generation, i, t)`. The episodes run on @p pool; the trials'
/// fitnesses are summed in trial order, so the result is the same, bit for bit, whatever the number
/// of threads. An exception thrown by the task is rethrown here (that of the lowest episode,
/// counted `i * trials + t`, among those that threw).
/// @throws InvalidArgument naming "EvaluationOptions.trials" if it is 0
template <class T, std::ranges::random_access_range Genomes>
requires Task<T, std::ranges::range_value_t<Genomes>> std::vector<double> evaluate(
    const T& task, const Genomes& genomes, const EvaluationOptions& options, ThreadPool& pool) {
  if (options.trials == 0)
    throw InvalidArgument("EvaluationOptions.trials", "must be at least 1 (got 0)");
  std::vector<double> episodes(std::ranges::size(genomes) * options.trials);
  evaluateEpisodes(task, genomes, options, 0, episodes, pool);
  return meanOverTrials(episodes, options.trials);
}

/// evaluate() on a pool of `options.threads` threads started for this call.
/// @throws InvalidArgument naming "EvaluationOptions.threads" if it is 0
template <class T, std::ranges::random_access_range Genomes>
requires Task<T, std::ranges::range_value_t<Genomes>> std::vector<double> evaluate(
    const T& task, const Genomes& genomes, const EvaluationOptions& options) {
  if (options.threads == 0)
    throw InvalidArgument("EvaluationOptions.threads", "must be at least 1 (got 0)");
  ThreadPool pool(options.threads);
  return evaluate(task, genomes, options, pool);
}

}  // namespace thyrix
