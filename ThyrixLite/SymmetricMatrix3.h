#pragma once
/// @file SymmetricMatrix3.h
/// @brief A symmetric 3x3 matrix stored as its six distinct entries.

#include <ThyrixLite/Matrix3.h>
#include <ThyrixLite/Vector3.h>

#include <cmath>

namespace thyrix {

/// A symmetric 3x3 matrix (a quasistatic "mass" or mobility), stored as its upper triangle.
struct SymmetricMatrix3 {
  real xx = 0;  ///< row 1, column 1
  real xy = 0;  ///< row 1, column 2 (and row 2, column 1)
  real xz = 0;  ///< row 1, column 3 (and row 3, column 1)
  real yy = 0;  ///< row 2, column 2
  real yz = 0;  ///< row 2, column 3 (and row 3, column 2)
  real zz = 0;  ///< row 3, column 3

  /// A diagonal matrix.
  static constexpr SymmetricMatrix3 diagonal(real a, real b, real c) {
    SymmetricMatrix3 s;
    s.xx = a;
    s.yy = b;
    s.zz = c;
    return s;
  }
  /// The full matrix.
  [[nodiscard]] constexpr Matrix3 toMatrix() const {
    Matrix3 r;
    r.m = {{{xx, xy, xz}, {xy, yy, yz}, {xz, yz, zz}}};
    return r;
  }
  /// Matrix-vector product.
  constexpr Vector3 operator*(const Vector3& v) const {
    return {xx * v.x + xy * v.y + xz * v.z, xy * v.x + yy * v.y + yz * v.z,
            xz * v.x + yz * v.y + zz * v.z};
  }
  /// Entry-wise sum.
  constexpr SymmetricMatrix3 operator+(const SymmetricMatrix3& o) const {
    return {xx + o.xx, xy + o.xy, xz + o.xz, yy + o.yy, yz + o.yz, zz + o.zz};
  }
  /// Solves `S x = b` by Cholesky factorization (S must be positive definite).
  [[nodiscard]] Vector3 solve(const Vector3& b) const {
    const real l11 = std::sqrt(xx);
    const real l21 = xy / l11;
    const real l31 = xz / l11;
    const real l22 = std::sqrt(yy - l21 * l21);
    const real l32 = (yz - l31 * l21) / l22;
    const real l33 = std::sqrt(zz - l31 * l31 - l32 * l32);
    // Forward substitution L y = b, then back substitution L^T x = y.
    const real y1 = b.x / l11;
    const real y2 = (b.y - l21 * y1) / l22;
    const real y3 = (b.z - l31 * y1 - l32 * y2) / l33;
    const real x3 = y3 / l33;
    const real x2 = (y2 - l32 * x3) / l22;
    const real x1 = (y1 - l21 * x2 - l31 * x3) / l11;
    return {x1, x2, x3};
  }
};

}  // namespace thyrix
