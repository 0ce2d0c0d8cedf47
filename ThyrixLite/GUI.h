#pragma once
/// @file GUI.h
/// @brief The abstract drawing interface: the engine draws through it and never knows the
/// front-end.

#include <ThyrixLite/Color.h>
#include <ThyrixLite/Vector2.h>

#include <span>
#include <string_view>

namespace thyrix {

/// What a front-end (wxWidgets, SVG, a test recorder) implements so objects can draw themselves.
/// All coordinates are world coordinates in metres; the front-end maps them to its device.
class GUI {
 public:
  virtual ~GUI() = default;

  /// A filled circle; @p angle marks the body's orientation with a radius line.
  virtual void drawCircle(Vector2 centre, real radius, real angle, Color fill, Color outline) = 0;
  /// A filled capsule: the segment @p a - @p b swept by a disk of @p radius.
  virtual void drawCapsule(Vector2 a, Vector2 b, real radius, Color fill, Color outline) = 0;
  /// A line segment of @p width metres (0 = the thinnest the device draws).
  virtual void drawLine(Vector2 a, Vector2 b, Color color, real width = 0) = 0;
  /// A filled closed polygon.
  virtual void drawPolygon(std::span<const Vector2> vertices, Color fill, Color outline) = 0;
  /// Text whose baseline starts at @p position.
  virtual void drawText(Vector2 position, std::string_view text, Color color) = 0;
  /// The border of a half-plane: @p point on the line, @p normal into the simulation area.
  virtual void drawBorder(Vector2 point, Vector2 normal, Color color) = 0;
};

}  // namespace thyrix
