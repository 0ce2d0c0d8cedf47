#pragma once
/// @file Matrix3.h
/// @brief A general 3x3 matrix of `real`, row-major.

#include <ThyrixLite/Vector3.h>

#include <array>

namespace thyrix {

/// A 3x3 matrix, stored row-major: `m[row][column]`.
struct Matrix3 {
  std::array<std::array<real, 3>, 3> m{};  ///< the entries, zero by default

  /// The identity matrix.
  static constexpr Matrix3 identity() {
    Matrix3 r;
    r.m[0][0] = r.m[1][1] = r.m[2][2] = 1;
    return r;
  }
  /// A diagonal matrix.
  static constexpr Matrix3 diagonal(real a, real b, real c) {
    Matrix3 r;
    r.m[0][0] = a;
    r.m[1][1] = b;
    r.m[2][2] = c;
    return r;
  }

  /// The entry at @p row, @p col.
  constexpr real& operator()(int row, int col) { return m[row][col]; }
  /// The entry at @p row, @p col.
  constexpr real operator()(int row, int col) const { return m[row][col]; }

  /// The transpose.
  [[nodiscard]] constexpr Matrix3 transposed() const {
    Matrix3 r;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) r.m[i][j] = m[j][i];
    return r;
  }
  /// Matrix-vector product.
  constexpr Vector3 operator*(const Vector3& v) const {
    return {m[0][0] * v.x + m[0][1] * v.y + m[0][2] * v.z,
            m[1][0] * v.x + m[1][1] * v.y + m[1][2] * v.z,
            m[2][0] * v.x + m[2][1] * v.y + m[2][2] * v.z};
  }
  /// Matrix-matrix product.
  constexpr Matrix3 operator*(const Matrix3& o) const {
    Matrix3 r;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        r.m[i][j] = m[i][0] * o.m[0][j] + m[i][1] * o.m[1][j] + m[i][2] * o.m[2][j];
    return r;
  }
  /// Entry-wise sum.
  constexpr Matrix3 operator+(const Matrix3& o) const {
    Matrix3 r;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) r.m[i][j] = m[i][j] + o.m[i][j];
    return r;
  }
  /// Difference.
  constexpr Matrix3 operator-(const Matrix3& o) const {
    Matrix3 r;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) r.m[i][j] = m[i][j] - o.m[i][j];
    return r;
  }
  /// Entry-wise product with a scalar.
  constexpr Matrix3 operator*(real s) const {
    Matrix3 r;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) r.m[i][j] = m[i][j] * s;
    return r;
  }
  /// The determinant.
  [[nodiscard]] constexpr real determinant() const {
    return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
           m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
           m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
  }
  /// The inverse by cofactors; the caller guarantees the matrix is invertible.
  [[nodiscard]] constexpr Matrix3 inverse() const {
    Matrix3 r;
    const real invDet = 1 / determinant();
    r.m[0][0] = (m[1][1] * m[2][2] - m[1][2] * m[2][1]) * invDet;
    r.m[0][1] = (m[0][2] * m[2][1] - m[0][1] * m[2][2]) * invDet;
    r.m[0][2] = (m[0][1] * m[1][2] - m[0][2] * m[1][1]) * invDet;
    r.m[1][0] = (m[1][2] * m[2][0] - m[1][0] * m[2][2]) * invDet;
    r.m[1][1] = (m[0][0] * m[2][2] - m[0][2] * m[2][0]) * invDet;
    r.m[1][2] = (m[0][2] * m[1][0] - m[0][0] * m[1][2]) * invDet;
    r.m[2][0] = (m[1][0] * m[2][1] - m[1][1] * m[2][0]) * invDet;
    r.m[2][1] = (m[0][1] * m[2][0] - m[0][0] * m[2][1]) * invDet;
    r.m[2][2] = (m[0][0] * m[1][1] - m[0][1] * m[1][0]) * invDet;
    return r;
  }
};

}  // namespace thyrix
