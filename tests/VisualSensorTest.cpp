// The visual sensor against hand-computed arcs (a disk of radius R at distance d subtends
// 2 asin(R / d)) and against an independent ray-casting reference; its culling, its exclusions
// (own body, borders), the eye inside or touching an object, following the body, validation,
// and no allocation once warmed up. This executable links support/AllocationCounter.cpp to count
// allocations (as AllocationTest does).

#include <ThyrixLite/AngularCoverage.h>
#include <ThyrixLite/Border.h>
#include <ThyrixLite/CappedRectangle.h>
#include <ThyrixLite/Circle.h>
#include <ThyrixLite/ComposedPhysicalObject.h>
#include <ThyrixLite/InvalidArgument.h>
#include <ThyrixLite/Simulator.h>
#include <ThyrixLite/VisualSensor.h>
#include <Tools/MTRandom.h>
#include <Tools/MathTools.h>
#include <gtest/gtest.h>
#include <scenes/Scenes.h>

#include "TestTolerances.h"
#include "support/AllocationCounter.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <memory>
#include <new>
#include <string>
#include <vector>

namespace thyrix {
namespace {

using test::tight;
constexpr real kPi = pi<real>;

/// A world with the sensor's body: a small circle at the origin, not rotated.
class VisualSensorTest : public ::testing::Test {
 protected:
  Circle& addCircle(real radius, Vector2 centre) {
    auto& circle = world.registerObject(std::make_unique<Circle>(radius, real(1)));
    circle.r = centre;
    return circle;
  }
  CappedRectangle& addCapsule(real halfLength, real radius, Vector2 centre, real angle) {
    auto& capsule =
        world.registerObject(std::make_unique<CappedRectangle>(halfLength, radius, real(1)));
    capsule.r = centre;
    capsule.alpha = angle;
    return capsule;
  }
  /// A point at @p distance from the origin in direction @p angle.
  static Vector2 polar(real distance, real angle) {
    return {distance * std::cos(angle), distance * std::sin(angle)};
  }
  /// A sensor at the body's centre looking along +x.
  VisualSensor eye(int pixelCount, real pixelAngle) {
    return VisualSensor(body, Vector2{}, 0, pixelCount, pixelAngle);
  }
  void expectActivations(const VisualSensor& sensor, const std::vector<real>& expected,
                         real tolerance = tight) {
    ASSERT_EQ(sensor.activations().size(), expected.size());
    for (std::size_t i = 0; i < expected.size(); ++i)
      EXPECT_NEAR(sensor.activations()[i], expected[i], tolerance) << "pixel " << i;
  }

