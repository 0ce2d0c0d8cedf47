// Picking the object under the mouse: the point-to-shape distance against circles and capsules
// worked out by hand, the top (last drawn) object winning, the tolerance for near misses.

#include <GUIWx/Picking.h>

#include <gtest/gtest.h>

#include <vector>

namespace thyrix {
namespace {

PickShape circle(Vector2 c, real r, std::uint32_t object) {
  return {ShapeType::Circle, c, c, r, object};
}

PickShape capsule(Vector2 a, Vector2 b, real r, std::uint32_t object) {
  return {ShapeType::Capsule, a, b, r, object};
}

TEST(Picking, DistanceToCircleAndCapsule) {
  EXPECT_NEAR(distanceToShape(circle({1, 1}, 0.5, 0), {1, 3}), 1.5, 1e-12);
  EXPECT_NEAR(distanceToShape(circle({1, 1}, 0.5, 0), {1, 1.25}), -0.25, 1e-12);
  // Capsule from (0, 0) to (2, 0), radius 0.5: beside the segment, then beyond an end.
  const PickShape c = capsule({0, 0}, {2, 0}, 0.5, 0);
  EXPECT_NEAR(distanceToShape(c, {1, 2}), 1.5, 1e-12);
  EXPECT_NEAR(distanceToShape(c, {1.5, -0.25}), -0.25, 1e-12);
  EXPECT_NEAR(distanceToShape(c, {5, 4}), 5 - 0.5, 1e-12);  // 3-4-5 from the end (2, 0)
}

TEST(Picking, ReturnsTheTopObjectUnderThePoint) {
  const std::vector<PickShape> shapes{circle({0, 0}, 1, 3), circle({0.5, 0}, 1, 7),
                                      capsule({5, 5}, {7, 5}, 0.2, 9)};
  EXPECT_EQ(pickObject(shapes, {0.25, 0}), 7u);   // inside both: the later one is on top
  EXPECT_EQ(pickObject(shapes, {-0.75, 0}), 3u);  // inside the first only
  EXPECT_EQ(pickObject(shapes, {6, 5.1}), 9u);
  EXPECT_FALSE(pickObject(shapes, {3, 3}).has_value());
  EXPECT_FALSE(pickObject({}, {0, 0}).has_value());
}

TEST(Picking, NearMissesWithinTheTolerance) {
  const std::vector<PickShape> shapes{circle({0, 0}, 1, 1), circle({3, 0}, 1, 2)};
  EXPECT_FALSE(pickObject(shapes, {1.1, 0}).has_value());
  EXPECT_EQ(pickObject(shapes, {1.1, 0}, 0.2), 1u);
  EXPECT_EQ(pickObject(shapes, {1.85, 0}, 0.2), 2u);  // nearer the second outline
}

}  // namespace
}  // namespace thyrix
