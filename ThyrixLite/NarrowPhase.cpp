#include <ThyrixLite/NarrowPhase.h>
#include <Tools/MathTools.h>

#include <cmath>

namespace thyrix {
namespace {

/// Axes whose angle has a sine below this are treated as parallel (two-point contact).
constexpr real parallelSine = real(0.02);

using narrow_phase::relativeTolerance;
using narrow_phase::single;

/// The endpoint of segment @p a - @p b that reaches furthest along @p direction.
Vector2 support(Vector2 a, Vector2 b, Vector2 direction) {
  return dot(b - a, direction) > 0 ? b : a;
}

/// Capsules whose axes intersect: separation along the normal of either axis, the cheaper one.
Manifold collideCrossingCapsules(Vector2 a0, Vector2 a1, real ra, Vector2 b0, Vector2 b1, real rb) {
  Manifold best;
  real bestDepth = realMax;
  const Vector2 axes[2] = {(a1 - a0).normalized().perpendicular(),
                           (b1 - b0).normalized().perpendicular()};
  for (int axis = 0; axis < 2; ++axis) {
    for (const real sign : {real(1), real(-1)}) {
      const Vector2 n = axes[axis] * sign;
      Vector2 surfaceA;
      Vector2 surfaceB;
      if (axis == 0) {  // the normal is A's: B's deepest end against A's face
        surfaceB = support(b0, b1, -n) - n * rb;
        surfaceA = closestPointOnSegment(a0, a1, surfaceB) + n * ra;
      } else {  // the normal is B's: A's deepest end against B's face
        surfaceA = support(a0, a1, n) + n * ra;
        surfaceB = closestPointOnSegment(b0, b1, surfaceA) - n * rb;
      }
      const real depth = dot(surfaceA - surfaceB, n);
      if (depth < bestDepth) {
        bestDepth = depth;
        best = single(n, surfaceA, surfaceB);
      }
    }
  }
  return best;
}

}  // namespace

Vector2 closestPointOnSegment(Vector2 a, Vector2 b, Vector2 p) {
  const Vector2 d = b - a;
  const real lengthSquared = d.lengthSquared();
  if (lengthSquared <= 0) return a;
  return a + d * clamp(dot(p - a, d) / lengthSquared, real(0), real(1));
}

Manifold collideHalfPlaneCapsule(Vector2 point, Vector2 normal, Vector2 b0, Vector2 b1, real radius,
                                 real margin) {
  Manifold m;
  m.normal = normal;
  const Vector2 ends[2] = {b0, b1};
  for (std::uint32_t end = 0; end < 2; ++end) {
    const real distance = dot(ends[end] - point, normal);
    if (distance - radius >= margin) continue;
    const Vector2 surfaceA = ends[end] - normal * distance;
    const Vector2 surfaceB = ends[end] - normal * radius;
    m.points[m.count++] = {(surfaceA + surfaceB) * real(0.5), radius - distance, end};
  }
  return m;
}

Manifold collideCircleCapsule(Vector2 centre, real radiusA, Vector2 b0, Vector2 b1, real radiusB,
                              real margin) {
  const Vector2 q = closestPointOnSegment(b0, b1, centre);
  const Vector2 d = q - centre;
  const real distance = d.length();
  if (distance - radiusA - radiusB >= margin) return {};
  Vector2 n;
  if (distance > relativeTolerance * (radiusA + radiusB)) {
    n = d / distance;
  } else {  // centre on the axis: push out sideways, toward -perpendicular of the axis
    n = (b1 - b0).normalized().perpendicular() * real(-1);
    if (n.lengthSquared() == 0) n = {1, 0};
  }
  return single(n, centre + n * radiusA, q - n * radiusB);
}

Manifold collideCapsules(Vector2 a0, Vector2 a1, real ra, Vector2 b0, Vector2 b1, real rb,
                         real margin) {
  // Closest points of the two axes (segments), after Ericson, Real-Time Collision Detection 5.1.9.
  const Vector2 dA = a1 - a0;
  const Vector2 dB = b1 - b0;
  const real a = dA.lengthSquared();
  const real e = dB.lengthSquared();
  // An axis that collapsed to a point (a tiny half length, or one lost to rounding far from the
  // origin) is a circle: the segment formulas below divide by its squared length.
  if (!(a > 0)) return collideCircleCapsule(a0, ra, b0, b1, rb, margin);
  if (!(e > 0)) {
    Manifold m = collideCircleCapsule(b0, rb, a0, a1, ra, margin);
    m.normal = -m.normal;  // from A to B; the depth and the midpoint do not depend on the side
    return m;
  }
  const Vector2 w = a0 - b0;
  const real f = dot(dB, w);
  const real c = dot(dA, w);
  const real b = dot(dA, dB);
  const real denominator = a * e - b * b;  // >= 0, zero when parallel
  real s = denominator > 0 ? clamp((b * f - c * e) / denominator, real(0), real(1)) : real(0);
  real t = (b * s + f) / e;
  if (t < 0) {
    t = 0;
    s = clamp(-c / a, real(0), real(1));
  } else if (t > 1) {
    t = 1;
    s = clamp((b - c) / a, real(0), real(1));
  }
  const Vector2 pA = a0 + dA * s;
  const Vector2 pB = b0 + dB * t;
  const real distance = (pB - pA).length();
  if (distance - ra - rb >= margin) return {};

  const real size = std::sqrt(a) + std::sqrt(e) + ra + rb;
  if (distance <= relativeTolerance * size) return collideCrossingCapsules(a0, a1, ra, b0, b1, rb);
  const Vector2 n = (pB - pA) / distance;

  // Nearly parallel axes whose projections overlap: two points at the ends of the overlap,
  // with A's face normal, so a capsule rests flat on another.
  const real lengthA = std::sqrt(a);
  if (std::abs(cross(dA, dB)) <= parallelSine * lengthA * std::sqrt(e)) {
    const Vector2 u = dA / lengthA;
    Vector2 faceNormal = u.perpendicular();
    if (dot(faceNormal, n) < 0) faceNormal = -faceNormal;
    const real t0 = dot(b0 - a0, u);
    const real t1 = dot(b1 - a0, u);
    const real low = std::max(real(0), std::min(t0, t1));
    const real high = std::min(lengthA, std::max(t0, t1));
    if (high - low > relativeTolerance * size) {
      Manifold m;
      m.normal = faceNormal;
      const real ends[2] = {low, high};
      for (std::uint32_t end = 0; end < 2; ++end) {
        const Vector2 onA = a0 + u * ends[end];
        const Vector2 onB = b0 + dB * ((ends[end] - t0) / (t1 - t0));
        const real gap = dot(onB - onA, faceNormal) - ra - rb;
        if (gap >= margin) continue;
        const Vector2 surfaceA = onA + faceNormal * ra;
        const Vector2 surfaceB = onB - faceNormal * rb;
        m.points[m.count++] = {(surfaceA + surfaceB) * real(0.5), -gap, end};
      }
      if (m.count > 0) return m;
    }
  }
  return single(n, pA + n * ra, pB - n * rb);
}

}  // namespace thyrix
