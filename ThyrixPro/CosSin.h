#pragma once
/// @file CosSin.h
/// @brief The unit vector `(cos a, sin a)` of an angle without a library call (inline for one
/// angle, a vectorized loop for many), for the forward kinematics' loop over links.

#include <ThyrixLite/ThyrixParameters.h>
#include <ThyrixLite/Vector2.h>

#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>

namespace thyrix {

namespace detail {

/// The kernel of cosSin() for `|a| < 2^19`, branch-free (the quadrant's swap and signs are bit
/// operations), so that a loop over many angles vectorizes.
inline Vector2 cosSinReduced(real a) {
  const double x = static_cast<double>(a);
  // Round to the nearest integer by adding 1.5 * 2^52: the sum's last bits are k (two's
  // complement), and subtracting the constant again gives k as a double, exactly.
  constexpr double roundingShift = 0x1.8p52;
  const double shifted = x * 0x1.45f306dc9c883p-1 + roundingShift;  // a 2/pi + 1.5 2^52
  const double k = shifted - roundingShift;
  const std::uint64_t quadrant = std::bit_cast<std::uint64_t>(shifted) & 3u;
  // pi/2 = C1 + C2 + C3, C1 and C2 of 31 and 32 significant bits (k C1 and k C2 exact for
  // |k| < 2^21).
  const double r = ((x - k * 0x1.921fb544p+0) - k * 0x1.0b4611a6p-34) - k * 0x1.3198a2e037073p-69;
  const double r2 = r * r;
  // Taylor coefficients (-1)^n / (2n)! and (-1)^n / (2n + 1)!, rounded once at compile time.
  constexpr double c2 = -1.0 / 2, c4 = 1.0 / 24, c6 = -1.0 / 720, c8 = 1.0 / 40320,
                   c10 = -1.0 / 3628800, c12 = 1.0 / 479001600, c14 = -1.0 / 87178291200.0,
                   c16 = 1.0 / 20922789888000.0;
  constexpr double s3 = -1.0 / 6, s5 = 1.0 / 120, s7 = -1.0 / 5040, s9 = 1.0 / 362880,
                   s11 = -1.0 / 39916800, s13 = 1.0 / 6227020800.0, s15 = -1.0 / 1307674368000.0,
                   s17 = 1.0 / 355687428096000.0;
  // Horner's rule for the first two terms (whose roundings decide the accuracy), Estrin's
  // scheme in u = r^2 for the rest: pairs of terms, then pairs of pairs, with u^2 and u^4
  // computed alongside. The same terms, but the longest chain of dependent operations is about
  // 9 of them, not 17: a loop over many angles waits on that latency.
  const double u = r2;
  const double u2 = u * u;
  const double u4 = u2 * u2;
  const double cosTail = ((c4 + c6 * u) + (c8 + c10 * u) * u2) + ((c12 + c14 * u) + c16 * u2) * u4;
  const double sinTail = ((s5 + s7 * u) + (s9 + s11 * u) * u2) + ((s13 + s15 * u) + s17 * u2) * u4;
  const double cosR = 1 + u * (c2 + u * cosTail);
  const double sinR = r + r * u * (s3 + u * sinTail);
  // Quadrant q: (cos, sin)(r + q pi/2) = (cos r, sin r), (-sin r, cos r), (-cos r, -sin r),
  // (sin r, -cos r): swapped for odd q, cos negated for q = 1, 2, sin for q = 2, 3.
  const std::uint64_t cosBits = std::bit_cast<std::uint64_t>(cosR);
  const std::uint64_t sinBits = std::bit_cast<std::uint64_t>(sinR);
  const std::uint64_t swap = 0 - (quadrant & 1u);  // all ones for odd q
  const std::uint64_t c = (sinBits & swap) | (cosBits & ~swap);
  const std::uint64_t s = (cosBits & swap) | (sinBits & ~swap);
  return {static_cast<real>(std::bit_cast<double>(c ^ (((quadrant + 1) & 2u) << 62))),
          static_cast<real>(std::bit_cast<double>(s ^ ((quadrant & 2u) << 62)))};
}

}  // namespace detail

/// Whether cosSinKernel() takes the angle @p a: `|a| < 2^19` (false for NaN).
inline bool cosSinKernelTakes(real a) { return std::abs(static_cast<double>(a)) < 0x1p19; }

/// `(cos a, sin a)` for the angle @p a (rad): within about 1.5 units in the last place of the
/// exact values for `|a| <= 100`, 2.2 up to 2^19 (measured against 113-bit references), the
/// library's own values beyond. In double, about one value in six differs from glibc's by an
/// ulp (tests/SpatialAlgebraTest.cpp). The sine of -0 is +0.
///
/// Why not `std::cos` and `std::sin`: the forward kinematics needs one pair per link in every
/// step; a library call costs as much as the rest of the link's kinematics, and calls one by
/// one do not vectorize.
///
/// How: `a = k pi/2 + r` with `|r| <= pi/4` (k the nearest integer to `a 2/pi`, r by
/// Cody-Waite reduction: pi/2 split in three parts whose products by k are exact or
/// negligible), then the Taylor series of cos and sin in r (to r^16 and r^17: the first terms
/// left out are below 2e-18 and 1e-19; all but the first two terms by Estrin's scheme, for a
/// short chain of dependent operations), and the quadrant `k mod 4` swaps and negates them.
/// Angles of magnitude 2^19 or more (or not finite) go to the library, whose reduction is exact.
inline Vector2 cosSin(real a) {
  if (!cosSinKernelTakes(a)) [[unlikely]]
    return {std::cos(a), std::sin(a)};  // also NaN for an angle that is not finite
  return detail::cosSinReduced(a);
}

/// cosSin() of every angle of @p angles into @p out (the same size), each of which
/// cosSinKernelTakes(): one loop that vectorizes, eight angles at a time where the processor
/// has AVX-512, four where it has AVX2 (GCC or Clang on x86-64, chosen at run time), else two
/// (SSE2) or one: the same operations on each angle, so the same bits either way. (A caller that
/// computes the angles in a loop of its own checks them there, for free.)
void cosSinKernel(std::span<const real> angles, std::span<Vector2> out);

/// cosSin() of every angle of @p angles into @p out (the same size): cosSinKernel(), then
/// cosSin() again for the angles out of its range.
inline void cosSin(std::span<const real> angles, std::span<Vector2> out) {
  cosSinKernel(angles, out);
  for (std::size_t k = 0; k < angles.size(); ++k)
    if (!cosSinKernelTakes(angles[k])) [[unlikely]]
      out[k] = cosSin(angles[k]);
}

}  // namespace thyrix
