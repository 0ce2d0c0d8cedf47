#pragma once
/// @file GuiOptions.h
/// @brief The command-line options every graphical program of Thyrix shares: window geometry,
/// speed, and the automation options that let a script drive and check the program.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace thyrix {

/// Options of the window and of automated runs (see guiOptionsUsage).
struct GuiOptions {
  /// Window position and size (pixels); a negative position lets the system choose.
  int x = -1;
  int y = -1;        ///< see x
  int width = 1000;  ///< window width (pixels)
  int height = 700;  ///< window height (pixels)
  /// Steps per second; 0 = as fast as possible; unset = the program's default (or, with
  /// --screenshot, as fast as possible).
  std::optional<double> stepsPerSecond;
  /// Pause when this many steps are done (0 = never).
  std::uint64_t stopAfter = 0;
  /// Save a PNG of the view to this file once `screenshotAfter` steps are done, then exit.
  std::string screenshot;
  /// Steps before the screenshot.
  std::uint64_t screenshotAfter = 100;
  /// Print the view's mapping, the objects' screen pixels and every drag event to stdout.
  bool printDrag = false;
  /// Start paused.
  bool paused = false;
};

/// Usage lines of the options parseGuiOption() accepts, for a program's --help.
extern const char* const guiOptionsUsage;

/// If `argv[i]` is one of the shared options, stores it (and its value, `argv[i + 1]`) in
/// @p options and returns how many arguments it used (1 or 2); returns 0 for any other
/// argument, which the program then parses itself. `--steps N` is shared: it pauses after N
/// steps.
/// @throws std::invalid_argument naming the option if its value is missing or malformed
int parseGuiOption(int argc, char** argv, int i, GuiOptions& options);

}  // namespace thyrix
