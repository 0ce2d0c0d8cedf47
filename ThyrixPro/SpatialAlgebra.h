#pragma once
/// @file SpatialAlgebra.h
/// @brief Planar spatial vector algebra (Featherstone 2008, chapter 2, planar vectors): motion
/// and force 3-vectors, the planar coordinate transform X and its dual, and the planar spatial
/// inertia with the quasistatic coefficients of docs/Algorithms.md section 2.
///
/// **Order of the components.** A planar spatial vector is a thyrix::Vector3 ordered
/// *(angular, linear x, linear y)*, as in Featherstone's planar vectors:
/// - a motion vector `(omega, vx, vy)`: the angular velocity and the linear velocity of the
///   body point that coincides with the frame origin, in the frame's axes;
/// - a force vector `(n, fx, fy)`: the moment about the frame origin and the force, in the
///   frame's axes.
///
/// So `Vector3::x` is the *angular* part here, unlike the `(vx, vy, omega)` order of the
/// ThyrixLite rigid-body quantities. Build and read spatial vectors through motionVector(),
/// forceVector(), angularPart() and linearPart() rather than through the fields, so the order
/// stays in one place.

#include <ThyrixLite/Matrix3.h>
#include <ThyrixLite/SymmetricMatrix3.h>
#include <ThyrixLite/ThyrixParameters.h>
#include <ThyrixLite/Vector2.h>
#include <ThyrixLite/Vector3.h>

namespace thyrix {

/// The planar spatial motion vector `(omega, v.x, v.y)`.
constexpr Vector3 motionVector(real omega, Vector2 v) { return {omega, v.x, v.y}; }

/// The planar spatial force vector `(moment, f.x, f.y)`.
constexpr Vector3 forceVector(real moment, Vector2 f) { return {moment, f.x, f.y}; }

/// The angular part of a planar spatial vector (angular velocity or moment).
constexpr real angularPart(const Vector3& spatial) { return spatial.x; }

/// The linear part of a planar spatial vector (linear velocity or force).
constexpr Vector2 linearPart(const Vector3& spatial) { return {spatial.y, spatial.z}; }

/// The spatial force, about @p origin and in world axes, of the world force @p force applied
/// at the world point @p point: `(cross(point - origin, force), force)`.
constexpr Vector3 spatialForceAt(Vector2 force, Vector2 point, Vector2 origin) {
  return forceVector(cross(point - origin, force), force);
}

/// A planar spatial inertia about a frame origin (Featherstone 2008, chapter 2: the rigid-body
/// inertia `I_O = [I_c + m c x c x^T, m c x; m c x^T, m 1]` specialised to the plane), here with
/// the quasistatic coefficients of `D` (docs/Algorithms.md section 2): the mass @p m (N s/m) and
/// the moment of inertia @p inertiaAboutCenter (N m s) about the centre of mass, which lies at
/// @p center from the origin, in the frame's axes:
///
///     [ I + m |c|^2   -m c_y   m c_x ]
///     [ -m c_y          m        0   ]
///     [  m c_x          0        m   ]
///
/// It maps the motion vector of the body to the force vector that drives it (`f = D v`).
constexpr SymmetricMatrix3 spatialInertia(real m, real inertiaAboutCenter, Vector2 center) {
  SymmetricMatrix3 d;
  d.xx = inertiaAboutCenter + m * center.lengthSquared();
  d.xy = -m * center.y;
  d.xz = m * center.x;
  d.yy = m;
  d.yz = 0;
  d.zz = m;
  return d;
}

/// The planar coordinate transform `X = B_X_A` from frame A to frame B, where B's origin lies
/// at @ref r and B's axes are turned by `theta` from A's, both expressed in A
/// (Featherstone 2008, chapter 2, planar vectors; the 3D formulas are in Table 2.2, p. 23):
///
///     X = [ 1                       0    0 ]      with c = cos(theta), s = sin(theta),
///         [ s r_x - c r_y           c    s ]      r = (r_x, r_y)
///         [ c r_x + s r_y          -s    c ]
///
/// X maps motion vectors in A coordinates to B coordinates. Force vectors map with the dual
/// `X* = X^-T`; the transpose `X^T` maps a force in B back to A, and `X^T D_B X` maps an
/// inertia in B back to A, which is how the articulated-body algorithm moves a child's terms
/// to its parent (Featherstone 2008, section 7.3).
struct PlanarTransform {
  real c = 1;  ///< cos(theta), theta the angle of B's axes in A
  real s = 0;  ///< sin(theta)
  Vector2 r;   ///< origin of B in A coordinates

  /// The transform to a frame turned by @p theta (rad) and placed at @p origin, in A.
  static PlanarTransform fromAngleAndOrigin(real theta, Vector2 origin);
  /// The transform to a frame with the same axes placed at @p origin, in A: a pure shift of
  /// the origin, the only kind the articulated-body algorithm needs in world-aligned frames.
  static constexpr PlanarTransform translation(Vector2 origin) { return {1, 0, origin}; }

