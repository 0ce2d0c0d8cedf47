#include <ThyrixLite/ElasticLink.h>
#include <ThyrixLite/GUI.h>
#include <ThyrixLite/InvalidArgument.h>

namespace thyrix {
namespace {
real checkedRestLength(real restLength) {
  if (!(restLength >= 0) || !std::isfinite(restLength))
    throw InvalidArgument("ElasticLink.restLength", "must be non-negative and finite (got " +
                                                        std::to_string(restLength) + ")");
  return restLength;
}
}  // namespace

ElasticLink::ElasticLink(PhysicalObject& a, Vector2 anchorA, PhysicalObject& b, Vector2 anchorB,
                         real restLength, real stiffness)
    : a_(&a),
      b_(&b),
      anchorA_(anchorA),
      anchorB_(anchorB),
      restLength_(checkedRestLength(restLength)),
      stiffness_(stiffness),
      anchorAAtCentre_(anchorA == Vector2{}),
      anchorBAtCentre_(anchorB == Vector2{}) {
  requirePositive(stiffness, "ElasticLink.stiffness");
  requireFinite(anchorA, "ElasticLink.anchorA");
  requireFinite(anchorB, "ElasticLink.anchorB");
  if (&a == &b) throw InvalidArgument("ElasticLink.b", "must be another body than a");
  color = colors::gray;
}

void ElasticLink::setRestLength(real restLength) { restLength_ = checkedRestLength(restLength); }

void ElasticLink::applyForces(real dt) {
  // Anchors at the centres of mass (the common case) need no rotation and give no torque.
  const Vector2 pa = anchorAAtCentre_ ? a_->r : worldAnchorA();
  const Vector2 pb = anchorBAtCentre_ ? b_->r : worldAnchorB();
  const Vector2 d = pb - pa;
  const real length = d.length();
  tension_ = 0;
  if (!(length > 0)) return;  // coincident anchors: no direction to pull along
  const Vector2 u = d / length;
  const real armA = anchorAAtCentre_ ? real(0) : cross(pa - a_->r, u);
  const real armB = anchorBAtCentre_ ? real(0) : cross(pb - b_->r, u);
  const real inverseMass = a_->inverseMass() + a_->inverseInertia() * armA * armA +
                           b_->inverseMass() + b_->inverseInertia() * armB * armB;
  tension_ = stiffness_ * (length - restLength_) / (1 + dt * stiffness_ * inverseMass);
  const Vector2 force = u * tension_;
  a_->externalForce += force;
  a_->externalTorque += armA * tension_;  // cross(pa - r_a, force)
  b_->externalForce -= force;
  b_->externalTorque -= armB * tension_;
}

void ElasticLink::draw(GUI& gui) const { gui.drawLine(worldAnchorA(), worldAnchorB(), color); }

}  // namespace thyrix
