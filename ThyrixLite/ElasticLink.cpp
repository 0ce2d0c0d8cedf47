#include <ThyrixLite/ElasticLink.h>
#include <ThyrixLite/GUI.h>
#include <ThyrixLite/InvalidArgument.h>

namespace thyrix {
namespace {
real checkedRestLength(real restLength) {
  if (!(restLength >= 0) || !std::isfinite(restLength))
    throw InvalidArgument("ElasticLink.restLength",
                          "must be non-negative and finite (got " + std::to_string(restLength) + ")");
  return restLength;
}
}  // namespace

ElasticLink::ElasticLink(PhysicalObject& a, Vector2 anchorA, PhysicalObject& b, Vector2 anchorB,
                         real restLength, real stiffness)
    : a_(&a), b_(&b), anchorA_(anchorA), anchorB_(anchorB),
      restLength_(checkedRestLength(restLength)), stiffness_(stiffness) {
  requirePositive(stiffness, "ElasticLink.stiffness");
  requireFinite(anchorA, "ElasticLink.anchorA");
  requireFinite(anchorB, "ElasticLink.anchorB");
  if (&a == &b) throw InvalidArgument("ElasticLink.b", "must be another body than a");
  color = colors::gray;
}

void ElasticLink::setRestLength(real restLength) { restLength_ = checkedRestLength(restLength); }

void ElasticLink::applyForces(real dt) {
  const Vector2 pa = worldAnchorA();
  const Vector2 pb = worldAnchorB();
  const Vector2 d = pb - pa;
  const real length = d.length();
  tension_ = 0;
  if (!(length > 0)) return;  // coincident anchors: no direction to pull along
  const Vector2 u = d / length;
  const real armA = cross(pa - a_->r, u);
  const real armB = cross(pb - b_->r, u);
  const real inverseMass = a_->inverseMass() + a_->inverseInertia() * armA * armA +
                           b_->inverseMass() + b_->inverseInertia() * armB * armB;
  tension_ = stiffness_ * (length - restLength_) / (1 + dt * stiffness_ * inverseMass);
  a_->applyForce(u * tension_, pa);
  b_->applyForce(u * -tension_, pb);
}

void ElasticLink::draw(GUI& gui) const { gui.drawLine(worldAnchorA(), worldAnchorB(), color); }

}  // namespace thyrix