  /// The first column's linear part `h = E (r x)`: `(s r_x - c r_y, c r_x + s r_y)`. A motion
  /// vector's angular part adds `h omega` to its linear part at B's origin.
  [[nodiscard]] constexpr Vector2 h() const { return {s * r.x - c * r.y, c * r.x + s * r.y}; }
  /// The rotation block `E` applied to a 2-vector of A coordinates.
  [[nodiscard]] constexpr Vector2 rotate(Vector2 a) const {
    return {c * a.x + s * a.y, -s * a.x + c * a.y};
  }
  /// The transposed rotation `E^T` applied to a 2-vector of B coordinates.
  [[nodiscard]] constexpr Vector2 rotateBack(Vector2 b) const {
    return {c * b.x - s * b.y, s * b.x + c * b.y};
  }

  /// `X m`: a motion vector given in A, in B coordinates.
  [[nodiscard]] constexpr Vector3 applyToMotion(const Vector3& m) const {
    const real omega = angularPart(m);
    return motionVector(omega, rotate(linearPart(m)) + h() * omega);
  }
  /// `X^-1 m`: a motion vector given in B, in A coordinates.
  [[nodiscard]] constexpr Vector3 inverseApplyToMotion(const Vector3& m) const {
    const real omega = angularPart(m);
    return motionVector(omega, rotateBack(linearPart(m) - h() * omega));
  }
  /// `X* f = X^-T f`: a force vector given in A, in B coordinates (the moment is now about
  /// B's origin).
  [[nodiscard]] constexpr Vector3 applyToForce(const Vector3& f) const {
    const Vector2 fb = rotate(linearPart(f));
    return forceVector(angularPart(f) - h().dot(fb), fb);
  }
  /// `X^T f`: a force vector given in B, in A coordinates (the moment is now about A's origin).
  [[nodiscard]] constexpr Vector3 transposeApplyToForce(const Vector3& f) const {
    const Vector2 fb = linearPart(f);
    return forceVector(angularPart(f) + h().dot(fb), rotateBack(fb));
  }
  /// `X^T D X`: a symmetric inertia (or articulated inertia) given in B, in A coordinates.
  [[nodiscard]] SymmetricMatrix3 transposeCongruence(const SymmetricMatrix3& d) const;

  /// X as a matrix, for motion vectors.
  [[nodiscard]] Matrix3 motionMatrix() const;
  /// `X* = X^-T` as a matrix, for force vectors.
  [[nodiscard]] Matrix3 forceMatrix() const;
};

// Pure translations. With world-aligned frames (E = 1) the transform of a child's frame at
// `r` from its parent's is `X = [1 0; h 1]`, `h = (-r_y, r_x)`: the three functions below are
// PlanarTransform::translation(r) applied without the rotation's multiplications by 1 and 0,
// for the articulated-body algorithm's inner loops.

/// `X m` for `X = PlanarTransform::translation(r)`: a motion vector at the old origin, moved to
/// the point @p r: `(omega, v + omega x r)`.
constexpr Vector3 translateMotion(const Vector3& m, Vector2 r) {
  const real omega = angularPart(m);
  return motionVector(omega, linearPart(m) + cross(omega, r));
}

/// `X^T f` for `X = PlanarTransform::translation(r)`: a force vector about the point @p r,
/// moved back to the old origin: `(n + r x f, f)`.
constexpr Vector3 translateForceBack(const Vector3& f, Vector2 r) {
  const Vector2 force = linearPart(f);
  return forceVector(angularPart(f) + cross(r, force), force);
}

/// `X^T D X` for `X = PlanarTransform::translation(r)`: an inertia about the point @p r, moved
/// back to the old origin (the parallel-axis theorem of spatial inertias).
constexpr SymmetricMatrix3 translateInertiaBack(const SymmetricMatrix3& d, Vector2 r) {
  const Vector2 h{-r.y, r.x};
  const Vector2 d11h{d.yy * h.x + d.yz * h.y, d.yz * h.x + d.zz * h.y};
  SymmetricMatrix3 result = d;
  result.xx += 2 * (d.xy * h.x + d.xz * h.y) + h.dot(d11h);
  result.xy += d11h.x;
  result.xz += d11h.y;
  return result;
}

/// A world force @p force at the world point @p point as a spatial force in the coordinates
/// of the frame at @p frameOrigin turned by @p frameAngle (rad) from the world axes: the
/// moment is about the frame origin, both parts in the frame's axes.
Vector3 spatialForceInFrame(Vector2 force, Vector2 point, Vector2 frameOrigin, real frameAngle);

}  // namespace thyrix
