#pragma once
/// @file World.h
/// @brief A process updated in discrete time steps: its objects, its clock and its drawing.

#include <ThyrixLite/ObjectList.h>
#include <ThyrixLite/PhysicalObject.h>

#include <concepts>
#include <cstdint>
#include <memory>
#include <span>

namespace thyrix {

class GUI;

/// A process updated in discrete time steps of timestep() seconds: each advanceTime() call
/// advances it by one step. It owns the objects it is made of and draws them (or whatever its
/// draw() shows), so that anything that steps and draws worlds (a console loop, GUIWx's
/// window) runs any kind of World. Simulator, the physics, is one kind; a program may derive
/// its own, physical or not.
class World {
 public:
  /// A world stepped by @p timestep seconds at each advanceTime().
  /// @throws InvalidArgument naming "World.timestep" unless positive and finite
  explicit World(real timestep = real(0.01));
  World(const World&) = delete;
  World& operator=(const World&) = delete;
  virtual ~World() = default;

  /// The objects, in registration order.
  ObjectList objects;

  /// Advances the world by one time step. World's own only counts the step (stepCount() and
  /// time() advance); an override updates its world, then calls its base class's
  /// advanceTime() (a subclass of Simulator: its per-step logic, then Simulator::advanceTime()),
  /// so that every program that steps the world, console or window, runs that logic.
  virtual void advanceTime() {
    ++stepCount_;
    time_ += static_cast<double>(timestep_);
  }

  /// The time step (s).
  [[nodiscard]] real timestep() const { return timestep_; }
  /// Sets the time step for the next steps.
  /// @throws InvalidArgument naming "World.timestep" unless positive and finite (the step is
  ///         then unchanged)
  void setTimestep(real timestep);
  /// Steps done so far.
  [[nodiscard]] std::uint64_t stepCount() const { return stepCount_; }
  /// Simulated time so far (s): the sum of the steps' time steps.
  [[nodiscard]] double time() const { return time_; }

  /// Takes ownership of @p object and returns it, typed as given.
  ///
  /// The object is validated first (sizes, masses, finite position and angle); on failure an
  /// InvalidArgument names the field and the world is left unchanged. An object owned
  /// elsewhere (registered with this or another world, a part of a body, a sub-body of
  /// another object: PhysicalObject::ownedElsewhere) is refused naming
  /// "World.registerObject.object" and left to its owner: @p object only releases it. An agent's
  /// sub-bodies (PhysicalObject::addSubBody) are registered right after it, all or nothing.
  /// Register between steps, not from an object's hooks during one: the step walks `objects` as it
  /// was when the step began.
  template <std::derived_from<PhysicalObject> T>
  T& registerObject(std::unique_ptr<T> object) {
    T* added = object.get();
    adopt(std::unique_ptr<PhysicalObject>(std::move(object)));
    return *added;
  }

  /// Draws the world: World's own draws every object, in registration order.
  virtual void draw(GUI& gui) const;

 protected:
  /// Called for validated objects before they join `objects` (an object and its sub-bodies),
  /// so that completing their registration cannot fail. May throw (the world is then
  /// unchanged); must leave no observable trace when it throws.
  virtual void prepareRegistration(std::span<PhysicalObject* const> added);
  /// Called once the object has joined `objects`; must not throw.
  virtual void completeRegistration(PhysicalObject& object, std::size_t index) noexcept;
  /// Sets the step count and the time (a restored state's: Simulator::restoreState()).
  void setClock(std::uint64_t stepCount, double time) {
    stepCount_ = stepCount;
    time_ = time;
  }

 private:
  friend class PhysicalObject;  // PhysicalObject::contacts() has its lists made when first read
  /// Makes each object's contact list if the world's contacts changed since it was made
  /// (PhysicalObject::contacts()); World's own has none to make.
  virtual void listContacts() {}
  void adopt(std::unique_ptr<PhysicalObject> object);

  real timestep_;
  std::uint64_t stepCount_ = 0;
  double time_ = 0;
};

}  // namespace thyrix
