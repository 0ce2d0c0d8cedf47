#include <ThyrixLite/InvalidArgument.h>
#include <ThyrixLite/PhysicalObject.h>
#include <ThyrixLite/Primitive.h>
#include <ThyrixLite/VisualSensor.h>
#include <ThyrixLite/World.h>

namespace thyrix {

// Defined only here, for the one definition of controll(): elsewhere the type stays incomplete,
// so a call of controll() cannot compile.
struct renamed::controll_is_now_control {};

void PhysicalObject::control() {}

renamed::controll_is_now_control PhysicalObject::controll() { return {}; }

void PhysicalObject::updateSensors(const World& /*world*/) {}

std::span<ContactInfo> PhysicalObject::contacts() const {
  if (world_ != nullptr) world_->listContacts();
  return contacts_;
}

std::span<const VisualSensor> PhysicalObject::visualSensors() const { return {}; }

void PhysicalObject::saveState(StateRecord& record) const {
  record.add(r);
  record.add(alpha);
  record.add(v);
  record.add(omega);
  record.add(externalForce);
  record.add(externalTorque);
  record.add(fixed);
  record.addWord(collisionGroup);
  record.add(boxMin);  // (the next detection recomputes them: saved for what is drawn until then)
  record.add(boxMax);
  for (const Primitive* part : primitives_)
    if (part != this) part->saveState(record);
}

void PhysicalObject::restoreState(StateRecord::Reader& reader) {
  r = reader.vector();
  alpha = reader.value();
  v = reader.vector();
  omega = reader.value();
  externalForce = reader.vector();
  externalTorque = reader.value();
  fixed = reader.flag();
  collisionGroup = static_cast<std::uint32_t>(reader.word());
  boxMin = reader.vector();
  boxMax = reader.vector();
  for (Primitive* part : primitives_)
    if (part != this) part->restoreState(reader);
}

void PhysicalObject::onRegistered(Simulator& /*simulator*/) noexcept {}

void PhysicalObject::validate() const {
  const std::string type = typeName();
  const auto field = [&](const char* name) { return type + "." + name; };
  if (!std::isfinite(r.x) || !std::isfinite(r.y))
    throw InvalidArgument(field("r"), "must be finite");
  if (!std::isfinite(alpha)) throw InvalidArgument(field("alpha"), "must be finite");
  if (!std::isfinite(externalForce.x) || !std::isfinite(externalForce.y))
    throw InvalidArgument(field("externalForce"), "must be finite");
  if (!std::isfinite(externalTorque))
    throw InvalidArgument(field("externalTorque"), "must be finite");
  if (!fixed) {
    requireInvertible(m, field("m").c_str());
    requireInvertible(I, field("I").c_str());
  }
}

const char* PhysicalObject::ownedElsewhere() const {
  if (world_ != nullptr) return "is already registered with a world";
  if (carrier_ != nullptr) return "is a sub-body of another object, which registers it";
  for (const Primitive* primitive : primitives_) {
    if (primitive == this && &primitive->owner() != this)
      return "is a part of another body: register the body, not its part";
  }
  return nullptr;
}

void PhysicalObject::adoptSubBody(std::unique_ptr<PhysicalObject> body) {
  const char* field = "PhysicalObject.addSubBody.body";
  if (!body) throw InvalidArgument(field, "must not be null");
  if (body.get() == this) {
    (void)body.release();  // this object's own pointer: the refusal must not destroy it
    throw InvalidArgument(field, "must be another object than this one");
  }
  if (const char* problem = body->ownedElsewhere()) {
    (void)body.release();  // its owner keeps it: the refusal must not destroy it
    throw InvalidArgument(field, problem);
  }
  subBodies_.reserve(subBodies_.size() + 1);  // nothing below fails
  body->carrier_ = this;
  subBodies_.push_back(std::move(body));
}

void PhysicalObject::applyForce(Vector2 force, Vector2 worldPoint) {
  externalForce += force;
  externalTorque += cross(worldPoint - r, force);
}

}  // namespace thyrix
