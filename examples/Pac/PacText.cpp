// PacText: runs two Pacs in their arena, each with a random controller (or Pac 0 eating with the
// scripted PacEater), and prints, at each printed step, both agents' centres and how many food
// circles each holds inside its ring. Run with --help for the options.

#include "PacEater.h"
#include "PacSimulator.h"

#include <CommandLine.h>
#include <Controller/RandomController.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace {

const thyrix::examples::ConsoleProgram program{
    "PacText",
    "Usage: PacText [options]\n"
    "Runs two Pacs with random controllers and prints 'step x0 y0 n0 x1 y1 n1': each Pac's\n"
    "centre and the number of food circles inside its ring.\n"
    "  --food N        food circles in the arena (default 16)\n"
    "  --eat           Pac 0 eats the nearest food, one after another, by a script\n",
    "--food", 16, "--eat"};

/// The food circle nearest to Pac 0 that no Pac holds, that is not in @p skipped, and that
/// lies far enough from the walls for Pac to get its mouth past it; or null.
const thyrix::Circle* nearestFreeFood(const thyrix::PacSimulator& simulator,
                                      const std::vector<const thyrix::PhysicalObject*>& skipped) {
  const thyrix::Circle* nearest = nullptr;
  thyrix::real best = 0;
  const thyrix::PacParameters& pac = simulator.options().pac;
  const thyrix::real margin = pac.ringRadius + 2 * pac.radius;
  const thyrix::real size = simulator.options().size;
  for (const thyrix::Circle* food : simulator.food()) {
    if (simulator.pac(0).contains(food->r) || simulator.pac(1).contains(food->r)) continue;
    if (std::find(skipped.begin(), skipped.end(), food) != skipped.end()) continue;
    if (std::min({food->r.x, food->r.y, size - food->r.x, size - food->r.y}) < margin) continue;
    const thyrix::real d = thyrix::distance(food->r, simulator.pac(0).centre());
    if (nearest == nullptr || d < best) {
      nearest = food;
      best = d;
    }
  }
  return nearest;
}

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
    PacSimulator::Options world;
    world.food = options.count;
    world.seed = options.run.seed;
    // Distinct streams for the two controllers, both from the one seed.
    PacSimulator simulator(
        world, options.flag ? nullptr : std::make_unique<RandomController>(options.run.seed),
        std::make_unique<RandomController>(options.run.seed ^ 0x9e3779b9u));
    simulator.setContactSolver(options.run.solver);

    // The script, for --eat: a new target once the last one is carried for a while, or when
    // it could not be eaten for too long (held against the other Pac, say; it is then
    // skipped). With nothing left to eat, Pac 0 stands still, its mouth closed.
    std::optional<PacEater> eater;
    std::vector<const PhysicalObject*> skipped;
    long sinceTarget = 0;
    for (long step = 1; step <= options.run.steps; ++step) {
      if (options.flag) {
        const bool givenUp = eater && !eater->done() && sinceTarget > 2000;
        if (givenUp) skipped.push_back(&eater->target());
        if (!eater || givenUp || (eater->done() && sinceTarget > 300)) {
          const Circle* target = nearestFreeFood(simulator, skipped);
          if (target == nullptr)
            eater.reset();
          else if (eater)
            eater->setTarget(*target);
          else
            eater.emplace(simulator.pac(0), *target);
          sinceTarget = 0;
        }
        if (eater)
          eater->step();
        else
          std::fill(simulator.pac(0).effectors().begin(), simulator.pac(0).effectors().end(),
                    real(0));
        ++sinceTarget;
      }
      simulator.advanceTime();
      if (step % options.run.every == 0) {
        const Vector2 c0 = simulator.pac(0).centre();
        const Vector2 c1 = simulator.pac(1).centre();
        std::printf("%ld %.6f %.6f %d %.6f %.6f %d\n", step, static_cast<double>(c0.x),
                    static_cast<double>(c0.y), simulator.foodInside(simulator.pac(0)),
                    static_cast<double>(c1.x), static_cast<double>(c1.y),
                    simulator.foodInside(simulator.pac(1)));
      }
      examples::writeSvgIfDue(options.run, simulator, step, {0, 0}, {world.size, world.size});
    }
  } catch (const std::exception& error) {
    std::fprintf(stderr, "PacText: %s\n", error.what());
    return 1;
  }
  return 0;
}
