// Tests of the small linear algebra types (Vector2, Vector3, Matrix3, SymmetricMatrix3) and of
// Tools/MathTools.h. Every expectation comes from the mathematics, worked by hand in comments.

#include <ThyrixLite/Matrix3.h>
#include <ThyrixLite/SymmetricMatrix3.h>
#include <ThyrixLite/ThyrixParameters.h>
#include <ThyrixLite/Vector2.h>
#include <ThyrixLite/Vector3.h>
#include <Tools/MTRandom.h>
#include <Tools/MathTools.h>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>
#include <numbers>

#include "TestTolerances.h"
#include "support/ExpectNear.h"

namespace thyrix {
namespace {

using test::expectNear;
using test::tight;

constexpr real kPi = pi<real>;

/// Uniform in [low, high) as a real.
real draw(MTRandom& random, double low, double high) {
  return static_cast<real>(random.uniform(low, high));
}

// ---------------------------------------------------------------------------------------------
// Vector2

TEST(Vector2Test, DefaultIsZero) {
  const Vector2 v;
  EXPECT_EQ(v.x, 0);
  EXPECT_EQ(v.y, 0);
}

TEST(Vector2Test, Arithmetic) {
  // Small integers and halves: every result is exact in float and double.
  const Vector2 a{1, 2};
  const Vector2 b{3, -5};
  EXPECT_EQ(a + b, (Vector2{4, -3}));
  EXPECT_EQ(a - b, (Vector2{-2, 7}));
  EXPECT_EQ(-a, (Vector2{-1, -2}));
  EXPECT_EQ(a * real(3), (Vector2{3, 6}));
  EXPECT_EQ(real(3) * a, (Vector2{3, 6}));
  EXPECT_EQ(b / real(2), (Vector2{real(1.5), real(-2.5)}));

  Vector2 c = a;
  c += b;
  EXPECT_EQ(c, (Vector2{4, -3}));
  c -= b;
  EXPECT_EQ(c, a);
  c *= real(-2);
  EXPECT_EQ(c, (Vector2{-2, -4}));
  EXPECT_NE(a, b);
}

TEST(Vector2Test, DotAndCross) {
  const Vector2 a{1, 2};
  const Vector2 b{3, -5};
  // 1*3 + 2*(-5) = -7;  1*(-5) - 2*3 = -11.
  EXPECT_EQ(a.dot(b), -7);
  EXPECT_EQ(dot(a, b), -7);
  EXPECT_EQ(a.cross(b), -11);
  EXPECT_EQ(cross(a, b), -11);
  EXPECT_EQ(cross(b, a), 11);  // anti-symmetric
  EXPECT_EQ(cross(a, a), 0);
  // The unit axes: x cross y = +1 (counter-clockwise is positive).
  EXPECT_EQ(cross(Vector2{1, 0}, Vector2{0, 1}), 1);
  EXPECT_EQ(a.lengthSquared(), 5);
}

TEST(Vector2Test, ScalarCrossVector) {
  // w x v = (0, 0, w) x (vx, vy, 0) = (-w vy, w vx, 0).
  EXPECT_EQ(cross(real(2), Vector2{3, 4}), (Vector2{-8, 6}));
  EXPECT_EQ(cross(real(1), Vector2{1, 0}), (Vector2{0, 1}));
  EXPECT_EQ(cross(real(-1), Vector2{0, 1}), (Vector2{1, 0}));
  // The velocity of a rotating point is perpendicular to its arm: (w x v) . v = 0.
  const Vector2 arm{real(0.75), real(-2.5)};
  EXPECT_EQ(cross(real(3), arm).dot(arm), 0);
  // And equals w times the perpendicular.
  EXPECT_EQ(cross(real(3), arm), real(3) * arm.perpendicular());
}

TEST(Vector2Test, Length) {
  EXPECT_NEAR((Vector2{3, 4}).length(), 5, 5 * tight);
  EXPECT_NEAR((Vector2{-5, 12}).length(), 13, 13 * tight);
  EXPECT_EQ(Vector2{}.length(), 0);
  EXPECT_NEAR((Vector2{1, 1}).length(), std::sqrt(real(2)), tight);
  EXPECT_NEAR(distance(Vector2{1, 1}, Vector2{4, 5}), 5, 5 * tight);
  // hypot avoids overflow: (3e30, 4e30) has length 5e30 even in float, where x*x overflows.
  const real big = real(1e30);
  EXPECT_NEAR((Vector2{3 * big, 4 * big}).length() / big, 5, 5 * tight);
}

TEST(Vector2Test, Perpendicular) {
  EXPECT_EQ((Vector2{1, 0}).perpendicular(), (Vector2{0, 1}));
  EXPECT_EQ((Vector2{0, 1}).perpendicular(), (Vector2{-1, 0}));
  const Vector2 a{3, -7};
  EXPECT_EQ(a.perpendicular(), (Vector2{7, 3}));
  EXPECT_EQ(a.perpendicular().dot(a), 0);
  EXPECT_EQ(a.cross(a.perpendicular()), a.lengthSquared());  // turned counter-clockwise
  EXPECT_EQ(a.perpendicular().perpendicular(), -a);
}

TEST(Vector2Test, RotatedByKnownAngles) {
  // 90 degrees counter-clockwise: (1, 0) -> (0, 1), (0, 1) -> (-1, 0), (2, 3) -> (-3, 2).
  expectNear((Vector2{1, 0}).rotated(kPi / 2), Vector2{0, 1}, tight);
  expectNear((Vector2{0, 1}).rotated(kPi / 2), Vector2{-1, 0}, tight);
  expectNear((Vector2{2, 3}).rotated(kPi / 2), Vector2{-3, 2}, 3 * tight);
  // -90 degrees: (2, 3) -> (3, -2).
  expectNear((Vector2{2, 3}).rotated(-kPi / 2), Vector2{3, -2}, 3 * tight);
  // 180 degrees: negation.
  expectNear((Vector2{2, 3}).rotated(kPi), Vector2{-2, -3}, 3 * tight);
  // 30 degrees: cos = sqrt(3)/2, sin = 1/2.
  const real c30 = std::sqrt(real(3)) / 2;
  expectNear((Vector2{1, 0}).rotated(kPi / 6), Vector2{c30, real(0.5)}, tight);
  expectNear((Vector2{0, 1}).rotated(kPi / 6), Vector2{real(-0.5), c30}, tight);
  // (2, 4) by 30 degrees: (2 c - 4 s, 2 s + 4 c) = (sqrt(3) - 2, 1 + 2 sqrt(3)).
  const real s3 = std::sqrt(real(3));
  expectNear((Vector2{2, 4}).rotated(kPi / 6), Vector2{s3 - 2, 1 + 2 * s3}, 4 * tight);
  // 45 degrees: (1, 1) -> (0, sqrt 2).
  expectNear((Vector2{1, 1}).rotated(kPi / 4), Vector2{0, std::sqrt(real(2))}, tight);
  // Zero angle is the identity, exactly (cos 0 = 1, sin 0 = 0).
  EXPECT_EQ((Vector2{real(0.3), real(-1.7)}).rotated(0), (Vector2{real(0.3), real(-1.7)}));
}

TEST(Vector2Test, RotationPreservesLengthAndComposes) {
  MTRandom random(7);
  for (int i = 0; i < 100; ++i) {
    const Vector2 v{draw(random, -10, 10), draw(random, -10, 10)};
    const real a = draw(random, -4, 4);
    const real b = draw(random, -4, 4);
    EXPECT_NEAR(v.rotated(a).length(), v.length(), 20 * tight);
    expectNear(v.rotated(a).rotated(b), v.rotated(a + b), 40 * tight);
    expectNear(v.rotated(a).rotated(-a), v, 40 * tight);
  }
}

TEST(Vector2Test, Normalized) {
  expectNear((Vector2{3, 4}).normalized(), Vector2{real(0.6), real(0.8)}, tight);
  expectNear((Vector2{0, -7}).normalized(), Vector2{0, -1}, tight);
  expectNear((Vector2{real(1e-20), 0}).normalized(), Vector2{1, 0}, tight);
  EXPECT_NEAR((Vector2{real(-2.5), real(9.25)}).normalized().length(), 1, tight);
  // The zero vector stays zero (no NaN from 0 / 0).
  const Vector2 zero = Vector2{}.normalized();
  EXPECT_EQ(zero.x, 0);
  EXPECT_EQ(zero.y, 0);
}

// ---------------------------------------------------------------------------------------------
// Vector3

TEST(Vector3Test, Arithmetic) {
  const Vector3 a{1, 2, 3};
  const Vector3 b{-4, real(0.5), 2};
  EXPECT_EQ(Vector3{}, (Vector3{0, 0, 0}));
  EXPECT_EQ(a + b, (Vector3{-3, real(2.5), 5}));
  EXPECT_EQ(a - b, (Vector3{5, real(1.5), 1}));
  EXPECT_EQ(-a, (Vector3{-1, -2, -3}));
  EXPECT_EQ(a * real(2), (Vector3{2, 4, 6}));
  EXPECT_EQ(real(2) * a, (Vector3{2, 4, 6}));
  Vector3 c = a;
  c += b;
  EXPECT_EQ(c, a + b);
  c -= b;
  EXPECT_EQ(c, a);
  c *= real(-1);
  EXPECT_EQ(c, -a);
  // 1*(-4) + 2*0.5 + 3*2 = 3.
  EXPECT_EQ(a.dot(b), 3);
  // sqrt(2^2 + 3^2 + 6^2) = sqrt(49) = 7, exact (sqrt is correctly rounded).
  EXPECT_EQ((Vector3{2, 3, 6}).length(), 7);
  EXPECT_EQ(a.xy(), (Vector2{1, 2}));
}

// ---------------------------------------------------------------------------------------------
// Matrix3

Matrix3 makeMatrix(std::array<std::array<real, 3>, 3> entries) {
  Matrix3 m;
  m.m = entries;
  return m;
}

TEST(Matrix3Test, IdentityDiagonalAndAccess) {
  const Matrix3 id = Matrix3::identity();
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) EXPECT_EQ(id(i, j), i == j ? 1 : 0);
  const Matrix3 d = Matrix3::diagonal(2, 3, 4);
  EXPECT_EQ((d * Vector3{1, 1, 1}), (Vector3{2, 3, 4}));
  EXPECT_EQ(d(0, 1), 0);
  Matrix3 zero;
  EXPECT_EQ(zero(2, 2), 0);
  zero(1, 2) = 5;
  EXPECT_EQ(zero.m[1][2], 5);  // row-major: m[row][column]
}

TEST(Matrix3Test, Products) {
  const Matrix3 a = makeMatrix({{{1, 2, 3}, {4, 5, 6}, {7, 8, 10}}});
  const Matrix3 b = makeMatrix({{{2, 0, 1}, {1, 3, 0}, {0, 1, 4}}});
  // Row i of A times column j of B, by hand:
  //   (1,2,3).(2,1,0)=4   (1,2,3).(0,3,1)=9    (1,2,3).(1,0,4)=13
  //   (4,5,6).(2,1,0)=13  (4,5,6).(0,3,1)=21   (4,5,6).(1,0,4)=28
  //   (7,8,10).(2,1,0)=22 (7,8,10).(0,3,1)=34  (7,8,10).(1,0,4)=47
  const Matrix3 ab = makeMatrix({{{4, 9, 13}, {13, 21, 28}, {22, 34, 47}}});
  EXPECT_EQ((a * b).m, ab.m);
  // A (1, -1, 2) = (1-2+6, 4-5+12, 7-8+20).
  EXPECT_EQ((a * Vector3{1, -1, 2}), (Vector3{5, 11, 19}));
  EXPECT_EQ((a * Matrix3::identity()).m, a.m);
  EXPECT_EQ((Matrix3::identity() * a).m, a.m);
  // Sum, difference, scaling.
  EXPECT_EQ((a + b).m, makeMatrix({{{3, 2, 4}, {5, 8, 6}, {7, 9, 14}}}).m);
  EXPECT_EQ((a - b).m, makeMatrix({{{-1, 2, 2}, {3, 2, 6}, {7, 7, 6}}}).m);
  EXPECT_EQ((b * real(2)).m, makeMatrix({{{4, 0, 2}, {2, 6, 0}, {0, 2, 8}}}).m);
}

TEST(Matrix3Test, Transpose) {
  const Matrix3 a = makeMatrix({{{1, 2, 3}, {4, 5, 6}, {7, 8, 10}}});
  const Matrix3 t = a.transposed();
  EXPECT_EQ(t.m, makeMatrix({{{1, 4, 7}, {2, 5, 8}, {3, 6, 10}}}).m);
  EXPECT_EQ(t.transposed().m, a.m);
  // (A B)^T = B^T A^T.
  const Matrix3 b = makeMatrix({{{2, 0, 1}, {1, 3, 0}, {0, 1, 4}}});
  EXPECT_EQ((a * b).transposed().m, (b.transposed() * a.transposed()).m);
}

TEST(Matrix3Test, Determinant) {
  // Cofactor expansion along the first row:
  //   2 * (3*4 - 2*1) - (-1) * (1*4 - 2*0) + 0 = 2*10 + 4 = 24.
  const Matrix3 a = makeMatrix({{{2, -1, 0}, {1, 3, 2}, {0, 1, 4}}});
  EXPECT_EQ(a.determinant(), 24);
  // 1*(5*10 - 6*8) - 2*(4*10 - 6*7) + 3*(4*8 - 5*7) = 2 + 4 - 9 = -3.
  const Matrix3 b = makeMatrix({{{1, 2, 3}, {4, 5, 6}, {7, 8, 10}}});
  EXPECT_EQ(b.determinant(), -3);
  EXPECT_EQ(Matrix3::identity().determinant(), 1);
  EXPECT_EQ(Matrix3::diagonal(2, 3, 4).determinant(), 24);
  // Rows 1 and 3 equal: singular.
  EXPECT_EQ(makeMatrix({{{1, 2, 3}, {4, 5, 6}, {1, 2, 3}}}).determinant(), 0);
  // det(A^T) = det(A), det(A B) = det(A) det(B).
  EXPECT_EQ(a.transposed().determinant(), 24);
  EXPECT_EQ((a * b).determinant(), -72);
}

TEST(Matrix3Test, InverseOfKnownMatrices) {
  // A diagonal matrix of powers of two inverts exactly.
  EXPECT_EQ(Matrix3::diagonal(2, 4, real(0.5)).inverse().m,
            Matrix3::diagonal(real(0.5), real(0.25), 2).m);
  // The inverse of [[2,-1,0],[1,3,2],[0,1,4]] is adj / 24, with the adjugate by hand:
  //   [[10, 4, -2], [-4, 8, -4], [1, -2, 7]].
  const Matrix3 a = makeMatrix({{{2, -1, 0}, {1, 3, 2}, {0, 1, 4}}});
  const Matrix3 expected = makeMatrix({{{10, 4, -2}, {-4, 8, -4}, {1, -2, 7}}}) * (real(1) / 24);
  expectNear(a.inverse(), expected, tight);
}

TEST(Matrix3Test, InverseTimesMatrixIsIdentity) {
  MTRandom random(20240611u);
  for (int trial = 0; trial < 50; ++trial) {
    // Entries in [-1, 1) plus 4 on the diagonal: strictly diagonally dominant, so well
    // conditioned (every eigenvalue lies in a Gershgorin disc of centre >= 3, radius < 2).
    Matrix3 a;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) a(i, j) = draw(random, -1, 1) + (i == j ? 4 : 0);
    const Matrix3 inv = a.inverse();
    expectNear(inv * a, Matrix3::identity(), 10 * tight);
    expectNear(a * inv, Matrix3::identity(), 10 * tight);
    EXPECT_NEAR(inv.determinant() * a.determinant(), 1, 10 * tight);
  }
}

