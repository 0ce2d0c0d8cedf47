#pragma once
/// @file Vector3.h
/// @brief A 3-vector of `real`: a body's generalized velocity or force `(x, y, angular)`.

#include <ThyrixLite/ThyrixParameters.h>
#include <ThyrixLite/Vector2.h>

#include <cmath>

namespace thyrix {

/// A 3-vector. Thyrix orders rigid-body quantities as `(vx, vy, omega)` and
/// `(fx, fy, torque)`; ThyrixPro's spatial vectors use the same type.
struct Vector3 {
  real x = 0;  ///< first component
  real y = 0;  ///< second component
  real z = 0;  ///< third component (the angular part of a body quantity)

  /// Adds another vector.
  constexpr Vector3& operator+=(const Vector3& o) {
    x += o.x;
    y += o.y;
    z += o.z;
    return *this;
  }
  /// Subtracts another vector.
  constexpr Vector3& operator-=(const Vector3& o) {
    x -= o.x;
    y -= o.y;
    z -= o.z;
    return *this;
  }
  /// Scales by a scalar.
  constexpr Vector3& operator*=(real s) {
    x *= s;
    y *= s;
    z *= s;
    return *this;
  }
  /// Exact equality.
  constexpr bool operator==(const Vector3&) const = default;

  /// Dot product.
  [[nodiscard]] constexpr real dot(const Vector3& o) const { return x * o.x + y * o.y + z * o.z; }
  /// Euclidean length.
  [[nodiscard]] real length() const { return std::sqrt(dot(*this)); }
  /// The linear part `(x, y)`.
  [[nodiscard]] constexpr Vector2 xy() const { return {x, y}; }
};

/// Sum.
constexpr Vector3 operator+(Vector3 a, const Vector3& b) { return a += b; }
/// Difference.
constexpr Vector3 operator-(Vector3 a, const Vector3& b) { return a -= b; }
/// Negation.
constexpr Vector3 operator-(const Vector3& a) { return {-a.x, -a.y, -a.z}; }
/// Product with a scalar.
constexpr Vector3 operator*(Vector3 a, real s) { return a *= s; }
/// Product with a scalar.
constexpr Vector3 operator*(real s, Vector3 a) { return a *= s; }

}  // namespace thyrix
