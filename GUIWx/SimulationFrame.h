#pragma once
/// @file SimulationFrame.h
/// @brief The main window of a simulation: the world view, the agent's activity, the controls.

#include <GUIWx/GuiOptions.h>
#include <GUIWx/SimulationRunner.h>
#include <GUIWx/SimulationSetup.h>

#include <wx/frame.h>
#include <wx/timer.h>

#include <chrono>
#include <functional>
#include <memory>
#include <string>
#include <vector>

class wxChoice;

namespace thyrix {

class ActivationPanel;
class WorldView;

/// A window that runs any World: give it a SimulationSetup (how to build the world, and
/// optionally the agent's sensors and effectors) and show it. A Simulator's objects can be
/// dragged and its contacts drawn; another World is stepped and drawn, the solver control off.
///
/// It owns a SimulationRunner (the simulation thread) and shows a WorldView, a side panel of
/// live activation bars (when the setup has agentSignals), a menu and a toolbar (run/pause,
/// single step, reset, speed, solver, overlays, fit, screenshot) and a status bar (steps,
/// simulated steps per second, contacts). Closing it stops and joins the simulation thread
/// before the window goes.
///
/// The GuiOptions add what scripts need: a fixed geometry; `screenshot` (save a PNG of the
/// view after `screenshotAfter` steps, print the mapping and the objects, then close);
/// `printDrag` (print the view's mapping, each object's screen pixel, then "ready", and
/// every drag event).
class SimulationFrame : public wxFrame {
 public:
  /// A frame for the world that @p setup describes.
  /// @param setup how to build the world, and the agent's signals (see SimulationSetup)
  /// @param options window geometry, speed and automation; they override @p setup's defaults
  /// @param exitCode optional, told the process exit code an automated run ends with
  ///        (0, or 1 if the screenshot could not be written or the world failed)
  explicit SimulationFrame(SimulationSetup setup, const GuiOptions& options = {},
                           std::function<void(int)> exitCode = {});
  ~SimulationFrame() override;

  /// The simulation thread's controller.
  [[nodiscard]] SimulationRunner& runner() { return *runner_; }
  /// The world view.
  [[nodiscard]] WorldView& view() { return *view_; }

 private:
  void buildMenus();
  void buildToolBar();
  void setSpeed(std::size_t index);
  void setSolver(ContactSolverKind solver);
  void toggleOverlay(bool DrawOptions::*overlay);
  void saveScreenshotDialog();
  void showControls();
  void onKey(wxKeyEvent& event);
  void onSnapshot(const WorldSnapshot& snapshot);
  void onAutomationTimer(wxTimerEvent& event);
  void printLayout(const WorldSnapshot& snapshot);
  void finishAutomation(int code);
  void shutDown();

  GuiOptions options_;
  std::function<void(int)> exitCode_;
  std::unique_ptr<SimulationRunner> runner_;
  WorldView* view_ = nullptr;            // owned by this frame (wx child window)
  ActivationPanel* activity_ = nullptr;  // owned by this frame; null without an agent
  wxChoice* speedChoice_ = nullptr;      // owned by the toolbar
  wxChoice* solverChoice_ = nullptr;     // owned by the toolbar
  std::vector<double> speeds_;           // steps per second of each speed choice, 0 = max
  DrawOptions draw_;
  wxTimer automationTimer_;
  std::chrono::steady_clock::time_point lastStatus_;
  std::chrono::steady_clock::time_point readySince_;
  bool readySeen_ = false;
  bool layoutPrinted_ = false;
  bool finished_ = false;
  std::string lastViewLine_;
};

}  // namespace thyrix
