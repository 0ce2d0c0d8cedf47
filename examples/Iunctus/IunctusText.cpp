// IunctusText: runs Iunctus in its arena, with the random controller or (--grasp) the scripted
// grasper, and prints at each printed step the agent's base position and the first object's
// position. Run with --help for the options.

#include <Agents/IunctusGrasper.h>
#include <Agents/IunctusSimulator.h>

#include <CommandLine.h>
#include <Controller/RandomController.h>

#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <string_view>

namespace {

const thyrix::examples::ConsoleProgram program{
    "IunctusText",
    "Usage: IunctusText [options]\n"
    "Runs Iunctus and prints 'step x y ox oy': the agent's base centre and the first object's\n"
    "centre (ox oy are 'nan nan' without objects).\n"
    "  --objects N     circles to catch in the arena (default 1)\n"
    "  --grasp         drive it with the scripted grasper (catch the first object and carry\n"
    "                  it 2 m) instead of the random controller\n",
    "--objects", 1, "--grasp"};

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
    IunctusSimulator::Options world;
    world.objects = options.count;
    world.seed = options.run.seed;
    IunctusSimulator simulator(
        world, options.flag ? nullptr : std::make_unique<RandomController>(options.run.seed));
    simulator.setContactSolver(options.run.solver);
    const auto& objects = simulator.objectsToCatch();
    if (options.flag) simulator.useGrasper();
    examples::AnimationRecorder animation(options.run, {0, 0}, {world.size, world.size});
    for (long step = 1; step <= options.run.steps; ++step) {
      simulator.advanceTime();
      if (step % options.run.every == 0) {
        const Vector2 c = simulator.iunctus().r;
        if (objects.empty()) {
          std::printf("%ld %.6f %.6f nan nan\n", step, static_cast<double>(c.x),
                      static_cast<double>(c.y));
        } else {
          const Vector2 o = objects.front()->r;
          std::printf("%ld %.6f %.6f %.6f %.6f\n", step, static_cast<double>(c.x),
                      static_cast<double>(c.y), static_cast<double>(o.x), static_cast<double>(o.y));
        }
      }
      examples::writeSvgIfDue(options.run, simulator, step, {0, 0}, {world.size, world.size});
      animation.record(simulator, step);
    }
    animation.finish();
  } catch (const std::exception& error) {
    std::fprintf(stderr, "IunctusText: %s\n", error.what());
    return 1;
  }
  return 0;
}
