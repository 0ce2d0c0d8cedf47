#include <ThyrixLite/ComposedPhysicalObject.h>
#include <ThyrixLite/InvalidArgument.h>

namespace thyrix {

ComposedPhysicalObject::ComposedPhysicalObject() : PhysicalObject(0, 0) {}

void ComposedPhysicalObject::addPart(std::unique_ptr<Primitive> part, Vector2 relativePosition,
                                     real relativeAngle) {
  if (!part) throw InvalidArgument("ComposedPhysicalObject.part", "must not be null");
  if (const char* problem = part->ownedElsewhere()) {
    (void)part.release();  // its owner keeps it: the refusal must not destroy it
    throw InvalidArgument("ComposedPhysicalObject.part", problem);
  }
  if (part->shapeType() == ShapeType::HalfPlane)
    throw InvalidArgument("ComposedPhysicalObject.part", "cannot be a Border");
  requireFinite(relativePosition, "ComposedPhysicalObject.relativePosition");
  requireFinite(relativeAngle, "ComposedPhysicalObject.relativeAngle");
  parts_.reserve(parts_.size() + 1);  // so nothing below can fail half-way

  // Parts' local positions are relative to the centre of mass (the body's r); the building
  // frame stays put in the world while the centre of mass moves within it.
  const Vector2 buildingOrigin = r - centreOffset_.rotated(alpha);
  const real newMass = m + part->m;
  Vector2 centre = relativePosition * part->m;  // new centre of mass, building frame
  for (const auto& existing : parts_)
    centre += (existing->localPosition() + centreOffset_) * existing->m;
  centre = centre / newMass;

  real inertia = 0;
  for (const auto& existing : parts_) {
    const Vector2 p = existing->localPosition() + centreOffset_ - centre;
    existing->attachTo(*this, p, existing->localAngle());
    inertia += existing->I + existing->m * p.lengthSquared();
  }
  const Vector2 p = relativePosition - centre;
  part->attachTo(*this, p, relativeAngle);
  inertia += part->I + part->m * p.lengthSquared();

  centreOffset_ = centre;
  r = buildingOrigin + centre.rotated(alpha);
  m = newMass;
  I = inertia;
  addPrimitive(*part);
  parts_.push_back(std::move(part));
  for (const auto& existing : parts_) existing->followOwner();
}

void ComposedPhysicalObject::validate() const {
  if (parts_.empty()) throw InvalidArgument("ComposedPhysicalObject.parts", "must not be empty");
  PhysicalObject::validate();
}

void ComposedPhysicalObject::draw(GUI& gui) const {
  for (const auto& part : parts_) part->draw(gui);
}

}  // namespace thyrix