  Simulator world;
  Circle& body = world.registerObject(std::make_unique<Circle>(real(0.1), real(1)));
};

// ---------------------------------------------------------------------------------------------
// Hand-computed arcs

TEST_F(VisualSensorTest, CircleStraightAheadCoversTwiceTheArcsine) {
  // R = 1 at d = 2: 2 asin(1/2) = pi/3 of a pi/2 pixel.
  addCircle(1, {2, 0});
  VisualSensor sensor = eye(1, kPi / 2);
  sensor.update(world.objects);
  expectActivations(sensor, {real(2) / 3});
}

TEST_F(VisualSensorTest, SmallFarCircleCoversTwiceTheArcsine) {
  addCircle(real(0.5), {0, -3});
  VisualSensor sensor(body, {}, -kPi / 2, 1, real(0.5));  // looking along -y
  sensor.update(world.objects);
  expectActivations(sensor, {2 * std::asin(real(0.5) / 3) / real(0.5)});
}

TEST_F(VisualSensorTest, CircleStraddlingAPixelBoundaryIsSplitBetweenThePixels) {
  // Four pixels of pi/4 over [-pi/2, pi/2]; R = 1 at d = 2 in direction 0.1 covers
  // [0.1 - pi/6, 0.1 + pi/6], across the boundary at 0 between pixels 1 and 2.
  addCircle(1, polar(2, real(0.1)));
  VisualSensor sensor = eye(4, kPi / 4);
  sensor.update(world.objects);
  expectActivations(sensor,
                    {0, (kPi / 6 - real(0.1)) / (kPi / 4), (kPi / 6 + real(0.1)) / (kPi / 4), 0});
}

TEST_F(VisualSensorTest, WideCircleSpreadsOverFourPixels) {
  // R = 1 at d = 1.2: half angle h = asin(1/1.2) > pi/4, so the two middle pixels are full
  // and the outer ones hold h - pi/4 each.
  addCircle(1, {real(1.2), 0});
  VisualSensor sensor = eye(4, kPi / 4);
  sensor.update(world.objects);
  const real h = std::asin(1 / real(1.2));
  const real outer = (h - kPi / 4) / (kPi / 4);
  expectActivations(sensor, {outer, 1, 1, outer});
}

TEST_F(VisualSensorTest, PixelZeroIsTheRightmost) {
  addCircle(real(0.2), polar(3, real(-0.4)));  // clockwise of the view direction
  VisualSensor sensor = eye(2, real(0.5));
  sensor.update(world.objects);
  EXPECT_GT(sensor.activations()[0], 0);
  EXPECT_EQ(sensor.activations()[1], 0);
}

TEST_F(VisualSensorTest, CapsuleBroadside) {
  // Axis along y at x = 1, ends (1, -1) and (1, 1), R = sqrt(2)/2: each end centre is at
  // 45 degrees and distance sqrt 2, so its outer tangent is at pi/4 + asin(1/2) = 5 pi/12.
  addCapsule(1, std::sqrt(real(2)) / 2, {1, 0}, kPi / 2);
  VisualSensor sensor = eye(2, kPi / 2);
  sensor.update(world.objects);
  expectActivations(sensor, {real(5) / 6, real(5) / 6});
}

TEST_F(VisualSensorTest, CapsuleEndOnIsSeenAsItsNearerCap) {
  // Axis along the view line from x = 2 to x = 4, R = 1: the near cap (d = 2) hides the rest,
  // 2 asin(1/2) = pi/3 of a pi/2 pixel, whichever way round the capsule lies.
  for (const real angle : {real(0), kPi}) {
    SCOPED_TRACE(angle);
    Simulator scene;
    auto& viewer = scene.registerObject(std::make_unique<Circle>(real(0.1), real(1)));
    auto& capsule = scene.registerObject(std::make_unique<CappedRectangle>(1, 1, real(1)));
    capsule.r = {3, 0};
    capsule.alpha = angle;
    VisualSensor sensor(viewer, {}, 0, 1, kPi / 2);
    sensor.update(scene.objects);
    EXPECT_NEAR(sensor.activations()[0], real(2) / 3, tight);
  }
}

TEST_F(VisualSensorTest, ObliqueCapsuleBetweenItsEndTangents) {
  // Ends at (2, -1) and (4, 3), R = 0.5: the arc runs from the clockwise tangent of the lower
  // end to the counter-clockwise tangent of the upper one.
  addCapsule(std::sqrt(real(5)), real(0.5), {3, 1}, std::atan2(real(2), real(1)));
  VisualSensor sensor = eye(1, kPi);
  sensor.update(world.objects);
  const real low = std::atan2(real(-1), real(2)) - std::asin(real(0.5) / std::sqrt(real(5)));
  const real high = std::atan2(real(3), real(4)) + std::asin(real(0.5) / 5);
  expectActivations(sensor, {(high - low) / kPi});
}

TEST_F(VisualSensorTest, OverlappingObjectsAreNotCountedTwice) {
  // [-pi/6, pi/6] and [0, pi/3]: the union is pi/2 of a pi pixel (the sum would be 2/3).
  addCircle(1, {2, 0});
  addCircle(1, polar(2, kPi / 6));
  // A circle inside the first, and a capsule inside the second.
  addCircle(real(0.5), {2, 0});
  addCapsule(real(0.3), real(0.5), polar(2, kPi / 6), 1);
  VisualSensor sensor = eye(1, kPi);
  sensor.update(world.objects);
  expectActivations(sensor, {real(1) / 2});
}

// ---------------------------------------------------------------------------------------------
// What is not seen

TEST_F(VisualSensorTest, OwnBodyIsNotSeen) {
  // The eye inside its own body sees through it; from outside, looking back at it, too.
  VisualSensor inside = eye(14, real(0.4));
  inside.update(world.objects);
  expectActivations(inside, std::vector<real>(14, 0));
  VisualSensor outside(body, {real(0.5), 0}, kPi, 4, real(0.5));
  outside.update(world.objects);
  expectActivations(outside, std::vector<real>(4, 0));
  // Another circle is still seen from inside the body.
  addCircle(1, {2, 0});
  VisualSensor seeing = eye(1, kPi / 2);
  seeing.update(world.objects);
  expectActivations(seeing, {real(2) / 3});
}

TEST_F(VisualSensorTest, PartsOfTheOwnBodyAreNotSeen) {
  // A primitive attached to the body (a part of it) is not seen; the same one detached is.
  Circle& part = addCircle(1, {2, 0});
  part.attachTo(body, {2, 0}, 0);
  VisualSensor sensor = eye(1, kPi / 2);
  sensor.update(world.objects);
  expectActivations(sensor, {0});
  part.attachTo(part, {}, 0);
  sensor.update(world.objects);
  expectActivations(sensor, {real(2) / 3});
}

TEST_F(VisualSensorTest, ComposedBodies) {
  // The sensor's body: two circles of radius 0.5 at (0, 0) and (0, -2), the eye at the first's
  // centre looking along +x, all around in six pixels of pi/3. Its parts are not seen.
  Simulator scene;  // without the fixture's body, which surrounds the origin
  auto own = std::make_unique<ComposedPhysicalObject>();
  own->add(std::make_unique<Circle>(real(0.5), real(1)), {0, 0});
  own->add(std::make_unique<Circle>(real(0.5), real(1)), {0, -2});
  ComposedPhysicalObject& ownBody = scene.registerObject(std::move(own));
  // Another body of two circles R = 1 at d = 2 in directions 0 and pi/6: its parts' arcs
  // [-pi/6, pi/6] and [0, pi/3] overlap; the union covers half of pixel 2 and all of pixel 3.
  auto other = std::make_unique<ComposedPhysicalObject>();
  other->add(std::make_unique<Circle>(1, real(1)), polar(2, 0));
  other->add(std::make_unique<Circle>(1, real(1)), polar(2, kPi / 6));
  scene.registerObject(std::move(other));
  VisualSensor sensor(ownBody, ownBody.toLocal({0, 0}), 0, 6, kPi / 3);
  sensor.update(scene.objects);
  expectActivations(sensor, {0, 0, real(0.5), 1, 0, 0});
}

TEST_F(VisualSensorTest, SeesPartsAddedLaterAndAnotherObjectList) {
  // The sensor lists the primitives it may see: a part added to a composed body after an
  // update(), or another world's objects, are seen on the next one.
  Simulator scene;  // without the fixture's body, which surrounds the origin
  Circle& own = scene.registerObject(std::make_unique<Circle>(real(0.5), real(1)));
  auto other = std::make_unique<ComposedPhysicalObject>();
  other->add(std::make_unique<Circle>(1, real(1)), polar(2, 0));
  ComposedPhysicalObject& otherBody = scene.registerObject(std::move(other));
  VisualSensor sensor(own, {}, 0, 6, kPi / 3);
  sensor.update(scene.objects);
  expectActivations(sensor, {0, 0, real(0.5), real(0.5), 0, 0});
  otherBody.add(std::make_unique<Circle>(1, real(1)), polar(2, kPi / 6));
  sensor.update(scene.objects);
  expectActivations(sensor, {0, 0, real(0.5), 1, 0, 0});
  Simulator elsewhere;  // as many objects: two circles behind the eye, across +-pi
  for (int i = 0; i < 2; ++i)
    elsewhere.registerObject(std::make_unique<Circle>(1, real(1))).r = polar(2, kPi);
  sensor.update(elsewhere.objects);
  expectActivations(sensor, {real(0.5), 0, 0, 0, 0, real(0.5)});
}

TEST_F(VisualSensorTest, BordersAreNotSeen) {
  world.registerObject(std::make_unique<Border>(Vector2{2, 0}, Vector2{-1, 0}));
  world.registerObject(std::make_unique<Border>(Vector2{0, -2}, Vector2{0, 1}));
  scenes::addWalls(world, 10, 10);
  VisualSensor sensor = eye(6, kPi / 3);  // all around
  sensor.update(world.objects);
  expectActivations(sensor, std::vector<real>(6, 0));
}

TEST_F(VisualSensorTest, ObjectsBehindTheEyeAreNotSeen) {
  addCircle(1, {-3, 0});
  addCapsule(2, real(0.5), {-3, 1}, real(0.3));
  VisualSensor narrow = eye(4, kPi / 8);
  narrow.update(world.objects);
  expectActivations(narrow, std::vector<real>(4, 0));
  VisualSensor half = eye(2, kPi / 2);  // exactly the front half-plane
  half.update(world.objects);
  expectActivations(half, std::vector<real>(2, 0));
}

TEST_F(VisualSensorTest, ObjectsOutsideAWideFieldAreNotSeenAndEdgesClip) {
  // Three pixels of pi/2 see [-3pi/4, 3pi/4]. R = 1 at d = 3 behind (h = asin(1/3) < pi/4) is
  // out of view; the same at direction 3pi/4 is cut in half by the field's left edge.
  addCircle(1, {-3, 0});
  addCircle(1, polar(3, 3 * kPi / 4));
  VisualSensor sensor = eye(3, kPi / 2);
  sensor.update(world.objects);
  expectActivations(sensor, {0, 0, std::asin(real(1) / 3) / (kPi / 2)});
}

TEST_F(VisualSensorTest, AllAroundSeesBehindAcrossPlusMinusPi) {
  // Six pixels of pi/3 from -pi to pi; R = 1 at d = 2 straight behind covers pi/6 on each side
  // of +-pi: half of pixel 0 and half of pixel 5.
  addCircle(1, {-2, 0});
  VisualSensor sensor = eye(6, kPi / 3);
  sensor.update(world.objects);
  expectActivations(sensor, {real(0.5), 0, 0, 0, 0, real(0.5)});
}

// ---------------------------------------------------------------------------------------------
// The eye inside or touching an object

TEST_F(VisualSensorTest, EyeInsideAnObjectSeesItInEveryPixel) {
  // A circle whose centre is behind the eye but which contains it: not culled as "behind".
  addCircle(5, {-3, 0});
  VisualSensor sensor = eye(14, real(0.1));
  sensor.update(world.objects);
  expectActivations(sensor, std::vector<real>(14, 1), 0);
}

TEST_F(VisualSensorTest, EyeInsideACapsuleSeesItInEveryPixel) {
  addCapsule(3, real(0.5), {-2, real(0.2)}, 0);
  VisualSensor sensor = eye(5, real(0.2));
  sensor.update(world.objects);
  expectActivations(sensor, std::vector<real>(5, 1), 0);
}

TEST_F(VisualSensorTest, EyeTouchingAnObjectSeesItInEveryPixel) {
  for (const Vector2 centre : {Vector2{2, 0}, Vector2{-2, 0}, Vector2{0, 2}}) {
    SCOPED_TRACE(centre.x + 10 * centre.y);
    Simulator scene;
    auto& viewer = scene.registerObject(std::make_unique<Circle>(real(0.1), real(1)));
    scene.registerObject(std::make_unique<Circle>(2, real(1))).r = centre;  // d = R exactly
    VisualSensor sensor(viewer, {}, 0, 3, real(0.3));
    sensor.update(scene.objects);
    expectActivations(sensor, std::vector<real>(3, 1), 0);
  }
}

TEST_F(VisualSensorTest, EyeTouchingACapsuleSeesItInEveryPixel) {
  addCapsule(1, 1, {1, 0}, kPi / 2);  // the segment (1, -1)-(1, 1) is at distance 1 = R
  VisualSensor sensor = eye(3, real(0.3));
  sensor.update(world.objects);
  expectActivations(sensor, std::vector<real>(3, 1), 0);
}

// ---------------------------------------------------------------------------------------------
// Attached to a moving body

TEST_F(VisualSensorTest, FollowsTheBodysRotationAndTranslation) {
  body.r = {5, 5};
  body.alpha = kPi / 2;
  // Eye one metre along the body's x axis, looking along it: at (5, 6), looking up.
  VisualSensor sensor(body, {1, 0}, 0, 1, kPi / 2);
  EXPECT_NEAR(sensor.eyePosition().x, 5, tight);
  EXPECT_NEAR(sensor.eyePosition().y, 6, tight);
  EXPECT_NEAR(sensor.viewDirection(), kPi / 2, tight);
  const auto [first, last] = sensor.pixelBounds(0);
  EXPECT_NEAR(first, kPi / 4, tight);
  EXPECT_NEAR(last, 3 * kPi / 4, tight);

  addCircle(1, {5, 8});  // d = 2 above the eye
  addCircle(1, {2, 5});  // d = 2 left of the eye once the body has turned
  sensor.update(world.objects);
  expectActivations(sensor, {real(2) / 3});

  body.alpha = kPi;  // eye at (4, 5), looking along -x
  body.r = {5, 5};
  sensor.update(world.objects);
  EXPECT_NEAR(sensor.eyePosition().x, 4, tight);
  EXPECT_NEAR(sensor.eyePosition().y, 5, tight);
  EXPECT_NEAR(std::abs(sensor.viewDirection()), kPi, tight);
  expectActivations(sensor, {real(2) / 3});

  body.r = {6, 5};  // translated: eye at (5, 5), the left circle now at d = 3
  sensor.update(world.objects);
  expectActivations(sensor, {2 * std::asin(real(1) / 3) / (kPi / 2)});

  body.r = {0, 0};
  body.alpha = 0;  // eye at (1, 0) looking along +x: nothing there
  sensor.update(world.objects);
  expectActivations(sensor, {0});
}

TEST_F(VisualSensorTest, PixelBoundsAreSideBySideCentredOnTheView) {
  body.alpha = real(0.3);
  VisualSensor sensor(body, {}, real(0.2), 5, real(0.1));
  EXPECT_EQ(sensor.pixelCount(), 5);
  EXPECT_EQ(sensor.pixelAngle(), real(0.1));
  EXPECT_EQ(&sensor.body(), &body);
  EXPECT_NEAR(sensor.viewDirection(), real(0.5), tight);
  for (int i = 0; i < 5; ++i) {
    const auto [low, high] = sensor.pixelBounds(i);
    EXPECT_NEAR(low, real(0.25) + real(0.1) * static_cast<real>(i), tight);
    EXPECT_NEAR(high, real(0.35) + real(0.1) * static_cast<real>(i), tight);
  }
}

// ---------------------------------------------------------------------------------------------
// Against ray casting: an independent reference, in double precision

/// Whether the ray from @p eye in direction @p t (unit) meets the capsule p0 p1 of @p radius
/// (a disk when p0 == p1): the distance from the ray to the segment is at most the radius.
bool rayHits(double ex, double ey, double tx, double ty, double p0x, double p0y, double p1x,
             double p1y, double radius) {
  const auto pointToRay = [&](double px, double py) {
    const double s = std::max(0.0, (px - ex) * tx + (py - ey) * ty);
    return std::hypot(px - ex - s * tx, py - ey - s * ty);
  };
  const double dx = p1x - p0x;
  const double dy = p1y - p0y;
  const double denominator = tx * dy - ty * dx;
  if (denominator != 0) {  // do the ray and the segment cross?
    const double wx = p0x - ex;
    const double wy = p0y - ey;
    const double s = (wx * dy - wy * dx) / denominator;
    const double u = (wx * ty - wy * tx) / denominator;
    if (s >= 0 && u >= 0 && u <= 1) return true;
  }
  double distance = std::min(pointToRay(p0x, p0y), pointToRay(p1x, p1y));
  const double lengthSquared = dx * dx + dy * dy;
  const double u = lengthSquared > 0
                       ? std::clamp(((ex - p0x) * dx + (ey - p0y) * dy) / lengthSquared, 0.0, 1.0)
                       : 0.0;
  distance = std::min(distance, std::hypot(ex - p0x - u * dx, ey - p0y - u * dy));
  return distance <= radius;
}

/// Fraction of each pixel's rays (@p samples per pixel, evenly spread) that hit an object.
std::vector<double> rayCast(const VisualSensor& sensor, const ObjectList& objects, int samples) {
  const Vector2 eye = sensor.eyePosition();
  std::vector<double> result;
  for (int i = 0; i < sensor.pixelCount(); ++i) {
    const auto [low, high] = sensor.pixelBounds(i);
    int hits = 0;
    for (int k = 0; k < samples; ++k) {
      const double angle = low + (high - low) * (k + 0.5) / samples;
      const double tx = std::cos(angle);
      const double ty = std::sin(angle);
      bool hit = false;
      for (const PhysicalObject& object : objects) {
        for (const Primitive* p : object.primitives()) {
          if (&p->owner() == &sensor.body() || p->shapeType() == ShapeType::HalfPlane) continue;
          const double l = p->halfLength();
          const double ax = l * std::cos(double(p->alpha));
          const double ay = l * std::sin(double(p->alpha));
          hit = hit || rayHits(eye.x, eye.y, tx, ty, p->r.x - ax, p->r.y - ay, p->r.x + ax,
                               p->r.y + ay, p->radius());
        }
      }
      hits += hit ? 1 : 0;
    }
    result.push_back(double(hits) / samples);
  }
  return result;
}

TEST_F(VisualSensorTest, AgreesWithRayCastingInAClutteredScene) {
  scenes::addWalls(world, 20, 20);
  addCircle(1, {4, 1});
  addCircle(real(0.7), {5, real(2.2)});  // overlaps the first as seen from the eye
  addCircle(real(0.3), {-2, 3});
  addCircle(real(1.5), {-6, -5});
  addCircle(real(0.4), {real(0.5), -3});
  addCapsule(real(1.5), real(0.4), {3, -3}, real(0.7));
  addCapsule(real(2.5), real(0.3), {-4, 1}, real(-1.2));
  addCapsule(real(0.8), real(0.6), {1, 5}, real(0.1));
  addCapsule(1, real(0.5), {4, real(1.5)}, real(2.0));  // crosses the first two circles
  body.r = {real(0.2), real(-0.1)};
  // Errors of the reference: half a sample per arc end in a pixel.
  const int samples = 5000;
  const double tolerance = 4.0 / samples + (test::isFloat ? 1e-5 : 0.0);
  struct Eye {
    real direction;
    int pixels;
    real angle;
  };
  for (const Eye& e :
       {Eye{0, 14, real(0.1)}, Eye{real(0.4), 7, real(0.3)}, Eye{real(2.5), 10, kPi / 10},
        Eye{real(-2), 6, kPi / 4}, Eye{real(1), 12, 2 * kPi / 12}}) {
    for (const real bodyAngle : {real(0), real(1.3), real(-2.9)}) {
      SCOPED_TRACE(std::to_string(e.direction) + " " + std::to_string(e.pixels) + " " +
                   std::to_string(bodyAngle));
      body.alpha = bodyAngle;
      VisualSensor sensor(body, {real(0.05), 0}, e.direction, e.pixels, e.angle);
      sensor.update(world.objects);
      const std::vector<double> reference = rayCast(sensor, world.objects, samples);
      double seen = 0;
      for (int i = 0; i < e.pixels; ++i) {
        EXPECT_NEAR(sensor.activations()[i], reference[i], tolerance) << "pixel " << i;
        EXPECT_GE(sensor.activations()[i], 0);
        EXPECT_LE(sensor.activations()[i], 1);
        seen += reference[i];
      }
      EXPECT_GT(seen, 0) << "the eye should see something";
    }
  }
}

TEST_F(VisualSensorTest, AgreesWithRayCastingInADenseArena) {
  // 100 objects, many overlapping as seen from the eye; all around and a quarter turn.
  scenes::addWalls(world, 10, 10);
  const auto circles = scenes::addRandomCircles(world, 60, real(0.2), 10, 11);
  for (int i = 0; i < 40; ++i)
    addCapsule(real(0.3), real(0.1),
               {real(0.5) + real(0.23) * static_cast<real>(i),
                real(1) + real(0.2) * static_cast<real>(i % 7)},
               real(0.4) * static_cast<real>(i));
  const int samples = 2000;
  for (const real field : {2 * kPi, kPi / 2}) {
    for (const real angle : {real(0.3), real(2.2)}) {
      SCOPED_TRACE(std::to_string(field) + " " + std::to_string(angle));
      circles[0]->alpha = angle;
      VisualSensor sensor(*circles[0], {real(0.2), 0}, 0, 14, field / 14);
      sensor.update(world.objects);
      const std::vector<double> reference = rayCast(sensor, world.objects, samples);
      for (int i = 0; i < 14; ++i)
        EXPECT_NEAR(sensor.activations()[i], reference[i], 10.0 / samples) << "pixel " << i;
    }
  }
}

// ---------------------------------------------------------------------------------------------
// Bit for bit against the extent functions

/// The activations the sensor's definition gives, composed from the public geometry without any
/// of update()'s shortcuts: every primitive's extent (diskExtent, capsuleExtent) relative to the
/// view, clipped to the field, then the union's covered fractions. The eye and the view are
/// computed with update()'s arithmetic so that the two agree bit for bit.
std::vector<real> referenceActivations(const VisualSensor& sensor, const ObjectList& objects) {
  const PhysicalObject& body = sensor.body();
  const real c = std::cos(body.alpha);
  const real s = std::sin(body.alpha);
  const auto rotate = [](Vector2 v, real cs, real sn) {
    return Vector2{cs * v.x - sn * v.y, sn * v.x + cs * v.y};
  };
  const Vector2 eye = body.r + rotate(sensor.localPosition(), c, s);
  const Vector2 view =
      rotate({std::cos(sensor.localDirection()), std::sin(sensor.localDirection())}, c, s);
  const real half = static_cast<real>(sensor.pixelCount()) * sensor.pixelAngle() / 2;
  std::vector<real> result(static_cast<std::size_t>(sensor.pixelCount()), real(0));
  AngularCoverage coverage;
  for (const PhysicalObject& object : objects) {
    for (const Primitive* p : object.primitives()) {
      if (&p->owner() == &body || p->shapeType() == ShapeType::HalfPlane) continue;
      AngularExtent extent;
      if (p->shapeType() == ShapeType::Circle) {
        extent = diskExtent(eye, view, p->r, p->radius());
      } else {
        const Vector2 axis{p->halfLength() * std::cos(p->alpha),
                           p->halfLength() * std::sin(p->alpha)};
        extent = capsuleExtent(eye, view, p->r - axis, p->r + axis, p->radius());
      }
      if (extent.wholeCircle) {
        std::fill(result.begin(), result.end(), real(1));
        return result;
      }
      for (const AngularInterval& piece : extent.pieces())
        coverage.add(AngularInterval{std::max(piece.begin, -half), std::min(piece.end, half)});
    }
  }
  coverage.merge();
  coverage.coveredFractions(-half, sensor.pixelAngle(), result);
  return result;
}

TEST_F(VisualSensorTest, MatchesTheExtentFunctionsBitForBit) {
  // update()'s culling and shortcuts must not change a single bit: random arenas of circles,
  // capsules and a composed body, eyes of various fields (narrow to all around) at random poses,
  // some inside or touching an object.
  scenes::addWalls(world, 10, 10);
  const auto circles = scenes::addRandomCircles(world, 40, real(0.2), 10, 3);
  MTRandom random(17);
  const auto uniform = [&random](double low, double high) {
    return static_cast<real>(random.uniform(low, high));
  };
  std::vector<CappedRectangle*> capsules;
  for (int i = 0; i < 15; ++i)
    capsules.push_back(&addCapsule(uniform(0.05, 0.8), uniform(0.05, 0.4),
                                   {uniform(0.5, 9.5), uniform(0.5, 9.5)}, uniform(-4, 4)));
  auto composed = std::make_unique<ComposedPhysicalObject>();
  for (int k = 0; k < 4; ++k)
    composed->add(std::make_unique<Circle>(real(0.15), real(1)),
                  {real(5), real(2) + real(0.25) * static_cast<real>(k)});
  world.registerObject(std::move(composed));
  struct Eye {
    int pixels;
    real angle;
  };
  const Eye eyes[] = {{7, kPi / 12}, {14, real(0.1)},    {1, real(0.3)},
                      {5, kPi / 10}, {12, 2 * kPi / 12}, {9, real(0.3)},
                      {3, kPi / 3},  {20, kPi / 20},     {4, kPi / 4}};
  int compared = 0;
  int partial = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const Eye& e = eyes[trial % std::size(eyes)];
    PhysicalObject& host = *circles[static_cast<std::size_t>(trial) % circles.size()];
    host.r = {uniform(0.3, 9.7), uniform(0.3, 9.7)};
    host.alpha = uniform(-7, 7);
    // Move the objects a little so that every trial sees a different arrangement.
    for (CappedRectangle* capsule : capsules) capsule->alpha += uniform(-0.5, 0.5);
    VisualSensor sensor(host, {uniform(-0.3, 0.3), uniform(-0.3, 0.3)}, uniform(-4, 4), e.pixels,
                        e.angle);
    sensor.update(world.objects);
    const std::vector<real> expected = referenceActivations(sensor, world.objects);
    for (int i = 0; i < e.pixels; ++i) {
      const real a = sensor.activations()[static_cast<std::size_t>(i)];
      EXPECT_EQ(a, expected[static_cast<std::size_t>(i)]) << "trial " << trial << " pixel " << i;
      partial += (a > 0 && a < 1) ? 1 : 0;
      ++compared;
    }
  }
  EXPECT_GT(partial, compared / 10) << "the trials should cover many pixel ends";
}

TEST_F(VisualSensorTest, EyesOnBodiesTurnedAlikeMatchTheExtentFunctionsBitForBit) {
  // update() remembers the cosine and sine of the last body angle it saw (an agent's eyes often
  // sit on bodies turned alike): two eyes kept from step to step, on bodies turned alike or not,
  // at +0 and -0 (their sines differ in sign), must still give the definition's bits.
  scenes::addWalls(world, 10, 10);
  const auto circles = scenes::addRandomCircles(world, 30, real(0.2), 10, 5);
  PhysicalObject& left = *circles[0];
  PhysicalObject& right = *circles[1];
  VisualSensor leftEye(left, {real(0.1), real(0.05)}, real(0.4), 7, kPi / 12);
  VisualSensor rightEye(right, {real(0.1), real(-0.05)}, real(-0.4), 7, kPi / 12);
  MTRandom random(23);
  const auto uniform = [&random](double low, double high) {
    return static_cast<real>(random.uniform(low, high));
  };
  const real angles[] = {0, -real(0), uniform(-7, 7), uniform(-7, 7)};
  for (int trial = 0; trial < 300; ++trial) {
    left.r = {uniform(0.3, 9.7), uniform(0.3, 9.7)};
    right.r = left.r + Vector2{uniform(-0.6, 0.6), uniform(-0.6, 0.6)};
    left.alpha = angles[static_cast<std::size_t>(trial) % std::size(angles)];
    right.alpha = trial % 3 == 0 ? angles[static_cast<std::size_t>(trial / 3) % std::size(angles)]
                                 : left.alpha;
    for (VisualSensor* eye : {&leftEye, &rightEye}) {
      eye->update(world.objects);
      const std::vector<real> expected = referenceActivations(*eye, world.objects);
      for (std::size_t i = 0; i < expected.size(); ++i)
        EXPECT_EQ(eye->activations()[i], expected[i]) << "trial " << trial << " pixel " << i;
    }
  }
}

// ---------------------------------------------------------------------------------------------
// Validation

/// The field named by the InvalidArgument that @p action throws, or a marker.
template <class Action>
std::string thrownField(Action&& action) {
  try {
    action();
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find(e.field()), std::string::npos) << e.what();
    return e.field();
  } catch (...) {
    return "<other exception>";
  }
  return "<no exception>";
}