// ---------------------------------------------------------------------------------------------
// SymmetricMatrix3

SymmetricMatrix3 fromMatrix(const Matrix3& m) {
  SymmetricMatrix3 s;
  s.xx = m(0, 0);
  s.xy = m(0, 1);
  s.xz = m(0, 2);
  s.yy = m(1, 1);
  s.yz = m(1, 2);
  s.zz = m(2, 2);
  return s;
}

TEST(SymmetricMatrix3Test, ToMatrixAndProduct) {
  SymmetricMatrix3 s;
  s.xx = 1;
  s.xy = 2;
  s.xz = 3;
  s.yy = 4;
  s.yz = 5;
  s.zz = 6;
  const Matrix3 full = s.toMatrix();
  EXPECT_EQ(full.m, makeMatrix({{{1, 2, 3}, {2, 4, 5}, {3, 5, 6}}}).m);
  EXPECT_EQ(full.transposed().m, full.m);
  // (1,2,3).(1,-1,2)=5, (2,4,5).(1,-1,2)=8, (3,5,6).(1,-1,2)=10.
  EXPECT_EQ((s * Vector3{1, -1, 2}), (Vector3{5, 8, 10}));
  EXPECT_EQ((s * Vector3{1, -1, 2}), (full * Vector3{1, -1, 2}));
  EXPECT_EQ(SymmetricMatrix3::diagonal(2, 3, 4).toMatrix().m, Matrix3::diagonal(2, 3, 4).m);
  const SymmetricMatrix3 sum = s + SymmetricMatrix3::diagonal(1, 1, 1);
  EXPECT_EQ(sum.toMatrix().m, (full + Matrix3::identity()).m);
}

