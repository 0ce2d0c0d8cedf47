#pragma once
/// @file ContactInfo.h
/// @brief One contact as seen from one of its two objects.

#include <ThyrixLite/Vector2.h>

#include <cstdint>

namespace thyrix {

class PhysicalObject;
class Primitive;

/// A contact of this object, in its `contacts` list. Written by Simulator::indexContacts;
/// `force` is filled in once the contact solver has run in the same step.
struct ContactInfo {
  std::uint32_t index = 0;              ///< position of the pair in Simulator::contacts
  PhysicalObject* other = nullptr;      ///< the other object (its owner body for a part)
  Primitive* primitive = nullptr;       ///< this object's primitive that is touched
  Primitive* otherPrimitive = nullptr;  ///< the other object's primitive
  Vector2 point;                        ///< contact point, world coordinates
  Vector2 normal;                       ///< unit direction of the contact force on this object
  real depth = 0;  ///< overlap (positive) or gap (negative, a speculative contact)
  real force = 0;  ///< magnitude of the contact force, >= 0
};

}  // namespace thyrix
