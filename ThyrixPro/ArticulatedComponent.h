#pragma once
/// @file ArticulatedComponent.h
/// @brief A collision shape of an articulated agent that knows which of the agent's bodies (the
/// base or a link) it belongs to.

#include <ThyrixLite/CappedRectangle.h>
#include <ThyrixLite/Circle.h>
#include <ThyrixLite/Primitive.h>

#include <utility>

namespace thyrix {

/// A Circle or CappedRectangle (@p Shape) that is part of an articulated agent: its body()
/// is the agent's body it moves with, ArticulatedBody::base (-1) for the base, else the index
/// of a link.
///
/// The simulator hands an agent its contacts as primitives (MultiBodyObject::UnitForce); the
/// agent needs the body each one belongs to for every contact and test force of every step.
/// Storing the index in the shape makes that lookup O(1) and independent of addresses
/// (articulatedBodyOf()), instead of a search among the agent's primitives.
///
/// It behaves exactly like @p Shape otherwise (drawing, tactile sensors, colours). The agent
/// creates its components itself and attaches them with `attachTo(agent, ..., false)`: it
/// places them from its forward kinematics.
template <class Shape>
class ArticulatedComponent final : public Shape {
 public:
  /// A @p Shape built from @p args (a Circle: radius, mass; a CappedRectangle: half length,
  /// radius, mass) belonging to the agent's body @p body (-1 the base).
  template <class... Args>
  explicit ArticulatedComponent(int body, Args&&... args)
      : Shape(std::forward<Args>(args)...), body_(body) {}

  /// The agent's body this shape moves with: -1 the base, else a link index.
  [[nodiscard]] int body() const { return body_; }

 private:
  int body_;
};

/// The agent's body (-1 the base, else a link index) of @p primitive, which must be an
/// ArticulatedComponent (every primitive of an articulated agent is one): a switch on the
/// shape type, no virtual call and no search.
inline int articulatedBodyOf(const Primitive& primitive) {
  if (primitive.shapeType() == ShapeType::Circle)
    return static_cast<const ArticulatedComponent<Circle>&>(primitive).body();
  return static_cast<const ArticulatedComponent<CappedRectangle>&>(primitive).body();
}

}  // namespace thyrix
