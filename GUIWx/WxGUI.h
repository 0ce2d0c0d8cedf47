#pragma once
/// @file WxGUI.h
/// @brief The GUI drawing interface implemented on a wxWidgets device context.

#include <GUIWx/ViewTransform.h>

#include <ThyrixLite/GUI.h>

class wxDC;

namespace thyrix {

/// Draws through a wxDC (a window, a memory bitmap, a wxGCDC for anti-aliasing) with the
/// world-to-pixel map of a ViewTransform (zoom, pan, y up). Outlines and hairlines are one
/// pixel wide whatever the zoom, as in SvgGUI; shapes entirely outside the view are skipped
/// and lines are clipped to it, so any zoom stays within the device's integer coordinates.
class WxGUI : public GUI {
 public:
  /// Draws on @p dc with @p view; both must outlive this object.
  WxGUI(wxDC& dc, const ViewTransform& view) : dc_(dc), view_(view) {}

  void drawCircle(Vector2 centre, real radius, real angle, Color fill, Color outline) override;
  void drawCapsule(Vector2 a, Vector2 b, real radius, Color fill, Color outline) override;
  void drawLine(Vector2 a, Vector2 b, Color color, real width = 0) override;
  void drawPolygon(std::span<const Vector2> vertices, Color fill, Color outline) override;
  void drawText(Vector2 position, std::string_view text, Color color) override;
  /// The border line across the view, with a translucent strip on the solid side.
  void drawBorder(Vector2 point, Vector2 normal, Color color) override;

 private:
  [[nodiscard]] bool visible(PixelPoint low, PixelPoint high) const;

  wxDC& dc_;
  const ViewTransform& view_;
};

}  // namespace thyrix
