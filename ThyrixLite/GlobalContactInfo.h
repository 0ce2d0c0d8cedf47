#pragma once
/// @file GlobalContactInfo.h
/// @brief One contact between two primitives, as the simulator stores it.

#include <ThyrixLite/Vector2.h>

#include <cstdint>

namespace thyrix {

class PhysicalObject;
class Primitive;

/// A contact point between primitive A (of body A) and primitive B (of body B).
///
/// The normal points from A to B: the contact force pushes B along `normal` and A against it.
/// `(shapeA, shapeB, feature)` identifies the contact stably from step to step while the same
/// features touch (the indices are those of the primitives in registration order).
struct GlobalContactInfo {
  PhysicalObject* objectA = nullptr;  ///< body A (the owner of primitiveA)
  PhysicalObject* objectB = nullptr;  ///< body B
  Primitive* primitiveA = nullptr;    ///< the primitive of A that is touched
  Primitive* primitiveB = nullptr;    ///< the primitive of B that is touched
  std::uint32_t bodyA = 0;            ///< index of objectA in Simulator::objects
  std::uint32_t bodyB = 0;            ///< index of objectB in Simulator::objects
  std::uint32_t shapeA = 0;           ///< index of primitiveA among the simulator's primitives
  std::uint32_t shapeB = 0;           ///< index of primitiveB among the simulator's primitives
  std::uint32_t feature = 0;          ///< which feature pair of the two primitives (0 or 1)
  // The force next to the identity: the next step's warm start reads both, and nothing else.
  real force = 0;  ///< normal force magnitude found by the contact solver, >= 0
  Vector2 point;   ///< contact point, midway between the two surfaces
  Vector2 normal;  ///< unit normal from A to B
  real depth = 0;  ///< overlap along the normal; negative is a gap (speculative contact)

  /// Whether @p other is the same contact, in this step or another: the same shapes and
  /// feature.
  [[nodiscard]] bool sameContactAs(const GlobalContactInfo& other) const {
    return shapeA == other.shapeA && shapeB == other.shapeB && feature == other.feature;
  }
};

}  // namespace thyrix
