// SpherusWx: Spherus with the random controller in its arena, in a window. The same world
// options as SpherusText, plus the shared GUI options (speed, geometry, and the automation
// options --screenshot, --after and --print-drag). Run with --help for the list.

#include <Agents/SpherusSimulator.h>

#include <Controller/RandomController.h>
#include <WindowCommandLine.h>

int main(int argc, char** argv) {
  using namespace thyrix;
  const examples::WindowProgram program{
      "SpherusWx",
      "Usage: SpherusWx [options]\n"
      "Shows Spherus with a random controller in its arena; drag objects with the mouse.\n"
      "  --seed S             seed of the arena layout and of the controller (default 1)\n"
      "  --solver S           baraff or gauss-seidel (default baraff)\n"
      "  --objects N          circles in the arena (default 20)\n",
      "--objects", 20};
  return examples::runWindowProgram(program, argc, argv, [](const examples::WindowOptions& o) {
    SimulationSetup setup;
    setup.title = "SpherusWx - Thyrix";
    // Called on the simulation thread at start and at each reset: the same seed rebuilds the
    // same arena and controller.
    setup.makeWorld = [seed = o.seed, objects = o.count] {
      SpherusSimulator::Options world;
      world.objects = objects;
      world.seed = seed;
      return std::make_unique<SpherusSimulator>(world, std::make_unique<RandomController>(seed));
    };
    setup.agentSignals = agentSignalsOf<SpherusSimulator>([](const SpherusSimulator& world) {
      const Spherus& agent = world.spherus();
      return AgentSignals{agent.sensors(), agent.effectors()};
    });
    return setup;
  });
}
