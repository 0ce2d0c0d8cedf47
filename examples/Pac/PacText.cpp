// PacText: runs two Pacs in their arena, each with a random controller (or Pac 0 eating with the
// scripted PacEater), and prints, at each printed step, both agents' centres and how many food
// circles each holds inside its ring. Run with --help for the options.

#include "PacEater.h"
#include "PacSimulator.h"

#include <Controller/RandomController.h>
#include <ThyrixLite/SvgGUI.h>
#include <ThyrixLite/WorldDrawing.h>

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace {

struct Options {
  long steps = 1000;
  std::uint32_t seed = 1;
  int food = 16;
  long every = 1;
  bool eat = false;
  thyrix::ContactSolverKind solver = thyrix::ContactSolverKind::Baraff;
  std::string svgDirectory;
  long svgEvery = 100;
};

const char* const usage =
    "Usage: PacText [options]\n"
    "Runs two Pacs with random controllers and prints 'step x0 y0 n0 x1 y1 n1': each Pac's\n"
    "centre and the number of food circles inside its ring.\n"
    "  --steps N       steps to simulate (default 1000)\n"
    "  --seed S        seed of the arena layout and of the controllers (default 1)\n"
    "  --food N        food circles in the arena (default 16)\n"
    "  --solver S      baraff or gauss-seidel (default baraff)\n"
    "  --every K       print every K-th step (default 1)\n"
    "  --eat           Pac 0 eats the nearest food, one after another, by a script\n"
    "  --svg DIR       write an SVG picture of the world to DIR every --svg-every steps\n"
    "  --svg-every K   (default 100)\n"
    "  --help          this text\n";

template <class T>
T number(std::string_view option, std::string_view text, T low) {
  T value{};
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || value < low)
    throw std::invalid_argument(std::string(option) + " needs a whole number >= " +
                                std::to_string(low) + ", not '" + std::string(text) + "'");
  return value;
}

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string_view option = argv[i];
    if (option == "--help") {
      std::fputs(usage, stdout);
      std::exit(0);
    }
    if (option == "--eat") {
      o.eat = true;
      continue;
    }
    if (i + 1 >= argc)
      throw std::invalid_argument("unknown option or missing value: " + std::string(option));
    const std::string_view value = argv[++i];
    if (option == "--steps")
      o.steps = number<long>(option, value, 0);
    else if (option == "--seed")
      o.seed = number<std::uint32_t>(option, value, 0);
    else if (option == "--food")
      o.food = number<int>(option, value, 0);
    else if (option == "--every")
      o.every = number<long>(option, value, 1);
    else if (option == "--svg-every")
      o.svgEvery = number<long>(option, value, 1);
    else if (option == "--svg")
      o.svgDirectory = value;
    else if (option == "--solver") {
      if (value == "baraff")
        o.solver = thyrix::ContactSolverKind::Baraff;
      else if (value == "gauss-seidel")
        o.solver = thyrix::ContactSolverKind::GaussSeidel;
      else
        throw std::invalid_argument("--solver must be baraff or gauss-seidel, not '" +
                                    std::string(value) + "'");
    } else {
      throw std::invalid_argument("unknown option: " + std::string(option));
    }
  }
  return o;
}

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
  Options options;
  try {
    options = parse(argc, argv);
  } catch (const std::invalid_argument& error) {
    std::fprintf(stderr, "PacText: %s\n%s", error.what(), usage);
    return 2;
  }
  try {
    PacSimulator::Options world;
    world.food = options.food;
    world.seed = options.seed;
    // Distinct streams for the two controllers, both from the one seed.
    PacSimulator simulator(world,
                           options.eat ? nullptr : std::make_unique<RandomController>(options.seed),
                           std::make_unique<RandomController>(options.seed ^ 0x9e3779b9u));
    simulator.setContactSolver(options.solver);

    // The script, for --eat: a new target once the last one is carried for a while, or when
    // it could not be eaten for too long (held against the other Pac, say; it is then
    // skipped). With nothing left to eat, Pac 0 stands still, its mouth closed.
    std::optional<PacEater> eater;
    std::vector<const PhysicalObject*> skipped;
    long sinceTarget = 0;
    for (long step = 1; step <= options.steps; ++step) {
      if (options.eat) {
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
      if (step % options.every == 0) {
        const Vector2 c0 = simulator.pac(0).centre();
        const Vector2 c1 = simulator.pac(1).centre();
        std::printf("%ld %.6f %.6f %d %.6f %.6f %d\n", step, static_cast<double>(c0.x),
                    static_cast<double>(c0.y), simulator.foodInside(simulator.pac(0)),
                    static_cast<double>(c1.x), static_cast<double>(c1.y),
                    simulator.foodInside(simulator.pac(1)));
      }
      if (!options.svgDirectory.empty() && step % options.svgEvery == 0) {
        SvgGUI svg({0, 0}, {world.size, world.size}, 600);
        DrawOptions draw;
        draw.contacts = draw.contactForces = true;
        drawWorld(simulator, svg, draw);
        char name[64];
        std::snprintf(name, sizeof name, "/step_%06ld.svg", step);
        svg.save(options.svgDirectory + name);
      }
    }
  } catch (const std::exception& error) {
    std::fprintf(stderr, "PacText: %s\n", error.what());
    return 1;
  }
  return 0;
}
