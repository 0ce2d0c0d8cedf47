// Closed-form quasistatic dynamics, F = m v: bodies alone, against borders, in rows, on capsules.

#include "TestTolerances.h"

#include <ThyrixLite/Border.h>
#include <ThyrixLite/CappedRectangle.h>
#include <ThyrixLite/Circle.h>
#include <ThyrixLite/Simulator.h>

#include <gtest/gtest.h>

#include <cmath>

namespace thyrix {
namespace {

using test::loose;
using test::tight;

class QuasistaticTest : public ::testing::TestWithParam<ContactSolverKind> {
 protected:
  QuasistaticTest() { simulator.setContactSolver(GetParam()); }
  Simulator simulator{real(0.01)};
};

TEST_P(QuasistaticTest, VelocityIsForceOverMassAndStopsWithTheForce) {
  auto& circle = simulator.registerObject(std::make_unique<Circle>(real(0.5), real(2)));
  circle.r = {1, 1};
  circle.externalForce = {3, -4};
  simulator.advanceTime();
  EXPECT_NEAR(circle.v.x, real(1.5), tight);
  EXPECT_NEAR(circle.v.y, real(-2), tight);
  EXPECT_NEAR(circle.r.x, real(1.015), tight);
  EXPECT_NEAR(circle.r.y, real(0.98), tight);
  EXPECT_EQ(circle.externalForce, Vector2{});  // reset after use
  simulator.advanceTime();
  EXPECT_EQ(circle.v, Vector2{});
  EXPECT_NEAR(circle.r.x, real(1.015), tight);
}

TEST_P(QuasistaticTest, TorqueTurnsAndStops) {
  // Capsule I from its shape: a torque tau turns it at tau / I, then it stops.
  auto& capsule =
      simulator.registerObject(std::make_unique<CappedRectangle>(real(1), real(0.25), real(3)));
  capsule.externalTorque = 2;
  simulator.advanceTime();
  EXPECT_NEAR(capsule.omega, 2 / capsule.I, tight);
  EXPECT_NEAR(capsule.alpha, real(0.01) * 2 / capsule.I, tight);
  EXPECT_EQ(capsule.v, Vector2{});
  simulator.advanceTime();
  EXPECT_EQ(capsule.omega, 0);
}

TEST_P(QuasistaticTest, BorderStopsNormalMotionButNotTangential) {
  simulator.registerObject(std::make_unique<Border>(Vector2{0, 0}, Vector2{0, 1}));
  auto& circle = simulator.registerObject(std::make_unique<Circle>(real(0.5), real(1)));
  circle.r = {0, real(0.5)};  // touching the floor
  for (int step = 0; step < 100; ++step) {
    circle.externalForce = {2, -5};  // pushed along and into the floor
    simulator.advanceTime();
    EXPECT_NEAR(circle.v.x, 2, loose) << "frictionless: the tangential motion is kept";
    EXPECT_NEAR(circle.v.y, 0, loose);
    EXPECT_GE(circle.r.y, real(0.5) - loose);
  }
  EXPECT_NEAR(circle.r.x, 2, 100 * loose);
}

TEST_P(QuasistaticTest, PushedRowMovesAtTotalForceOverTotalMass) {
  // Three touching circles in a row; only the first is pushed: all move at F / (m1 + m2 + m3).
  const real masses[3] = {1, 2, 3};
  PhysicalObject* circles[3];
  for (int i = 0; i < 3; ++i) {
    circles[i] = &simulator.registerObject(std::make_unique<Circle>(real(0.5), masses[i]));
    circles[i]->r = {static_cast<real>(i), 0};
  }
  for (int step = 0; step < 50; ++step) {
    circles[0]->externalForce = {12, 0};
    simulator.advanceTime();
    for (PhysicalObject* c : circles) {
      EXPECT_NEAR(c->v.x, 2, loose);
      EXPECT_NEAR(c->v.y, 0, loose);
    }
  }
}

TEST_P(QuasistaticTest, CircleRestsOnCapsuleSideAndSlidesOffItsCap) {
  // A fixed horizontal capsule; a circle pressed down onto its flat side stays on it, pressed
  // down beyond the cap's centre it slides off around the cap.
  auto& capsule =
      simulator.registerObject(std::make_unique<CappedRectangle>(real(1), real(0.25), real(1)));
  capsule.fixed = true;
  auto& circle = simulator.registerObject(std::make_unique<Circle>(real(0.25), real(1)));
  circle.r = {real(0.3), real(0.5)};
  for (int step = 0; step < 100; ++step) {
    circle.externalForce = {0, -1};
    simulator.advanceTime();
  }
  EXPECT_NEAR(circle.r.x, real(0.3), loose);
  EXPECT_NEAR(circle.r.y, real(0.5), 10 * loose);
  EXPECT_NEAR(circle.v.y, 0, loose);

  circle.r = {real(1.1), real(0.5)};  // beyond the cap centre at x = 1
  for (int step = 0; step < 400; ++step) {
    circle.externalForce = {0, -1};
    simulator.advanceTime();
    EXPECT_GE(distance(circle.r, Vector2{1, 0}), real(0.5) - real(1e-3)) << "never into the cap";
  }
  EXPECT_GT(circle.r.x, real(1.4)) << "slid off around the cap";
  EXPECT_LT(circle.r.y, 0);
}

TEST_P(QuasistaticTest, PushingCapsuleEndTurnsIt) {
  auto& capsule =
      simulator.registerObject(std::make_unique<CappedRectangle>(real(1), real(0.25), real(2)));
  // A force F along +y at the +x end: v = F / m, omega = l F / I.
  capsule.applyForce({0, 1}, {1, 0});
  simulator.advanceTime();
  EXPECT_NEAR(capsule.v.y, real(0.5), tight);
  EXPECT_NEAR(capsule.omega, 1 / capsule.I, tight);
  EXPECT_GT(capsule.alpha, 0);
}

INSTANTIATE_TEST_SUITE_P(BothSolvers, QuasistaticTest,
                         ::testing::Values(ContactSolverKind::Baraff,
                                           ContactSolverKind::GaussSeidel),
                         [](const auto& solver) {
                           return solver.param == ContactSolverKind::Baraff ? "Baraff"
                                                                            : "GaussSeidel";
                         });

}  // namespace
}  // namespace thyrix
