// SpherusText: runs Spherus with the random controller in its arena and prints, at each printed
// step, the position of the agent's centre. Run with --help for the options.

#include "SpherusSimulator.h"

#include <Controller/RandomController.h>
#include <ThyrixLite/SvgGUI.h>
#include <ThyrixLite/WorldDrawing.h>

#include <charconv>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <string_view>

namespace {

struct Options {
  long steps = 1000;
  std::uint32_t seed = 1;
  int objects = 20;
  long every = 1;
  thyrix::ContactSolverKind solver = thyrix::ContactSolverKind::Baraff;
  std::string svgDirectory;
  long svgEvery = 100;
};

const char* const usage =
    "Usage: SpherusText [options]\n"
    "Runs Spherus with a random controller and prints 'step x y' (the agent's centre).\n"
    "  --steps N       steps to simulate (default 1000)\n"
    "  --seed S        seed of the arena layout and of the controller (default 1)\n"
    "  --objects N     circles in the arena (default 20)\n"
    "  --solver S      baraff or gauss-seidel (default baraff)\n"
    "  --every K       print every K-th step (default 1)\n"
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
    if (i + 1 >= argc)
      throw std::invalid_argument("unknown option or missing value: " + std::string(option));
    const std::string_view value = argv[++i];
    if (option == "--steps")
      o.steps = number<long>(option, value, 0);
    else if (option == "--seed")
      o.seed = number<std::uint32_t>(option, value, 0);
    else if (option == "--objects")
      o.objects = number<int>(option, value, 0);
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

}  // namespace

int main(int argc, char** argv) {
  using namespace thyrix;
  Options options;
  try {
    options = parse(argc, argv);
  } catch (const std::invalid_argument& error) {
    std::fprintf(stderr, "SpherusText: %s\n%s", error.what(), usage);
    return 2;
  }
  try {
    SpherusSimulator::Options world;
    world.objects = options.objects;
    world.seed = options.seed;
    SpherusSimulator simulator(world, std::make_unique<RandomController>(options.seed));
    simulator.setContactSolver(options.solver);
    for (long step = 1; step <= options.steps; ++step) {
      simulator.advanceTime();
      if (step % options.every == 0) {
        const Vector2 c = simulator.spherus().centre();
        std::printf("%ld %.6f %.6f\n", step, static_cast<double>(c.x), static_cast<double>(c.y));
      }
      if (!options.svgDirectory.empty() && step % options.svgEvery == 0) {
        SvgGUI svg({0, 0}, {world.size, world.size}, 600);
        DrawOptions draw;
        draw.contacts = draw.contactForces = draw.tactile = draw.visualRays = true;
        drawWorld(simulator, svg, draw);
        char name[64];
        std::snprintf(name, sizeof name, "/step_%06ld.svg", step);
        svg.save(options.svgDirectory + name);
      }
    }
  } catch (const std::exception& error) {
    std::fprintf(stderr, "SpherusText: %s\n", error.what());
    return 1;
  }
  return 0;
}
