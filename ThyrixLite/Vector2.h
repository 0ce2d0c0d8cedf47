#pragma once
/// @file Vector2.h
/// @brief A 2D vector of `real`.

#include <ThyrixLite/ThyrixParameters.h>

#include <cmath>
#include <limits>

namespace thyrix {

/// A point or direction in the plane. A plain aggregate: `Vector2{x, y}`.
struct Vector2 {
  real x = 0;  ///< x coordinate
  real y = 0;  ///< y coordinate

  /// Adds another vector.
  constexpr Vector2& operator+=(Vector2 o) {
    x += o.x;
    y += o.y;
    return *this;
  }
  /// Subtracts another vector.
  constexpr Vector2& operator-=(Vector2 o) {
    x -= o.x;
    y -= o.y;
    return *this;
  }
  /// Scales by a scalar.
  constexpr Vector2& operator*=(real s) {
    x *= s;
    y *= s;
    return *this;
  }
  /// Exact equality.
  constexpr bool operator==(const Vector2&) const = default;

  /// Dot product.
  [[nodiscard]] constexpr real dot(Vector2 o) const { return x * o.x + y * o.y; }
  /// 2D cross product (the z of the 3D one): `x * o.y - y * o.x`.
  [[nodiscard]] constexpr real cross(Vector2 o) const { return x * o.y - y * o.x; }
  /// Squared length.
  [[nodiscard]] constexpr real lengthSquared() const { return x * x + y * y; }
  /// Euclidean length.
  [[nodiscard]] real length() const {
    // sqrt of the square sum is several times faster than hypot; hypot only where the squares
    // would overflow or underflow (lengths near the limits of `real`).
    const real squared = x * x + y * y;
    if (squared < realMax && squared > std::numeric_limits<real>::min()) return std::sqrt(squared);
    return std::hypot(x, y);
  }
  /// This vector turned by +90 degrees: `(-y, x)`.
  [[nodiscard]] constexpr Vector2 perpendicular() const { return {-y, x}; }
  /// This vector rotated by @p angle radians (counter-clockwise).
  [[nodiscard]] Vector2 rotated(real angle) const {
    const real c = std::cos(angle);
    const real s = std::sin(angle);
    return {c * x - s * y, s * x + c * y};
  }
  /// This vector scaled to length 1; the zero vector stays zero.
  [[nodiscard]] Vector2 normalized() const {
    const real len = length();
    return len > 0 ? Vector2{x / len, y / len} : Vector2{};
  }
};

/// Sum.
constexpr Vector2 operator+(Vector2 a, Vector2 b) { return {a.x + b.x, a.y + b.y}; }
/// Difference.
constexpr Vector2 operator-(Vector2 a, Vector2 b) { return {a.x - b.x, a.y - b.y}; }
/// Negation.
constexpr Vector2 operator-(Vector2 a) { return {-a.x, -a.y}; }
/// Product with a scalar.
constexpr Vector2 operator*(Vector2 a, real s) { return {a.x * s, a.y * s}; }
/// Product with a scalar.
constexpr Vector2 operator*(real s, Vector2 a) { return {a.x * s, a.y * s}; }
/// Division by a scalar.
constexpr Vector2 operator/(Vector2 a, real s) { return {a.x / s, a.y / s}; }

/// Dot product.
constexpr real dot(Vector2 a, Vector2 b) { return a.dot(b); }
/// 2D cross product `a.x * b.y - a.y * b.x`.
constexpr real cross(Vector2 a, Vector2 b) { return a.cross(b); }
/// Cross product of a scalar (an angular velocity) with a vector: `w x v = (-w v.y, w v.x)`.
constexpr Vector2 cross(real w, Vector2 v) { return {-w * v.y, w * v.x}; }
/// Euclidean distance between two points.
inline real distance(Vector2 a, Vector2 b) { return (a - b).length(); }

}  // namespace thyrix
