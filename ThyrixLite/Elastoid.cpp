#include <ThyrixLite/Elastoid.h>
#include <ThyrixLite/InvalidArgument.h>
#include <ThyrixLite/Simulator.h>

#include <algorithm>
#include <limits>

namespace thyrix {

Elastoid::Elastoid()
    : PhysicalObject(std::numeric_limits<real>::infinity(), std::numeric_limits<real>::infinity()) {
  fixed = true;
}

ElasticLink& Elastoid::addLink(PhysicalObject& a, Vector2 anchorA, PhysicalObject& b,
                               Vector2 anchorB, real restLength, real stiffness) {
  const auto isBody = [this](const PhysicalObject& body) {
    return std::find(bodies_.begin(), bodies_.end(), &body) != bodies_.end();
  };
  if (!isBody(a)) throw InvalidArgument("Elastoid.addLink.a", "is not a body of this elastoid");
  if (!isBody(b)) throw InvalidArgument("Elastoid.addLink.b", "is not a body of this elastoid");
  links_.push_back(std::make_unique<ElasticLink>(a, anchorA, b, anchorB, restLength, stiffness));
  return *links_.back();
}

void Elastoid::onRegistered(Simulator& simulator) noexcept {
  simulator_ = &simulator;
  // One collision group per elastoid, unique in its world: the index it was registered at + 1.
  std::uint32_t group = 0;
  for (const PhysicalObject& object : simulator.objects) {
    ++group;
    if (&object == this) break;
  }
  for (PhysicalObject* body : bodies_)
    if (body->collisionGroup == 0) body->collisionGroup = group;
}

void Elastoid::computeDerivativesWithoutContacts() {
  const real dt = simulator_ != nullptr ? simulator_->timestep() : real(0);
  for (const auto& link : links_) link->applyForces(dt);
  PhysicalObject::computeDerivativesWithoutContacts();
}

void Elastoid::applyWeight(Vector2 /*gravity*/) {}

void Elastoid::integrate(real /*dt*/) {}

void Elastoid::validate() const {
  if (bodies_.empty()) throw InvalidArgument(typeName() + ".bodies", "must not be empty");
}

void Elastoid::draw(GUI& gui) const {
  for (const auto& link : links_) link->draw(gui);
}

void Elastoid::saveState(StateRecord& record) const {
  PhysicalObject::saveState(record);
  for (const auto& link : links_) link->saveState(record);
}

void Elastoid::restoreState(StateRecord::Reader& reader) {
  PhysicalObject::restoreState(reader);
  for (const auto& link : links_) link->restoreState(reader);
}

}  // namespace thyrix
