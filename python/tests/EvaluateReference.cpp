// thyrix_evaluate_reference: the C++ side of the Python tests' and benchmark's evaluate()
// comparisons. Reads genomes (one line each, whitespace-separated numbers in any format
// strtod reads, e.g. %.17g or hexadecimal) from standard input, runs thyrix::evaluate of a
// SpherusTask on them and prints each fitness with %a (exact), then the seconds evaluate took
// on standard error.
//
// Usage: thyrix_evaluate_reference TASK STEPS NETWORK TRIALS THREADS SEED GENERATION < genomes

#include <SpherusTask.h>

#include <Evolution/Evaluate.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

int main(int argc, char** argv) {
  using namespace thyrix;
  if (argc != 8) {
    std::fprintf(stderr, "usage: %s TASK STEPS NETWORK TRIALS THREADS SEED GENERATION < genomes\n",
                 argv[0]);
    return 2;
  }
  try {
    SpherusTask task;
    task.goal = parseSpherusGoal(argv[1]);
    task.stepCount = std::stol(argv[2]);
    task.network = parseSpherusNetwork(argv[3]);
    EvaluationOptions options;
    options.trials = std::stoul(argv[4]);
    options.threads = std::stoul(argv[5]);
    options.seed = std::stoull(argv[6]);
    options.generation = std::stoull(argv[7]);
    std::vector<std::vector<double>> genomes;
    std::string line;
    while (std::getline(std::cin, line)) {
      std::vector<double> genome;
      std::istringstream words(line);
      std::string word;
      while (words >> word) genome.push_back(std::strtod(word.c_str(), nullptr));
      if (!genome.empty()) genomes.push_back(std::move(genome));
    }
    const auto start = std::chrono::steady_clock::now();
    const std::vector<double> fitness = evaluate(task, genomes, options);
    const std::chrono::duration<double> seconds = std::chrono::steady_clock::now() - start;
    for (const double f : fitness) std::printf("%a\n", f);
    std::fprintf(stderr, "%.6f\n", seconds.count());
  } catch (const std::exception& error) {
    std::fprintf(stderr, "thyrix_evaluate_reference: %s\n", error.what());
    return 1;
  }
  return 0;
}