TEST_F(VisualSensorTest, ValidationNamesTheField) {
  constexpr real nan = std::numeric_limits<real>::quiet_NaN();
  constexpr real inf = std::numeric_limits<real>::infinity();
  const auto make = [&](Vector2 position, real direction, int count, real angle) {
    return [=, this] { VisualSensor sensor(body, position, direction, count, angle); };
  };
  for (const int count : {0, -1})
    EXPECT_EQ(thrownField(make({}, 0, count, real(0.1))), "VisualSensor.pixelCount");
  for (const real angle : {real(0), real(-0.1), nan, inf})
    EXPECT_EQ(thrownField(make({}, 0, 3, angle)), "VisualSensor.pixelAngle");
  EXPECT_EQ(thrownField(make({}, 0, 7, real(1))), "VisualSensor.pixelAngle");  // 7 > 2 pi
  EXPECT_EQ(thrownField(make({}, 0, 2, kPi + real(0.001))), "VisualSensor.pixelAngle");
  EXPECT_EQ(thrownField(make({nan, 0}, 0, 3, real(0.1))), "VisualSensor.localPosition");
  EXPECT_EQ(thrownField(make({0, inf}, 0, 3, real(0.1))), "VisualSensor.localPosition");
  EXPECT_EQ(thrownField(make({}, nan, 3, real(0.1))), "VisualSensor.localDirection");
  EXPECT_EQ(thrownField(make({}, -inf, 3, real(0.1))), "VisualSensor.localDirection");
  // All around, with 2 pi / n rounded either way, is accepted.
  for (const int count : {1, 3, 7, 14, 100})
    EXPECT_EQ(thrownField(make({}, 0, count, 2 * kPi / static_cast<real>(count))), "<no exception>")
        << count;
  const VisualSensor sensor = eye(3, real(0.1));
  EXPECT_EQ(thrownField([&] { (void)sensor.pixelBounds(3); }), "VisualSensor.pixelBounds.i");
  EXPECT_EQ(thrownField([&] { (void)sensor.pixelBounds(-1); }), "VisualSensor.pixelBounds.i");
}

