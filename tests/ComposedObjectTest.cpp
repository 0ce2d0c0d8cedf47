// Composed bodies: mass properties against hand computation, and motion as one rigid body.

#include "TestTolerances.h"

#include <ThyrixLite/Border.h>
#include <ThyrixLite/CappedRectangle.h>
#include <ThyrixLite/Circle.h>
#include <ThyrixLite/ComposedPhysicalObject.h>
#include <ThyrixLite/InvalidArgument.h>
#include <ThyrixLite/Simulator.h>
#include <Tools/MathTools.h>

#include <gtest/gtest.h>

#include <limits>

namespace thyrix {
namespace {

using test::loose;
using test::tight;

TEST(ComposedPhysicalObject, MassCentreAndInertiaFromTheParts) {
  // A dumbbell: circles of mass 1 (R 0.5) at x = 0 and mass 3 (R 0.25) at x = 2, and a capsule
  // l 1, R 0.1, mass 2 at (1, 0) across them.
  ComposedPhysicalObject body;
  body.add(std::make_unique<Circle>(real(0.5), real(1)), {0, 0});
  body.add(std::make_unique<Circle>(real(0.25), real(3)), {2, 0});
  body.add(std::make_unique<CappedRectangle>(real(1), real(0.1), real(2)), {1, 0});
  EXPECT_NEAR(body.m, 6, tight);
  // Centre: (1*0 + 3*2 + 2*1) / 6 = 4/3, and r moved there.
  EXPECT_NEAR(body.r.x, real(4) / 3, tight);
  EXPECT_NEAR(body.r.y, 0, tight);
  // I = sum I_own + m d^2: 1*0.5^2/2 + 1*(4/3)^2 + 3*0.25^2/2 + 3*(2/3)^2 + I_caps + 2*(1/3)^2.
  const real capsule = CappedRectangle::momentOfInertia(1, real(0.1), 2);
  const real expected =
      real(0.125) + real(16) / 9 + real(0.09375) + real(4) / 3 + capsule + real(2) / 9;
  EXPECT_NEAR(body.I, expected, tight);
}

TEST(ComposedPhysicalObject, OneCapsuleBodyGetsTheStandaloneCapsulesBoxesBitForBit) {
  // A capsule on its own and the same capsule as the one part of a composed body go through
  // the same computation (Simulator::updateCapsule): the same poses give the same body boxes,
  // to the bit, as they move, turn and rest.
  Simulator simulator;
  auto& alone =
      simulator.registerObject(std::make_unique<CappedRectangle>(real(0.7), real(0.2), real(1)));
  auto composed = std::make_unique<ComposedPhysicalObject>();
  composed->add(std::make_unique<CappedRectangle>(real(0.7), real(0.2), real(1)), {0, 0});
  auto& body = simulator.registerObject(std::move(composed));
  alone.collisionGroup = body.collisionGroup = 1;  // they overlap: never touching
  const Vector2 start = body.r;
  for (int step = 0; step < 12; ++step) {
    // Moved by hand, turned every third step, at rest every fourth.
    if (step % 4 != 3) {
      body.r = start + Vector2{real(0.37) * real(step), real(-0.11) * real(step)};
      if (step % 3 == 0) body.alpha = real(0.3) * real(step) + real(0.1);
    }
    alone.r = body.r;
    alone.alpha = body.alpha;
    simulator.advanceTime();
    EXPECT_EQ(alone.boxMin.x, body.boxMin.x) << step;
    EXPECT_EQ(alone.boxMin.y, body.boxMin.y) << step;
    EXPECT_EQ(alone.boxMax.x, body.boxMax.x) << step;
    EXPECT_EQ(alone.boxMax.y, body.boxMax.y) << step;
    EXPECT_GT(alone.boxMax.x - alone.boxMin.x, real(0.4)) << step;  // a real box
  }
}

TEST(ComposedPhysicalObject, PartsFollowTheBodyAndKeepTheirWorldPlaceWhenAdded) {
  ComposedPhysicalObject body;
  auto& first = body.add(std::make_unique<Circle>(real(0.5), real(1)), {0, 0});
  body.add(std::make_unique<Circle>(real(0.5), real(1)), {2, 0});
  EXPECT_NEAR(first.r.x, 0, tight) << "the first part did not move when the second was added";
  body.r = {5, 5};
  body.alpha = pi<real> / 2;
  first.followOwner();
  // The first part sits 1 behind the centre along the body's x axis, now world +y.
  EXPECT_NEAR(first.r.x, 5, tight);
  EXPECT_NEAR(first.r.y, 4, tight);
  EXPECT_NEAR(first.alpha, pi<real> / 2, tight);
}

TEST(ComposedPhysicalObject, MovesAsOneBodyUnderContact) {
  // An L-shaped body pushed against a wall by a force at its centre: the contact on one part
  // stops the whole body, and an off-centre contact turns it.
  Simulator simulator;
  simulator.registerObject(std::make_unique<Border>(Vector2{3, 0}, Vector2{-1, 0}));
  auto composed = std::make_unique<ComposedPhysicalObject>();
  auto& tip = composed->add(std::make_unique<Circle>(real(0.25), real(1)), {1, 1});
  composed->add(std::make_unique<CappedRectangle>(real(0.5), real(0.25), real(1)), {0, 0});
  auto& body = simulator.registerObject(std::move(composed));
  for (int step = 0; step < 800; ++step) {  // 0.5 m/s: the tip reaches the wall after 350
    body.externalForce = {1, 0};
    simulator.advanceTime();
  }
  // The circle part reached the wall and stays out of it; the body turned about the contact.
  EXPECT_LE(tip.r.x + real(0.25), 3 + loose);
  EXPECT_GT(tip.r.x + real(0.25), real(2.99));
  EXPECT_NE(body.alpha, 0);
  // Contacts of the part are the body's contacts, with the part named.
  ASSERT_FALSE(body.contacts().empty());
  for (const ContactInfo& info : body.contacts()) EXPECT_TRUE(info.primitive != nullptr);
  EXPECT_TRUE(tip.contacts().empty()) << "contacts belong to the body, not the part";
}

TEST(ComposedPhysicalObject, BadPartsAreRefusedAndTheBodyUnchanged) {
  ComposedPhysicalObject body;
  body.add(std::make_unique<Circle>(real(0.5), real(1)), {0, 0});
  const auto expectField = [&](auto&& call, const char* field) {
    try {
      call();
      ADD_FAILURE() << "no exception for " << field;
    } catch (const InvalidArgument& error) {
      EXPECT_EQ(error.field(), field);
    }
    EXPECT_EQ(body.partCount(), 1u);
    EXPECT_NEAR(body.m, 1, tight);
  };
  expectField([&] { body.add(std::unique_ptr<Circle>(), {0, 0}); }, "ComposedPhysicalObject.part");
  expectField(
      [&] {
        body.add(std::make_unique<Border>(Vector2{0, 0}, Vector2{0, 1}), {0, 0});
      },
      "ComposedPhysicalObject.part");
  expectField(
      [&] {
        body.add(std::make_unique<Circle>(real(1), real(1)),
                 {std::numeric_limits<real>::quiet_NaN(), 0});
      },
      "ComposedPhysicalObject.relativePosition");
  expectField(
      [&] {
        body.add(std::make_unique<Circle>(real(1), real(1)), {0, 0}, real(INFINITY));
      },
      "ComposedPhysicalObject.relativeAngle");

  Simulator simulator;
  try {
    simulator.registerObject(std::make_unique<ComposedPhysicalObject>());
    ADD_FAILURE() << "an empty composed body was registered";
  } catch (const InvalidArgument& error) {
    EXPECT_EQ(error.field(), "ComposedPhysicalObject.parts");
  }
  EXPECT_EQ(simulator.objects.size(), 0u);
}

}  // namespace
}  // namespace thyrix
