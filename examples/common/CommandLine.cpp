#include "CommandLine.h"

#include <ThyrixLite/SvgGUI.h>
#include <ThyrixLite/WorldDrawing.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <system_error>

namespace thyrix::examples {

const char* const consoleOptionsUsage =
    "  --steps N       steps to simulate (default 1000)\n"
    "  --seed S        seed of the layout and of the controllers (default 1)\n"
    "  --solver S      baraff or gauss-seidel (default baraff)\n"
    "  --every K       print every K-th step (default 1)\n"
    "  --svg DIR       write an SVG picture of the world to DIR every --svg-every steps\n"
    "  --svg-every K   (default 100)\n"
    "  --animation F   write the episode as an animated SVG F (opens in a browser)\n"
    "  --animation-every K  a frame every K steps (default 10)\n";

ContactSolverKind parseSolver(std::string_view text) {
  if (text == "baraff") return ContactSolverKind::Baraff;
  if (text == "gauss-seidel") return ContactSolverKind::GaussSeidel;
  throw std::invalid_argument("--solver must be baraff or gauss-seidel, not '" + std::string(text) +
                              "'");
}

int parseConsoleOption(int argc, char** argv, int i, ConsoleOptions& options) {
  const std::string_view option = argv[i];
  if (option != "--steps" && option != "--seed" && option != "--solver" && option != "--every" &&
      option != "--svg" && option != "--svg-every" && option != "--animation" &&
      option != "--animation-every")
    return 0;
  if (i + 1 >= argc) throw std::invalid_argument(std::string(option) + " needs a value");
  const std::string_view value = argv[i + 1];
  if (option == "--steps") options.steps = parseNumber<long>(option, value, 0);
  if (option == "--seed") options.seed = parseNumber<std::uint32_t>(option, value, 0);
  if (option == "--solver") options.solver = parseSolver(value);
  if (option == "--every") options.every = parseNumber<long>(option, value, 1);
  if (option == "--svg-every") options.svgEvery = parseNumber<long>(option, value, 1);
  if (option == "--animation-every") options.animationEvery = parseNumber<long>(option, value, 1);
  if (option == "--animation") {
    if (value.empty()) throw std::invalid_argument("--animation needs a file");
    options.animation = value;
  }
  if (option == "--svg") {
    if (value.empty()) throw std::invalid_argument("--svg needs a directory");
    options.svgDirectory = value;
  }
  return 2;
}

ConsoleArguments parseConsoleProgram(const ConsoleProgram& program, int argc, char** argv) {
  ConsoleArguments o;
  o.count = program.defaultCount;
  for (int i = 1; i < argc; ++i) {
    const std::string_view option = argv[i];
    if (option == "--help") {
      std::printf("%s%s  --help          this text\n", program.usage, consoleOptionsUsage);
      std::exit(0);
    }
    if (!program.flagOption.empty() && option == program.flagOption) {
      o.flag = true;
      continue;
    }
    if (const int used = parseConsoleOption(argc, argv, i, o.run)) {
      i += used - 1;
      continue;
    }
    if (!program.fileOption.empty() && option == program.fileOption) {
      if (i + 1 >= argc) throw std::invalid_argument(std::string(option) + " needs a file");
      o.file = argv[++i];
      if (o.file.empty()) throw std::invalid_argument(std::string(option) + " needs a file");
      continue;
    }
    if (option != program.countOption)
      throw std::invalid_argument("unknown option: " + std::string(option));
    if (i + 1 >= argc) throw std::invalid_argument(std::string(option) + " needs a value");
    o.count = parseNumber<int>(option, argv[++i], 0);
  }
  return o;
}

int reportUsageError(const ConsoleProgram& program, const std::exception& error) {
  std::fprintf(stderr, "%s: %s\n%s%s", program.name, error.what(), program.usage,
               consoleOptionsUsage);
  return 2;
}

AnimationRecorder::AnimationRecorder(const ConsoleOptions& options, Vector2 lower, Vector2 upper)
    : options_(options) {
  if (options.animation.empty()) return;
  // Frames at the pace of the simulation: a frame every k steps shows k timesteps.
  animation_ = std::make_unique<SvgAnimation>(lower, upper, 600,
                                              0.01 * static_cast<double>(options.animationEvery));
}

AnimationRecorder::~AnimationRecorder() = default;

void AnimationRecorder::record(const Simulator& simulator, long step) {
  if (!animation_ || (step % options_.animationEvery != 0 && step != 1)) return;
  char caption[48];
  std::snprintf(caption, sizeof caption, "step %ld", step);
  animation_->addFrame(simulator, {}, caption);
}

void AnimationRecorder::finish() const {
  if (animation_) animation_->save(options_.animation);
}

void prepareSvgDirectory(const ConsoleOptions& options) {
  if (options.svgDirectory.empty()) return;
  const std::string& directory = options.svgDirectory;
  std::error_code error;
  std::filesystem::create_directories(directory, error);
  if (error)
    throw std::runtime_error("--svg: cannot create the directory " + directory + ": " +
                             error.message());
  // A file written and removed: permissions and a read-only file system show only on writing.
  const std::string probe = directory + "/.thyrix-svg-probe";
  std::FILE* file = std::fopen(probe.c_str(), "wb");
  if (file == nullptr)
    throw std::runtime_error("--svg: cannot write to the directory " + directory + ": " +
                             std::strerror(errno));
  std::fclose(file);
  std::remove(probe.c_str());
}

void writeSvgIfDue(const ConsoleOptions& options, const Simulator& simulator, long step,
                   Vector2 lower, Vector2 upper) {
  if (options.svgDirectory.empty() || step % options.svgEvery != 0) return;
  std::filesystem::create_directories(options.svgDirectory);
  SvgGUI svg(lower, upper, 600);
  DrawOptions draw;
  draw.contacts = draw.contactForces = draw.tactile = draw.visualRays = true;
  drawWorld(simulator, svg, draw);
  char name[32];
  std::snprintf(name, sizeof name, "/step_%06ld.svg", step);
  svg.save(options.svgDirectory + name);
}

}  // namespace thyrix::examples