TEST(SymmetricMatrix3Test, SolveOfKnownSystem) {
  // diag(2, 4, 8) x = (1, 1, 1)  =>  x = (1/2, 1/4, 1/8).
  expectNear(SymmetricMatrix3::diagonal(2, 4, 8).solve({1, 1, 1}),
             Vector3{real(0.5), real(0.25), real(0.125)}, tight);
  // [[4,2,0],[2,5,1],[0,1,3]] (1, -1, 2) = (2, -1, 5).
  SymmetricMatrix3 s;
  s.xx = 4;
  s.xy = 2;
  s.yy = 5;
  s.yz = 1;
  s.zz = 3;
  expectNear(s.solve({2, -1, 5}), Vector3{1, -1, 2}, 10 * tight);
}

TEST(SymmetricMatrix3Test, SolveAgreesWithInverse) {
  MTRandom random(99);
  for (int trial = 0; trial < 50; ++trial) {
    // S = B B^T + I is symmetric positive definite, its eigenvalues in [1, 1 + |B|^2] with
    // |B|^2 <= 9: condition number at most 10.
    Matrix3 b;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) b(i, j) = draw(random, -1, 1);
    const Matrix3 full = b * b.transposed() + Matrix3::identity();
    const SymmetricMatrix3 s = fromMatrix(full);  // its upper triangle
    const Vector3 rhs{draw(random, -5, 5), draw(random, -5, 5), draw(random, -5, 5)};
    const Vector3 x = s.solve(rhs);
    expectNear(x, s.toMatrix().inverse() * rhs, 50 * tight);
    expectNear(s * x, rhs, 50 * tight);
  }
}

