// evaluate(): one fitness per genome, the mean of its trials, each trial seeded by
// deriveSeed(), the same bits on any number of threads, and a task's exception passed to the
// caller. The ThreadPool under it runs every index once.

#include <Evolution/Evaluate.h>
#include <ThyrixLite/Circle.h>
#include <ThyrixLite/Simulator.h>

#include <gtest/gtest.h>

#include <atomic>
#include <memory>
#include <stdexcept>
#include <vector>

#include "TestTolerances.h"

namespace thyrix {
namespace {

using test::loose;

// The start of the circle, a function of the episode's seed.
double startOf(std::uint64_t seed) { return static_cast<double>(seed % 1000) / 100; }

// A circle that drifts in a gravity field g = (genome, 0). Quasistatic, v = g, so after S
// steps of dt its x is x0 + S dt g, with x0 = startOf(seed).
struct DriftTask {
  long stepCount = 50;
  [[nodiscard]] long steps() const { return stepCount; }
  [[nodiscard]] std::unique_ptr<Simulator> makeWorld(double genome, std::uint64_t seed) const {
    auto world = std::make_unique<Simulator>(real(0.01));
    world->setGravity({static_cast<real>(genome), 0});
    auto& circle = world->registerObject(std::make_unique<Circle>(real(0.5), real(1)));
    circle.r = {static_cast<real>(startOf(seed)), 0};
    return world;
  }
  [[nodiscard]] double fitness(const Simulator& world) const {
    return static_cast<double>(world.objects[0].r.x);
  }
};
static_assert(Task<DriftTask, double>);

// Throws for one genome value.
struct ThrowingTask : DriftTask {
  [[nodiscard]] std::unique_ptr<Simulator> makeWorld(double genome, std::uint64_t seed) const {
    if (genome == 13) throw std::runtime_error("unlucky genome");
    return DriftTask::makeWorld(genome, seed);
  }
};

TEST(SeedDerivationTest, DependsOnEachNumberAndIsTheDocumentedChain) {
  // splitMix64 of 0 is the first output of SplitMix64 seeded with 0 (Vigna's reference code).
  EXPECT_EQ(splitMix64(0), 0xE220A8397B1DCDAFull);
  const std::uint64_t s = deriveSeed(7, 3, 5, 1);
  EXPECT_EQ(s, splitMix64(splitMix64(splitMix64(splitMix64(7) ^ 3) ^ 5) ^ 1));
  EXPECT_NE(s, deriveSeed(8, 3, 5, 1));
  EXPECT_NE(s, deriveSeed(7, 4, 5, 1));
  EXPECT_NE(s, deriveSeed(7, 3, 6, 1));
  EXPECT_NE(s, deriveSeed(7, 3, 5, 2));
  EXPECT_NE(deriveSeed(1, 0, 1, 0), deriveSeed(1, 1, 0, 0));  // not a sum of the numbers
}

TEST(ThreadPoolTest, RunsEveryIndexOnceAndRefusesNoThreads) {
  for (std::size_t threads : {1u, 2u, 3u, 8u}) {
    ThreadPool pool(threads);
    EXPECT_EQ(pool.threadCount(), threads);
    for (std::size_t count : {0u, 1u, 7u, 1000u}) {
      std::vector<std::atomic<int>> calls(count);
      pool.forEach(count, [&](std::size_t i) { ++calls[i]; });
      for (std::size_t i = 0; i < count; ++i) EXPECT_EQ(calls[i].load(), 1) << i;
    }
  }
  EXPECT_THROW(ThreadPool(0), InvalidArgument);
}

TEST(ThreadPoolTest, RethrowsTheLowestFailedIndexAndStaysUsable) {
  ThreadPool pool(3);
  try {
    pool.forEach(100, [](std::size_t i) {
      if (i == 40) throw std::runtime_error("forty");
    });
    FAIL() << "no exception";
  } catch (const std::runtime_error& error) {
    EXPECT_STREQ(error.what(), "forty");
  }
  std::atomic<int> calls = 0;
  pool.forEach(10, [&](std::size_t) { ++calls; });
  EXPECT_EQ(calls.load(), 10);
}

TEST(EvaluateTest, FitnessIsTheMeanOfTheTrialsSeededByDeriveSeed) {
  const DriftTask task;
  const std::vector<double> genomes = {0.5, -1, 2, 0};
  EvaluationOptions options;
  options.trials = 3;
  options.seed = 42;
  options.generation = 7;
  const std::vector<double> fitness = evaluate(task, genomes, options);
  ASSERT_EQ(fitness.size(), genomes.size());
  for (std::size_t i = 0; i < genomes.size(); ++i) {
    double expected = 0;
    for (std::uint64_t t = 0; t < 3; ++t)
      expected += startOf(deriveSeed(42, 7, i, t)) + 50 * 0.01 * genomes[i];
    EXPECT_NEAR(fitness[i], expected / 3, loose * 10) << i;
  }
}

TEST(EvaluateTest, SameBitsForAnyThreadCount) {
  // Two hundred episodes, in chunks that finish in a different order on each run.
  DriftTask task;
  task.stepCount = 20;
  std::vector<double> genomes;
  for (int i = 0; i < 40; ++i) genomes.push_back(0.1 * i - 2);
  EvaluationOptions options;
  options.trials = 5;
  options.seed = 9;
  const std::vector<double> one = evaluate(task, genomes, options);
  for (std::size_t threads : {2u, 3u, 8u}) {
    options.threads = threads;
    const std::vector<double> many = evaluate(task, genomes, options);
    ASSERT_EQ(many.size(), one.size());
    for (std::size_t i = 0; i < one.size(); ++i)
      EXPECT_EQ(std::bit_cast<std::uint64_t>(many[i]), std::bit_cast<std::uint64_t>(one[i]))
          << threads << " threads, genome " << i;
  }
  options.generation = 1;  // another generation draws other layouts
  EXPECT_NE(evaluate(task, genomes, options), one);
}

TEST(EvaluateTest, TaskExceptionReachesTheCaller) {
  const ThrowingTask task;
  const std::vector<double> genomes = {1, 2, 13, 4, 5};
  for (std::size_t threads : {1u, 2u, 8u}) {
    EvaluationOptions options;
    options.threads = threads;
    options.trials = 2;
    EXPECT_THROW(
        {
          try {
            (void)evaluate(task, genomes, options);
          } catch (const std::runtime_error& error) {
            EXPECT_STREQ(error.what(), "unlucky genome");
            throw;
          }
        },
        std::runtime_error);
  }
}

TEST(EvaluateTest, RefusesNoTrialsOrThreads) {
  const DriftTask task;
  const std::vector<double> genomes = {1};
  EvaluationOptions options;
  options.trials = 0;
  try {
    (void)evaluate(task, genomes, options);
    FAIL() << "no exception";
  } catch (const InvalidArgument& error) {
    EXPECT_EQ(error.field(), "EvaluationOptions.trials");
  }
  options.trials = 1;
  options.threads = 0;
  try {
    (void)evaluate(task, genomes, options);
    FAIL() << "no exception";
  } catch (const InvalidArgument& error) {
    EXPECT_EQ(error.field(), "EvaluationOptions.threads");
  }
}

}  // namespace
}  // namespace thyrix
