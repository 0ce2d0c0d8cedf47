#pragma once
/// @file Border.h
/// @brief A static half-plane bounding the simulation area.

#include <ThyrixLite/Primitive.h>

namespace thyrix {

/// A fixed wall: the line through `point` with `normal` pointing into the simulation area;
/// everything behind the line is solid. `r` is the point on the line; the normal turns with
/// `alpha`. A border never moves and never collides with other fixed objects.
class Border : public Primitive {
 public:
  /// @throws InvalidArgument naming "Border.point" (non-finite) or "Border.normal"
  ///         (zero, of a subnormal length, or non-finite); the normal is normalized.
  Border(Vector2 point, Vector2 normal);

  /// The unit normal in world coordinates, into the simulation area.
  [[nodiscard]] Vector2 normal() const { return normal_.rotated(alpha); }

  void draw(GUI& gui) const override;
  [[nodiscard]] std::string typeName() const override { return "Border"; }

 private:
  Vector2 normal_;
};

}  // namespace thyrix
