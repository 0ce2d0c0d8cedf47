#pragma once
/// @file ActivationPanel.h
/// @brief A side panel showing an agent's sensor and effector activations as live bars.

#include <ThyrixLite/ThyrixParameters.h>

#include <wx/panel.h>

#include <span>
#include <vector>

namespace thyrix {

/// Two groups of horizontal bars, "Sensors" then "Effectors", one bar per value in [0, 1]
/// (values outside are clamped), numbered from 0 as in the agent's documentation. The rows
/// shrink to fit the panel's height. Fed from the snapshots by SimulationFrame.
class ActivationPanel : public wxPanel {
 public:
  /// A panel in @p parent, @p width pixels wide.
  ActivationPanel(wxWindow* parent, int width = 220);

  /// Shows these values (copied) from the next repaint on.
  void setValues(std::span<const real> sensors, std::span<const real> effectors);

 private:
  void onPaint(wxPaintEvent& event);

  std::vector<real> sensors_;
  std::vector<real> effectors_;
};

}  // namespace thyrix
