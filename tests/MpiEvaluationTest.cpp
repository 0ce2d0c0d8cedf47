// evaluate() over MPI ranks (MpiEvaluation): the closed-form fitnesses of a drifting circle,
// the same bits as evaluate() in one process whatever the split, empty populations and bad
// input refused with the ranks still usable. Run under `mpirun -n 3` and alone: rank 0 runs
// the tests while the other ranks serve.

#include <Evolution/Evaluate.h>
#include <Evolution/MpiEvaluation.h>
#include <ThyrixLite/Circle.h>
#include <ThyrixLite/InvalidArgument.h>
#include <ThyrixLite/Simulator.h>

#include <gtest/gtest.h>

#include <memory>
#include <vector>

#include "TestTolerances.h"

namespace thyrix {
namespace {

using test::loose;

MpiEvaluation* ranks = nullptr;

// The start of the circle, a function of the episode's seed.
double startOf(std::uint64_t seed) { return static_cast<double>(seed % 1000) / 100; }

// A circle that drifts in a gravity field g = (genome[0], 0). Quasistatic, v = g, so after S
// steps of dt its x is x0 + S dt g, with x0 = startOf(seed).
struct DriftTask {
  [[nodiscard]] long steps() const { return 50; }
  [[nodiscard]] std::unique_ptr<Simulator> makeWorld(const std::vector<double>& genome,
                                                     std::uint64_t seed) const {
    auto world = std::make_unique<Simulator>(real(0.01));
    world->setGravity({static_cast<real>(genome[0]), 0});
    auto& circle = world->registerObject(std::make_unique<Circle>(real(0.5), real(1)));
    circle.r = {static_cast<real>(startOf(seed)), 0};
    return world;
  }
  [[nodiscard]] double fitness(const Simulator& world) const {
    return static_cast<double>(world.objects[0].r.x);
  }
};

std::vector<std::vector<double>> population(std::size_t count) {
  std::vector<std::vector<double>> genomes;
  for (std::size_t i = 0; i < count; ++i)
    genomes.push_back({0.25 * static_cast<double>(i) - 3, static_cast<double>(i)});
  return genomes;
}

TEST(MpiEvaluation, FitnessIsTheMeanOfTheClosedFormTrials) {
  const DriftTask task;
  ThreadPool pool(2);
  const auto genomes = population(7);
  EvaluationOptions options;
  options.trials = 3;
  options.seed = 9;
  options.generation = 4;
  const std::vector<double> fitness = evaluate(task, std::span(genomes), options, pool, *ranks);
  ASSERT_EQ(fitness.size(), genomes.size());
  for (std::size_t i = 0; i < genomes.size(); ++i) {
    double expected = 0;
    for (std::uint64_t t = 0; t < 3; ++t) expected += startOf(deriveSeed(9, 4, i, t));
    expected = expected / 3 + 50 * 0.01 * genomes[i][0];
    EXPECT_NEAR(fitness[i], expected, loose * (1 + std::abs(expected))) << "genome " << i;
  }
}

TEST(MpiEvaluation, SameBitsAsOneProcess) {
  const DriftTask task;
  ThreadPool pool(2);
  ThreadPool one(1);
  const auto genomes = population(37);
  for (std::uint64_t generation = 1; generation <= 3; ++generation) {
    EvaluationOptions options;
    options.trials = generation;
    options.seed = 5;
    options.generation = generation;
    const std::vector<double> alone = evaluate(task, genomes, options, one);
    // The leader with a pool of 2 threads (a thread of its own runs its chunks) and of 1 (it
    // runs its episodes between the answers to the other ranks).
    for (ThreadPool* leader : {&pool, &one}) {
      const std::vector<double> spread =
          evaluate(task, std::span(genomes), options, *leader, *ranks);
      ASSERT_EQ(spread.size(), alone.size());
      for (std::size_t i = 0; i < alone.size(); ++i)
        EXPECT_EQ(spread[i], alone[i]) << "generation " << generation << ", genome " << i
                                       << ", leader threads " << leader->threadCount();
    }
  }
  ASSERT_EQ(ranks->rankTimes().size(), static_cast<std::size_t>(ranks->size()));
  EXPECT_GT(ranks->rankTimes()[0].busySeconds + ranks->rankTimes()[0].idleSeconds, 0);
}

TEST(MpiEvaluation, EmptyPopulation) {
  const DriftTask task;
  ThreadPool pool(1);
  const std::vector<std::vector<double>> none;
  EXPECT_TRUE(evaluate(task, std::span(none), EvaluationOptions{}, pool, *ranks).empty());
}

TEST(MpiEvaluation, BadInputIsRefusedAndTheRanksGoOn) {
  const DriftTask task;
  ThreadPool pool(1);
  auto genomes = population(4);
  EvaluationOptions options;
  options.trials = 0;
  try {
    (void)evaluate(task, std::span(genomes), options, pool, *ranks);
    FAIL() << "trials 0 accepted";
  } catch (const InvalidArgument& error) {
    EXPECT_NE(std::string(error.what()).find("EvaluationOptions.trials"), std::string::npos);
  }
  options.trials = 1;
  genomes[2].push_back(1);
  try {
    (void)evaluate(task, std::span(genomes), options, pool, *ranks);
    FAIL() << "genomes of different sizes accepted";
  } catch (const InvalidArgument& error) {
    EXPECT_NE(std::string(error.what()).find("genomes"), std::string::npos);
  }
  genomes[2].pop_back();
  ThreadPool one(1);
  EXPECT_EQ(evaluate(task, std::span(genomes), options, pool, *ranks),
            evaluate(task, genomes, options, one));
}

}  // namespace
}  // namespace thyrix

int main(int argc, char** argv) {
  thyrix::MpiEvaluation evaluation(argc, argv);
  if (evaluation.rank() != 0) {
    thyrix::ThreadPool pool(2);
    thyrix::serveEvaluations(thyrix::DriftTask{}, pool, evaluation);
    return 0;
  }
  ::testing::InitGoogleTest(&argc, argv);
  thyrix::ranks = &evaluation;
  return RUN_ALL_TESTS();
}
