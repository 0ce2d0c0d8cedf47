#include <ThyrixLite/InvalidArgument.h>
#include <ThyrixLite/Primitive.h>
#include <ThyrixLite/World.h>

namespace thyrix {

void World::draw(GUI& gui) const {
  for (const PhysicalObject& object : objects) object.draw(gui);
}

void World::prepareRegistration(PhysicalObject& /*object*/, std::size_t /*index*/) {}

void World::completeRegistration(PhysicalObject& /*object*/, std::size_t /*index*/) noexcept {}

void World::adopt(std::unique_ptr<PhysicalObject> object) {
  if (!object) throw InvalidArgument("World.registerObject.object", "must not be null");
  object->validate();
  for (const Primitive* part : object->primitives()) {
    if (&part->owner() != object.get())
      throw InvalidArgument(object->typeName() + ".owner",
                            "is a part of another body: register the body, not its part");
  }
  const std::size_t index = objects.items_.size();
  objects.items_.reserve(index + 1);  // the only allocation that could fail after preparing
  prepareRegistration(*object, index);
  objects.items_.push_back(std::move(object));
  completeRegistration(*objects.items_.back(), index);
}

}  // namespace thyrix
