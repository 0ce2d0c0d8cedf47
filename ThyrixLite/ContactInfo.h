#pragma once
/// @file ContactInfo.h
/// @brief One contact as seen from one of its two objects.

#include <ThyrixLite/Vector2.h>

#include <cstdint>

namespace thyrix {

class PhysicalObject;
class Primitive;

/// What a contact transmits: a force at a point, or a torque (a joint at its limit,
/// ArticulatedAgentBase::linkContacts()).
enum class ContactType : std::uint8_t {
  Force,   ///< a force `sigma * force * n` at the point `p`
  Torque,  ///< a torque `sigma * force` (N m) about the point `p` (a joint at its limit)
};

/// A contact of this object, in its PhysicalObject::contacts() list, with the fields of the
/// original users' guide (`p` relative to the object, `n`, `sigma`, the type;
/// docs/PortingFromThyrix.md) and their world-frame forms.
///
/// Written by Simulator::indexContacts(), which the first read of a list after a detection
/// runs; `force` is filled in once the contact solver has run in the same step (a list read
/// before the solve is given the forces by it). Every field is a copy of the step's
/// GlobalContactInfo, seen from this object, and does not change when the object moves:
/// the force on this object is `sigma * force * n` = `force * normal`, applied at the world
/// point `point` = `r + p`, where `r` is the object's reference point when the contact was
/// detected (phase 2, before phase 8 moved it: after the step, `object.r + p` differs from
/// `point` by the step's displacement). For contacts restored by Simulator::restoreState(),
/// `r` is the restored reference point.
struct ContactInfo {
  /// `index` of a contact that is not in Simulator::contacts (a joint limit's torque contact).
  static constexpr std::uint32_t noIndex = ~std::uint32_t{0};

  std::uint32_t index = 0;              ///< position of the pair in Simulator::contacts
  PhysicalObject* other = nullptr;      ///< the other object (its owner body for a part)
  Primitive* primitive = nullptr;       ///< this object's primitive that is touched
  Primitive* otherPrimitive = nullptr;  ///< the other object's primitive
  /// Contact point relative to the object's reference point `r` at detection (m): `point - r`,
  /// in world axes.
  Vector2 p;
  Vector2 point;  ///< contact point, world coordinates (m)
  /// Unit normal of the contact (GlobalContactInfo::normal, from body A to body B); zero for a
  /// torque contact.
  Vector2 n;
  /// The sign of the force's direction on this object along `n`: -1 on body A, +1 on body B
  /// (for a torque contact, the sign of the torque on this object, counter-clockwise positive).
  real sigma = 1;
  Vector2 normal;  ///< unit direction of the contact force on this object, `sigma * n`
  real depth = 0;  ///< overlap (positive) or gap (negative, a speculative contact), m or rad
  real force = 0;  ///< magnitude of the contact force (N) or torque (N m), >= 0
  ContactType type = ContactType::Force;  ///< a force, or a torque (a joint at its limit)
};

}  // namespace thyrix
