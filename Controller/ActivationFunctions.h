#pragma once
/// @file ActivationFunctions.h
/// @brief The units' squashing functions, over whole layers, from +, *, / and bit operations
///        only: the same bits on every platform, and loops the compiler vectorizes.

#include <Controller/NeuralNetwork.h>
#include <ThyrixLite/ThyrixParameters.h>

#include <bit>
#include <cstdint>
#include <span>

namespace thyrix {

/// e^a for |a| <= 64, within 3 units in the last place of a double. The C library's exp may
/// differ from platform to platform in the last bit and is a call the compiler cannot
/// vectorize; this is a handful of multiplications and additions.
inline double boundedExp(double a) {
  // a = k ln 2 + r with k an integer and |r| <= ln 2 / 2; adding 1.5 * 2^52 rounds to an integer.
  constexpr double shifter = 0x1.8p52;
  constexpr double log2e = 0x1.71547652b82fep0;
  constexpr double ln2High = 0x1.62e42feep-1;  // zero low bits: k * ln2High is exact
  constexpr double ln2Low = 0x1.a39ef35793c76p-33;
  const double t = a * log2e + shifter;
  const double k = t - shifter;
  const double r = (a - k * ln2High) - k * ln2Low;
  // e^r by its Taylor series to r^12 (the remainder is below 2e-16 of the sum for
  // |r| <= 0.35), evaluated by Estrin's scheme: pairs of terms, then pairs of pairs, so that
  // the chain of dependent operations is 8 long instead of Horner's 24.
  const double r2 = r * r;
  const double r4 = r2 * r2;
  const double r8 = r4 * r4;
  const double q0 = 1 + r;
  const double q1 = 1.0 / 2 + r * (1.0 / 6);
  const double q2 = 1.0 / 24 + r * (1.0 / 120);
  const double q3 = 1.0 / 720 + r * (1.0 / 5040);
  const double q4 = 1.0 / 40320 + r * (1.0 / 362880);
  const double q5 = 1.0 / 3628800 + r * (1.0 / 39916800);
  const double s0 = q0 + q1 * r2;
  const double s1 = q2 + q3 * r2;
  const double s2 = q4 + q5 * r2;
  const double t0 = s0 + s1 * r4;
  const double t1 = s2 + (1.0 / 479001600) * r4;
  const double p = t0 + t1 * r8;
  // 2^k, built from k's bits (t's low bits hold k), times e^r.
  const std::uint64_t kBits =
      std::bit_cast<std::uint64_t>(t) - std::bit_cast<std::uint64_t>(shifter);
  return p * std::bit_cast<double>((kBits + 1023) << 52);
}

/// @p x limited to [-bound, bound], written as two selects so that whole layers vectorize.
inline double limit(double x, double bound) {
  x = x < -bound ? -bound : x;
  return x > bound ? bound : x;
}

/// Where tanh rounds to +-1 in double (|x| >= 20) and the logistic to within 5e-18 of 0 or 1
/// (|x| >= 40): the functions limit their argument there, so boundedExp() can take it.
inline constexpr double tanhBound = 20;
/// See tanhBound.
inline constexpr double logisticBound = 40;

/// tanh(x) for |x| <= tanhBound, within 4e-16 of it (absolute): 1 - 2 / (e^(2x) + 1).
inline double limitedTanh(double x) { return 1 - 2 / (boundedExp(2 * x) + 1); }
/// 1 / (1 + e^-x) for |x| <= logisticBound, within 3e-16 of it (absolute).
inline double limitedLogistic(double x) { return 1 / (1 + boundedExp(-x)); }

/// tanh(x) for any finite x, within 4e-16 of it (absolute).
inline double portableTanh(double x) { return limitedTanh(limit(x, tanhBound)); }
/// 1 / (1 + e^-x) for any finite x, within 3e-16 of it (absolute).
inline double portableLogistic(double x) { return limitedLogistic(limit(x, logisticBound)); }

// The layer functions limit the values in a loop of their own: GCC 12 does not vectorize a loop
// where the limit's selections feed further arithmetic.

/// Applies the units' function to every value of @p values (a layer's net inputs).
inline void activateLayer(Activation activation, std::span<real> values) {
  const bool tanh = activation == Activation::Tanh;
  const double bound = tanh ? tanhBound : logisticBound;
  for (real& value : values) value = static_cast<real>(limit(value, bound));
  if (tanh) {
    for (real& value : values) value = static_cast<real>(limitedTanh(value));
  } else {
    for (real& value : values) value = static_cast<real>(limitedLogistic(value));
  }
}

/// Applies the units' function mapped to [0, 1] to every value of @p values (the outputs):
/// logistic, or (1 + tanh(x)) / 2, which is the logistic of 2x.
inline void activateOutputs(Activation activation, std::span<real> values) {
  const double scale = activation == Activation::Tanh ? 2 : 1;
  for (real& value : values) value = static_cast<real>(limit(scale * value, logisticBound));
  for (real& value : values) value = static_cast<real>(limitedLogistic(value));
}

}  // namespace thyrix
