// ArenaText: a console scene of ThyrixLite. Circles in a walled arena are pushed by a force
// whose direction turns every 100 steps; the program prints the position of the pushed
// group's centre. With --svg it also writes pictures of the arena, contacts and forces drawn,
// as SVG files. Run with --help for the options.

#include <Scenes.h>
#include <ThyrixLite/Simulator.h>
#include <ThyrixLite/SvgGUI.h>
#include <ThyrixLite/WorldDrawing.h>

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
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
  std::string svgDirectory;  // empty: no pictures
  long svgEvery = 0;         // 0: not given, 100 once --svg is
};

const char* const usage =
    "Usage: ArenaText [options]\n"
    "  --steps N     steps to simulate (default 1000)\n"
    "  --seed S      seed of the random layout (default 1)\n"
    "  --bodies N    circles in the arena (default 20)\n"
    "  --every K     print every K-th step (default 10)\n"
    "  --solver S    baraff or gauss-seidel (default baraff)\n"
    "  --svg DIR     also write SVG pictures of the arena, with contacts and contact\n"
    "                forces, to DIR/step_000100.svg and so on (DIR is created if needed)\n"
    "  --svg-every K write a picture every K-th step (default 100; needs --svg)\n"
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
    } else if (option == "--svg") {
      if (*value == '\0') throw std::invalid_argument("--svg needs a directory, not ''");
      options.svgDirectory = value;
    } else if (option == "--svg-every") {
      options.svgEvery = parseNumber<long>(option, value, 1);
    } else {
      throw std::invalid_argument("unknown option: " + std::string(option));
    }
  }
  if (options.svgEvery != 0 && options.svgDirectory.empty())
    throw std::invalid_argument("--svg-every needs --svg DIR");
  if (!options.svgDirectory.empty() && options.svgEvery == 0) options.svgEvery = 100;
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
  // The 10 x 10 arena with a margin, so the walls' shaded solid sides show.
  SvgGUI picture(Vector2{real(-0.3), real(-0.3)}, Vector2{real(10.3), real(10.3)}, 600);
  if (!options.svgDirectory.empty()) {
    std::error_code error;
    std::filesystem::create_directories(options.svgDirectory, error);
    if (error || !std::filesystem::is_directory(options.svgDirectory)) {
      std::fprintf(stderr, "ArenaText: --svg: cannot create the directory '%s'%s%s\n",
                   options.svgDirectory.c_str(), error ? ": " : "",
                   error ? error.message().c_str() : "");
      return 1;
    }
  }
  for (long step = 1; step <= options.steps; ++step) {
    const real angle = static_cast<real>((step - 1) / 100) * real(2.39996323);  // golden angle
    scenes::push(pushed, Vector2{std::cos(angle), std::sin(angle)});
    simulator.advanceTime();
    if (!options.svgDirectory.empty() && step % options.svgEvery == 0) {
      // Drawn right after the step, while its contacts and forces are still kept.
      picture.clear();
      drawWorld(simulator, picture, {.contacts = true, .contactForces = true});
      char name[32];
      std::snprintf(name, sizeof name, "step_%06ld.svg", step);
      try {
        picture.save((std::filesystem::path(options.svgDirectory) / name).string());
      } catch (const std::runtime_error& failure) {
        std::fprintf(stderr, "ArenaText: %s\n", failure.what());
        return 1;
      }
    }
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
