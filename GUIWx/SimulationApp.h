#pragma once
/// @file SimulationApp.h
/// @brief Runs a whole graphical program around one SimulationFrame, from an ordinary main().

#include <GUIWx/GuiOptions.h>
#include <GUIWx/SimulationSetup.h>

namespace thyrix {

/// Starts wxWidgets, shows a SimulationFrame for @p setup with @p options, and returns when
/// the window is closed, with the process exit code: 0, or 1 if the window system could not be
/// opened, the frame could not be built, or an automated run failed (see SimulationFrame).
///
/// The program parses its own command line (parseGuiOption() handles the shared options), so
/// wxWidgets sees only @p programName. SIGINT and SIGTERM close the window cleanly. In an
/// automated run (--screenshot or --print-drag) a failed wxWidgets assertion is printed to
/// stderr instead of opening a dialog that no one would answer.
int runSimulationApp(SimulationSetup setup, const GuiOptions& options, const char* programName);

}  // namespace thyrix
