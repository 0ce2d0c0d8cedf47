// SpherusText: runs Spherus with the random controller (or an evolved one, --genome) in its
// arena and prints, at each printed step, the position of the agent's centre; --animation
// writes the episode as an animated SVG. Run with --help for the options.

#include <Agents/SpherusSimulator.h>

#include <CommandLine.h>
#include <Controller/Genome.h>
#include <Controller/RandomController.h>

#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <string_view>

namespace {

const thyrix::examples::ConsoleProgram program{
    "SpherusText",
    "Usage: SpherusText [options]\n"
    "Runs Spherus with a random controller and prints 'step x y' (the agent's centre).\n"
    "  --objects N     circles in the arena (default 20)\n"
    "  --genome FILE   drive Spherus by the network in FILE (e.g. SpherusEvolve's best.genome)\n",
    "--objects",
    20,
    {},
    "--genome"};

}  // namespace

int main(int argc, char** argv) {
  using namespace thyrix;
  examples::ConsoleArguments options;
  try {
    options = examples::parseConsoleProgram(program, argc, argv);
  } catch (const std::invalid_argument& error) {
    return examples::reportUsageError(program, error);
  }
  try {
    const examples::ConsoleOptions& run = options.run;
    examples::prepareSvgDirectory(run);
    SpherusSimulator::Options world;
    world.objects = options.count;
    world.seed = run.seed;
    std::unique_ptr<Controller> controller;
    if (options.file.empty()) {
      controller = std::make_unique<RandomController>(run.seed);
    } else {
      const Genome genome = Genome::load(options.file);
      genome.requireShape(Spherus::sensorCount, Spherus::effectorCount);
      controller = genome.makeController(world.timestep);
    }
    SpherusSimulator simulator(world, std::move(controller));
    simulator.setContactSolver(run.solver);
    examples::AnimationRecorder animation(run, {0, 0}, {world.size, world.size});
    for (long step = 1; step <= run.steps; ++step) {
      simulator.advanceTime();
      animation.record(simulator, step);
      if (step % run.every == 0) {
        const Vector2 c = simulator.spherus().centre();
        std::printf("%ld %.6f %.6f\n", step, static_cast<double>(c.x), static_cast<double>(c.y));
      }
      examples::writeSvgIfDue(run, simulator, step, {0, 0}, {world.size, world.size});
    }
    animation.finish();
  } catch (const std::exception& error) {
    std::fprintf(stderr, "SpherusText: %s\n", error.what());
    return 1;
  }
  return 0;
}
