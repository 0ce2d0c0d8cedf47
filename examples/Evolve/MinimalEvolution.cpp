// MinimalEvolution: the experiment of `SpherusEvolve --task distance` against the library, as
// docs/EvolvingAController.md shows it. Usage: MinimalEvolution [generations] [threads]
#include <Agents/SpherusSimulator.h>
#include <Controller/Genome.h>
#include <Evolution/CmaEs.h>
#include <Evolution/Evaluate.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <vector>

using namespace thyrix;

// The task: a world for a genome and a seed, the episode's length, and the score.
struct CoverGround {
  NetworkSpec network{NetworkKind::FeedForward, {35, 8, 5}, Activation::Tanh};
  long steps() const { return 1000; }
  std::unique_ptr<SpherusSimulator> makeWorld(const std::vector<double>& genome,
                                              std::uint64_t seed) const {
    auto controller = std::make_unique<NeuralController>(network);
    controller->setParameters(std::vector<real>(genome.begin(), genome.end()));
    SpherusSimulator::Options arena;  // 10 m square, Spherus in the middle, 20 balls
    arena.seed = static_cast<std::uint32_t>(seed);
    return std::make_unique<SpherusSimulator>(arena, std::move(controller));
  }
  double fitness(const SpherusSimulator& world) const {  // distance from the middle (m)
    const Vector2 d = world.spherus().centre() - Vector2{5, 5};
    return std::sqrt(static_cast<double>(d.x * d.x + d.y * d.y));
  }
};

int main(int argc, char** argv) {
  const int generations = argc > 1 ? std::atoi(argv[1]) : 100;
  const CoverGround task;
  CmaEs strategy(std::vector<double>(task.network.parameterCount(), 0.0), 0.5, 20);
  EvaluationOptions options;
  options.threads = argc > 2 ? static_cast<std::size_t>(std::atoi(argv[2])) : 2;
  options.trials = 2;
  for (int g = 1; g <= generations; ++g) {
    options.generation = static_cast<std::uint64_t>(g);
    const std::vector<double> fitness = evaluate(task, strategy.ask(), options);
    strategy.tell(fitness);
    std::printf("%d %.4f\n", g, *std::max_element(fitness.begin(), fitness.end()));
  }
  const Genome best{task.network, {strategy.mean().begin(), strategy.mean().end()}};
  std::ofstream file("best.genome");
  best.write(file);  // replay: SpherusText --genome best.genome
}
