// Narrow phase: every expected point, normal and depth below is derived by hand from the
// geometry (the arithmetic is in the comments), never copied from a run of the code.
// Conventions: the normal goes from A to B, depth = overlap along it (negative: a gap), the
// point lies midway between the two surfaces, and contacts are reported while gap < margin.

#include "TestTolerances.h"

#include <ThyrixLite/NarrowPhase.h>
#include <Tools/MTRandom.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace thyrix {
namespace {

/// A vector from double literals (no float-conversion warnings when `real` is float).
constexpr Vector2 vec(double x, double y) { return {real(x), real(y)}; }

/// The 3-4-5 rotation (cos = 0.8, sin = 0.6) used for the rotated configurations: its entries
/// are short decimals, so rotated coordinates can be worked out by hand.
constexpr Vector2 rot(Vector2 v) {
  return {real(0.8) * v.x - real(0.6) * v.y, real(0.6) * v.x + real(0.8) * v.y};
}

::testing::AssertionResult vectorNear(Vector2 actual, Vector2 expected,
                                      real tolerance = test::tight) {
  if (std::abs(actual.x - expected.x) <= tolerance && std::abs(actual.y - expected.y) <= tolerance)
    return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure()
         << "(" << actual.x << ", " << actual.y << ") is not within " << tolerance << " of ("
         << expected.x << ", " << expected.y << ")";
}

/// Checks a one-point manifold.
void expectSingle(const Manifold& m, Vector2 normal, Vector2 point, double depth,
                  real tolerance = test::tight) {
  ASSERT_EQ(m.count, 1);
  EXPECT_TRUE(vectorNear(m.normal, normal, tolerance));
  EXPECT_TRUE(vectorNear(m.points[0].point, point, tolerance));
  EXPECT_NEAR(m.points[0].depth, depth, tolerance);
}

/// Checks one point of a manifold, with its feature.
void expectPoint(const ManifoldPoint& p, Vector2 point, double depth, std::uint32_t feature,
                 real tolerance = test::tight) {
  EXPECT_TRUE(vectorNear(p.point, point, tolerance));
  EXPECT_NEAR(p.depth, depth, tolerance);
  EXPECT_EQ(p.feature, feature);
}

// --- closestPointOnSegment ----------------------------------------------------------------

TEST(ClosestPointOnSegment, InteriorProjection) {
  // Segment (0,0)-(4,0), p = (1.5, 2): the foot of the perpendicular is (1.5, 0).
  EXPECT_TRUE(vectorNear(closestPointOnSegment(vec(0, 0), vec(4, 0), vec(1.5, 2)), vec(1.5, 0)));
  // Point on the segment itself.
  EXPECT_TRUE(vectorNear(closestPointOnSegment(vec(0, 0), vec(4, 0), vec(3, 0)), vec(3, 0)));
}

TEST(ClosestPointOnSegment, ClampsToTheEnds) {
  // Projections before a (x = -2) and after b (x = 7) clamp to the ends.
  EXPECT_TRUE(vectorNear(closestPointOnSegment(vec(0, 0), vec(4, 0), vec(-2, 1)), vec(0, 0)));
  EXPECT_TRUE(vectorNear(closestPointOnSegment(vec(0, 0), vec(4, 0), vec(7, -3)), vec(4, 0)));
}

TEST(ClosestPointOnSegment, Oblique) {
  // d = (4,2), |d|^2 = 20, p - a = (1,3): t = (4 + 6) / 20 = 0.5, so (2, 1).
  EXPECT_TRUE(vectorNear(closestPointOnSegment(vec(0, 0), vec(4, 2), vec(1, 3)), vec(2, 1)));
  // Offset segment (1,1)-(4,5), d = (3,4), p = (5,0): t = (12 - 4) / 25 = 0.32,
  // a + 0.32 d = (1.96, 2.28).
  EXPECT_TRUE(vectorNear(closestPointOnSegment(vec(1, 1), vec(4, 5), vec(5, 0)), vec(1.96, 2.28)));
}

TEST(ClosestPointOnSegment, DegenerateSegmentIsItsPoint) {
  EXPECT_TRUE(vectorNear(closestPointOnSegment(vec(2, 3), vec(2, 3), vec(-5, 8)), vec(2, 3)));
}

// --- half-plane / circle ------------------------------------------------------------------

// The border y = 0 with normal +y, used by most half-plane tests.
constexpr Vector2 floorPoint = vec(0, 0);
constexpr Vector2 up = vec(0, 1);

TEST(HalfPlaneCircle, Touching) {
  // Centre (3, 0.5), r 0.5: distance 0.5 = r, both surfaces at (3, 0).
  const Manifold m = collideHalfPlaneCircle(floorPoint, up, vec(3, 0.5), real(0.5), real(0.1));
  expectSingle(m, up, vec(3, 0), 0);
  EXPECT_EQ(m.points[0].feature, 0u);
}

TEST(HalfPlaneCircle, Overlapping) {
  // Centre (3, 0.3), r 0.5: depth 0.5 - 0.3 = 0.2; surfaces (3, 0) and (3, -0.2): mid (3, -0.1).
  const Manifold m = collideHalfPlaneCircle(floorPoint, up, vec(3, 0.3), real(0.5), real(0.1));
  expectSingle(m, up, vec(3, -0.1), 0.2);
}

TEST(HalfPlaneCircle, DeepOverlapCentreBehindTheBorder) {
  // Centre (3, -0.2), r 0.5: distance -0.2, depth 0.5 + 0.2 = 0.7; surfaces (3, 0) and
  // (3, -0.7): mid (3, -0.35).
  const Manifold m = collideHalfPlaneCircle(floorPoint, up, vec(3, -0.2), real(0.5), real(0.1));
  expectSingle(m, up, vec(3, -0.35), 0.7);
}

TEST(HalfPlaneCircle, GapInsideTheMarginIsSpeculative) {
  // Centre (3, 0.6), r 0.5, margin 0.2: gap 0.1 < 0.2, depth -0.1; surfaces (3, 0) and
  // (3, 0.1): mid (3, 0.05).
  const Manifold m = collideHalfPlaneCircle(floorPoint, up, vec(3, 0.6), real(0.5), real(0.2));
  expectSingle(m, up, vec(3, 0.05), -0.1);
}

TEST(HalfPlaneCircle, GapAtOrBeyondTheMarginGivesNothing) {
  // Gap 0.75 - 0.5 = 0.25 = margin (exact in binary): not reported (gap < margin only).
  EXPECT_EQ(collideHalfPlaneCircle(floorPoint, up, vec(3, 0.75), real(0.5), real(0.25)).count, 0);
  // Gap 0.3 > margin 0.2.
  EXPECT_EQ(collideHalfPlaneCircle(floorPoint, up, vec(3, 0.8), real(0.5), real(0.2)).count, 0);
}

TEST(HalfPlaneCircle, ObliqueBorder) {
  // Border through (1, 2) with n = (0.6, 0.8), tangent t = (-0.8, 0.6). Centre = (1,2) + 0.7 n
  // + 2 t = (1 + 0.42 - 1.6, 2 + 0.56 + 1.2) = (-0.18, 3.76), r 1: depth 1 - 0.7 = 0.3.
  // Surface A = centre - 0.7 n = (1,2) + 2 t = (-0.6, 3.2); surface B = centre - n =
  // (-0.6, 3.2) - 0.3 n = (-0.78, 2.96); mid = (-0.6, 3.2) - 0.15 n = (-0.69, 3.08).
  const Vector2 n = vec(0.6, 0.8);
  const Manifold m = collideHalfPlaneCircle(vec(1, 2), n, vec(-0.18, 3.76), real(1), real(0.1));
  expectSingle(m, n, vec(-0.69, 3.08), 0.3);
}

// --- half-plane / capsule -----------------------------------------------------------------

TEST(HalfPlaneCapsule, LyingFlatGivesTwoPoints) {
  // Ends (-1, 0.4), (1, 0.4), r 0.5: each end 0.1 deep; surfaces (x, 0) and (x, -0.1):
  // points (-1, -0.05) feature 0 and (1, -0.05) feature 1.
  const Manifold m =
      collideHalfPlaneCapsule(floorPoint, up, vec(-1, 0.4), vec(1, 0.4), real(0.5), real(0.1));
  ASSERT_EQ(m.count, 2);
  EXPECT_TRUE(vectorNear(m.normal, up));
  expectPoint(m.points[0], vec(-1, -0.05), 0.1, 0);
  expectPoint(m.points[1], vec(1, -0.05), 0.1, 1);
}

TEST(HalfPlaneCapsule, TouchingFlat) {
  // Ends at height 0.5 = r: both touch, depth 0, points on the border.
  const Manifold m =
      collideHalfPlaneCapsule(floorPoint, up, vec(-2, 0.5), vec(2, 0.5), real(0.5), real(0.1));
  ASSERT_EQ(m.count, 2);
  expectPoint(m.points[0], vec(-2, 0), 0, 0);
  expectPoint(m.points[1], vec(2, 0), 0, 1);
}

TEST(HalfPlaneCapsule, TiltedGivesOnePointWithinMargin) {
  // End 0 at (-1, 0.55): gap 0.05 < margin 0.1, depth -0.05; surfaces (-1, 0) and (-1, 0.05):
  // mid (-1, 0.025). End 1 at (1, 1.55): gap 1.05, out of reach.
  const Manifold m =
      collideHalfPlaneCapsule(floorPoint, up, vec(-1, 0.55), vec(1, 1.55), real(0.5), real(0.1));
  ASSERT_EQ(m.count, 1);
  EXPECT_TRUE(vectorNear(m.normal, up));
  expectPoint(m.points[0], vec(-1, 0.025), -0.05, 0);
}

TEST(HalfPlaneCapsule, OnlyTheSecondEndInReachKeepsItsFeature) {
  // End 0 at (-1, 2): far. End 1 at (1, 0.3), r 0.5: depth 0.2, mid of (1, 0) and (1, -0.2).
  const Manifold m =
      collideHalfPlaneCapsule(floorPoint, up, vec(-1, 2), vec(1, 0.3), real(0.5), real(0.1));
  ASSERT_EQ(m.count, 1);
  expectPoint(m.points[0], vec(1, -0.1), 0.2, 1);
}

TEST(HalfPlaneCapsule, TiltedWithBothEndsInReach) {
  // Ends (-1, 0.2) and (1, 0.55), r 0.5, margin 0.1: depths 0.3 and -0.05;
  // mids (-1, -0.15) and (1, 0.025).
  const Manifold m =
      collideHalfPlaneCapsule(floorPoint, up, vec(-1, 0.2), vec(1, 0.55), real(0.5), real(0.1));
  ASSERT_EQ(m.count, 2);
  expectPoint(m.points[0], vec(-1, -0.15), 0.3, 0);
  expectPoint(m.points[1], vec(1, 0.025), -0.05, 1);
}

TEST(HalfPlaneCapsule, DeepOverlapBothEndsBehindTheBorder) {
  // Ends at height -0.25, r 0.5: depth 0.75; surfaces (x, 0) and (x, -0.75): mid (x, -0.375).
  const Manifold m =
      collideHalfPlaneCapsule(floorPoint, up, vec(0, -0.25), vec(3, -0.25), real(0.5), real(0.1));
  ASSERT_EQ(m.count, 2);
  expectPoint(m.points[0], vec(0, -0.375), 0.75, 0);
  expectPoint(m.points[1], vec(3, -0.375), 0.75, 1);
}

TEST(HalfPlaneCapsule, BeyondTheMarginGivesNothing) {
  // Both ends at height 0.8, r 0.5: gap 0.3 > margin 0.2.
  EXPECT_EQ(collideHalfPlaneCapsule(floorPoint, up, vec(-1, 0.8), vec(1, 0.8), real(0.5), real(0.2))
                .count,
            0);
}

TEST(HalfPlaneCapsule, ObliqueBorderFlat) {
  // Border through (0,0) with n = (0.6, 0.8), tangent t = (0.8, -0.6). Ends 0.4 n -/+ t =
  // (0.24 -/+ 0.8, 0.32 +/- 0.6), r 0.5: depth 0.1 each; mids = ends - 0.45 n = -/+ t - 0.05 n
  // = (-0.8 - 0.03, 0.6 - 0.04) = (-0.83, 0.56) and (0.8 - 0.03, -0.6 - 0.04) = (0.77, -0.64).
  const Vector2 n = vec(0.6, 0.8);
  const Manifold m = collideHalfPlaneCapsule(vec(0, 0), n, vec(-0.56, 0.92), vec(1.04, -0.28),
                                             real(0.5), real(0.1));
  ASSERT_EQ(m.count, 2);
  EXPECT_TRUE(vectorNear(m.normal, n));
  expectPoint(m.points[0], vec(-0.83, 0.56), 0.1, 0);
  expectPoint(m.points[1], vec(0.77, -0.64), 0.1, 1);
}

// --- circle / circle ----------------------------------------------------------------------

TEST(Circles, Touching) {
  // A (0,0) r 1, B (3,0) r 2: distance 3 = 1 + 2; both surfaces at (1, 0).
  const Manifold m = collideCircles(vec(0, 0), real(1), vec(3, 0), real(2), real(0.1));
  expectSingle(m, vec(1, 0), vec(1, 0), 0);
  EXPECT_EQ(m.points[0].feature, 0u);
}

TEST(Circles, Overlapping) {
  // B at (2.5, 0): depth 3 - 2.5 = 0.5; surfaces (1, 0) and (0.5, 0): mid (0.75, 0).
  const Manifold m = collideCircles(vec(0, 0), real(1), vec(2.5, 0), real(2), real(0.1));
  expectSingle(m, vec(1, 0), vec(0.75, 0), 0.5);
}

TEST(Circles, Oblique) {
  // A (1,1) r 1, B = A + 2 (0.6, 0.8) = (2.2, 2.6) r 1.5: n = (0.6, 0.8), depth 2.5 - 2 = 0.5.
  // Surface A = (1.6, 1.8), surface B = (2.2, 2.6) - 1.5 n = (1.3, 1.4): mid (1.45, 1.6).
  const Manifold m = collideCircles(vec(1, 1), real(1), vec(2.2, 2.6), real(1.5), real(0.1));
  expectSingle(m, vec(0.6, 0.8), vec(1.45, 1.6), 0.5);
}

TEST(Circles, DeepOverlapCentreInside) {
  // A (0,0) r 2, B (0,-0.5) r 1: n = (0,-1), depth 3 - 0.5 = 2.5; surface A (0,-2),
  // surface B (0,-0.5) + (0,1) = (0, 0.5): mid (0, -0.75).
  const Manifold m = collideCircles(vec(0, 0), real(2), vec(0, -0.5), real(1), real(0.1));
  expectSingle(m, vec(0, -1), vec(0, -0.75), 2.5);
}

TEST(Circles, GapInsideTheMarginIsSpeculative) {
  // B (0, 2.25), both r 1, margin 0.5: gap 0.25, depth -0.25; surfaces (0,1) and (0,1.25):
  // mid (0, 1.125).
  const Manifold m = collideCircles(vec(0, 0), real(1), vec(0, 2.25), real(1), real(0.5));
  expectSingle(m, vec(0, 1), vec(0, 1.125), -0.25);
}

TEST(Circles, GapAtOrBeyondTheMarginGivesNothing) {
  // Gap 2.5 - 2 = 0.5 = margin (exact): not reported; gap 0.75 > 0.5: nothing.
  EXPECT_EQ(collideCircles(vec(0, 0), real(1), vec(0, 2.5), real(1), real(0.5)).count, 0);
  EXPECT_EQ(collideCircles(vec(0, 0), real(1), vec(0, 2.75), real(1), real(0.5)).count, 0);
}

TEST(Circles, CoincidentCentresGetNormalPlusX) {
  // Both at (1,2), r 1 and 0.5: n = +x, depth 1.5; surfaces (2,2) and (0.5,2): mid (1.25, 2).
  const Manifold m = collideCircles(vec(1, 2), real(1), vec(1, 2), real(0.5), real(0.1));
  expectSingle(m, vec(1, 0), vec(1.25, 2), 1.5);
}

// --- circle / capsule ---------------------------------------------------------------------

// Capsule B used by most circle-capsule tests: axis (0,0)-(4,0), radius 0.5.
constexpr Vector2 capsule0 = vec(0, 0);
constexpr Vector2 capsule1 = vec(4, 0);
constexpr real capsuleRadius = real(0.5);

TEST(CircleCapsule, TouchingTheSide) {
  // Centre (2, 1.5) r 1: closest axis point (2,0), distance 1.5 = 1 + 0.5, n = (0,-1);
  // both surfaces at (2, 0.5).
  const Manifold m =
      collideCircleCapsule(vec(2, 1.5), real(1), capsule0, capsule1, capsuleRadius, real(0.1));
  expectSingle(m, vec(0, -1), vec(2, 0.5), 0);
}

TEST(CircleCapsule, OverlappingTheSide) {
  // Centre (1, 1.2) r 1: axis point (1,0), distance 1.2, depth 0.3, n = (0,-1);
  // surfaces (1, 0.2) and (1, 0.5): mid (1, 0.35).
  const Manifold m =
      collideCircleCapsule(vec(1, 1.2), real(1), capsule0, capsule1, capsuleRadius, real(0.1));
  expectSingle(m, vec(0, -1), vec(1, 0.35), 0.3);
}

TEST(CircleCapsule, ObliqueOnTheEndCap) {
  // Centre = (4,0) + 1.25 (0.6, 0.8) = (4.75, 1) r 1: closest axis point is the end (4,0),
  // n = (-0.6, -0.8), depth 1.5 - 1.25 = 0.25. Surface A = (4.75,1) + n = (4.15, 0.2);
  // surface B = (4,0) - 0.5 n = (4.3, 0.4): mid (4.225, 0.3).
  const Manifold m =
      collideCircleCapsule(vec(4.75, 1), real(1), capsule0, capsule1, capsuleRadius, real(0.1));
  expectSingle(m, vec(-0.6, -0.8), vec(4.225, 0.3), 0.25);
}

TEST(CircleCapsule, DeepOverlap) {
  // Centre (2, 0.25) r 1: distance 0.25, depth 1.25, n = (0,-1); surfaces (2,-0.75) and
  // (2, 0.5): mid (2, -0.125).
  const Manifold m =
      collideCircleCapsule(vec(2, 0.25), real(1), capsule0, capsule1, capsuleRadius, real(0.1));
  expectSingle(m, vec(0, -1), vec(2, -0.125), 1.25);
}

TEST(CircleCapsule, GapInsideTheMarginIsSpeculative) {
  // Centre (2, -1.6) r 1, margin 0.2: distance 1.6, gap 0.1, n = (0, 1); surfaces (2, -0.6)
  // and (2, -0.5): mid (2, -0.55).
  const Manifold m =
      collideCircleCapsule(vec(2, -1.6), real(1), capsule0, capsule1, capsuleRadius, real(0.2));
  expectSingle(m, vec(0, 1), vec(2, -0.55), -0.1);
}

TEST(CircleCapsule, BeyondTheMarginGivesNothing) {
  // Centre (2, -1.8): gap 0.3 > margin 0.2. Beyond the end cap: centre (6, 0), gap 0.5.
  EXPECT_EQ(
      collideCircleCapsule(vec(2, -1.8), real(1), capsule0, capsule1, capsuleRadius, real(0.2))
          .count,
      0);
  EXPECT_EQ(
      collideCircleCapsule(vec(6, 0), real(1), capsule0, capsule1, capsuleRadius, real(0.2)).count,
      0);
}

TEST(CircleCapsule, RotatedCapsule) {
  // Axis (0,0)-(3,4), direction (0.6, 0.8), side normal (0.8, -0.6). Centre = (1.5, 2)
  // + 1.25 (-0.8, 0.6) = (0.5, 2.75) r 1: n = (0.8, -0.6), depth 0.25. Surface A =
  // (0.5, 2.75) + n = (1.3, 2.15); surface B = (1.5, 2) - 0.5 n = (1.1, 2.3): mid (1.2, 2.225).
  const Manifold m =
      collideCircleCapsule(vec(0.5, 2.75), real(1), vec(0, 0), vec(3, 4), real(0.5), real(0.1));
  expectSingle(m, vec(0.8, -0.6), vec(1.2, 2.225), 0.25);
}

TEST(CircleCapsule, CentreExactlyOnTheAxis) {
  // Centre (1, 0) r 1 on the axis: pushed out sideways, so n is perpendicular to the axis
  // (either side), depth 1 + 0.5 = 1.5, and the point is midway between centre + n and
  // (1,0) - 0.5 n, i.e. centre + 0.25 n.
  const Manifold m =
      collideCircleCapsule(vec(1, 0), real(1), capsule0, capsule1, capsuleRadius, real(0.1));
  ASSERT_EQ(m.count, 1);
  EXPECT_NEAR(m.normal.x, 0, test::tight);
  EXPECT_NEAR(std::abs(m.normal.y), 1, test::tight);
  EXPECT_NEAR(m.points[0].depth, 1.5, test::tight);
  EXPECT_TRUE(vectorNear(m.points[0].point, vec(1, 0) + m.normal * real(0.25)));

  // The same on the rotated axis (0,0)-(3,4) at (1.5, 2): n = +/-(0.8, -0.6).
  const Manifold r =
      collideCircleCapsule(vec(1.5, 2), real(1), vec(0, 0), vec(3, 4), real(0.5), real(0.1));
  ASSERT_EQ(r.count, 1);
  EXPECT_NEAR(std::abs(dot(r.normal, vec(0.8, -0.6))), 1, test::tight);
  EXPECT_NEAR(r.points[0].depth, 1.5, test::tight);
  EXPECT_TRUE(vectorNear(r.points[0].point, vec(1.5, 2) + r.normal * real(0.25)));
}

// --- capsule / capsule --------------------------------------------------------------------

/// A capsule half length that rounding loses at the coordinate farAway: its two end points are
/// the same number (half an ulp of 1e11 in double is 7.6e-6, of 1e6 in float 0.031).
constexpr real farAway = test::isFloat ? real(1e6) : real(1e11);
constexpr real lostHalfLength = test::isFloat ? real(0.01) : real(1e-6);

TEST(Capsules, AxisCollapsedFarFromTheOriginIsACircle) {
  // A's ends (X -/+ l, 0) round to one point (X, 0): A is a circle of radius 0.5 there. B's axis
  // (X-2, 1)-(X+2, 1) passes 1 above it: n = (0,1), gap 1 - 0.5 - 0.25 = 0.25 (depth -0.25),
  // surfaces (X, 0.5) and (X, 0.75), midpoint (X, 0.625).
  const Vector2 a0{farAway - lostHalfLength, 0};
  const Vector2 a1{farAway + lostHalfLength, 0};
  ASSERT_EQ(a0.x, a1.x) << "the axis should collapse";
  const Vector2 b0{farAway - 2, 1};
  const Vector2 b1{farAway + 2, 1};
  expectSingle(collideCapsules(a0, a1, real(0.5), b0, b1, real(0.25), real(0.5)), vec(0, 1),
               Vector2{farAway, real(0.625)}, -0.25);
  // B collapsed instead (the pair swapped): the normal still goes from A to B.
  expectSingle(collideCapsules(b0, b1, real(0.25), a0, a1, real(0.5), real(0.5)), vec(0, -1),
               Vector2{farAway, real(0.625)}, -0.25);
  // Both collapsed: two circles, (X, 0) r 0.5 and (X, 1) r 0.25.
  const Vector2 c0{farAway - lostHalfLength, 1};
  const Vector2 c1{farAway + lostHalfLength, 1};
  expectSingle(collideCapsules(a0, a1, real(0.5), c0, c1, real(0.25), real(0.5)), vec(0, 1),
               Vector2{farAway, real(0.625)}, -0.25);
  // Both collapsed onto the same point: circles with one centre, normal +x, depth 0.75.
  const Manifold same = collideCapsules(a0, a1, real(0.5), a0, a1, real(0.25), real(0.5));
  expectSingle(same, vec(1, 0), Vector2{farAway + real(0.125), 0}, 0.75,
               std::max(test::tight, farAway * std::numeric_limits<real>::epsilon()));
}

TEST(Capsules, AxisCollapsedOnTheOtherAxisIsACircleOnIt) {
  // A collapsed onto the middle of B's axis (1,0): as a circle centred on a capsule's axis it
  // gets the normal -perpendicular(1,0) = (0,-1) from A to B, depth 0.5 + 0.25 = 0.75; surfaces
  // (X, -0.5) and (X, 0.25), midpoint (X, -0.125).
  const Vector2 a0{farAway - lostHalfLength, 0};
  const Vector2 a1{farAway + lostHalfLength, 0};
  expectSingle(collideCapsules(a0, a1, real(0.5), Vector2{farAway - 2, 0}, Vector2{farAway + 2, 0},
                               real(0.25), real(0.5)),
               vec(0, -1), Vector2{farAway, real(-0.125)}, 0.75);
}

TEST(Capsules, TShapedTouching) {
  // A (0,0)-(4,0) r 0.5; B's stem (2,1)-(2,3) r 0.5 stands on A's middle: axis points (2,0)
  // and (2,1), distance 1 = 0.5 + 0.5, n = (0,1); both surfaces at (2, 0.5).
  const Manifold m =
      collideCapsules(vec(0, 0), vec(4, 0), real(0.5), vec(2, 1), vec(2, 3), real(0.5), real(0.1));
  expectSingle(m, vec(0, 1), vec(2, 0.5), 0);
}

TEST(Capsules, TShapedOverlapping) {
  // Stem end at (2, 0.8): depth 1 - 0.8 = 0.2; surfaces (2, 0.5) and (2, 0.3): mid (2, 0.4).
  const Manifold m = collideCapsules(vec(0, 0), vec(4, 0), real(0.5), vec(2, 0.8), vec(2, 3),
                                     real(0.5), real(0.1));
  expectSingle(m, vec(0, 1), vec(2, 0.4), 0.2);
}

TEST(Capsules, TShapedDeepOverlap) {
  // Stem end at (2, 0.1), still above A's axis: depth 1 - 0.1 = 0.9; surfaces (2, 0.5) and
  // (2, -0.4): mid (2, 0.05).
  const Manifold m = collideCapsules(vec(0, 0), vec(4, 0), real(0.5), vec(2, 0.1), vec(2, 3),
                                     real(0.5), real(0.1));
  expectSingle(m, vec(0, 1), vec(2, 0.05), 0.9);
}

TEST(Capsules, TShapedWithTheBarAsB) {
  // The T upside down and swapped: A is the stem (2,3)-(2,0.8) above, B the bar (0,0)-(4,0):
  // n = (0,-1) from the stem down to the bar, depth 0.2, mid (2, 0.4).
  const Manifold m = collideCapsules(vec(2, 3), vec(2, 0.8), real(0.5), vec(0, 0), vec(4, 0),
                                     real(0.5), real(0.1));
  expectSingle(m, vec(0, -1), vec(2, 0.4), 0.2);
}

TEST(Capsules, TShapedStemThroughTheBarAxis) {
  // Stem (2,-0.3)-(2,2) crosses A's axis at (2,0): SAT on the axis normals.
  //  +y (A's normal): B's lowest surface (2,-0.8) up to A's top (2,0.5): 1.3.
  //  -y: B's top (2, 2.5) down to A's bottom (2,-0.5): 3.
  //  -x / +x (B's normal): A's end surface (-0.5,0) / (4.5,0) past B's far side: 3 each.
  // Minimum: n = (0,1), depth 1.3, point midway between (2, 0.5) and (2, -0.8): (2, -0.15).
  const Manifold m = collideCapsules(vec(0, 0), vec(4, 0), real(0.5), vec(2, -0.3), vec(2, 2),
                                     real(0.5), real(0.1));
  expectSingle(m, vec(0, 1), vec(2, -0.15), 1.3);
}

TEST(Capsules, CrossingSeparatedAlongTheNormalOfA) {
  // A (-2,0)-(2,0) r 0.5, B (0,-1)-(0,3) r 0.5, crossing at the origin.
  //  +y: B's bottom (0,-1.5) up to A's top (0,0.5): 2.    -y: B's top (0,3.5) to (0,-0.5): 4.
  //  -x: B's right side (0.5,0) to A's left end (-2.5,0): 3.   +x: likewise 3.
  // Minimum: n = (0,1), depth 2, point midway between (0,0.5) and (0,-1.5): (0,-0.5).
  const Manifold m = collideCapsules(vec(-2, 0), vec(2, 0), real(0.5), vec(0, -1), vec(0, 3),
                                     real(0.5), real(0.1));
  expectSingle(m, vec(0, 1), vec(0, -0.5), 2);
}

TEST(Capsules, CrossingSeparatedAlongTheNormalOfB) {
  // A (-0.5,0)-(3,0) r 0.25, B (0,-3)-(0,3) r 0.25, crossing at the origin near A's left end.
  //  +/-y: B's far end (0,-/+3.25) past A's side (0,+/-0.25): 3.5 either way.
  //  -x: B's right side (0.25,0) to A's left end surface (-0.75,0): 1.
  //  +x: B's left side (-0.25,0) to A's right end surface (3.25,0): 3.5.
  // Minimum: n = (-1,0), depth 1, point midway between (-0.75,0) and (0.25,0): (-0.25, 0).
  const Manifold m = collideCapsules(vec(-0.5, 0), vec(3, 0), real(0.25), vec(0, -3), vec(0, 3),
                                     real(0.25), real(0.1));
  expectSingle(m, vec(-1, 0), vec(-0.25, 0), 1);
}

TEST(Capsules, CrossingRotated) {
  // CrossingSeparatedAlongTheNormalOfA turned by the 3-4-5 rotation R and shifted by (1,2):
  // a0 = R(-2,0) + (1,2) = (-0.6, 0.8), a1 = R(2,0) + (1,2) = (2.6, 3.2),
  // b0 = R(0,-1) + (1,2) = (1.6, 1.2), b1 = R(0,3) + (1,2) = (-0.8, 4.4).
  // Expected n = R(0,1) = (-0.6, 0.8), depth 2, point R(0,-0.5) + (1,2) = (1.3, 1.6).
  const Manifold m = collideCapsules(vec(-0.6, 0.8), vec(2.6, 3.2), real(0.5), vec(1.6, 1.2),
                                     vec(-0.8, 4.4), real(0.5), real(0.1));
  expectSingle(m, vec(-0.6, 0.8), vec(1.3, 1.6), 2);
  // The same expectations through R itself.
  expectSingle(m, rot(vec(0, 1)), rot(vec(0, -0.5)) + vec(1, 2), 2);
}

TEST(Capsules, ParallelOverlappingGivesTwoPoints) {
  // A (0,0)-(4,0) r 0.5, B (1,0.9)-(6,0.9) r 0.5: projections overlap on x in [1, 4], gap
  // 0.9 - 1 = -0.1. Face normal (0,1); points midway between (x, 0.5) and (x, 0.4), i.e.
  // (1, 0.45) feature 0 and (4, 0.45) feature 1, each 0.1 deep.
  const Manifold m = collideCapsules(vec(0, 0), vec(4, 0), real(0.5), vec(1, 0.9), vec(6, 0.9),
                                     real(0.5), real(0.1));
  ASSERT_EQ(m.count, 2);
  EXPECT_TRUE(vectorNear(m.normal, vec(0, 1)));
  expectPoint(m.points[0], vec(1, 0.45), 0.1, 0);
  expectPoint(m.points[1], vec(4, 0.45), 0.1, 1);
}

TEST(Capsules, ParallelOverlappingWithBReversed) {
  // The same with B's ends swapped: the points still follow A's axis, same as above.
  const Manifold m = collideCapsules(vec(0, 0), vec(4, 0), real(0.5), vec(6, 0.9), vec(1, 0.9),
                                     real(0.5), real(0.1));
  ASSERT_EQ(m.count, 2);
  EXPECT_TRUE(vectorNear(m.normal, vec(0, 1)));
  expectPoint(m.points[0], vec(1, 0.45), 0.1, 0);
  expectPoint(m.points[1], vec(4, 0.45), 0.1, 1);
}

TEST(Capsules, ParallelWithBBelow) {
  // B (-1,-0.8)-(2,-0.8) r 0.5 under A (0,0)-(4,0) r 0.5: overlap x in [0, 2], depth 0.2,
  // face normal (0,-1); points midway between (x,-0.5) and (x,-0.3): (0,-0.4) and (2,-0.4).
  const Manifold m = collideCapsules(vec(0, 0), vec(4, 0), real(0.5), vec(-1, -0.8), vec(2, -0.8),
                                     real(0.5), real(0.1));
  ASSERT_EQ(m.count, 2);
  EXPECT_TRUE(vectorNear(m.normal, vec(0, -1)));
  expectPoint(m.points[0], vec(0, -0.4), 0.2, 0);
  expectPoint(m.points[1], vec(2, -0.4), 0.2, 1);
}

TEST(Capsules, ParallelRotated) {
  // ParallelOverlappingGivesTwoPoints turned by R: a1 = R(4,0) = (3.2, 2.4),
  // b0 = R(1,0.9) = (0.8 - 0.54, 0.6 + 0.72) = (0.26, 1.32), b1 = R(6,0.9) = (4.26, 4.32).
  // n = R(0,1) = (-0.6, 0.8); points R(1,0.45) = (0.53, 0.96) and R(4,0.45) = (2.93, 2.76).
  const Manifold m = collideCapsules(vec(0, 0), vec(3.2, 2.4), real(0.5), vec(0.26, 1.32),
                                     vec(4.26, 4.32), real(0.5), real(0.1));
  ASSERT_EQ(m.count, 2);
  EXPECT_TRUE(vectorNear(m.normal, vec(-0.6, 0.8)));
  expectPoint(m.points[0], vec(0.53, 0.96), 0.1, 0);
  expectPoint(m.points[1], vec(2.93, 2.76), 0.1, 1);
}

TEST(Capsules, NearlyParallelGivesTwoPointsOfDifferentDepths) {
  // B (1,0.9)-(6,0.95): slope 0.01, sine well under the parallel threshold. On A's face normal
  // (0,1): at x = 1 B's axis is at 0.9 (depth 0.1, point midway between 0.5 and 0.4: 0.45); at
  // x = 4 it is at 0.9 + 3/5 * 0.05 = 0.93 (depth 0.07, point (0.5 + 0.43) / 2 = 0.465).
  const Manifold m = collideCapsules(vec(0, 0), vec(4, 0), real(0.5), vec(1, 0.9), vec(6, 0.95),
                                     real(0.5), real(0.1));
  ASSERT_EQ(m.count, 2);
  EXPECT_TRUE(vectorNear(m.normal, vec(0, 1)));
  expectPoint(m.points[0], vec(1, 0.45), 0.1, 0);
  expectPoint(m.points[1], vec(4, 0.465), 0.07, 1);
}

TEST(Capsules, NearlyParallelWithOneEndWithinTheMargin) {
  // B (1,1.05)-(6,1.1), margin 0.06: at x = 1 the gap is 0.05 (reported, depth -0.05, point
  // midway between 0.5 and 0.55: 0.525); at x = 4 B is at 1.08, gap 0.08 >= 0.06 (dropped).
  const Manifold m = collideCapsules(vec(0, 0), vec(4, 0), real(0.5), vec(1, 1.05), vec(6, 1.1),
                                     real(0.5), real(0.06));
  ASSERT_EQ(m.count, 1);
  EXPECT_TRUE(vectorNear(m.normal, vec(0, 1)));
  expectPoint(m.points[0], vec(1, 0.525), -0.05, 0);
}

TEST(Capsules, ParallelGapInsideTheMarginIsSpeculative) {
  // B (1,1.1)-(6,1.1), margin 0.2: gap 0.1 over x in [1, 4]; points midway between 0.5 and
  // 0.6: (1, 0.55) and (4, 0.55), depth -0.1.
  const Manifold m = collideCapsules(vec(0, 0), vec(4, 0), real(0.5), vec(1, 1.1), vec(6, 1.1),
                                     real(0.5), real(0.2));
  ASSERT_EQ(m.count, 2);
  expectPoint(m.points[0], vec(1, 0.55), -0.1, 0);
  expectPoint(m.points[1], vec(4, 0.55), -0.1, 1);
}

TEST(Capsules, ParallelDeepOverlap) {
  // A (0,0)-(4,0) r 1, B (1,0.5)-(3,0.5) r 1: overlap x in [1, 3], depth 2 - 0.5 = 1.5; points
  // midway between (x, 1) and (x, -0.5): (1, 0.25) and (3, 0.25).
  const Manifold m =
      collideCapsules(vec(0, 0), vec(4, 0), real(1), vec(1, 0.5), vec(3, 0.5), real(1), real(0.1));
  ASSERT_EQ(m.count, 2);
  EXPECT_TRUE(vectorNear(m.normal, vec(0, 1)));
  expectPoint(m.points[0], vec(1, 0.25), 1.5, 0);
  expectPoint(m.points[1], vec(3, 0.25), 1.5, 1);
}

TEST(Capsules, EndToEndCollinearGivesOnePoint) {
  // A (0,0)-(2,0), B (3,0)-(5,0), r 0.5 each: projections do not overlap; ends (2,0) and (3,0)
  // at distance 1: touching, n = (1,0), point (2.5, 0).
  const Manifold touching =
      collideCapsules(vec(0, 0), vec(2, 0), real(0.5), vec(3, 0), vec(5, 0), real(0.5), real(0.1));
  expectSingle(touching, vec(1, 0), vec(2.5, 0), 0);
  // B from (2.8, 0): depth 0.2, surfaces (2.5,0) and (2.3,0): mid (2.4, 0).
  const Manifold overlapping = collideCapsules(vec(0, 0), vec(2, 0), real(0.5), vec(2.8, 0),
                                               vec(5, 0), real(0.5), real(0.1));
  expectSingle(overlapping, vec(1, 0), vec(2.4, 0), 0.2);
}

TEST(Capsules, EndToEndOffsetGivesOneObliquePoint) {
  // A (0,0)-(2,0) r 0.6, B (2.6,0.8)-(4.6,0.8) r 0.5, parallel without overlap in projection:
  // closest ends (2,0) and (2.6,0.8), distance 1, n = (0.6,0.8), depth 1.1 - 1 = 0.1.
  // Surface A = (2,0) + 0.6 n = (2.36, 0.48); surface B = (2.6,0.8) - 0.5 n = (2.3, 0.4):
  // mid (2.33, 0.44).
  const Manifold m = collideCapsules(vec(0, 0), vec(2, 0), real(0.6), vec(2.6, 0.8), vec(4.6, 0.8),
                                     real(0.5), real(0.1));
  expectSingle(m, vec(0.6, 0.8), vec(2.33, 0.44), 0.1);
}

TEST(Capsules, EndToEndObliqueNonParallel) {
  // Same ends but B vertical (2.6,0.8)-(2.6,2.8): the closest points are still the ends,
  // so the same contact.
  const Manifold m = collideCapsules(vec(0, 0), vec(2, 0), real(0.6), vec(2.6, 0.8), vec(2.6, 2.8),
                                     real(0.5), real(0.1));
  expectSingle(m, vec(0.6, 0.8), vec(2.33, 0.44), 0.1);
}

TEST(Capsules, GapInsideTheMarginIsSpeculative) {
  // T with the stem end at (2, 1.3), margin 0.5: gap 0.3, depth -0.3; surfaces (2,0.5) and
  // (2,0.8): mid (2, 0.65).
  const Manifold m = collideCapsules(vec(0, 0), vec(4, 0), real(0.5), vec(2, 1.3), vec(2, 3),
                                     real(0.5), real(0.5));
  expectSingle(m, vec(0, 1), vec(2, 0.65), -0.3);
}

TEST(Capsules, BeyondTheMarginGivesNothing) {
  // T with the stem end at (2, 2): gap 1 > margin 0.5. Parallel at distance 2: gap 1 > 0.5.
  EXPECT_EQ(
      collideCapsules(vec(0, 0), vec(4, 0), real(0.5), vec(2, 2), vec(2, 4), real(0.5), real(0.5))
          .count,
      0);
  EXPECT_EQ(
      collideCapsules(vec(0, 0), vec(4, 0), real(0.5), vec(0, 2), vec(4, 2), real(0.5), real(0.5))
          .count,
      0);
}

// --- swapping A and B ---------------------------------------------------------------------

/// Expects @p swapped (B, A) to be @p m (A, B) with the normal flipped and the same points
/// (compared as a set) and depths.
void expectSwapped(const Manifold& m, const Manifold& swapped, real tolerance) {
  ASSERT_EQ(swapped.count, m.count);
  if (m.count == 0) return;
  EXPECT_TRUE(vectorNear(swapped.normal, -m.normal, tolerance));
  for (int i = 0; i < m.count; ++i) {
    bool found = false;
    for (int j = 0; j < swapped.count; ++j) {
      const ManifoldPoint& p = m.points[i];
      const ManifoldPoint& q = swapped.points[j];
      found = found || (std::abs(p.point.x - q.point.x) <= tolerance &&
                        std::abs(p.point.y - q.point.y) <= tolerance &&
                        std::abs(p.depth - q.depth) <= tolerance);
    }
    EXPECT_TRUE(found) << "point " << i << " (" << m.points[i].point.x << ", "
                       << m.points[i].point.y << ") depth " << m.points[i].depth
                       << " has no match after swapping";
  }
}

TEST(Symmetry, SwappingCirclesFlipsTheNormal) {
  // Hand cases: oblique overlap and speculative gap.
  expectSwapped(collideCircles(vec(1, 1), real(1), vec(2.2, 2.6), real(1.5), real(0.1)),
                collideCircles(vec(2.2, 2.6), real(1.5), vec(1, 1), real(1), real(0.1)),
                test::tight);
  expectSwapped(collideCircles(vec(0, 0), real(1), vec(0, 2.25), real(1), real(0.5)),
                collideCircles(vec(0, 2.25), real(1), vec(0, 0), real(1), real(0.5)), test::tight);

  MTRandom random(20240611u);
  int contacts = 0;
  for (int trial = 0; trial < 1000; ++trial) {
    const Vector2 ca{real(random.uniform(-2, 2)), real(random.uniform(-2, 2))};
    const Vector2 cb{real(random.uniform(-2, 2)), real(random.uniform(-2, 2))};
    const auto ra = real(random.uniform(0.1, 1.5));
    const auto rb = real(random.uniform(0.1, 1.5));
    const Manifold m = collideCircles(ca, ra, cb, rb, real(0.2));
    const Manifold s = collideCircles(cb, rb, ca, ra, real(0.2));
    SCOPED_TRACE(trial);
    expectSwapped(m, s, test::tight);
    contacts += m.count;
  }
  EXPECT_GT(contacts, 100);  // the random cases do exercise contacts
}

TEST(Symmetry, SwappingCapsulesFlipsTheNormal) {
  // Hand cases: T, crossing, parallel, end to end.
  const struct {
    Vector2 a0, a1;
    real ra;
    Vector2 b0, b1;
    real rb;
  } cases[] = {
      {vec(0, 0), vec(4, 0), real(0.5), vec(2, 0.8), vec(2, 3), real(0.5)},
      {vec(-2, 0), vec(2, 0), real(0.5), vec(0, -1), vec(0, 3), real(0.5)},
      {vec(-0.5, 0), vec(3, 0), real(0.25), vec(0, -3), vec(0, 3), real(0.25)},
      {vec(0, 0), vec(4, 0), real(0.5), vec(1, 0.9), vec(6, 0.9), real(0.5)},
      {vec(0, 0), vec(3.2, 2.4), real(0.5), vec(0.26, 1.32), vec(4.26, 4.32), real(0.5)},
      {vec(0, 0), vec(2, 0), real(0.6), vec(2.6, 0.8), vec(4.6, 0.8), real(0.5)},
  };
  for (const auto& c : cases) {
    expectSwapped(collideCapsules(c.a0, c.a1, c.ra, c.b0, c.b1, c.rb, real(0.1)),
                  collideCapsules(c.b0, c.b1, c.rb, c.a0, c.a1, c.ra, real(0.1)), test::tight);
  }

  // Random capsules: generic ones (avoiding the nearly parallel band, where the face normal is
  // A's by design and so changes slightly with the order) and exactly parallel ones.
  MTRandom random(777u);
  int single = 0;     // one point, axes apart
  int crossing = 0;   // one point, axes crossing (depth at least ra + rb)
  int twoPoints = 0;  // parallel
  for (int trial = 0; trial < 2000; ++trial) {
    const Vector2 a0{real(random.uniform(-2, 2)), real(random.uniform(-2, 2))};
    const Vector2 a1{real(random.uniform(-2, 2)), real(random.uniform(-2, 2))};
    Vector2 b0{real(random.uniform(-2, 2)), real(random.uniform(-2, 2))};
    Vector2 b1{real(random.uniform(-2, 2)), real(random.uniform(-2, 2))};
    if (trial % 4 == 0) {  // B parallel to A, shifted along and across the axis
      b1 = b0 + (a1 - a0) * real(random.uniform(-1.5, 1.5));
    } else {
      const real sine = std::abs(cross((a1 - a0).normalized(), (b1 - b0).normalized()));
      if (sine < real(0.05)) continue;
    }
    if ((a1 - a0).length() < real(0.1) || (b1 - b0).length() < real(0.1)) continue;
    const auto ra = real(random.uniform(0.1, 0.8));
    const auto rb = real(random.uniform(0.1, 0.8));
    const Manifold m = collideCapsules(a0, a1, ra, b0, b1, rb, real(0.2));
    const Manifold s = collideCapsules(b0, b1, rb, a0, a1, ra, real(0.2));
    SCOPED_TRACE(trial);
    expectSwapped(m, s, test::tight);
    if (m.count == 2) ++twoPoints;
    if (m.count == 1) ++(m.points[0].depth >= ra + rb ? crossing : single);
  }
  // The random cases exercise every branch.
  EXPECT_GT(single, 50);
  EXPECT_GT(crossing, 50);
  EXPECT_GT(twoPoints, 20);
}

}  // namespace
}  // namespace thyrix
