#pragma once
// A seeded random world in a closed box: 1 to 40 circles and capsules of masses 1e-2 to 1e2,
// placed apart, under gravity and smooth bounded pushes, inside four borders. Used to check
// that bounded forces never carry a shape out of the box, whatever the mass ratios.

#include <ThyrixLite/Border.h>
#include <ThyrixLite/CappedRectangle.h>
#include <ThyrixLite/Circle.h>
#include <ThyrixLite/Simulator.h>
#include <Tools/MTRandom.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <vector>

namespace thyrix::test {

/// One body of a boxed world and its push `amplitude * (sin(rate t + phaseX), sin(rate t +
/// phaseY))` (N), a smooth bounded force.
struct BoxedBody {
  PhysicalObject* object = nullptr;
  real radius = 0;      ///< the circle's radius or the capsule's R
  real halfLength = 0;  ///< the capsule's l, 0 for a circle
  real amplitude = 0;
  real rate = 0;
  real phaseX = 0;
  real phaseY = 0;
  real torque = 0;  ///< amplitude of the smooth torque (N m)
};

/// A simulator holding a box [-halfWidth, halfWidth] x [0, height] of four borders and its
/// bodies.
struct BoxedWorld {
  std::unique_ptr<Simulator> simulator;
  std::vector<BoxedBody> bodies;
  real halfWidth = 0;
  real height = 0;

  /// The end points of a body's core (a circle's centre twice), from its pose.
  static void corePoints(const BoxedBody& body, Vector2& p0, Vector2& p1) {
    const PhysicalObject& o = *body.object;
    const Vector2 axis{std::cos(o.alpha) * body.halfLength, std::sin(o.alpha) * body.halfLength};
    p0 = o.r - axis;
    p1 = o.r + axis;
  }

  /// The deepest a body's shape reaches past a wall, in units of its radius: 0 inside the box,
  /// above 1 when its core (centre or axis) is past the wall line. NaN-safe: a non-finite pose
  /// reads as infinitely far out.
  [[nodiscard]] real wallDepth(const BoxedBody& body) const {
    Vector2 p0;
    Vector2 p1;
    corePoints(body, p0, p1);
    real depth = 0;
    for (const Vector2 p : {p0, p1}) {
      const real inside = std::min({p.x + halfWidth, halfWidth - p.x, p.y, height - p.y});
      if (!(inside == inside) || !std::isfinite(inside)) return INFINITY;
      depth = std::max(depth, (body.radius - inside) / body.radius);
    }
    return depth;
  }

