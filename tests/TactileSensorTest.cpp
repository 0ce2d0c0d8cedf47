// Tactile sensors: sector numbering, activation from contact forces, saturation, rotation.

#include "TestTolerances.h"

#include <ThyrixLite/Border.h>
#include <ThyrixLite/CappedRectangle.h>
#include <ThyrixLite/Circle.h>
#include <ThyrixLite/InvalidArgument.h>
#include <ThyrixLite/Simulator.h>
#include <ThyrixLite/TactileSensors.h>
#include <Tools/MathTools.h>

#include <gtest/gtest.h>

#include <array>

namespace thyrix {
namespace {

using test::loose;

/// A circle resting on a floor, pushed down with @p force: the floor touches it at body-frame
/// angle -90 degrees - alpha.
struct CircleOnFloor {
  CircleOnFloor(int sensors, real startAngle, real saturation, real alpha) {
    simulator.registerObject(std::make_unique<Border>(Vector2{0, 0}, Vector2{0, 1}));
    circle = &simulator.registerObject(std::make_unique<Circle>(real(0.5), real(1)));
    circle->setTactileSensors(sensors, startAngle, saturation);
    circle->r = {0, real(0.5)};
    circle->alpha = alpha;
  }
  void press(real force) {
    circle->externalForce = {0, -force};
    simulator.advanceTime();
  }
  Simulator simulator;
  Circle* circle = nullptr;
};

TEST(TactileSensors, ContactLightsExactlyTheSectorUnderIt) {
  // 8 sectors from 0: the floor at -90 degrees = 270 degrees is in sector 6 ([270, 315)).
  CircleOnFloor scene(8, 0, 10, 0);
  scene.press(3);
  const auto a = scene.circle->tactileActivations();
  ASSERT_EQ(a.size(), 8u);
  for (int k = 0; k < 8; ++k) EXPECT_NEAR(a[k], k == 6 ? real(0.3) : real(0), loose) << k;
}

TEST(TactileSensors, SensorsGivenToABodyAlreadyAtRestFeelFromTheNextStep) {
  // The simulator notes sensing primitives as it reads their poses, from a flag the sensors'
  // setter keeps: a circle resting for a while, then given sensors, feels the floor at once.
  Simulator simulator;
  simulator.registerObject(std::make_unique<Border>(Vector2{0, 0}, Vector2{0, 1}));
  auto& circle = simulator.registerObject(std::make_unique<Circle>(real(0.5), real(1)));
  circle.r = {0, real(0.5)};
  for (int step = 0; step < 5; ++step) {
    circle.externalForce = {0, -3};
    simulator.advanceTime();
  }
  EXPECT_TRUE(circle.tactileActivations().empty());
  circle.setTactileSensors(8, 0, 10);
  circle.externalForce = {0, -3};
  simulator.advanceTime();
  const auto a = circle.tactileActivations();
  ASSERT_EQ(a.size(), 8u);
  EXPECT_NEAR(a[6], real(0.3), loose);
}

TEST(TactileSensors, ActivationSaturatesAtOne) {
  CircleOnFloor scene(4, 0, 2, 0);
  scene.press(5);                                       // force 5 > saturation 2
  EXPECT_EQ(scene.circle->tactileActivations()[3], 1);  // [270, 360)
}

TEST(TactileSensors, SectorsTurnWithTheBody) {
  // Rotated by +100 degrees, the floor (world -90) is at body angle -190 = 170 degrees:
  // sector 3 of 8 ([135, 180)), well inside it.
  CircleOnFloor scene(8, 0, 10, 100 * pi<real> / 180);
  scene.press(3);
  EXPECT_NEAR(scene.circle->tactileActivations()[3], real(0.3), loose);
  EXPECT_NEAR(scene.circle->tactileActivations()[6], 0, loose);
}

TEST(TactileSensors, StartAngleShiftsTheNumbering) {
  // Start at 250 degrees: the floor at 270 is 20 degrees into sector 0.
  CircleOnFloor scene(8, 250 * pi<real> / 180, 10, 0);
  scene.press(3);
  EXPECT_NEAR(scene.circle->tactileActivations()[0], real(0.3), loose);
}

TEST(TactileSensors, ZeroWithoutContactAndAfterContactEnds) {
  CircleOnFloor scene(8, 0, 10, 0);
  scene.press(3);
  scene.circle->r.y = 2;  // lifted well clear
  scene.press(0);
  for (const real a : scene.circle->tactileActivations()) EXPECT_EQ(a, 0);
}

TEST(TactileSensors, EveryStepStartsFromZeroWhateverTheLastOneFelt) {
  // clear() and finish() skip their loops while nothing was added since the last clear():
  // the activations must read as if they had run.
  TactileSensors sensors = TactileSensors::circle(4, 0, 10);
  const auto expect = [&](std::array<real, 4> wanted) {
    for (std::size_t k = 0; k < 4; ++k) EXPECT_EQ(sensors.activations()[k], wanted[k]) << k;
  };
  sensors.finish();  // a first step that felt nothing
  expect({0, 0, 0, 0});
  sensors.clear();
  sensors.add(1, 5);
  sensors.add(1, 1);
  sensors.add(3, 25);
  sensors.finish();
  expect({0, real(0.6), 0, 1});
  sensors.clear();  // nothing touches the next step
  sensors.finish();
  expect({0, 0, 0, 0});
  sensors.clear();
  sensors.finish();
  expect({0, 0, 0, 0});
  sensors.clear();  // a contact without force
  sensors.add(2, 0);
  sensors.finish();
  expect({0, 0, 0, 0});
  sensors.clear();
  sensors.add(0, 2);
  sensors.finish();
  expect({real(0.2), 0, 0, 0});
}

TEST(TactileSensors, CappedRectangleNumberingIsCounterClockwiseFromLowerLeft) {
  // perSide 2, perCap 2 on l = 1, R = 0.5: lower side 0 (x in [-1, 0)), 1 ([0, 1]); right cap
  // 2 (-90..0), 3 (0..90); upper side 4 (x in (0, 1]), 5 ([-1, 0)); left cap 6 (90..180),
  // 7 (180..270).
  const TactileSensors s = TactileSensors::cappedRectangle(2, 2, 1);
  const real l = 1;
  EXPECT_EQ(s.cappedRectangleSector({real(-0.5), real(-0.5)}, l), 0);
  EXPECT_EQ(s.cappedRectangleSector({real(0.5), real(-0.5)}, l), 1);
  EXPECT_EQ(s.cappedRectangleSector({real(1.3), real(-0.2)}, l), 2);
  EXPECT_EQ(s.cappedRectangleSector({real(1.3), real(0.2)}, l), 3);
  EXPECT_EQ(s.cappedRectangleSector({real(0.5), real(0.5)}, l), 4);
  EXPECT_EQ(s.cappedRectangleSector({real(-0.5), real(0.5)}, l), 5);
  EXPECT_EQ(s.cappedRectangleSector({real(-1.3), real(0.2)}, l), 6);
  EXPECT_EQ(s.cappedRectangleSector({real(-1.3), real(-0.2)}, l), 7);
}

TEST(TactileSensors, CapsuleLyingOnFloorFeelsItsLowerSideAndShareOfWeight) {
  Simulator simulator;
  simulator.registerObject(std::make_unique<Border>(Vector2{0, 0}, Vector2{0, 1}));
  auto& capsule =
      simulator.registerObject(std::make_unique<CappedRectangle>(real(1), real(0.25), real(1)));
  capsule.setTactileSensors(2, 1, 10);
  capsule.r = {0, real(0.25)};
  capsule.externalForce = {0, -4};
  simulator.advanceTime();
  // The two end contacts (x = -1 and x = +1 on the lower side) carry 2 each; the one at x = +1
  // lies on the boundary of sensors 1 and the right cap, the one at -1 on sensor 0.
  const auto a = capsule.tactileActivations();
  ASSERT_EQ(a.size(), 6u);
  EXPECT_NEAR(a[0], real(0.2), loose);
  EXPECT_NEAR(a[1] + a[2], real(0.2), loose);
  EXPECT_NEAR(a[3] + a[4] + a[5], 0, loose);
}

TEST(TactileSensors, BadLayoutsAreRefusedNamingTheField) {
  Circle circle(1, 1);
  const auto expectField = [](auto&& call, const char* field) {
    try {
      call();
      ADD_FAILURE() << "no exception for " << field;
    } catch (const InvalidArgument& error) {
      EXPECT_EQ(error.field(), field);
    }
  };
  expectField([&] { circle.setTactileSensors(0, 0, 1); }, "TactileSensors.count");
  expectField([&] { circle.setTactileSensors(4, real(NAN), 1); }, "TactileSensors.startAngle");
  expectField([&] { circle.setTactileSensors(4, 0, 0); }, "TactileSensors.saturation");
  CappedRectangle capsule(1, 1, 1);
  expectField([&] { capsule.setTactileSensors(-1, 1, 1); }, "TactileSensors.perSide");
  expectField([&] { capsule.setTactileSensors(0, 0, 1); }, "TactileSensors.perSide");
  EXPECT_FALSE(circle.tactileSensors().enabled());
}

}  // namespace
}  // namespace thyrix
