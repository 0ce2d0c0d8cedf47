// PacWx: two Pacs with random controllers in their arena, in a window. The same world options
// as PacText (--seed, --food, --solver), plus the shared GUI options (speed, geometry, and the
// automation options --screenshot, --after and --print-drag). Run with --help for the list.
// The side panel shows Pac 0's sensors and effectors. With --eat, Pac 0 eats by the script of
// PacEatingSimulator, as in PacText: the script runs in the world's advanceTime(), which the
// window's simulation thread calls.

#include <Agents/PacEatingSimulator.h>
#include <Agents/PacSimulator.h>

#include <Controller/RandomController.h>
#include <WindowCommandLine.h>

int main(int argc, char** argv) {
  using namespace thyrix;
  const examples::WindowProgram program{
      "PacWx",
      "Usage: PacWx [options]\n"
      "Shows two Pacs with random controllers and their food; drag objects with the mouse.\n"
      "  --seed S             seed of the layout and of the controllers (default 1)\n"
      "  --solver S           baraff or gauss-seidel (default baraff)\n"
      "  --food N             food circles in the arena (default 16)\n"
      "  --eat                Pac 0 eats the nearest food, one after another, by a script\n",
      "--food", 16, "--eat"};
  return examples::runWindowProgram(program, argc, argv, [](const examples::WindowOptions& o) {
    SimulationSetup setup;
    setup.title = "PacWx - Thyrix";
    // Called on the simulation thread at start and at each reset. The two controllers draw
    // from distinct streams of the one seed, as in PacText.
    setup.makeWorld = [seed = o.seed, food = o.count, eat = o.flag]() -> std::unique_ptr<World> {
      PacSimulator::Options world;
      world.food = food;
      world.seed = seed;
      auto second = std::make_unique<RandomController>(seed ^ 0x9e3779b9u);
      if (eat) return std::make_unique<PacEatingSimulator>(world, std::move(second));
      return std::make_unique<PacSimulator>(world, std::make_unique<RandomController>(seed),
                                            std::move(second));
    };
    setup.agentSignals = agentSignalsOf<PacSimulator>([](const PacSimulator& world) {
      const Pac& agent = world.pac(0);
      return AgentSignals{agent.sensors(), agent.effectors()};
    });
    return setup;
  });
}