// ---------------------------------------------------------------------------------------------
// MathTools

TEST(MathToolsTest, Pi) {
  EXPECT_EQ(pi<double>, std::numbers::pi);
  EXPECT_EQ(pi<float>, std::numbers::pi_v<float>);
  EXPECT_NEAR(pi<double>, 3.14159265358979323846, 1e-15);
  EXPECT_NEAR(std::cos(pi<real>), -1, tight);
  EXPECT_NEAR(std::sin(pi<real> / 6), real(0.5), tight);
}

TEST(MathToolsTest, SquareAndClamp) {
  EXPECT_EQ(square(3), 9);
  EXPECT_EQ(square(-3), 9);
  EXPECT_EQ(square(real(1.5)), real(2.25));
  EXPECT_EQ(square(real(0)), 0);
  static_assert(square(4) == 16, "square is constexpr");

  EXPECT_EQ(clamp(real(0.5), real(0), real(1)), real(0.5));
  EXPECT_EQ(clamp(real(-2), real(0), real(1)), 0);
  EXPECT_EQ(clamp(real(7), real(0), real(1)), 1);
  EXPECT_EQ(clamp(real(0), real(0), real(1)), 0);  // bounds included
  EXPECT_EQ(clamp(real(1), real(0), real(1)), 1);
  EXPECT_EQ(clamp(-5, -3, 3), -3);
  EXPECT_EQ(clamp(5, -3, 3), 3);
  static_assert(clamp(10, 0, 4) == 4, "clamp is constexpr");
}

