#pragma once
/// @file ArticulatedLink.h
/// @brief The description of one link of an articulated body: its parent, revolute joint,
/// geometry, quasistatic mass and inertia, and optional joint limits.

#include <ThyrixLite/ThyrixParameters.h>
#include <ThyrixLite/Vector2.h>

namespace thyrix {

/// One rigid link of an articulated body's tree, attached to its parent by a revolute joint.
///
/// **Frames.** The link frame has its origin at the joint and its x axis along the link; it is
/// turned by the joint angle `q` from the parent's frame. The parent's frame is the base frame
/// (origin at the base's centre of mass, turned by the base angle) or the parent link's frame.
///
/// A plain aggregate: fill the fields, or use capsule() for a uniform capsule. It is checked
/// by validate() when an ArticulatedBody is built from it.
struct ArticulatedLink {
  /// The parent body: ArticulatedLink::base (-1) for the base, else the index of an *earlier*
  /// link, so parents come before their children and a loop cannot be expressed.
  int parent = base;
  /// The joint, in the parent's frame (m): for the base, relative to the base's centre of
  /// mass in its axes; for a link, a point of the parent link's frame, typically its tip
  /// `(length, 0)`.
  Vector2 jointPosition;
  /// The distance from the joint to the tip along the link's x axis (m); children usually
  /// attach at tip().
  real length = 1;
  /// The centre of mass in the link frame (m): `(length / 2, 0)` for a symmetric link.
  Vector2 centerOfMass{real(0.5), 0};
  /// Quasistatic mass: force per unit velocity of the centre of mass (N s/m).
  real mass = 1;
  /// Quasistatic moment of inertia about the centre of mass: torque per unit angular velocity
  /// (N m s).
  real inertia = 1;
  /// Whether the joint angle is limited to [qMin, qMax]. The limits are a description for the
  /// contact solver (unilateral torque constraints); ArticulatedBody does not enforce them.
  bool hasLimits = false;
  real qMin = 0;  ///< lower joint limit (rad), used when hasLimits
  real qMax = 0;  ///< upper joint limit (rad), used when hasLimits

  /// The parent index that means "the base".
  static constexpr int base = -1;

  /// A uniform capsule link (the shape of a CappedRectangle) of half length @p halfLength and
  /// radius @p radius, with the joint at the centre of one end cap and the tip at the centre of
  /// the other: `length = 2 halfLength`, centre of mass `(halfLength, 0)`, inertia of a uniform
  /// capsule of mass @p mass about its centre.
  /// @throws InvalidArgument naming "ArticulatedLink.length", ".radius" or ".mass" unless
  /// positive and finite
  static ArticulatedLink capsule(int parent, Vector2 jointPosition, real halfLength, real radius,
                                 real mass);

  /// The tip `(length, 0)` in the link frame, where a child usually attaches.
  [[nodiscard]] constexpr Vector2 tip() const { return {length, 0}; }

  /// Checks the fields of the link at @p index in its tree.
  /// @throws InvalidArgument naming "ArticulatedLink.parent" unless `-1 <= parent < index` (a
  /// loop or a forward reference), ".jointPosition" or ".centerOfMass" unless finite,
  /// ".length", ".mass" or ".inertia" unless positive and finite, ".qMin" or ".qMax" unless
  /// finite with `qMin <= qMax` when hasLimits
  void validate(int index) const;
};

}  // namespace thyrix
