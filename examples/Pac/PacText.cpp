// PacText: runs two Pacs in their arena, each with a random controller (or Pac 0 eating by the
// script of PacEatingSimulator), and prints, at each printed step, both agents' centres and how
// many food circles each holds inside its ring. Run with --help for the options.

#include <Agents/PacEatingSimulator.h>
#include <Agents/PacSimulator.h>

#include <CommandLine.h>
#include <Controller/RandomController.h>

#include <cstdio>
#include <cstdlib>
#include <memory>
#include <stdexcept>

namespace {

const thyrix::examples::ConsoleProgram program{
    "PacText",
    "Usage: PacText [options]\n"
    "Runs two Pacs with random controllers and prints 'step x0 y0 n0 x1 y1 n1': each Pac's\n"
    "centre and the number of food circles inside its ring.\n"
    "  --food N        food circles in the arena (default 16)\n"
    "  --eat           Pac 0 eats the nearest food, one after another, by a script\n",
    "--food", 16, "--eat"};

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
    examples::prepareSvgDirectory(options.run);
    PacSimulator::Options world;
    world.food = options.count;
    world.seed = options.run.seed;
    // Distinct streams for the two controllers, both from the one seed. With --eat, Pac 0 is
    // driven by the script that PacEatingSimulator runs in each step.
    auto second = std::make_unique<RandomController>(options.run.seed ^ 0x9e3779b9u);
    const std::unique_ptr<PacSimulator> simulator =
        options.flag
            ? std::make_unique<PacEatingSimulator>(world, std::move(second))
            : std::make_unique<PacSimulator>(
                  world, std::make_unique<RandomController>(options.run.seed), std::move(second));
    simulator->setContactSolver(options.run.solver);

    examples::AnimationRecorder animation(options.run, {0, 0}, {world.size, world.size});
    for (long step = 1; step <= options.run.steps; ++step) {
      simulator->advanceTime();
      if (step % options.run.every == 0) {
        const Vector2 c0 = simulator->pac(0).centre();
        const Vector2 c1 = simulator->pac(1).centre();
        std::printf("%ld %.6f %.6f %d %.6f %.6f %d\n", step, static_cast<double>(c0.x),
                    static_cast<double>(c0.y), simulator->foodInside(simulator->pac(0)),
                    static_cast<double>(c1.x), static_cast<double>(c1.y),
                    simulator->foodInside(simulator->pac(1)));
      }
      examples::writeSvgIfDue(options.run, *simulator, step, {0, 0}, {world.size, world.size});
      animation.record(*simulator, step);
    }
    animation.finish();
  } catch (const std::exception& error) {
    std::fprintf(stderr, "PacText: %s\n", error.what());
    return 1;
  }
  return 0;
}
