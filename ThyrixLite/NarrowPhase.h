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
Manifold collideHalfPlaneCircle(Vector2 point, Vector2 normal, Vector2 centre, real radius,
                                real margin);

/// A border and a capsule with end-cap centres @p b0, @p b1: one point per end within reach.
Manifold collideHalfPlaneCapsule(Vector2 point, Vector2 normal, Vector2 b0, Vector2 b1, real radius,
                                 real margin);

/// Two circles. Coincident centres get the normal +x.
Manifold collideCircles(Vector2 centreA, real radiusA, Vector2 centreB, real radiusB, real margin);

/// A circle (A) and a capsule (B).
Manifold collideCircleCapsule(Vector2 centre, real radiusA, Vector2 b0, Vector2 b1, real radiusB,
                              real margin);

/// Two capsules. Nearly parallel overlapping capsules get two points; crossing axes are
/// separated along the axis normal that needs the least motion.
Manifold collideCapsules(Vector2 a0, Vector2 a1, real radiusA, Vector2 b0, Vector2 b1, real radiusB,
                         real margin);

/// The point of segment @p a - @p b closest to @p p.
Vector2 closestPointOnSegment(Vector2 a, Vector2 b, Vector2 p);

}  // namespace thyrix
