#pragma once
/// @file MathTools.h
/// @brief Small numeric helpers shared by the packages.

#include <algorithm>
#include <cmath>
#include <numbers>

namespace thyrix {

/// pi in the caller's floating-point type.
template <class T>
inline constexpr T pi = std::numbers::pi_v<T>;

/// The square of @p x.
template <class T>
constexpr T square(T x) {
  return x * x;
}

/// @p x limited to [low, high].
template <class T>
constexpr T clamp(T x, T low, T high) {
  return std::min(std::max(x, low), high);
}

/// @p angle brought into (-pi, pi].
template <class T>
T wrapAngle(T angle) {
  const T twoPi = 2 * pi<T>;
  angle = std::fmod(angle, twoPi);
  if (angle <= -pi<T>) angle += twoPi;
  if (angle > pi<T>) angle -= twoPi;
  return angle;
}

/// True when @p x is neither infinite nor NaN.
template <class T>
bool isFinite(T x) {
  return std::isfinite(x);
}

}  // namespace thyrix
