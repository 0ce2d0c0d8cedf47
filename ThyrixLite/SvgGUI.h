#pragma once
/// @file SvgGUI.h
/// @brief A GUI that renders to an SVG 1.1 document: pictures of a world with no GUI library.

#include <ThyrixLite/ColorDefinitions.h>
#include <ThyrixLite/GUI.h>

#include <string>

namespace thyrix {

/// Draws into an SVG 1.1 document held in memory, to be read with svg() or written with save().
///
/// The picture shows the world rectangle [lower, upper] (metres) at a uniform scale of
/// `width / (upper.x - lower.x)` pixels per metre, so circles stay round; the height in pixels
/// follows the rectangle's aspect ratio (rounded to a whole pixel, at least 1). World y points
/// up, SVG y points down: a world point (x, y) is drawn at pixel
/// `((x - lower.x) * scale, (upper.y - y) * scale)`. Shapes outside the rectangle are still
/// written; the viewer clips them.
///
/// Each drawing call appends one or two elements, each with a `class` attribute naming what it
/// is, so a picture can be restyled or inspected: `circle` (and its `orientation` line),
/// `capsule` (a path), `line`, `polygon`, `text`, `border` (the line) with `border-solid` (a
/// translucent strip on the solid side). Numbers are written with std::to_chars (three decimals
/// in pixels, trailing zeros dropped), so the output does not depend on the C++ or C locale.
/// A call whose coordinates are not finite draws nothing rather than write an invalid document.
class SvgGUI : public GUI {
 public:
  /// @param lower lower-left corner of the world rectangle shown (m)
  /// @param upper upper-right corner of the world rectangle shown (m)
  /// @param widthPixels width of the picture (pixels)
  /// @throws InvalidArgument naming "SvgGUI.lower" or "SvgGUI.upper" unless both are finite
  ///         and upper lies strictly above and to the right of lower, or "SvgGUI.widthPixels"
  ///         unless it is positive
  SvgGUI(Vector2 lower, Vector2 upper, int widthPixels);

  void drawCircle(Vector2 centre, real radius, real angle, Color fill, Color outline) override;
  void drawCapsule(Vector2 a, Vector2 b, real radius, Color fill, Color outline) override;
  void drawLine(Vector2 a, Vector2 b, Color color, real width = 0) override;
  void drawPolygon(std::span<const Vector2> vertices, Color fill, Color outline) override;
  /// Text in a sans-serif font of fontSize() pixels. The characters &, <, >, " and ' are
  /// escaped; control characters that XML 1.0 forbids are dropped and malformed UTF-8 bytes
  /// become U+FFFD, so any input gives a well-formed document.
  void drawText(Vector2 position, std::string_view text, Color color) override;
  /// The part of the border line inside the picture, plus a translucent strip of
  /// borderStripPixels() on the solid side (against the normal).
  void drawBorder(Vector2 point, Vector2 normal, Color color) override;

  /// The whole document: XML declaration, `svg` root with width, height and viewBox in
  /// pixels, a background rectangle, then everything drawn since construction or clear().
  [[nodiscard]] std::string svg() const;
  /// Writes svg() to the file @p path (created or truncated).
  /// @throws std::runtime_error naming the path if the file cannot be opened or written
  void save(const std::string& path) const;
  /// Erases everything drawn, keeping the view, background and settings.
  void clear();
  /// The elements drawn since construction or clear(), one per line: svg() without the
  /// document around them (e.g. to group them as one frame of an animation).
  [[nodiscard]] const std::string& elements() const { return body_; }

  /// Width of the picture (pixels).
  [[nodiscard]] int widthPixels() const { return width_; }
  /// Height of the picture (pixels), from the aspect ratio of the world rectangle.
  [[nodiscard]] int heightPixels() const { return height_; }
  /// Pixels per metre, the same along x and y.
  [[nodiscard]] double scale() const { return scale_; }
  /// The pixel position of world point @p p (x to the right, y down), unrounded.
  [[nodiscard]] Vector2 toPixels(Vector2 p) const;

  /// @p text as SVG character data or attribute value: the characters &, <, >, " and '
  /// escaped, the control characters XML 1.0 forbids dropped, malformed UTF-8 bytes replaced
  /// by U+FFFD, so that any input gives a well-formed document.
  [[nodiscard]] static std::string escaped(std::string_view text);

  /// Fill of the background rectangle (white by default).
  void setBackground(Color color) { background_ = color; }
  /// Font size of drawText (pixels, 12 by default); ignored unless positive and finite.
  void setFontSize(double pixels);
  /// Font size of drawText (pixels).
  [[nodiscard]] double fontSize() const { return fontSize_; }
  /// Width of the shaded strip drawn on the solid side of a border (pixels, 8 by default);
  /// ignored unless non-negative and finite. 0 draws the line alone.
  void setBorderStripPixels(double pixels);
  /// Width of the shaded strip drawn on the solid side of a border (pixels).
  [[nodiscard]] double borderStripPixels() const { return borderStrip_; }

 private:
  struct Pixel {
    double x;
    double y;
  };
  [[nodiscard]] Pixel pixel(Vector2 p) const;

  Vector2 lower_;
  Vector2 upper_;
  int width_;
  int height_;
  double scale_;
  Color background_ = colors::white;
  double fontSize_ = 12;
  double borderStrip_ = 8;
  std::string body_;  // the elements drawn so far, one per line
};

}  // namespace thyrix
