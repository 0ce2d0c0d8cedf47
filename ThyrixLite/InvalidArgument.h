#pragma once
/// @file InvalidArgument.h
/// @brief The exception for bad input, naming the offending field, and the checks that throw it.

#include <ThyrixLite/ThyrixParameters.h>
#include <ThyrixLite/Vector2.h>

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

namespace thyrix {

/// Thrown when a size, mass, position or other input is unusable. `field()` names it, e.g.
/// "Circle.radius"; the object or world being built is left as it was.
class InvalidArgument : public std::invalid_argument {
 public:
  /// @param field the offending field, as `Class.member`
  /// @param problem what is wrong with it, e.g. "must be positive and finite (got -1)"
  InvalidArgument(std::string field, const std::string& problem)
      : std::invalid_argument(field + " " + problem), field_(std::move(field)) {}

  /// The offending field, as `Class.member`.
  [[nodiscard]] const std::string& field() const noexcept { return field_; }

 private:
  std::string field_;
};

/// Throws InvalidArgument naming @p field unless @p value is finite.
inline void requireFinite(real value, const char* field) {
  if (!std::isfinite(value))
    throw InvalidArgument(field, "must be finite (got " + std::to_string(value) + ")");
}

/// Throws InvalidArgument naming @p field unless both coordinates of @p value are finite.
inline void requireFinite(Vector2 value, const char* field) {
  if (!std::isfinite(value.x) || !std::isfinite(value.y))
    throw InvalidArgument(field, "must be finite (got (" + std::to_string(value.x) + ", " +
                                     std::to_string(value.y) + "))");
}

/// Throws InvalidArgument naming @p field unless @p value is positive and finite.
inline void requirePositive(real value, const char* field) {
  if (!(value > 0) || !std::isfinite(value))
    throw InvalidArgument(field, "must be positive and finite (got " + std::to_string(value) + ")");
}

/// Throws InvalidArgument naming @p field unless @p value is positive, finite and so is its
/// inverse (a mass or moment of inertia, which the solvers divide by).
inline void requireInvertible(real value, const char* field) {
  requirePositive(value, field);
  if (!std::isfinite(1 / value)) {
    char text[32];
    std::snprintf(text, sizeof text, "%.6g", static_cast<double>(value));
    throw InvalidArgument(field, std::string("must have a finite inverse (got ") + text + ")");
  }
}

}  // namespace thyrix
