// PacWx: two Pacs with random controllers in their arena, in a window. The same world options
// as PacText (--seed, --food, --solver), plus the shared GUI options (speed, geometry, and the
// automation options --screenshot, --after and --print-drag). Run with --help for the list.
// The side panel shows Pac 0's sensors and effectors.

#include "PacSimulator.h"

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
  int food = 16;
  thyrix::ContactSolverKind solver = thyrix::ContactSolverKind::Baraff;
  thyrix::GuiOptions gui;
};

const char* const usage =
    "Usage: PacWx [options]\n"
    "Shows two Pacs with random controllers and their food; drag objects with the mouse.\n"
    "  --seed S             seed of the layout and of the controllers (default 1)\n"
    "  --food N             food circles in the arena (default 16)\n"
    "  --solver S           baraff or gauss-seidel (default baraff)\n";

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
    if (option != "--seed" && option != "--food" && option != "--solver")
      throw std::invalid_argument("unknown option: " + std::string(option));
    if (i + 1 >= argc) throw std::invalid_argument(std::string(option) + " needs a value");
    const std::string_view value = argv[++i];
    if (option == "--seed") {
      o.seed = thyrix::examples::parseNumber<std::uint32_t>(option, value, 0);
    } else if (option == "--food") {
      o.food = thyrix::examples::parseNumber<int>(option, value, 0);
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
    std::fprintf(stderr, "PacWx: %s\n%s", error.what(), usage);
    std::fputs(guiOptionsUsage, stderr);
    return 2;
  }

  SimulationSetup setup;
  setup.title = "PacWx - Thyrix";
  setup.solver = options.solver;
  // Called on the simulation thread at start and at each reset. The two controllers draw from
  // distinct streams of the one seed, as in PacText.
  setup.makeWorld = [seed = options.seed, food = options.food] {
    PacSimulator::Options world;
    world.food = food;
    world.seed = seed;
    return std::make_unique<PacSimulator>(world, std::make_unique<RandomController>(seed),
                                          std::make_unique<RandomController>(seed ^ 0x9e3779b9u));
  };
  setup.agentSignals = agentSignalsOf<PacSimulator>([](const PacSimulator& world) {
    const Pac& agent = world.pac(0);
    return AgentSignals{agent.sensors(), agent.effectors()};
  });
  return runSimulationApp(std::move(setup), options.gui, argv[0]);
}
