// EvolutionBenchmark: the throughput of evolving Spherus controllers (issue 28), in wall time:
//  1. evaluations per second of 1000-step episodes of Spherus driven by a 35-8-5 network, on
//     1 and on 2 threads, and the 2-thread efficiency rate(2) / (2 rate(1));
//  2. the wall time of a whole evolution: 100 generations of CMA-ES, population 100,
//     1000-step episodes (10^7 steps), on 2 threads, without the program's files.
// Usage: EvolutionBenchmark [generations] [population] [threads]. Wall time on a machine
// shared with other work measures the load too: run it idle (see bench/README.md). The
// process's CPU time is printed too: on a loaded machine, the CPU time of the same work on 1
// and 2 threads still shows whether the threads slow each other down (shared caches, memory,
// locks), which is what the efficiency of an idle machine is made of, with the wait at the end
// of each generation.

#include <Evolution/CmaEs.h>
#include <Evolution/Evaluate.h>
#include <SpherusTask.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <vector>

namespace {

using namespace thyrix;
using Clock = std::chrono::steady_clock;

double seconds(Clock::time_point since) {
  return std::chrono::duration<double>(Clock::now() - since).count();
}

// The process's CPU time, all threads (s).
double cpuSeconds() { return static_cast<double>(std::clock()) / CLOCKS_PER_SEC; }

struct Rate {
  double wall = 0;  // episodes a second of wall time
  double cpu = 0;   // episodes a second of CPU time
};

// Episodes a second over @p genomes on @p threads: the best of three rounds.
Rate rate(const SpherusTask& task, const std::vector<std::vector<double>>& genomes,
          std::size_t threads) {
  ThreadPool pool(threads);
  EvaluationOptions options;
  Rate best;
  const auto episodes = static_cast<double>(genomes.size());
  for (std::uint64_t round = 0; round < 3; ++round) {
    options.generation = round;
    const auto start = Clock::now();
    const double cpu = cpuSeconds();
    (void)evaluate(task, genomes, options, pool);
    best.wall = std::max(best.wall, episodes / seconds(start));
    best.cpu = std::max(best.cpu, episodes / (cpuSeconds() - cpu));
  }
  return best;
}

}  // namespace

int main(int argc, char** argv) {
  const int generations = argc > 1 ? std::atoi(argv[1]) : 100;
  const std::size_t population = argc > 2 ? static_cast<std::size_t>(std::atoi(argv[2])) : 100;
  const std::size_t threads = argc > 3 ? static_cast<std::size_t>(std::atoi(argv[3])) : 2;
  SpherusTask task;
  task.network = parseSpherusNetwork("ff:8");
  task.stepCount = 1000;
  const std::size_t n = task.network.parameterCount();

  // 1. Throughput: the first population of a run, so the networks move the agent.
  CmaEs sampler(std::vector<double>(n, 0.0), 0.5, population, 7);
  const auto asked = sampler.ask();
  const std::vector<std::vector<double>> genomes(asked.begin(), asked.end());
  const Rate one = rate(task, genomes, 1);
  const Rate two = rate(task, genomes, 2);
  std::printf("episodes of %ld steps, %zu parameters\n", task.stepCount, n);
  std::printf("1 thread:  %.0f evaluations/s (%.3f us a step); CPU: %.0f a CPU second\n", one.wall,
              1e6 / one.wall / 1000, one.cpu);
  std::printf(
      "2 threads: %.0f evaluations/s, efficiency %.3f; CPU: %.0f a CPU second, "
      "CPU efficiency %.3f\n",
      two.wall, two.wall / (2 * one.wall), two.cpu, two.cpu / one.cpu);

  // 2. A whole evolution.
  CmaEs strategy(std::vector<double>(n, 0.0), 0.5, population, 1);
  ThreadPool pool(threads);
  EvaluationOptions options;
  double evaluating = 0;
  double best = 0;
  const auto start = Clock::now();
  const double cpuStart = cpuSeconds();
  for (int g = 1; g <= generations; ++g) {
    options.generation = static_cast<std::uint64_t>(g);
    const auto evaluation = Clock::now();
    const std::vector<double> fitness = evaluate(task, strategy.ask(), options, pool);
    evaluating += seconds(evaluation);
    best = std::max(best, *std::max_element(fitness.begin(), fitness.end()));
    strategy.tell(fitness);
  }
  const double total = seconds(start);
  std::printf(
      "evolution: %d generations x %zu x %ld steps on %zu threads: %.2f s "
      "(evaluations %.2f s, CMA-ES %.2f s), CPU %.2f s; best distance %.2f m\n",
      generations, population, task.stepCount, threads, total, evaluating, total - evaluating,
      cpuSeconds() - cpuStart, best);
}
