#pragma once
/// @file World.h
/// @brief The set of objects that make up a simulated world.

#include <ThyrixLite/ObjectList.h>
#include <ThyrixLite/PhysicalObject.h>

#include <concepts>
#include <memory>
#include <span>

namespace thyrix {

class GUI;

/// Owns the objects of a world and draws them. Simulator adds time stepping.
class World {
 public:
  World() = default;
  World(const World&) = delete;
  World& operator=(const World&) = delete;
  virtual ~World() = default;

  /// The objects, in registration order.
  ObjectList objects;

  /// Takes ownership of @p object and returns it, typed as given.
  ///
  /// The object is validated first (sizes, masses, finite position and angle); on failure an
  /// InvalidArgument names the field and the world is left unchanged. An agent's sub-bodies
  /// (PhysicalObject::addSubBody) are registered right after it, all or nothing. Register
  /// between steps, not from an object's hooks during one: the step walks `objects` as it was
  /// when the step began.
  template <std::derived_from<PhysicalObject> T>
  T& registerObject(std::unique_ptr<T> object) {
    T* added = object.get();
    adopt(std::unique_ptr<PhysicalObject>(std::move(object)));
    return *added;
  }

  /// Draws every object, in registration order.
  virtual void draw(GUI& gui) const;

 protected:
  /// Called for validated objects before they join `objects` (an object and its sub-bodies),
  /// so that completing their registration cannot fail. May throw (the world is then
  /// unchanged); must leave no observable trace when it throws.
  virtual void prepareRegistration(std::span<PhysicalObject* const> added);
  /// Called once the object has joined `objects`; must not throw.
  virtual void completeRegistration(PhysicalObject& object, std::size_t index) noexcept;

 private:
  void adopt(std::unique_ptr<PhysicalObject> object);
};

}  // namespace thyrix