template <class T>
void checkWrapAngle(T tolerance) {
  const T p = pi<T>;
  // The range is (-pi, pi]: pi stays, -pi becomes pi.
  EXPECT_EQ(wrapAngle(p), p);
  EXPECT_EQ(wrapAngle(-p), p);
  EXPECT_EQ(wrapAngle(T(0)), T(0));
  // Just inside the range: unchanged.
  EXPECT_NEAR(wrapAngle(p - T(0.1)), p - T(0.1), tolerance);
  EXPECT_NEAR(wrapAngle(-p + T(0.1)), -p + T(0.1), tolerance);
  EXPECT_EQ(wrapAngle(T(1)), T(1));
  EXPECT_EQ(wrapAngle(T(-3)), T(-3));
  // Just past pi: wraps to just above -pi, and the other way round.
  EXPECT_NEAR(wrapAngle(p + T(0.1)), -p + T(0.1), tolerance);
  EXPECT_NEAR(wrapAngle(-p - T(0.1)), p - T(0.1), tolerance);
  // Whole turns are removed.
  EXPECT_NEAR(wrapAngle(2 * p), T(0), tolerance);
  EXPECT_NEAR(wrapAngle(T(0.5) + 2 * p), T(0.5), tolerance);
  EXPECT_NEAR(wrapAngle(T(0.5) - 2 * p), T(0.5), tolerance);
  EXPECT_NEAR(wrapAngle(T(-1) + 6 * p), T(-1), 4 * tolerance);
  EXPECT_NEAR(wrapAngle(T(2.5) + 3 * p), T(2.5) - p, 4 * tolerance);
  // 3 pi and -3 pi are (up to rounding) the angle pi, which may land on either end.
  EXPECT_NEAR(std::abs(wrapAngle(3 * p)), p, 4 * tolerance);
  EXPECT_NEAR(std::abs(wrapAngle(-3 * p)), p, 4 * tolerance);
  // Whatever the input, the result lies in (-pi, pi] and differs by a whole number of turns.
  MTRandom random(3);
  for (int i = 0; i < 1000; ++i) {
    const T angle = static_cast<T>(random.uniform(-50, 50));
    const T wrapped = wrapAngle(angle);
    EXPECT_GT(wrapped, -p);
    EXPECT_LE(wrapped, p);
    const T turns = (angle - wrapped) / (2 * p);
    EXPECT_NEAR(turns, std::round(turns), 100 * tolerance);
  }
}

TEST(MathToolsTest, WrapAngleDouble) { checkWrapAngle<double>(1e-12); }
TEST(MathToolsTest, WrapAngleFloat) { checkWrapAngle<float>(1e-5f); }
TEST(MathToolsTest, WrapAngleReal) { checkWrapAngle<real>(tight); }

TEST(MathToolsTest, IsFinite) {
  EXPECT_TRUE(isFinite(real(1)));
  EXPECT_TRUE(isFinite(realMax));
  EXPECT_FALSE(isFinite(std::numeric_limits<real>::infinity()));
  EXPECT_FALSE(isFinite(-std::numeric_limits<real>::infinity()));
  EXPECT_FALSE(isFinite(std::numeric_limits<real>::quiet_NaN()));
}

}  // namespace
}  // namespace thyrix
