// Planar spatial algebra (ThyrixPro/SpatialAlgebra.h): every transform checked against its
// definition (the velocity of a moving point, the moment of a force about a new point), the
// matrix forms against each other (X* = X^-T), power invariance, and the spatial inertia
// against the parallel-axis theorem.

#include "TestTolerances.h"
#include "support/ExpectNear.h"

#include <ThyrixLite/Matrix3.h>
#include <ThyrixLite/SymmetricMatrix3.h>
#include <ThyrixPro/CosSin.h>
#include <ThyrixPro/SpatialAlgebra.h>
#include <Tools/MTRandom.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

namespace thyrix {
namespace {

using test::expectNear;
using test::tight;

real draw(MTRandom& random, double low, double high) {
  return static_cast<real>(random.uniform(low, high));
}

Vector3 randomVector(MTRandom& random) {
  return {draw(random, -2, 2), draw(random, -2, 2), draw(random, -2, 2)};
}

// Tolerance for a few operations on values of order 10.
const real kTol = 20 * tight;

TEST(SpatialAlgebraTest, ComponentOrderIsAngularThenLinear) {
  const Vector3 m = motionVector(3, {4, 5});
  EXPECT_EQ(m, (Vector3{3, 4, 5}));
  EXPECT_EQ(angularPart(m), 3);
  EXPECT_EQ(linearPart(m), (Vector2{4, 5}));
  EXPECT_EQ(forceVector(-1, {2, 7}), (Vector3{-1, 2, 7}));
}

TEST(SpatialAlgebraTest, SpatialForceAtAPointHasTheMomentAboutTheOrigin) {
  // A force (0, 2) at (3, 1) about (1, 1): lever (2, 0), moment 2 * 2 - 0 * 0 = 4.
  EXPECT_EQ(spatialForceAt({0, 2}, {3, 1}, {1, 1}), (Vector3{4, 0, 2}));
}

TEST(SpatialAlgebraTest, MotionTransformIsTheVelocityOfTheNewOriginInTheNewAxes) {
  MTRandom random(11);
  for (int trial = 0; trial < 20; ++trial) {
    const real theta = draw(random, -4, 4);
    const Vector2 r{draw(random, -3, 3), draw(random, -3, 3)};
    const PlanarTransform x = PlanarTransform::fromAngleAndOrigin(theta, r);
    const Vector3 m = randomVector(random);
    // By definition: the body point at B's origin moves at v_A + omega x r (A axes); B's axes
    // are turned by theta, so its coordinates there are that vector turned by -theta.
    const Vector2 atB = (linearPart(m) + cross(angularPart(m), r)).rotated(-theta);
    expectNear(x.applyToMotion(m), motionVector(angularPart(m), atB), kTol);
    expectNear(x.motionMatrix() * m, x.applyToMotion(m), kTol);
    expectNear(x.inverseApplyToMotion(x.applyToMotion(m)), m, kTol);
  }
}

TEST(SpatialAlgebraTest, MotionMatrixIsFeatherstonesPlanarTransform) {
  // X = [1 0 0; s r_x - c r_y, c, s; c r_x + s r_y, -s, c] for theta = pi / 2, r = (2, 3):
  // c = 0, s = 1: X = [1 0 0; 2 0 1; 3 -1 0].
  const PlanarTransform x = PlanarTransform::fromAngleAndOrigin(std::acos(real(-1)) / 2, {2, 3});
  Matrix3 expected;
  expected.m = {{{1, 0, 0}, {2, 0, 1}, {3, -1, 0}}};
  expectNear(x.motionMatrix(), expected, tight * 10);
}

TEST(SpatialAlgebraTest, ForceTransformIsTheDualAndKeepsPower) {
  MTRandom random(12);
  for (int trial = 0; trial < 20; ++trial) {
    const real theta = draw(random, -4, 4);
    const Vector2 r{draw(random, -3, 3), draw(random, -3, 3)};
    const PlanarTransform x = PlanarTransform::fromAngleAndOrigin(theta, r);
    const Vector3 f = randomVector(random);
    const Vector3 m = randomVector(random);
    expectNear(x.forceMatrix(), x.motionMatrix().inverse().transposed(), kTol);
    expectNear(x.forceMatrix() * f, x.applyToForce(f), kTol);
    // By definition: the moment about B's origin is n - r x f; the force turns by -theta.
    const Vector2 force = linearPart(f);
    expectNear(x.applyToForce(f),
               forceVector(angularPart(f) - cross(r, force), force.rotated(-theta)), kTol);
    expectNear(x.transposeApplyToForce(x.applyToForce(f)), f, kTol);
    expectNear(x.motionMatrix().transposed() * f, x.transposeApplyToForce(f), kTol);
    // Power is frame-independent: (X* f) . (X m) = f . m.
    EXPECT_NEAR(x.applyToForce(f).dot(x.applyToMotion(m)), f.dot(m), kTol);
  }
}

TEST(SpatialAlgebraTest, CongruenceIsTheMatrixProduct) {
  MTRandom random(13);
  for (int trial = 0; trial < 20; ++trial) {
    const PlanarTransform x = PlanarTransform::fromAngleAndOrigin(
        draw(random, -4, 4), {draw(random, -3, 3), draw(random, -3, 3)});
    const SymmetricMatrix3 d{draw(random, 1, 3), draw(random, -1, 1), draw(random, -1, 1),
                             draw(random, 1, 3), draw(random, -1, 1), draw(random, 1, 3)};
    const Matrix3 expected = x.motionMatrix().transposed() * d.toMatrix() * x.motionMatrix();
    expectNear(x.transposeCongruence(d).toMatrix(), expected, 5 * kTol);
  }
}

TEST(SpatialAlgebraTest, TranslationsMatchThePlanarTransform) {
  MTRandom random(14);
  for (int trial = 0; trial < 20; ++trial) {
    const Vector2 r{draw(random, -3, 3), draw(random, -3, 3)};
    const PlanarTransform x = PlanarTransform::translation(r);
    const Vector3 v = randomVector(random);
    expectNear(translateMotion(v, r), x.applyToMotion(v), kTol);
    expectNear(translateForceBack(v, r), x.transposeApplyToForce(v), kTol);
    const SymmetricMatrix3 d{draw(random, 1, 3), draw(random, -1, 1), draw(random, -1, 1),
                             draw(random, 1, 3), draw(random, -1, 1), draw(random, 1, 3)};
    expectNear(translateInertiaBack(d, r).toMatrix(), x.transposeCongruence(d).toMatrix(),
               5 * kTol);
  }
}

TEST(SpatialAlgebraTest, SpatialInertiaIsTheParallelAxisTheorem) {
  MTRandom random(15);
  for (int trial = 0; trial < 20; ++trial) {
    const real m = draw(random, 0.5, 3);
    const real inertia = draw(random, 0.1, 2);
    const Vector2 c{draw(random, -2, 2), draw(random, -2, 2)};
    const SymmetricMatrix3 d = spatialInertia(m, inertia, c);
    // About the centre of mass the inertia is diag(I, m, m); moved back from c to the origin:
    const SymmetricMatrix3 moved =
        translateInertiaBack(SymmetricMatrix3::diagonal(inertia, m, m), c);
    expectNear(d.toMatrix(), moved.toMatrix(), kTol);
    // And by definition: the centre of mass moves at v_O + omega x c, so the force is
    // m (v_O + omega x c) and the moment about O is I omega + c x force.
    const Vector3 v = randomVector(random);
    const Vector2 vc = linearPart(v) + cross(angularPart(v), c);
    const Vector2 force = vc * m;
    expectNear(d * v, forceVector(inertia * angularPart(v) + cross(c, force), force), kTol);
  }
}

TEST(SpatialAlgebraTest, ForceInAFrameIsTheWorldForceTransformed) {
  MTRandom random(16);
  for (int trial = 0; trial < 20; ++trial) {
    const Vector2 force{draw(random, -2, 2), draw(random, -2, 2)};
    const Vector2 point{draw(random, -3, 3), draw(random, -3, 3)};
    const Vector2 origin{draw(random, -3, 3), draw(random, -3, 3)};
    const real angle = draw(random, -4, 4);
    // The world force about the world origin, then X* into the frame.
    const Vector3 expected = PlanarTransform::fromAngleAndOrigin(angle, origin)
                                 .applyToForce(spatialForceAt(force, point, {0, 0}));
    expectNear(spatialForceInFrame(force, point, origin, angle), expected, kTol);
  }
}

/// How many units in the last place of @p reference the value @p got is from it.
double ulpsFrom(real got, real reference) {
  const real ulp = std::nextafter(std::abs(reference), std::numeric_limits<real>::infinity()) -
                   std::abs(reference);
  return static_cast<double>(std::abs(got - reference) / ulp);
}

TEST(SpatialAlgebraTest, CosSinIsTheLibrarysToAFewUnitsInTheLastPlace) {
  // ThyrixPro/CosSin.h: Taylor series after a Cody-Waite reduction, 1.5 ulp from the exact
  // values for the angles of a simulation, 2.2 up to 2^19 (near a zero the value is small and
  // its ulp too), exactly the library's beyond, where it hands over. Against the library,
  // itself up to an ulp off (glibc: 0.51), 3 and 4 ulp: a wrong constant gives thousands.
  MTRandom random(17);
  for (const double range : {1.0, 4.0, 100.0, 500000.0}) {
    const double allowed = range <= 100 ? 3 : 4;
    double worst = 0;
    for (int trial = 0; trial < 20000; ++trial) {
      const real a = draw(random, -range, range);
      const Vector2 v = cosSin(a);
      worst = std::max({worst, ulpsFrom(v.x, std::cos(a)), ulpsFrom(v.y, std::sin(a))});
    }
    EXPECT_LE(worst, allowed) << "angles within " << range;
  }
  // Near the zeros, k pi/2, the result is the small remainder r itself: the whole reduction
  // (the third part of pi/2 too) shows in it.
  for (int k = 1; k <= 64; ++k) {
    const real a = static_cast<real>(k * 1.5707963267948966);
    const Vector2 v = cosSin(a);
    EXPECT_LE(ulpsFrom(v.x, std::cos(a)), 3) << "k = " << k;
    EXPECT_LE(ulpsFrom(v.y, std::sin(a)), 3) << "k = " << k;
  }
  for (const real a : {real(0), real(1e6), real(-3e7), real(0x1p19)}) {
    EXPECT_EQ(cosSin(a).x, std::cos(a)) << a;
    EXPECT_EQ(cosSin(a).y, std::sin(a)) << a;
  }
  EXPECT_TRUE(std::isnan(cosSin(std::numeric_limits<real>::quiet_NaN()).x));
  EXPECT_TRUE(std::isnan(cosSin(std::numeric_limits<real>::infinity()).y));
}

TEST(SpatialAlgebraTest, CosSinOfManyAnglesIsCosSinOfEach) {
  MTRandom random(18);
  std::vector<real> angles;
  for (int k = 0; k < 101; ++k) angles.push_back(draw(random, -20, 20));
  angles[7] = real(4e6);  // beyond the kernel's range
  std::vector<Vector2> out(angles.size());
  cosSin(angles, out);
  for (std::size_t k = 0; k < angles.size(); ++k) {
    EXPECT_EQ(out[k].x, cosSin(angles[k]).x) << k;
    EXPECT_EQ(out[k].y, cosSin(angles[k]).y) << k;
  }
}

TEST(SpatialAlgebraTest, CosSinKernelIsCosSinOfEachAtEverySizeAndOffset) {
  // The kernel runs eight angles at a time where the processor has AVX-512, four with AVX2,
  // two with SSE2: every count and start exercises the vector loops' leftovers; each pair must
  // have cosSin()'s bits.
  MTRandom random(19);
  std::vector<real> angles;
  for (int k = 0; k < 40; ++k) angles.push_back(draw(random, -100, 100));
  angles[5] = real(0);
  angles[6] = -real(0);
  std::vector<Vector2> out(angles.size());
  for (std::size_t start = 0; start < 8; ++start) {
    for (std::size_t count = 0; start + count <= angles.size(); ++count) {
      std::fill(out.begin(), out.end(), Vector2{7, 7});
      cosSinKernel(std::span<const real>(angles).subspan(start, count),
                   std::span<Vector2>(out).subspan(start, count));
      for (std::size_t k = 0; k < out.size(); ++k) {
        const bool inside = k >= start && k < start + count;
        const Vector2 expected = inside ? cosSin(angles[k]) : Vector2{7, 7};
        EXPECT_EQ(std::bit_cast<std::uint64_t>(static_cast<double>(out[k].x)),
                  std::bit_cast<std::uint64_t>(static_cast<double>(expected.x)))
            << start << " " << count << " " << k;
        EXPECT_EQ(std::bit_cast<std::uint64_t>(static_cast<double>(out[k].y)),
                  std::bit_cast<std::uint64_t>(static_cast<double>(expected.y)))
            << start << " " << count << " " << k;
      }
    }
  }
}

}  // namespace
}  // namespace thyrix
