#pragma once
// A world of fuzz/WorldFuzzer.cpp given by the values the fuzzer decodes from its bytes, built
// and stepped as the fuzzer does (its walls, bodies, ramped smooth pushes and gravity), with the
// fuzzer's leak check: a test replays a fuzzer's finding without libFuzzer.

#include <ThyrixLite/Border.h>
#include <ThyrixLite/CappedRectangle.h>
#include <ThyrixLite/Circle.h>
#include <ThyrixLite/ComposedPhysicalObject.h>
#include <ThyrixLite/Simulator.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <memory>
#include <vector>

namespace thyrix::test {

/// One body as WorldFuzzer decodes it (doubles: the fuzzer's values in a double build exactly).
struct FuzzedBody {
  int kind = 0;  ///< 0 a circle, 1 a capsule, 2 a capsule with a circle at its right end
  double mass = 0;
  double radius = 0;
  double halfLength = 0;
  double x = 0;
  double y = 0;
  double alpha = 0;
  double forceX = 0;  ///< amplitude of the push's x (times a sine)
  double forceY = 0;  ///< amplitude of the push's y (times a cosine)
  double torque = 0;  ///< amplitude of the push's torque (times the sine)
  double frequency = 0;
  double phase = 0;
};

/// A whole world as WorldFuzzer decodes it: the box [-halfWidth, halfWidth] x [-halfHeight,
/// halfHeight] of four borders, the bodies, gravity (along y) and the steps it runs.
struct FuzzedWorld {
  double timestep = 0;
  ContactSolverKind solver = ContactSolverKind::Baraff;
  double halfWidth = 0;
  double halfHeight = 0;
  double gravity = 0;
  int steps = 0;
  std::vector<FuzzedBody> bodies;
};

/// The first time a shape's axis end (a circle's centre) was behind a wall, as the fuzzer
/// checks it after each step, or not finite; step -1 when none ever was.
struct FuzzedLeak {
  int step = -1;
  std::size_t object = 0;  ///< index in Simulator::objects (the walls are 0 to 3)
  real depth = 0;          ///< how far behind the wall (m)
};

/// Builds @p world as WorldFuzzer does and runs its steps (all of them, or @p steps if fewer).
inline FuzzedLeak runFuzzedWorld(const FuzzedWorld& world, int steps) {
  Simulator simulator(static_cast<real>(world.timestep));
  simulator.setContactSolver(world.solver);
  const auto halfWidth = static_cast<real>(world.halfWidth);
  const auto halfHeight = static_cast<real>(world.halfHeight);
  const Vector2 wallPoints[4] = {
      {0, -halfHeight}, {0, halfHeight}, {-halfWidth, 0}, {halfWidth, 0}};
  const Vector2 wallNormals[4] = {{0, 1}, {0, -1}, {1, 0}, {-1, 0}};
  for (int k = 0; k < 4; ++k)
    simulator.registerObject(std::make_unique<Border>(wallPoints[k], wallNormals[k]));
  std::vector<PhysicalObject*> objects;
  for (const FuzzedBody& b : world.bodies) {
    const auto mass = static_cast<real>(b.mass);
    const auto radius = static_cast<real>(b.radius);
    const auto halfLength = static_cast<real>(b.halfLength);
    std::unique_ptr<PhysicalObject> body;
    if (b.kind == 0) {
      body = std::make_unique<Circle>(radius, mass);
    } else if (b.kind == 1) {
      body = std::make_unique<CappedRectangle>(halfLength, radius, mass);
    } else {
      auto composed = std::make_unique<ComposedPhysicalObject>();
      composed->add(std::make_unique<CappedRectangle>(halfLength, radius, mass), {0, 0});
      composed->add(std::make_unique<Circle>(radius * real(1.5), mass * real(0.5)),
                    {halfLength, 0});
      body = std::move(composed);
    }
    body->r = {static_cast<real>(b.x), static_cast<real>(b.y)};
    body->alpha = static_cast<real>(b.alpha);
    objects.push_back(&simulator.registerObject(std::move(body)));
  }
  const Vector2 gravity{0, static_cast<real>(world.gravity)};
  constexpr int ramp = 20;  // the fuzzer's: forces and gravity grow over the first steps
  FuzzedLeak leak;
  for (int step = 0; step < std::min(steps, world.steps); ++step) {
    const auto t = static_cast<real>(simulator.time());
    const real grow = real(std::min(step, ramp)) / real(ramp);
    simulator.setGravity(gravity * grow);
    for (std::size_t i = 0; i < objects.size(); ++i) {
      const FuzzedBody& b = world.bodies[i];
      const real angle = static_cast<real>(b.frequency) * t + static_cast<real>(b.phase);
      const real s = std::sin(angle);
      const real c = std::cos(angle);
      objects[i]->externalForce = {static_cast<real>(b.forceX) * s * grow,
                                   static_cast<real>(b.forceY) * c * grow};
      objects[i]->externalTorque = static_cast<real>(b.torque) * s * grow;
    }
    simulator.advanceTime();
    for (std::size_t i = 4; i < simulator.objects.size() && leak.step < 0; ++i) {
      for (const Primitive* primitive : simulator.objects[i].primitives()) {
        const PhysicalObject& owner = primitive->owner();
        const bool part = &owner != primitive;
        const Vector2 centre = part ? owner.toWorld(primitive->localPosition()) : primitive->r;
        const real angle = part ? owner.alpha + primitive->localAngle() : primitive->alpha;
        const Vector2 half = Vector2{primitive->halfLength(), 0}.rotated(angle);
        for (const Vector2 end : {centre - half, centre + half})
          for (int w = 0; w < 4; ++w) {
            const real inside = dot(end - wallPoints[w], wallNormals[w]);
            // (A pose not finite is as far out as can be.)
            if (!(inside >= 0) && leak.step < 0)
              leak = {step, i, std::isfinite(inside) ? -inside : real(INFINITY)};
          }
      }
    }
  }
  return leak;
}

}  // namespace thyrix::test
