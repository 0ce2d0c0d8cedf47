#pragma once
// Component-wise EXPECT_NEAR for the small linear algebra types, shared by the tests.

#include <ThyrixLite/Matrix3.h>
#include <ThyrixLite/Vector2.h>
#include <ThyrixLite/Vector3.h>

#include <gtest/gtest.h>

namespace thyrix::test {

inline void expectNear(Vector2 actual, Vector2 expected, real tolerance) {
  EXPECT_NEAR(actual.x, expected.x, tolerance);
  EXPECT_NEAR(actual.y, expected.y, tolerance);
}

inline void expectNear(const Vector3& actual, const Vector3& expected, real tolerance) {
  EXPECT_NEAR(actual.x, expected.x, tolerance);
  EXPECT_NEAR(actual.y, expected.y, tolerance);
  EXPECT_NEAR(actual.z, expected.z, tolerance);
}

inline void expectNear(const Matrix3& actual, const Matrix3& expected, real tolerance) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      EXPECT_NEAR(actual(i, j), expected(i, j), tolerance) << "entry (" << i << ", " << j << ")";
}

}  // namespace thyrix::test
