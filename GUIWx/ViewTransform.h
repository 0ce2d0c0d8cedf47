#pragma once
/// @file ViewTransform.h
/// @brief The map between world coordinates (metres, y up) and the pixels of a view (y down),
/// with zoom about a point, pan and fit.

#include <ThyrixLite/BroadPhase.h>
#include <ThyrixLite/Vector2.h>

namespace thyrix {

/// A point on a view, in pixels from its top-left corner (x right, y down), unrounded.
struct PixelPoint {
  double x = 0;  ///< pixels to the right of the left edge
  double y = 0;  ///< pixels below the top edge
};

/// A uniform scale and a translation from the world to a view of `width` x `height` pixels:
/// the world point `centre()` is drawn at the middle of the view and one metre spans `scale()`
/// pixels along both axes, so circles stay round. World y points up, pixel y down:
///
///     pixel.x = width / 2 + (x - centre.x) * scale
///     pixel.y = height / 2 - (y - centre.y) * scale
///
/// Holds no wx type, so it is the same for the screen, a screenshot or a test.
class ViewTransform {
 public:
  /// Smallest and largest allowed scale (pixels per metre): zooming stops there rather than
  /// reach a singular or overflowing map.
  static constexpr double minScale = 1e-4;
  static constexpr double maxScale = 1e5;  ///< see minScale (10 micrometres per pixel)

  /// The world point drawn at pixel @p p.
  [[nodiscard]] Vector2 toWorld(PixelPoint p) const;
  /// The pixel where world point @p w is drawn.
  [[nodiscard]] PixelPoint toPixel(Vector2 w) const;
  /// A world length in pixels.
  [[nodiscard]] double toPixels(double metres) const { return metres * scale_; }

  /// Sets the size of the view (pixels); the world point at its middle stays there.
  void setSize(int width, int height);
  /// Multiplies the scale by @p factor keeping the world point under pixel @p anchor fixed (a
  /// mouse-wheel zoom about the cursor). The scale is clamped to [minScale, maxScale].
  void zoomAbout(PixelPoint anchor, double factor);
  /// Moves the picture by (@p dx, @p dy) pixels (a drag of the view).
  void panBy(double dx, double dy);
  /// Shows the whole of @p box, centred, as large as fits in the view.
  void fit(const BoundingBox& box);

  /// Pixels per metre.
  [[nodiscard]] double scale() const { return scale_; }
  /// The world point at the middle of the view.
  [[nodiscard]] Vector2 centre() const { return {static_cast<real>(cx_), static_cast<real>(cy_)}; }
  /// View width (pixels).
  [[nodiscard]] int width() const { return width_; }
  /// View height (pixels).
  [[nodiscard]] int height() const { return height_; }
  /// Sets the scale (clamped to [minScale, maxScale]) and the world point at the middle.
  void set(double scale, Vector2 centre);

 private:
  double scale_ = 50;
  double cx_ = 0;  // world point at the middle of the view, in double so that panning by a
  double cy_ = 0;  // pixel at a large zoom does not round away in float builds
  int width_ = 1;
  int height_ = 1;
};

}  // namespace thyrix
