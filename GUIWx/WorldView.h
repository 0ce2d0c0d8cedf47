#pragma once
/// @file WorldView.h
/// @brief The panel that shows a running world and lets the mouse grab its objects.

#include <GUIWx/SimulationRunner.h>
#include <GUIWx/ViewTransform.h>
#include <GUIWx/WorldSnapshot.h>

#include <wx/panel.h>
#include <wx/timer.h>

#include <functional>
#include <memory>

class wxDC;

namespace thyrix {

/// Shows the latest snapshot of a SimulationRunner, repainted (double-buffered) when a new one
/// arrives, polled 60 times a second by a wxTimer. It draws only from snapshots, never from the
/// world being stepped.
///
/// Mouse and keys: left-drag grabs the object under the cursor (picked against the snapshot's
/// circles and capsules) and pulls it with the simulator's mouse force until the button is
/// released; the wheel zooms about the cursor; right- or middle-drag pans; F fits the world to
/// the window. Until the user zooms or pans, the view keeps the world fitted when resized.
class WorldView : public wxPanel {
 public:
  /// A view in @p parent of the world run by @p runner, which must outlive the view or be
  /// detached first (detach()).
  WorldView(wxWindow* parent, SimulationRunner& runner);
  ~WorldView() override;

  /// Called on the GUI thread for each new snapshot the view takes (status bar, side panel).
  void setSnapshotListener(std::function<void(const WorldSnapshot&)> listener) {
    listener_ = std::move(listener);
  }
  /// Stops polling and forgets the runner: call before the runner is destroyed.
  void detach();

  /// Shows the whole world (thyrix::worldBounds of the latest snapshot), and keeps it fitted
  /// on resize until the next zoom or pan.
  void fitWorld();
  /// Draws the current snapshot on @p dc (of the view's size) as the view shows it.
  void render(wxDC& dc) const;
  /// Renders the current snapshot off-screen at the view's size and saves it as a PNG.
  /// @return false (and writes nothing sensible) if the file cannot be written
  [[nodiscard]] bool saveScreenshot(const wxString& path) const;

  /// The snapshot on show (null before the first).
  [[nodiscard]] const std::shared_ptr<const WorldSnapshot>& snapshot() const { return snapshot_; }
  /// The world-to-pixel map of the view.
  [[nodiscard]] const ViewTransform& transform() const { return transform_; }
  /// True once the view has a size and has fitted a world.
  [[nodiscard]] bool ready() const { return fitted_; }

 private:
  void onTimer(wxTimerEvent& event);
  void onPaint(wxPaintEvent& event);
  void onSize(wxSizeEvent& event);
  void onLeftDown(wxMouseEvent& event);
  void onLeftUp(wxMouseEvent& event);
  void onPanDown(wxMouseEvent& event);
  void onPanUp(wxMouseEvent& event);
  void onMotion(wxMouseEvent& event);
  void onWheel(wxMouseEvent& event);
  void onKey(wxKeyEvent& event);
  void onCaptureLost(wxMouseCaptureLostEvent& event);
  void endDrag();
  void releaseMouseIfDone();
  [[nodiscard]] Vector2 worldAt(const wxPoint& pixel) const;

  SimulationRunner* runner_;
  std::shared_ptr<const WorldSnapshot> snapshot_;
  std::function<void(const WorldSnapshot&)> listener_;
  ViewTransform transform_;
  wxTimer timer_;
  bool fitted_ = false;     // a world has been fitted once
  bool keepFitted_ = true;  // fit again on resize (until the user zooms or pans)
  bool dragging_ = false;
  bool panning_ = false;
  wxPoint lastPan_;
};

}  // namespace thyrix
