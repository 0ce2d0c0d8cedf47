#pragma once
/// @file CommandLine.h
/// @brief The command-line options the example programs share, parsed in one place.

#include <ThyrixLite/ContactSolver.h>
#include <ThyrixLite/Simulator.h>
#include <ThyrixLite/SvgAnimation.h>

#include <charconv>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>

namespace thyrix::examples {

/// @p text as a whole number of at least @p low.
/// @throws std::invalid_argument naming @p option ("--steps needs a whole number >= 0, ...")
template <class T>
T parseNumber(std::string_view option, std::string_view text, T low) {
  T value{};
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || value < low)
    throw std::invalid_argument(std::string(option) + " needs a whole number >= " +
                                std::to_string(low) + ", not '" + std::string(text) + "'");
  return value;
}

/// "baraff" or "gauss-seidel". @throws std::invalid_argument naming --solver
ContactSolverKind parseSolver(std::string_view text);

/// The options of every console demo.
struct ConsoleOptions {
  long steps = 1000;       ///< --steps: steps to simulate
  std::uint32_t seed = 1;  ///< --seed: seed of the layout and of the controllers
  long every = 1;          ///< --every: print every k-th step
  ContactSolverKind solver = ContactSolverKind::Baraff;  ///< --solver
  std::string svgDirectory;  ///< --svg: where to write pictures (none if empty)
  long svgEvery = 100;       ///< --svg-every: a picture every k-th step
  std::string animation;     ///< --animation: the animated SVG to write (none if empty)
  long animationEvery = 10;  ///< --animation-every: a frame every k-th step
};

/// The usage lines of ConsoleOptions, for --help.
extern const char* const consoleOptionsUsage;

/// If `argv[i]` is one of ConsoleOptions, reads it and its value into @p options.
/// @return how many arguments it used (2), or 0 when `argv[i]` is not one of them
/// @throws std::invalid_argument for a missing or bad value, naming the option
int parseConsoleOption(int argc, char** argv, int i, ConsoleOptions& options);

/// What a console program accepts besides ConsoleOptions.
struct ConsoleProgram {
  const char* name;                  ///< the program, e.g. "SpherusText"
  const char* usage;                 ///< its usage lines, ending with its own options
  std::string_view countOption;      ///< its object-count option, e.g. "--objects"
  int defaultCount = 0;              ///< that option's default
  std::string_view flagOption = {};  ///< an on/off option, e.g. "--eat", or none
  std::string_view fileOption = {};  ///< an option naming a file, e.g. "--genome", or none
};

/// A console program's parsed options.
struct ConsoleArguments {
  ConsoleOptions run;  ///< the shared options
  int count = 0;       ///< the count option
  bool flag = false;   ///< the on/off option
  std::string file;    ///< the file option's value (empty if not given)
};

/// Parses a console program's command line; --help prints the usage and exits 0.
/// @throws std::invalid_argument naming a bad or unknown option
ConsoleArguments parseConsoleProgram(const ConsoleProgram& program, int argc, char** argv);

/// Prints @p error and the usage to stderr; returns 2, the status of a bad command line.
int reportUsageError(const ConsoleProgram& program, const std::exception& error);

/// With --animation, the episode's frames, the world's square [lower, upper] drawn every
/// --animation-every steps, written to that file by finish(). Without it, does nothing.
class AnimationRecorder {
 public:
  /// Records for @p options, showing [lower, upper].
  AnimationRecorder(const ConsoleOptions& options, Vector2 lower, Vector2 upper);
  ~AnimationRecorder();
  AnimationRecorder(const AnimationRecorder&) = delete;
  AnimationRecorder& operator=(const AnimationRecorder&) = delete;
  /// Adds a frame of @p simulator if @p step is due (and the first step).
  void record(const Simulator& simulator, long step);
  /// Writes the animation. @throws std::runtime_error if the file cannot be written
  void finish() const;

 private:
  const ConsoleOptions& options_;
  std::unique_ptr<SvgAnimation> animation_;
};

/// With --svg, creates its directory and checks that a file can be written there, so that a
/// bad directory is reported at the start, not when the first picture is due.
/// @throws std::runtime_error naming the directory if it cannot be created or written to
void prepareSvgDirectory(const ConsoleOptions& options);

/// At the steps --svg-every asks for (and only with --svg), writes
/// `DIR/step_NNNNNN.svg`: the square [lower, upper] of the world, contacts, forces and
/// sensors drawn. @throws std::runtime_error if the file cannot be written
void writeSvgIfDue(const ConsoleOptions& options, const Simulator& simulator, long step,
                   Vector2 lower, Vector2 upper);

}  // namespace thyrix::examples
