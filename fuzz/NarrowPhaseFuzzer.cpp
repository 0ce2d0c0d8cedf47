/// @file NarrowPhaseFuzzer.cpp
/// @brief libFuzzer target: any two shapes in any poses give a finite manifold with a unit
/// normal and depths that agree with a long-double computation of the shapes' distance.
///
/// The bytes choose the pair's types, the sizes (radii 1e-4 to 1e3, half lengths 1e-12 to 1e3,
/// so axes that rounding collapses), a position anywhere up to 1e15 from the origin (1e7 in
/// float), the angles (exactly parallel, perpendicular or any) and the offset of B from A
/// (within reach of each other, where the narrow phase is called).
#include <ThyrixLite/NarrowPhase.h>
#include <ThyrixLite/Primitive.h>

#include <fuzzer/FuzzedDataProvider.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <type_traits>

namespace {

using thyrix::Manifold;
using thyrix::real;
using thyrix::ShapeType;
using thyrix::Vector2;
using Long = long double;

constexpr bool isFloat = std::is_same_v<real, float>;
constexpr real epsilon = std::numeric_limits<real>::epsilon();

/// A shape as the simulator hands it to the narrow phase: centre or axis end points, radius;
/// a half-plane's point and unit normal.
struct Shape {
  ShapeType type = ShapeType::Circle;
  Vector2 p0;  // centre, first end, or the border's point
  Vector2 p1;  // second end, or the border's normal
  real radius = 0;
};

struct LongVector {
  Long x = 0;
  Long y = 0;
};
LongVector toLong(Vector2 v) { return {Long(v.x), Long(v.y)}; }
LongVector operator-(LongVector a, LongVector b) { return {a.x - b.x, a.y - b.y}; }
Long dot(LongVector a, LongVector b) { return a.x * b.x + a.y * b.y; }
Long cross(LongVector a, LongVector b) { return a.x * b.y - a.y * b.x; }
Long length(LongVector a) { return std::hypot(a.x, a.y); }

/// Distance from @p p to segment @p a - @p b, in long double.
Long pointSegment(LongVector p, LongVector a, LongVector b) {
  const LongVector d = b - a;
  const Long lengthSquared = dot(d, d);
  Long t = lengthSquared > 0 ? dot(p - a, d) / lengthSquared : 0;
  t = std::clamp(t, Long(0), Long(1));
  return length(p - LongVector{a.x + d.x * t, a.y + d.y * t});
}

/// Distance between segments (zero when they cross), in long double.
Long segmentSegment(LongVector a0, LongVector a1, LongVector b0, LongVector b1) {
  const Long d0 = cross(a1 - a0, b0 - a0);
  const Long d1 = cross(a1 - a0, b1 - a0);
  const Long d2 = cross(b1 - b0, a0 - b0);
  const Long d3 = cross(b1 - b0, a1 - b0);
  if (((d0 > 0 && d1 < 0) || (d0 < 0 && d1 > 0)) && ((d2 > 0 && d3 < 0) || (d2 < 0 && d3 > 0)))
    return 0;
  return std::min({pointSegment(a0, b0, b1), pointSegment(a1, b0, b1), pointSegment(b0, a0, a1),
                   pointSegment(b1, a0, a1)});
}

[[noreturn]] void fail(const char* what, Long value, Long bound) {
  std::fprintf(stderr, "NarrowPhaseFuzzer: %s (%Lg against %Lg)\n", what, value, bound);
  std::abort();
}

real consumeLog(FuzzedDataProvider& data, double lowExponent, double highExponent) {
  return static_cast<real>(
      std::pow(10.0, data.ConsumeFloatingPointInRange(lowExponent, highExponent)));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* bytes, std::size_t size) {
  FuzzedDataProvider data(bytes, size);
  // The pair, A of the lower type: border-circle, border-capsule, circles, circle-capsule,
  // capsules.
  constexpr ShapeType pairs[5][2] = {{ShapeType::HalfPlane, ShapeType::Circle},
                                     {ShapeType::HalfPlane, ShapeType::Capsule},
                                     {ShapeType::Circle, ShapeType::Circle},
                                     {ShapeType::Circle, ShapeType::Capsule},
                                     {ShapeType::Capsule, ShapeType::Capsule}};
  const int pair = data.ConsumeIntegralInRange(0, 4);
  const double farthest = isFloat ? 7 : 15;
  const Vector2 centre{real(data.ConsumeBool() ? -1 : 1) * consumeLog(data, -3, farthest),
                       real(data.ConsumeBool() ? -1 : 1) * consumeLog(data, -3, farthest)};
  const real angleA = static_cast<real>(data.ConsumeFloatingPointInRange(0.0, 6.3));
  real angleB = static_cast<real>(data.ConsumeFloatingPointInRange(0.0, 6.3));
  switch (data.ConsumeIntegralInRange(0, 3)) {  // the special relative angles
    case 0:
      angleB = angleA;
      break;
    case 1:
      angleB = angleA + real(1.5707963267948966);
      break;
    case 2:
      angleB = angleA + real(3.141592653589793);
      break;
    default:
      break;
  }
  Shape shapes[2];
  real extent = 0;  // the two shapes' sizes summed
  for (int k = 0; k < 2; ++k) {
    shapes[k].type = pairs[pair][k];
    shapes[k].radius = shapes[k].type == ShapeType::HalfPlane ? 0 : consumeLog(data, -4, 3);
    const real halfLength =
        shapes[k].type == ShapeType::Capsule ? consumeLog(data, -12, 3) : real(0);
    extent += shapes[k].radius + halfLength;
    const real angle = k == 0 ? angleA : angleB;
    shapes[k].p1 = {halfLength * std::cos(angle), halfLength * std::sin(angle)};
  }
  // B's centre: A's plus an offset within reach, sometimes snapped onto A's axis or centre.
  Vector2 offset{static_cast<real>(data.ConsumeFloatingPointInRange(-2.0, 2.0)) * extent,
                 static_cast<real>(data.ConsumeFloatingPointInRange(-2.0, 2.0)) * extent};
  switch (data.ConsumeIntegralInRange(0, 3)) {
    case 0:
      offset = {0, 0};
      break;
    case 1:
      offset = shapes[0].p1 * static_cast<real>(data.ConsumeFloatingPointInRange(-1.5, 1.5));
      break;
    default:
      break;
  }
  const real margin =
      static_cast<real>(data.ConsumeFloatingPointInRange(0.0, 0.5)) *
      std::min(shapes[0].type == ShapeType::HalfPlane ? shapes[1].radius : shapes[0].radius,
               shapes[1].radius);
  for (int k = 0; k < 2; ++k) {
    const Vector2 at = k == 0 ? centre : centre + offset;
    if (shapes[k].type == ShapeType::HalfPlane) {
      const real angle = k == 0 ? angleA : angleB;
      shapes[k].p0 = at;
      shapes[k].p1 = {std::cos(angle), std::sin(angle)};
    } else {
      const Vector2 half = shapes[k].p1;
      shapes[k].p0 = at - half;
      shapes[k].p1 = at + half;  // a circle's centre is p0 (half is zero)
    }
  }

  const Shape& a = shapes[0];
  const Shape& b = shapes[1];
  Manifold m;
  Long gap = 0;      // the shapes' distance, negative when they overlap (long double)
  Long between = 0;  // the distance of their axes (or centres); the border's plane is none
  const LongVector a0 = toLong(a.p0), a1 = toLong(a.p1), b0 = toLong(b.p0), b1 = toLong(b.p1);
  switch (pair) {
    case 0:
      m = thyrix::collideHalfPlaneCircle(a.p0, a.p1, b.p0, b.radius, margin);
      gap = dot(b0 - a0, a1) - b.radius;
      between = std::numeric_limits<Long>::infinity();
      break;
    case 1:
      m = thyrix::collideHalfPlaneCapsule(a.p0, a.p1, b.p0, b.p1, b.radius, margin);
      gap = std::min(dot(b0 - a0, a1), dot(b1 - a0, a1)) - b.radius;
      between = std::numeric_limits<Long>::infinity();
      break;
    case 2:
      m = thyrix::collideCircles(a.p0, a.radius, b.p0, b.radius, margin);
      between = length(b0 - a0);
      break;
    case 3:
      m = thyrix::collideCircleCapsule(a.p0, a.radius, b.p0, b.p1, b.radius, margin);
      between = pointSegment(a0, b0, b1);
      break;
    default:
      m = thyrix::collideCapsules(a.p0, a.p1, a.radius, b.p0, b.p1, b.radius, margin);
      between = segmentSegment(a0, a1, b0, b1);
      break;
  }
  if (pair >= 2) gap = between - a.radius - b.radius;

  // Rounding: the end points and surface points are rounded where they lie (up to 1e15 from
  // the origin), the rest at the pair's size; nearly parallel capsules measure their gap along
  // A's face normal, within 1 - cos(0.02) = 2e-4 of the axes' distance.
  const Long where = std::max(std::abs(Long(centre.x)), std::abs(Long(centre.y)));
  const Long tolerance = 64 * Long(epsilon) * (where + 4 * Long(extent)) +
                         (isFloat ? Long(1e-4) : Long(1e-8)) * Long(extent);
  const Long parallel = pair == 4 ? Long(4e-4) * between : Long(0);

  if (m.count < 0 || m.count > 2) fail("point count out of range", m.count, 2);
  if (gap > Long(margin) + tolerance + parallel && m.count != 0)
    fail("contact beyond the margin", gap, Long(margin));
  if (gap < Long(margin) - tolerance - parallel && m.count == 0)
    fail("no contact within the margin", gap, Long(margin));
  if (m.count == 0) return 0;
  if (!std::isfinite(m.normal.x) || !std::isfinite(m.normal.y)) fail("normal not finite", 0, 0);
  const Long normalLength = length(toLong(m.normal));
  if (std::abs(normalLength - 1) > 64 * Long(epsilon))
    fail("normal not of unit length", normalLength, 1);
  Long deepest = -std::numeric_limits<Long>::infinity();
  for (int i = 0; i < m.count; ++i) {
    const thyrix::ManifoldPoint& point = m.points[static_cast<std::size_t>(i)];
    if (!std::isfinite(point.point.x) || !std::isfinite(point.point.y) ||
        !std::isfinite(point.depth))
      fail("point or depth not finite", point.depth, 0);
    deepest = std::max(deepest, Long(point.depth));
  }
  // The depth is at least the overlap; it equals it unless the axes cross (where the separation
  // along an axis normal is reported, at most the shapes' size).
  if (deepest < -gap - tolerance - parallel) fail("depth below the overlap", deepest, -gap);
  const bool crossing = between <= tolerance;
  const Long highest = crossing ? 4 * Long(extent) + tolerance : -gap + tolerance + parallel;
  if (deepest > highest) fail("depth above the overlap", deepest, highest);
  return 0;
}
