// SpherusWx: Spherus with the random controller (or an evolved one, --genome) in its arena, in
// a window. The same world
// options as SpherusText, plus the shared GUI options (speed, geometry, and the automation
// options --screenshot, --after and --print-drag). Run with --help for the list.

#include <Agents/SpherusSimulator.h>

#include <Controller/Genome.h>
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
      "  --objects N          circles in the arena (default 20)\n"
      "  --genome FILE        drive Spherus by the network in FILE (SpherusEvolve's best.genome)\n",
      "--objects",
      20,
      {},
      "--genome"};
  return examples::runWindowProgram(program, argc, argv, [](const examples::WindowOptions& o) {
    SimulationSetup setup;
    setup.title = o.file.empty() ? "SpherusWx - Thyrix" : "SpherusWx - " + o.file + " - Thyrix";
    // Called on the simulation thread at start and at each reset: the same seed rebuilds the
    // same arena and controller.
    // The genome is read once, here, so that a bad file is reported before the window opens.
    std::shared_ptr<const Genome> genome;
    if (!o.file.empty()) {
      genome = std::make_shared<const Genome>(Genome::load(o.file));
      genome->requireShape(Spherus::sensorCount, Spherus::effectorCount);
    }
    setup.makeWorld = [seed = o.seed, objects = o.count, genome] {
      SpherusSimulator::Options world;
      world.objects = objects;
      world.seed = seed;
      std::unique_ptr<Controller> controller;
      if (genome)
        controller = genome->makeController(world.timestep);
      else
        controller = std::make_unique<RandomController>(seed);
      return std::make_unique<SpherusSimulator>(world, std::move(controller));
    };
    setup.agentSignals = agentSignalsOf<SpherusSimulator>([](const SpherusSimulator& world) {
      const Spherus& agent = world.spherus();
      return AgentSignals{agent.sensors(), agent.effectors()};
    });
    return setup;
  });
}
