#pragma once
/// @file LinkContactInfo.h
/// @brief One contact of an articulated agent, seen from the body (base or link) it touches.

#include <ThyrixLite/ContactInfo.h>
#include <ThyrixLite/ThyrixParameters.h>
#include <ThyrixLite/Vector2.h>

namespace thyrix {

class PhysicalObject;
class Primitive;

/// A contact of an articulated agent, as ArticulatedAgentBase::linkContact() reports it: the
/// ContactInfo of the agent's `contacts` plus the agent's body it touches. A contact between
/// two of the agent's own links (self-collision) appears twice in `contacts`, once from each
/// side, with `other` the agent itself.
struct LinkContactInfo {
  int body = -1;                        ///< the agent's body touched: -1 the base, else a link
  Vector2 point;                        ///< contact point, world coordinates (m)
  Vector2 normal;                       ///< unit direction of the contact force on this body
  real depth = 0;                       ///< overlap (positive) or gap (negative), m
  real force = 0;                       ///< magnitude of the contact force (N), >= 0
  PhysicalObject* other = nullptr;      ///< the other object (the agent itself for a self-contact)
  Primitive* otherPrimitive = nullptr;  ///< the other object's primitive that is touched
};

}  // namespace thyrix