  /// Sets every body's push for the step at time @p t.
  void push(real t) {
    for (BoxedBody& body : bodies) {
      body.object->externalForce = {body.amplitude * std::sin(body.rate * t + body.phaseX),
                                    body.amplitude * std::sin(body.rate * t + body.phaseY)};
      body.object->externalTorque = body.torque * std::sin(body.rate * t);
    }
  }
};

namespace boxed_detail {
// The distance between segments [a0, a1] and [b0, b1] (exact enough to keep shapes apart).
inline real segmentPointDistance(Vector2 p, Vector2 a, Vector2 b) {
  const Vector2 ab = b - a;
  const real l2 = ab.lengthSquared();
  const real t = l2 > 0 ? std::clamp(dot(p - a, ab) / l2, real(0), real(1)) : real(0);
  return (a + ab * t - p).length();
}
inline real segmentDistance(Vector2 a0, Vector2 a1, Vector2 b0, Vector2 b1) {
  // Segments that cross are at distance 0; otherwise the closest pair involves an end point.
  const auto side = [](Vector2 p, Vector2 q, Vector2 x) { return cross(q - p, x - p); };
  const bool crossing =
      side(a0, a1, b0) * side(a0, a1, b1) < 0 && side(b0, b1, a0) * side(b0, b1, a1) < 0;
  if (crossing) return 0;
  return std::min({segmentPointDistance(a0, b0, b1), segmentPointDistance(a1, b0, b1),
                   segmentPointDistance(b0, a0, a1), segmentPointDistance(b1, a0, a1)});
}
}  // namespace boxed_detail

/// The world of @p seed, solved by @p solver.
inline BoxedWorld makeBoxedWorld(std::uint32_t seed, ContactSolverKind solver) {
  MTRandom random(seed);
  const auto uniform = [&random](double low, double high) {
    return static_cast<real>(random.uniform(low, high));
  };
  const auto logUniform = [&random](double low, double high) {
    return static_cast<real>(std::exp(random.uniform(std::log(low), std::log(high))));
  };
  BoxedWorld world;
  world.simulator = std::make_unique<Simulator>(real(0.01));
  Simulator& simulator = *world.simulator;
  simulator.setContactSolver(solver);
  world.halfWidth = uniform(1.5, 4);
  world.height = uniform(2, 6);
  const real w = world.halfWidth;
  const real h = world.height;
  simulator.registerObject(std::make_unique<Border>(Vector2{0, 0}, Vector2{0, 1}));
  simulator.registerObject(std::make_unique<Border>(Vector2{0, h}, Vector2{0, -1}));
  simulator.registerObject(std::make_unique<Border>(Vector2{-w, 0}, Vector2{1, 0}));
  simulator.registerObject(std::make_unique<Border>(Vector2{w, 0}, Vector2{-1, 0}));
  // Gravity is a velocity under F = m v: up to 2 m/s.
  if (random.bernoulli(0.8)) simulator.setGravity({0, -uniform(0.2, 2)});

  const int count = static_cast<int>(random.integer(1, 40));
  for (int i = 0; i < count; ++i) {
    const bool capsule = random.bernoulli(0.5);
    const real radius = capsule ? uniform(0.03, 0.3) : uniform(0.05, 0.4);
    const real halfLength = capsule ? std::min(uniform(0.05, 1.5), w - radius) : 0;
    const real mass = logUniform(1e-2, 1e2);
    // A free place: up to 40 tries, else the body is left out.
    for (int attempt = 0; attempt < 40; ++attempt) {
      const real alpha = uniform(-3.15, 3.15);
      const Vector2 axis{std::cos(alpha) * halfLength, std::sin(alpha) * halfLength};
      const real reachX = std::abs(axis.x) + radius;
      const real reachY = std::abs(axis.y) + radius;
      if (reachX >= w || 2 * reachY >= h) continue;
      const Vector2 r{uniform(-w + reachX, w - reachX), uniform(reachY, h - reachY)};
      const bool free =
          std::none_of(world.bodies.begin(), world.bodies.end(), [&](const BoxedBody& other) {
            Vector2 q0;
            Vector2 q1;
            BoxedWorld::corePoints(other, q0, q1);
            return boxed_detail::segmentDistance(r - axis, r + axis, q0, q1) <
                   radius + other.radius;
          });
      if (!free) continue;
      std::unique_ptr<PhysicalObject> object;
      if (capsule)
        object = std::make_unique<CappedRectangle>(halfLength, radius, mass);
      else
        object = std::make_unique<Circle>(radius, mass);
      object->r = r;
      object->alpha = alpha;
      BoxedBody body;
      body.object = &simulator.registerObject(std::move(object));
      body.radius = radius;
      body.halfLength = halfLength;
      // Pushes that move the body at up to 2 m/s alone (a force per unit mass: what drives a
      // light body is as bounded as what drives a heavy one).
      body.amplitude = mass * uniform(0, 2);
      body.rate = uniform(0.2, 3);
      body.phaseX = uniform(0, 6.3);
      body.phaseY = uniform(0, 6.3);
      body.torque = body.object->I * uniform(0, 1);
      world.bodies.push_back(body);
      break;
    }
  }
  return world;
}

/// What a run of a boxed world saw.
struct BoxedRun {
  real deepest = 0;   ///< the deepest a shape reached past a wall (in radii, wallDepth())
  real fastest = 0;   ///< the largest speed of a body (m/s)
  int leakStep = -1;  ///< the first step after which a core was past a wall, -1 if none
  int bodyCount = 0;
};

/// Runs @p world for @p steps steps.
inline BoxedRun runBoxedWorld(BoxedWorld& world, int steps) {
  BoxedRun run;
  run.bodyCount = static_cast<int>(world.bodies.size());
  Simulator& simulator = *world.simulator;
  for (int step = 0; step < steps; ++step) {
    world.push(static_cast<real>(step) * simulator.timestep());
    simulator.advanceTime();
    for (const BoxedBody& body : world.bodies) {
      const real depth = world.wallDepth(body);
      run.deepest = std::max(run.deepest, depth);
      const real speed = body.object->v.length();
      run.fastest = std::max(run.fastest, std::isfinite(speed) ? speed : INFINITY);
      if (depth > 1 && run.leakStep < 0) run.leakStep = step;
    }
  }
  return run;
}

}  // namespace thyrix::test
