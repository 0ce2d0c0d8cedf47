// IunctusWx: Iunctus and the circles it catches, in a window, driven by the random controller
// or (--grasp) by the scripted grasper. The same world options as IunctusText, plus the shared
// GUI options (speed, geometry, and the automation options --screenshot, --after and
// --print-drag). Run with --help for the list.

#include <Agents/IunctusSimulator.h>

#include <Controller/RandomController.h>
#include <WindowCommandLine.h>

int main(int argc, char** argv) {
  using namespace thyrix;
  const examples::WindowProgram program{
      "IunctusWx",
      "Usage: IunctusWx [options]\n"
      "Shows Iunctus and the circles it catches; drag objects (and its links) with the mouse.\n"
      "  --seed S             seed of the arena layout and of the controller (default 1)\n"
      "  --solver S           baraff or gauss-seidel (default baraff)\n"
      "  --objects N          circles to catch in the arena (default 1)\n"
      "  --grasp              drive it with the scripted grasper instead of the random "
      "controller\n",
      "--objects", 1, "--grasp"};
  return examples::runWindowProgram(program, argc, argv, [](const examples::WindowOptions& o) {
    SimulationSetup setup;
    setup.title = "IunctusWx - Thyrix";
    // Called on the simulation thread at start and at each reset: the same seed rebuilds the
    // same arena and controller.
    setup.makeWorld = [seed = o.seed, objects = o.count,
                       grasp = o.flag]() -> std::unique_ptr<Simulator> {
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
    return setup;
  });
}
