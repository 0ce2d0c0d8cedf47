#pragma once
/// @file ElasticLink.h
/// @brief A virtual spring between anchor points on two bodies.

#include <ThyrixLite/GraphicalObject.h>
#include <ThyrixLite/PhysicalObject.h>

namespace thyrix {

/// A spring from an anchor on body A to an anchor on body B, pulling them toward `restLength`.
/// It is virtual: other objects pass through it, it makes no contacts.
///
/// Under `F = m v` a spring of stiffness k relaxes its stretch e at the rate `k w e`, with w the
/// inverse mass of the two anchors along the link (rotation included). An explicit step would be
/// stable only for `dt k w < 2`; the link applies instead the force of the implicit step,
/// `F = k e / (1 + dt k w)`, which relaxes the stretch by the factor `1 / (1 + dt k w)` per
/// step: for a link alone, stable and monotone for any stiffness, and equal to `k e` when
/// `dt k w` is small. Each link is made implicit on its own, not the network: where several
/// links pull on the same bodies their pulls add up, and a dense, stiff network can still
/// overshoot. Keep `dt` times the summed stiffness of the links on a body, over its mass,
/// below about 2 (Pac documents its own bound).
class ElasticLink : public GraphicalObject {
 public:
  /// @param a, b the two bodies
  /// @param anchorA, anchorB anchor points in the frames of @p a and @p b
  /// @param restLength the length the link pulls toward (m)
  /// @param stiffness force per metre of stretch (N/m)
  /// @throws InvalidArgument naming "ElasticLink.restLength" (negative or not finite),
  ///         "ElasticLink.stiffness" (not positive and finite), "ElasticLink.anchorA"/"anchorB",
  ///         or "ElasticLink.b" (the same body as a)
  ElasticLink(PhysicalObject& a, Vector2 anchorA, PhysicalObject& b, Vector2 anchorB,
              real restLength, real stiffness);

  /// Adds the spring force at both anchors to the bodies' external forces, for a step of @p dt.
  void applyForces(real dt);

  /// Commands the rest length. @throws InvalidArgument naming "ElasticLink.restLength".
  void setRestLength(real restLength);
  /// The commanded rest length.
  [[nodiscard]] real restLength() const { return restLength_; }
  /// The stiffness (N/m).
  [[nodiscard]] real stiffness() const { return stiffness_; }
  /// The current distance between the anchors.
  [[nodiscard]] real length() const { return (worldAnchorB() - worldAnchorA()).length(); }
  /// The tension applied by the last applyForces (positive pulls the anchors together).
  [[nodiscard]] real tension() const { return tension_; }
  /// Appends the rest length and the last tension to @p record (Elastoid::saveState()).
  void saveState(StateRecord& record) const {
    record.add(restLength_);
    record.add(tension_);
  }
  /// Reads back what saveState() appended.
  void restoreState(StateRecord::Reader& reader) {
    restLength_ = reader.value();
    tension_ = reader.value();
  }
  /// Anchor on body A, world coordinates.
  [[nodiscard]] Vector2 worldAnchorA() const { return a_->toWorld(anchorA_); }
  /// Anchor on body B, world coordinates.
  [[nodiscard]] Vector2 worldAnchorB() const { return b_->toWorld(anchorB_); }
  /// Body A.
  [[nodiscard]] PhysicalObject& bodyA() const { return *a_; }
  /// Body B.
  [[nodiscard]] PhysicalObject& bodyB() const { return *b_; }

  void draw(GUI& gui) const override;

 private:
  PhysicalObject* a_;
  PhysicalObject* b_;
  Vector2 anchorA_;
  Vector2 anchorB_;
  real restLength_;
  real stiffness_;
  real tension_ = 0;
  bool anchorAAtCentre_;  // zero anchors: no rotation to compute and no torque to apply
  bool anchorBAtCentre_;
};

}  // namespace thyrix
