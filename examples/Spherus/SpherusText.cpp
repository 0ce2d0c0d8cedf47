// SpherusText: runs Spherus with the random controller in its arena and prints, at each printed
// step, the position of the agent's centre. Run with --help for the options.

#include "SpherusSimulator.h"

#include <CommandLine.h>
#include <Controller/RandomController.h>

#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <string_view>

namespace {

struct Options {
  thyrix::examples::ConsoleOptions console;
  int objects = 20;
};

const char* const usage =
    "Usage: SpherusText [options]\n"
    "Runs Spherus with a random controller and prints 'step x y' (the agent's centre).\n"
    "  --objects N     circles in the arena (default 20)\n";

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string_view option = argv[i];
    if (option == "--help") {
      std::printf("%s%s  --help          this text\n", usage,
                  thyrix::examples::consoleOptionsUsage);
      std::exit(0);
    }
    if (const int used = thyrix::examples::parseConsoleOption(argc, argv, i, o.console)) {
      i += used - 1;
      continue;
    }
    if (option != "--objects")
      throw std::invalid_argument("unknown option: " + std::string(option));
    if (i + 1 >= argc) throw std::invalid_argument("--objects needs a value");
    o.objects = thyrix::examples::parseNumber<int>(option, argv[++i], 0);
  }
  return o;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace thyrix;
  Options options;
  try {
    options = parse(argc, argv);
  } catch (const std::invalid_argument& error) {
    std::fprintf(stderr, "SpherusText: %s\n%s%s", error.what(), usage,
                 examples::consoleOptionsUsage);
    return 2;
  }
  try {
    const examples::ConsoleOptions& run = options.console;
    SpherusSimulator::Options world;
    world.objects = options.objects;
    world.seed = run.seed;
    SpherusSimulator simulator(world, std::make_unique<RandomController>(run.seed));
    simulator.setContactSolver(run.solver);
    for (long step = 1; step <= run.steps; ++step) {
      simulator.advanceTime();
      if (step % run.every == 0) {
        const Vector2 c = simulator.spherus().centre();
        std::printf("%ld %.6f %.6f\n", step, static_cast<double>(c.x), static_cast<double>(c.y));
      }
      examples::writeSvgIfDue(run, simulator, step, {0, 0}, {world.size, world.size});
    }
  } catch (const std::exception& error) {
    std::fprintf(stderr, "SpherusText: %s\n", error.what());
    return 1;
  }
  return 0;
}
