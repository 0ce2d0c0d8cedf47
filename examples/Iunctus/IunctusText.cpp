// IunctusText: runs Iunctus in its arena, with the random controller or (--grasp) the scripted
// grasper, and prints at each printed step the agent's base position and the first object's
// position. Run with --help for the options.

#include "IunctusGrasper.h"
#include "IunctusSimulator.h"

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
  int objects = 1;
  bool grasp = false;
};

const char* const usage =
    "Usage: IunctusText [options]\n"
    "Runs Iunctus and prints 'step x y ox oy': the agent's base centre and the first object's\n"
    "centre (ox oy are 'nan nan' without objects).\n"
    "  --objects N     circles to catch in the arena (default 1)\n"
    "  --grasp         drive it with the scripted grasper (catch the first object and carry\n"
    "                  it 2 m) instead of the random controller\n";

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string_view option = argv[i];
    if (option == "--help") {
      std::printf("%s%s  --help          this text\n", usage,
                  thyrix::examples::consoleOptionsUsage);
      std::exit(0);
    }
    if (option == "--grasp") {
      o.grasp = true;
      continue;
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
    std::fprintf(stderr, "IunctusText: %s\n%s%s", error.what(), usage,
                 thyrix::examples::consoleOptionsUsage);
    return 2;
  }
  try {
    IunctusSimulator::Options world;
    world.objects = options.objects;
    world.seed = options.console.seed;
    IunctusSimulator simulator(
        world, options.grasp ? nullptr : std::make_unique<RandomController>(options.console.seed));
    simulator.setContactSolver(options.console.solver);
    const auto& objects = simulator.objectsToCatch();
    if (options.grasp) simulator.useGrasper();
    for (long step = 1; step <= options.console.steps; ++step) {
      simulator.advanceTime();
      if (step % options.console.every == 0) {
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
      examples::writeSvgIfDue(options.console, simulator, step, {0, 0}, {world.size, world.size});
    }
  } catch (const std::exception& error) {
    std::fprintf(stderr, "IunctusText: %s\n", error.what());
    return 1;
  }
  return 0;
}
