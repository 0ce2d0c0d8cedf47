#pragma once
/// @file Circle.h
/// @brief A solid disk.

#include <ThyrixLite/Primitive.h>

namespace thyrix {

/// A solid disk of uniform density; its moment of inertia is `m R^2 / 2`.
class Circle : public Primitive {
 public:
  /// @throws InvalidArgument naming "Circle.radius" or "Circle.mass" unless positive and finite
  Circle(real radius, real mass);

  void draw(GUI& gui) const override;
  [[nodiscard]] std::string typeName() const override { return "Circle"; }
};

}  // namespace thyrix
