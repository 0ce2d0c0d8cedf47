#pragma once
/// @file MultiBodyObject.h
/// @brief An object whose primitives move relative to each other (an articulated agent), as the
/// contact solver sees it.

#include <ThyrixLite/PhysicalObject.h>
#include <ThyrixLite/SelfCollisionFilter.h>

#include <span>
#include <vector>

namespace thyrix {

/// An object made of sub-bodies that move relative to each other, such as ThyrixPro's
/// articulated agents. The simulator cannot treat it as one rigid body: for its contacts it asks
/// the object itself, through unit constraint forces, for velocities and responses (Kokkevis,
/// "Practical Physics for Articulated Characters", 2004; docs/Algorithms.md section 3).
///
/// Its primitives are attached with `Primitive::attachTo(*this, ..., /*rigid=*/false)`: the
/// object places them itself (in integrate() and when registered) instead of following a
/// fixed pose. Islands that contain such an object are solved on an explicitly formed matrix.
class MultiBodyObject : public PhysicalObject {
 public:
  /// One unit generalized force: a unit force along `direction` (world) at the world `point` of
  /// the sub-body carrying `primitive`, or, when `primitive` is null, a torque `torque` on the
  /// object's internal joint `joint`. It is also a constraint's Jacobian row: the velocity it
  /// "reads" is the point's velocity along `direction`, or `torque` times the joint's rate.
  struct UnitForce {
    const Primitive* primitive = nullptr;  ///< the touched primitive, or null for a joint
    Vector2 point;                         ///< world point of application
    Vector2 direction;                     ///< world direction (unit)
    int joint = -1;                        ///< joint index, when primitive is null
    real torque = 0;                       ///< joint torque per unit magnitude (+1 or -1)
  };

  /// A unilateral constraint of the object's own (a joint at its limit): `J u >= target` with
  /// a non-negative multiplier, J being `force`'s row.
  struct InternalConstraint {
    UnitForce force;  ///< the constraint's generalized force (and Jacobian row)
    real target = 0;  ///< the least allowed constraint velocity
  };

  /// The velocity @p force reads with the current velocities (those of the last
  /// computeDerivativesWithoutContacts(), i.e. without contact forces).
  [[nodiscard]] virtual real velocityAlong(const UnitForce& force) const = 0;

  /// Fills @p matrix (n x n, row-major, n = forces.size()) with `K_ij`, the velocity read by
  /// force i caused by a unit magnitude of force j: symmetric positive semi-definite.
  virtual void responseMatrix(std::span<const UnitForce> forces, std::span<real> matrix) = 0;

  /// Sets the final velocities: those without contacts plus the response to @p forces with
  /// magnitudes @p magnitudes (the solved constraint forces).
  virtual void applyConstraintForces(std::span<const UnitForce> forces,
                                     std::span<const real> magnitudes) = 0;

  /// Appends this step's internal constraints (joints at or beyond a limit) for a step of @p dt.
  virtual void collectInternalConstraints(real dt, std::vector<InternalConstraint>& out) = 0;

  /// Which of its own primitives may touch each other (e.g. links that are not neighbours).
  /// The simulator reads it for every candidate pair of two of the object's primitives, which
  /// is why it is a table and not a virtual function. Every pair may touch unless the
  /// subclass sets selfCollision_.
  [[nodiscard]] const SelfCollisionFilter& selfCollision() const { return selfCollision_; }

 protected:
  using PhysicalObject::PhysicalObject;

  /// The self-collision rules, set by the subclass when it is built, before registration.
  SelfCollisionFilter selfCollision_;
};

}  // namespace thyrix
