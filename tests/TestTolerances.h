#pragma once
// Tolerances for tests, looser when Thyrix is built with THYRIX_REAL=float.

#include <ThyrixLite/ThyrixParameters.h>

#include <type_traits>

namespace thyrix::test {

inline constexpr bool isFloat = std::is_same_v<real, float>;
/// For quantities computed in a few operations.
inline constexpr real tight = isFloat ? real(1e-5) : real(1e-12);
/// For the outcome of a solver or of many steps.
inline constexpr real loose = isFloat ? real(2e-3) : real(1e-7);

}  // namespace thyrix::test
