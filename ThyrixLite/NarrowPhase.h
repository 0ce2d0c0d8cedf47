#pragma once
/// @file NarrowPhase.h
/// @brief Exact contact geometry between pairs of primitives in world coordinates.
///
/// Conventions shared by every function: the normal is a unit vector from shape A to shape B;
/// a point's depth is the overlap along the normal (negative: a gap); the point lies midway
/// between the two surfaces. Points are reported while the gap is below @p margin, so a contact
/// can be handled before the shapes touch (speculative contacts).

#include <ThyrixLite/Vector2.h>

#include <array>
#include <cstdint>
#include <type_traits>

namespace thyrix {

/// One contact point of a manifold.
struct ManifoldPoint {
  Vector2 point;              ///< midway between the surfaces
  real depth = 0;             ///< overlap along the normal, negative for a gap
  std::uint32_t feature = 0;  ///< stable identity of the touching features (0 or 1)
};

/// The contact points between two shapes: none, one, or two sharing a normal (flat contact
/// of a capsule on a border or on a parallel capsule).
struct Manifold {
  Vector2 normal;                         ///< unit normal from A to B
  int count = 0;                          ///< number of valid points
  std::array<ManifoldPoint, 2> points{};  ///< the first `count` are valid
};

/// A border (half-plane through @p point with unit @p normal into the free side) and a circle.
/// (Inline, as collideCircles: a pile's steps call them thousands of times.)
inline Manifold collideHalfPlaneCircle(Vector2 point, Vector2 normal, Vector2 centre, real radius,
                                       real margin);

/// A border and a capsule with end-cap centres @p b0, @p b1: one point per end within reach.
Manifold collideHalfPlaneCapsule(Vector2 point, Vector2 normal, Vector2 b0, Vector2 b1, real radius,
                                 real margin);

/// Two circles. Coincident centres get the normal +x.
inline Manifold collideCircles(Vector2 centreA, real radiusA, Vector2 centreB, real radiusB,
                               real margin);

/// A circle (A) and a capsule (B).
Manifold collideCircleCapsule(Vector2 centre, real radiusA, Vector2 b0, Vector2 b1, real radiusB,
                              real margin);

/// Two capsules. Nearly parallel overlapping capsules get two points; crossing axes are
/// separated along the axis normal that needs the least motion.
Manifold collideCapsules(Vector2 a0, Vector2 a1, real radiusA, Vector2 b0, Vector2 b1, real radiusB,
                         real margin);

/// The point of segment @p a - @p b closest to @p p.
Vector2 closestPointOnSegment(Vector2 a, Vector2 b, Vector2 p);

namespace narrow_phase {

/// Below this fraction of the shapes' size two centres or axes count as coincident.
inline constexpr real relativeTolerance = std::is_same_v<real, float> ? real(1e-5) : real(1e-10);

/// A one-point manifold between the surface points @p surfaceA and @p surfaceB.
inline Manifold single(Vector2 normal, Vector2 surfaceA, Vector2 surfaceB,
                       std::uint32_t feature = 0) {
  Manifold m;
  m.normal = normal;
  m.count = 1;
  m.points[0] = {(surfaceA + surfaceB) * real(0.5), dot(surfaceA - surfaceB, normal), feature};
  return m;
}

}  // namespace narrow_phase

inline Manifold collideHalfPlaneCircle(Vector2 point, Vector2 normal, Vector2 centre, real radius,
                                       real margin) {
  const real distance = dot(centre - point, normal);
  if (distance - radius >= margin) return {};
  return narrow_phase::single(normal, centre - normal * distance, centre - normal * radius);
}

namespace narrow_phase {

/// collideCircles without a Manifold: false when out of reach, else true with the one point's
/// @p normal and @p point (feature 0). For a caller that stores the point itself.
inline bool circlesPoint(Vector2 centreA, real radiusA, Vector2 centreB, real radiusB, real margin,
                         Vector2& normal, ManifoldPoint& point) {
  const Vector2 d = centreB - centreA;
  const real distance = d.length();
  if (distance - radiusA - radiusB >= margin) return false;
  normal = distance > relativeTolerance * (radiusA + radiusB) ? d / distance : Vector2{1, 0};
  const Vector2 surfaceA = centreA + normal * radiusA;
  const Vector2 surfaceB = centreB - normal * radiusB;
  point = {(surfaceA + surfaceB) * real(0.5), dot(surfaceA - surfaceB, normal), 0};
  return true;
}

}  // namespace narrow_phase

inline Manifold collideCircles(Vector2 centreA, real radiusA, Vector2 centreB, real radiusB,
                               real margin) {
  Manifold m;
  if (narrow_phase::circlesPoint(centreA, radiusA, centreB, radiusB, margin, m.normal, m.points[0]))
    m.count = 1;
  return m;
}

}  // namespace thyrix