// ---------------------------------------------------------------------------------------------
// No allocation

TEST_F(VisualSensorTest, UpdateAllocatesNothingAfterTheFirstCall) {
  scenes::addWalls(world, 10, 10);
  const auto circles = scenes::addRandomCircles(world, 60, real(0.2), 10, 7);
  for (int i = 0; i < 40; ++i)
    addCapsule(real(0.3), real(0.1), {real(0.25) * static_cast<real>(i), real(9)},
               real(0.1) * static_cast<real>(i));
  // Composed bodies have more primitives than objects.
  for (int i = 0; i < 3; ++i) {
    auto composed = std::make_unique<ComposedPhysicalObject>();
    for (int k = 0; k < 8; ++k)
      composed->add(
          std::make_unique<Circle>(real(0.1), real(1)),
          {real(2) + real(2) * static_cast<real>(i), real(0.3) + real(0.2) * static_cast<real>(k)});
    world.registerObject(std::move(composed));
  }
  VisualSensor sensor(*circles[0], {real(0.2), 0}, 0, 14, real(0.15));
  sensor.update(world.objects);
  const long before = test::allocationCount();
  for (int i = 0; i < 100; ++i) {
    circles[0]->alpha = real(0.0628) * static_cast<real>(i);  // looks all around
    sensor.update(world.objects);
  }
  EXPECT_EQ(test::allocationCount() - before, 0);
}

TEST(VisualSensorAllocationCounter, CountsAllocations) {
  const long before = test::allocationCount();
  std::vector<int> grown;
  grown.reserve(static_cast<std::size_t>(::testing::UnitTest::GetInstance()->random_seed()) + 10);
  EXPECT_EQ(test::allocationCount() - before, 1);
}

}  // namespace
}  // namespace thyrix
