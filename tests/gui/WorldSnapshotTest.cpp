// A snapshot copies what the view needs from a simulator: the movable circles and capsules
// where the objects are (fixed bodies and borders cannot be grabbed), the step, the contacts,
// the solver, and a box to fit that takes in the objects and the borders' anchor points.

#include <GUIWx/WorldSnapshot.h>

#include <ThyrixLite/Border.h>
#include <ThyrixLite/CappedRectangle.h>
#include <ThyrixLite/Circle.h>
#include <ThyrixLite/Simulator.h>

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

namespace thyrix {
namespace {

TEST(WorldSnapshot, CapturesShapesCountersAndBounds) {
  Simulator simulator;
  simulator.setContactSolver(ContactSolverKind::GaussSeidel);
  simulator.registerObject(std::make_unique<Border>(Vector2{0, 0}, Vector2{0, 1}));
  simulator.registerObject(std::make_unique<Border>(Vector2{10, 0}, Vector2{-1, 0}));
  auto& ball = simulator.registerObject(std::make_unique<Circle>(real(0.5), real(1)));
  ball.r = {3, 4};
  auto& post = simulator.registerObject(std::make_unique<Circle>(real(0.2), real(1)));
  post.r = {6, 6};
  post.fixed = true;
  auto& rod = simulator.registerObject(std::make_unique<CappedRectangle>(real(1), real(0.25), 1));
  rod.r = {5, 2};
  rod.alpha = real(std::acos(-1.0) / 2);  // vertical: ends at (5, 1) and (5, 3)
  simulator.advanceTime();

  WorldSnapshot snapshot;
  snapshot.capture(simulator, {});
  ASSERT_EQ(snapshot.shapes.size(), 2u);  // the ball and the rod; not the fixed post
  EXPECT_EQ(snapshot.shapes[0].object, 2u);
  EXPECT_EQ(snapshot.shapes[0].type, ShapeType::Circle);
  EXPECT_EQ(snapshot.shapes[0].a, ball.r);
  EXPECT_EQ(snapshot.shapes[0].radius, real(0.5));
  EXPECT_EQ(snapshot.shapes[1].object, 4u);
  EXPECT_EQ(snapshot.shapes[1].type, ShapeType::Capsule);
  EXPECT_NEAR(snapshot.shapes[1].a.x, 5, 1e-5);
  EXPECT_NEAR(snapshot.shapes[1].a.y, 1, 1e-5);
  EXPECT_NEAR(snapshot.shapes[1].b.y, 3, 1e-5);
  EXPECT_EQ(snapshot.step, 1u);
  EXPECT_EQ(snapshot.contacts, simulator.contacts.size());
  EXPECT_EQ(snapshot.solver, ContactSolverKind::GaussSeidel);
  EXPECT_FALSE(snapshot.drawing.commands().empty());
  // The box holds every object and both border anchors, (0, 0) and (10, 0).
  EXPECT_LT(snapshot.bounds.lower.x, 0);
  EXPECT_LT(snapshot.bounds.lower.y, 0);
  EXPECT_GT(snapshot.bounds.upper.x, 10);
  EXPECT_GT(snapshot.bounds.upper.y, 6.2);

  // A second capture reuses the snapshot and replaces everything.
  ball.r = {1, 1};
  snapshot.capture(simulator, {});
  EXPECT_EQ(snapshot.shapes.size(), 2u);
  EXPECT_EQ(snapshot.shapes[0].a, (Vector2{1, 1}));
}

}  // namespace
}  // namespace thyrix
