#pragma once
/// @file WindowCommandLine.h
/// @brief The command line of the example window programs: their world options and the GUI's.
/// Header-only, because only the programs built with the wxWidgets front-end include it.

#include <CommandLine.h>
#include <GUIWx/GuiOptions.h>
#include <GUIWx/SimulationApp.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <string_view>

namespace thyrix::examples {

/// What a window program accepts besides --seed, --solver and the GUI options.
struct WindowProgram {
  const char* name;                  ///< the program, e.g. "SpherusWx"
  const char* usage;                 ///< its usage lines, ending with its own options
  std::string_view countOption;      ///< its object-count option, e.g. "--objects"
  int defaultCount = 0;              ///< that option's default
  std::string_view flagOption = {};  ///< an on/off option, e.g. "--grasp", or none
  std::string_view fileOption = {};  ///< an option naming a file, e.g. "--genome", or none
};

/// A window program's parsed options.
struct WindowOptions {
  std::uint32_t seed = 1;                                ///< --seed
  int count = 0;                                         ///< the count option
  bool flag = false;                                     ///< the on/off option
  ContactSolverKind solver = ContactSolverKind::Baraff;  ///< --solver
  GuiOptions gui;                                        ///< the GUI's own options
  std::string file;  ///< the file option's value (empty if not given)
};

/// Parses a window program's command line; --help prints the usage and exits 0.
/// @throws std::invalid_argument naming a bad or unknown option
inline WindowOptions parseWindowOptions(const WindowProgram& program, int argc, char** argv) {
  WindowOptions o;
  o.count = program.defaultCount;
  for (int i = 1; i < argc; ++i) {
    const std::string_view option = argv[i];
    if (option == "--help") {
      std::printf("%s%s  --help               this text\n", program.usage, guiOptionsUsage);
      std::exit(0);
    }
    if (const int used = parseGuiOption(argc, argv, i, o.gui); used > 0) {
      i += used - 1;
      continue;
    }
    if (!program.flagOption.empty() && option == program.flagOption) {
      o.flag = true;
      continue;
    }
    if (!program.fileOption.empty() && option == program.fileOption) {
      if (i + 1 >= argc || std::string_view(argv[i + 1]).empty())
        throw std::invalid_argument(std::string(option) + " needs a file");
      o.file = argv[++i];
      continue;
    }
    if (option != "--seed" && option != "--solver" && option != program.countOption)
      throw std::invalid_argument("unknown option: " + std::string(option));
    if (i + 1 >= argc) throw std::invalid_argument(std::string(option) + " needs a value");
    const std::string_view value = argv[++i];
    if (option == "--seed")
      o.seed = parseNumber<std::uint32_t>(option, value, 0);
    else if (option == "--solver")
      o.solver = parseSolver(value);
    else
      o.count = parseNumber<int>(option, value, 0);
  }
  return o;
}

/// The main() of a window program: parses the command line (status 2 and the usage on a bad
/// option), builds the SimulationSetup with @p makeSetup(options) (status 1 and its message if
/// it throws, e.g. on an unreadable file) and runs the application.
template <class MakeSetup>
int runWindowProgram(const WindowProgram& program, int argc, char** argv, MakeSetup&& makeSetup) {
  WindowOptions options;
  try {
    options = parseWindowOptions(program, argc, argv);
  } catch (const std::invalid_argument& error) {
    std::fprintf(stderr, "%s: %s\n%s%s", program.name, error.what(), program.usage,
                 guiOptionsUsage);
    return 2;
  }
  SimulationSetup setup;
  try {
    setup = makeSetup(options);
  } catch (const std::exception& error) {
    std::fprintf(stderr, "%s: %s\n", program.name, error.what());
    return 1;
  }
  setup.solver = options.solver;
  return runSimulationApp(std::move(setup), options.gui, argv[0]);
}

}  // namespace thyrix::examples
