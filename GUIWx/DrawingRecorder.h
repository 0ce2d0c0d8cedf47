#pragma once
/// @file DrawingRecorder.h
/// @brief A GUI that records the drawing calls it receives, to replay them later into another
/// GUI: how a picture of the world crosses from the simulation thread to the window.

#include <ThyrixLite/GUI.h>

#include <cstdint>
#include <string>
#include <vector>

namespace thyrix {

/// One recorded drawing call. Its points (and text) live in the recorder's shared arrays, so
/// recording a frame allocates nothing once the arrays have grown to a frame's size.
struct DrawCommand {
  /// Which GUI function was called.
  enum class Kind : std::uint8_t { Circle, Capsule, Line, Polygon, Text, Border };
  Kind kind = Kind::Line;       ///< the function
  Color fill;                   ///< fill (or the only colour of a line, text or border)
  Color outline;                ///< outline of circles, capsules and polygons
  real radius = 0;              ///< circle or capsule radius (m)
  real angle = 0;               ///< circle orientation (rad)
  real width = 0;               ///< line width (m)
  std::uint32_t first = 0;      ///< index of the first point in the recorder's points
  std::uint32_t count = 0;      ///< number of points
  std::uint32_t textFirst = 0;  ///< index of the first character of a Text command's text
  std::uint32_t textCount = 0;  ///< number of characters of a Text command's text
};

/// Records every call as a DrawCommand, in order; replay() makes the same calls, in the same
/// order, on another GUI. A recorder is a plain value: copy it, clear it, draw it anywhere.
class DrawingRecorder : public GUI {
 public:
  void drawCircle(Vector2 centre, real radius, real angle, Color fill, Color outline) override;
  void drawCapsule(Vector2 a, Vector2 b, real radius, Color fill, Color outline) override;
  void drawLine(Vector2 a, Vector2 b, Color color, real width = 0) override;
  void drawPolygon(std::span<const Vector2> vertices, Color fill, Color outline) override;
  void drawText(Vector2 position, std::string_view text, Color color) override;
  void drawBorder(Vector2 point, Vector2 normal, Color color) override;

  /// Makes every recorded call on @p gui, in the order recorded.
  void replay(GUI& gui) const;
  /// Forgets every call, keeping the capacity (so the next frame reuses the memory).
  void clear();

  /// The recorded calls.
  [[nodiscard]] const std::vector<DrawCommand>& commands() const { return commands_; }
  /// The points of command @p c.
  [[nodiscard]] std::span<const Vector2> points(const DrawCommand& c) const {
    return std::span<const Vector2>(points_).subspan(c.first, c.count);
  }
  /// The text of a Text command @p c.
  [[nodiscard]] std::string_view text(const DrawCommand& c) const {
    return std::string_view(text_).substr(c.textFirst, c.textCount);
  }

 private:
  DrawCommand& add(DrawCommand::Kind kind, std::initializer_list<Vector2> points);

  std::vector<DrawCommand> commands_;
  std::vector<Vector2> points_;
  std::string text_;
};

}  // namespace thyrix
