#pragma once
/// @file Circle.h
/// @brief A solid disk.

#include <ThyrixLite/Primitive.h>

namespace thyrix {

/// A solid disk of uniform density; its moment of inertia is `m R^2 / 2`.
class Circle : public Primitive {
 public:
  /// @throws InvalidArgument naming "Circle.radius" or "Circle.mass" unless positive and finite
  /// (the mass with a finite inverse too)
  Circle(real radius, real mass);

  /// Puts @p count touch sensors around the circle, sensor 0 starting at body-frame angle
  /// @p startAngle and each covering `2 pi / count` counter-clockwise; a sensor saturates at a
  /// summed contact force of @p saturation. @throws InvalidArgument naming the field.
  void setTactileSensors(int count, real startAngle, real saturation);

  void draw(GUI& gui) const override;
  [[nodiscard]] std::string typeName() const override { return "Circle"; }
};

}  // namespace thyrix
