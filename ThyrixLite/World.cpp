/// @file World.cpp
/// @brief Registration of a world's objects, its clock and its drawing.
#include <ThyrixLite/InvalidArgument.h>
#include <ThyrixLite/Primitive.h>
#include <ThyrixLite/World.h>

#include <algorithm>

namespace thyrix {

World::World(real timestep) : timestep_(timestep) { requirePositive(timestep, "World.timestep"); }

void World::setTimestep(real timestep) {
  requirePositive(timestep, "World.timestep");
  timestep_ = timestep;
}

void World::draw(GUI& gui) const {
  for (const PhysicalObject& object : objects) object.draw(gui);
}

void World::prepareRegistration(std::span<PhysicalObject* const> /*added*/) {}

void World::completeRegistration(PhysicalObject& /*object*/, std::size_t /*index*/) noexcept {}

namespace {
void validateForRegistration(const PhysicalObject& object) {
  object.validate();
  for (const Primitive* part : object.primitives()) {
    if (&part->owner() != &object)
      throw InvalidArgument(object.typeName() + ".owner",
                            "is a part of another body: register the body, not its part");
  }
}
}  // namespace

void World::adopt(std::unique_ptr<PhysicalObject> object) {
  const char* field = "World.registerObject.object";
  if (!object) throw InvalidArgument(field, "must not be null");
  // An object owned elsewhere came in a second unique_ptr: refusing it must not destroy it.
  if (object->world_ == this) {
    (void)object.release();
    throw InvalidArgument(field, "is already registered with this world");
  }
  if (const char* problem = object->ownedElsewhere()) {
    (void)object.release();
    throw InvalidArgument(field, problem);
  }
  // Everything is checked and prepared before anything is added: all or nothing.
  validateForRegistration(*object);
  for (const auto& body : object->subBodies_) validateForRegistration(*body);
  const std::size_t index = objects.items_.size();
  std::vector<PhysicalObject*> added{object.get()};
  for (const auto& body : object->subBodies_) added.push_back(body.get());
  if (index + added.size() > objects.items_.capacity())  // geometric growth: see Simulator
    objects.items_.reserve(std::max(index + added.size(), 2 * objects.items_.capacity()));
  prepareRegistration(added);

  // The object comes first, so its phase hooks run before its sub-bodies' in every step.
  std::vector<std::unique_ptr<PhysicalObject>> subBodies = std::move(object->subBodies_);
  object->world_ = this;
  objects.items_.push_back(std::move(object));
  completeRegistration(*objects.items_.back(), index);
  for (auto& body : subBodies) {
    body->world_ = this;
    body->carrier_ = nullptr;
    objects.items_.push_back(std::move(body));
    completeRegistration(*objects.items_.back(), objects.items_.size() - 1);
  }
}

}  // namespace thyrix
