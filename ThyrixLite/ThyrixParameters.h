#pragma once
/// @file ThyrixParameters.h
/// @brief The scalar type `real` and the numeric constants that depend on it.

#include <ThyrixLite/Config.h>

#include <limits>
#include <type_traits>

namespace thyrix {

/// The simulation's floating-point type: `double`, or `float` when built with THYRIX_REAL=float.
using real = THYRIX_REAL_TYPE;
static_assert(std::is_same_v<real, double> || std::is_same_v<real, float>,
              "THYRIX_REAL must be double or float");

/// Machine epsilon of `real`.
inline constexpr real realEpsilon = std::numeric_limits<real>::epsilon();

/// Largest finite `real`, used as "infinite" distance or time.
inline constexpr real realMax = std::numeric_limits<real>::max();

}  // namespace thyrix
