// ArenaText: a console scene of ThyrixLite. Circles in a walled arena are pushed by a force
// whose direction turns every 100 steps; the program prints the position of the pushed
// group's centre. Run with --help for the options.

#include <Scenes.h>
#include <ThyrixLite/Simulator.h>

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <string>
#include <string_view>

namespace {

struct Options {
  long steps = 1000;
  unsigned seed = 1;
  int bodies = 20;
  long every = 10;
  thyrix::ContactSolverKind solver = thyrix::ContactSolverKind::Baraff;
};

const char* const usage =
    "Usage: ArenaText [options]\n"
    "  --steps N     steps to simulate (default 1000)\n"
    "  --seed S      seed of the random layout (default 1)\n"
    "  --bodies N    circles in the arena (default 20)\n"
    "  --every K     print every K-th step (default 10)\n"
    "  --solver S    baraff or gauss-seidel (default baraff)\n"
    "  --help        this text\n"
    "Prints 'step x y' for the centre of the pushed circles.\n";

template <class T>
T parseNumber(std::string_view option, const char* text, T low) {
  T value{};
  const std::string_view s(text);
  const auto [end, error] = std::from_chars(s.data(), s.data() + s.size(), value);
  if (error != std::errc() || end != s.data() + s.size() || value < low)
    throw std::invalid_argument(std::string(option) + " needs a whole number >= " +
                                std::to_string(low) + ", not '" + std::string(s) + "'");
  return value;
}

Options parse(int argc, char** argv) {
  Options options;
  for (int i = 1; i < argc; ++i) {
    const std::string_view option = argv[i];
    if (option == "--help") {
      std::fputs(usage, stdout);
      std::exit(0);
    }
    if (i + 1 >= argc)
      throw std::invalid_argument("unknown option or missing value: " + std::string(option));
    const char* value = argv[++i];
    if (option == "--steps")
      options.steps = parseNumber<long>(option, value, 0);
    else if (option == "--seed")
      options.seed = parseNumber<unsigned>(option, value, 0);
    else if (option == "--bodies")
      options.bodies = parseNumber<int>(option, value, 1);
    else if (option == "--every")
      options.every = parseNumber<long>(option, value, 1);
    else if (option == "--solver") {
      if (std::strcmp(value, "baraff") == 0)
        options.solver = thyrix::ContactSolverKind::Baraff;
      else if (std::strcmp(value, "gauss-seidel") == 0)
        options.solver = thyrix::ContactSolverKind::GaussSeidel;
      else
        throw std::invalid_argument("--solver must be baraff or gauss-seidel, not '" +
                                    std::string(value) + "'");
    } else {
      throw std::invalid_argument("unknown option: " + std::string(option));
    }
  }
  return options;
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  try {
    options = parse(argc, argv);
  } catch (const std::invalid_argument& error) {
    std::fprintf(stderr, "ArenaText: %s\n%s", error.what(), usage);
    return 2;
  }
  using namespace thyrix;
  Simulator simulator(real(0.01));
  simulator.setContactSolver(options.solver);
  scenes::addWalls(simulator, 10, 10);
  const auto circles =
      scenes::addRandomCircles(simulator, options.bodies, real(0.25), 10, options.seed);
  // The first quarter of the circles are pushed; the rest are obstacles.
  const std::vector<PhysicalObject*> pushed(circles.begin(),
                                            circles.begin() + (circles.size() + 3) / 4);
  for (long step = 1; step <= options.steps; ++step) {
    const real angle = static_cast<real>((step - 1) / 100) * real(2.39996323);  // golden angle
    scenes::push(pushed, Vector2{std::cos(angle), std::sin(angle)});
    simulator.advanceTime();
    if (step % options.every == 0) {
      Vector2 centre;
      for (const PhysicalObject* body : pushed) centre += body->r;
      centre = centre / static_cast<real>(pushed.size());
      std::printf("%ld %.6f %.6f\n", step, static_cast<double>(centre.x),
                  static_cast<double>(centre.y));
    }
  }
  return 0;
}
