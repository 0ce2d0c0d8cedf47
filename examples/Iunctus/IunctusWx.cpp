// IunctusWx: Iunctus in its arena, in a window, with the random controller or (--grasp) the
// scripted grasper. The same options as IunctusText for the world, plus the shared GUI options
// (speed, geometry, and the automation options --screenshot, --after and --print-drag). Run with
// --help for the list.

#include "IunctusSimulator.h"

#include <CommandLine.h>
#include <Controller/RandomController.h>
#include <GUIWx/GuiOptions.h>
#include <GUIWx/SimulationApp.h>

#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <string_view>

namespace {

struct Options {
  std::uint32_t seed = 1;
  int objects = 1;
  bool grasp = false;
  thyrix::ContactSolverKind solver = thyrix::ContactSolverKind::Baraff;
  thyrix::GuiOptions gui;
};

const char* const usage =
    "Usage: IunctusWx [options]\n"
    "Shows Iunctus and the circles it catches; drag objects (and its links) with the mouse.\n"
    "  --seed S             seed of the arena layout and of the controller (default 1)\n"
    "  --objects N          circles to catch in the arena (default 1)\n"
    "  --solver S           baraff or gauss-seidel (default baraff)\n"
    "  --grasp              drive it with the scripted grasper instead of the random controller\n";

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string_view option = argv[i];
    if (option == "--help") {
      std::fputs(usage, stdout);
      std::fputs(thyrix::guiOptionsUsage, stdout);
      std::fputs("  --help               this text\n", stdout);
      std::exit(0);
    }
    if (const int used = thyrix::parseGuiOption(argc, argv, i, o.gui); used > 0) {
      i += used - 1;
      continue;
    }
    if (option == "--grasp") {
      o.grasp = true;
      continue;
    }
    if (option != "--seed" && option != "--objects" && option != "--solver")
      throw std::invalid_argument("unknown option: " + std::string(option));
    if (i + 1 >= argc) throw std::invalid_argument(std::string(option) + " needs a value");
    const std::string_view value = argv[++i];
    if (option == "--seed") {
      o.seed = thyrix::examples::parseNumber<std::uint32_t>(option, value, 0);
    } else if (option == "--objects") {
      o.objects = thyrix::examples::parseNumber<int>(option, value, 0);
    } else {
      o.solver = thyrix::examples::parseSolver(value);
    }
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
    std::fprintf(stderr, "IunctusWx: %s\n%s", error.what(), usage);
    std::fputs(guiOptionsUsage, stderr);
    return 2;
  }

  SimulationSetup setup;
  setup.title = "IunctusWx - Thyrix";
  setup.solver = options.solver;
  // Called on the simulation thread at start and at each reset: the same seed rebuilds the
  // same arena and controller.
  setup.makeWorld = [seed = options.seed, objects = options.objects,
                     grasp = options.grasp]() -> std::unique_ptr<Simulator> {
    IunctusSimulator::Options world;
    world.objects = objects;
    world.seed = seed;
    auto simulator = std::make_unique<IunctusSimulator>(
        world, grasp ? nullptr : std::make_unique<RandomController>(seed));
    if (grasp) simulator->useGrasper();
    return simulator;
  };
  setup.agentSignals = agentSignalsOf<IunctusSimulator>([](const IunctusSimulator& world) {
    const Iunctus& agent = world.iunctus();
    return AgentSignals{agent.sensors(), agent.effectors()};
  });
  return runSimulationApp(std::move(setup), options.gui, argv[0]);
}
