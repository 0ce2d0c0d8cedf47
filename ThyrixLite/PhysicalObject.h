#pragma once
/// @file PhysicalObject.h
/// @brief A rigid body under quasistatic dynamics, `F = m v`.

#include <ThyrixLite/ContactInfo.h>
#include <ThyrixLite/GraphicalObject.h>
#include <ThyrixLite/Renamed.h>
#include <ThyrixLite/StateRecord.h>
#include <ThyrixLite/ThyrixParameters.h>
#include <ThyrixLite/Vector2.h>
#include <Tools/Inlining.h>

#include <bit>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <type_traits>
#include <vector>

namespace thyrix {

class Primitive;
class Simulator;
class VisualSensor;
class World;

/// A rigid body of the plane with quasistatic (Aristotelian) dynamics: its velocity is the
/// force on it divided by its mass, `v = F / m` and `omega = torque / I`, so it stops the
/// instant nothing pushes it.
///
/// The fields are public, as in the users' guide (docs/UsersGuide.md): set `r` and `alpha` before
/// or after registering the object with a Simulator; add to `externalForce` and `externalTorque`
/// (typically in control()) to push it during the next step. A body collides through its
/// primitives(): a Circle or CappedRectangle is its own single primitive.
///
/// Objects are not copyable or movable: the simulator and contacts refer to them by address.
class PhysicalObject : public GraphicalObject {
 public:
  PhysicalObject(const PhysicalObject&) = delete;
  PhysicalObject& operator=(const PhysicalObject&) = delete;
  ~PhysicalObject() override = default;

  // The fields every step reads come first, together (184 bytes with the object's first 16),
  // ordered so that each phase that visits the bodies reads few cache lines of each (a pile's
  // circles, in simulated caches, about as few as before the direction cache came here). The
  // pose sits in the 64 bytes from the 64th with the flags and Primitive's direction cache: an
  // articulated link (a CappedRectangle, aligned to 64 bytes) is placed by its agent and read
  // back by the simulator in that one line at each step, not two.
  /// This step's contacts of this object (ContactInfo): a view into the simulator's contact
  /// storage, valid until the next step starts or the world's contacts change. The simulator
  /// lists them on the first read after its contacts changed (Simulator::indexContacts()), so
  /// that a step in which nothing reads them pays nothing for them; empty for an object not
  /// registered with a Simulator. Not to be called from two threads at once on one world.
  [[nodiscard]] std::span<ContactInfo> contacts() const;

 private:
  std::span<ContactInfo> contacts_;  // the list as the simulator last indexed it

 public:
  Vector2 boxMin;  ///< lower corner of the axis-aligned bounding box, updated each step
  Vector2 boxMax;  ///< upper corner of the axis-aligned bounding box, updated each step

 private:
  // Primitive's cache of its direction, `(cos, sin)` of directionAngle_ (Primitive::direction()
  // and place()), unused by other objects. It belongs to the primitive but sits here, next to
  // the pose: a link's kinematics writes both at each step and the simulator reads them back
  // (measured: one line instead of two, for a chain of 1000 links).
  Vector2 direction_{1, 0};

 public:
  Vector2 r;       ///< position of the centre of mass, world coordinates (m)
  real alpha = 0;  ///< orientation (rad, counter-clockwise)

 private:
  // (After alpha: place() writes the two, equal, with one store; and the pairs above are at
  // multiples of 16 bytes, each stored at once.)
  real directionAngle_ = 0;

 public:
  bool fixed = false;  ///< a fixed object never moves: it has infinite mass

 private:
  // True for a primitive with tactile sensors, kept by Primitive::installTactileSensors alone
  // (private: a subclass cannot make it disagree with the sensors). The simulator notes such
  // primitives as it reads their pose, from the same cache line (in what is otherwise padding).
  bool sensing_ = false;
  // Primitive's: true when it keeps a fixed pose in its owner's frame (Primitive::attachTo).
  // Here, in padding next to the pose, for the same reason as the direction above.
  bool rigid_ = true;

 public:
  /// Objects sharing a non-zero group never touch each other (the bodies of one agent, say);
  /// group 0 touches everything.
  std::uint32_t collisionGroup = 0;
  Vector2 v;                ///< linear velocity (m/s), computed each step
  real omega = 0;           ///< angular velocity (rad/s), computed each step
  real m;                   ///< quasistatic mass: force per unit velocity (N s/m)
  real I;                   ///< moment of inertia about the centre of mass: torque per unit rate
  Vector2 externalForce;    ///< force accumulated for the next step, reset after use (N)
  real externalTorque = 0;  ///< torque accumulated for the next step, reset after use (N m)

  /// Phase 5 of a step: velocities from the accumulated external force and torque alone,
  /// `v = F / m`, `omega = torque / I`; the accumulators are then reset to zero. (With a
  /// gravity field, the simulator has added the weight to them just before: applyWeight().)
  virtual void computeDerivativesWithoutContacts() { velocitiesFromAccumulators<false>({}); }

  /// Phase 5 of a step, while the simulator has a gravity field (Simulator::setGravity()): adds
  /// this object's weight in the field @p gravity (m/s) to its accumulators, just before its
  /// computeDerivativesWithoutContacts(). The default adds `m * gravity` to `externalForce` (at
  /// the centre of mass, no torque), nothing for a fixed object.
  ///
  /// The simulator calls it, once per step, for every registered object that is not exactly one
  /// of the core shapes (Circle, CappedRectangle, Border, ComposedPhysicalObject, told by
  /// type: a subclass of Circle is weighed here even if it overrides nothing); the core shapes
  /// move at `F / m + gravity` inside their own velocity computation instead, which gives the same
  /// velocities up to the rounding of `(F + m g) / m`. Override it for an object whose parts
  /// move relative to each other (an articulated agent weighs each body at its own centre of
  /// mass) or that has no mass of its own (an Elastoid, whose bodies are weighed as objects).
  virtual void applyWeight(Vector2 gravity) {
    if (!fixed) externalForce += gravity * m;
  }

  /// Phase 7 of a step: sensors to controller to motor forces for the next step.
  /// The default does nothing (a passive object).
  virtual void control();
  /// The original spelling of control(): overriding or calling it fails to compile, naming
  /// control() (ThyrixLite/Renamed.h).
  virtual renamed::controll_is_now_control controll() final;

  /// Phase 8 of a step: moves the body by its velocity for @p dt (explicit Euler).
  virtual void integrate(real dt) {
    if (fixed) return;
    r += v * dt;
    alpha += omega * dt;
  }

  /// Checks the state before registration; throws InvalidArgument naming the field.
  virtual void validate() const;

  /// Phase 2 of a step, after contact detection: updates this object's visual sensors from
  /// the world. The default does nothing.
  virtual void updateSensors(const World& world);

  /// Appends to @p record everything of this object that can change the next step (Simulator::
  /// saveState()): the pose, velocities, pending force and torque, `fixed`, `collisionGroup`, the
  /// box, then each part's (Primitive::saveState()). A subclass with state of its own (an agent's
  /// controller, a link's commanded length) overrides it, calls its base's first, then appends
  /// its own values.
  virtual void saveState(StateRecord& record) const;
  /// Reads back, in the same order, what saveState() appended (Simulator::restoreState()).
  virtual void restoreState(StateRecord::Reader& reader);

  /// The visual sensors this object carries, for drawing and inspection (none by default).
  [[nodiscard]] virtual std::span<const VisualSensor> visualSensors() const;

  /// The class name used in error messages, e.g. "Circle".
  [[nodiscard]] virtual std::string typeName() const { return "PhysicalObject"; }

  /// The collision geometry of this body.
  [[nodiscard]] std::span<Primitive* const> primitives() const { return primitives_; }

  /// The world this object is registered with, or nullptr before registration.
  [[nodiscard]] const World* registeredWith() const { return world_; }
  /// Why this object cannot be handed to a new owner: it is registered with a world, a
  /// sub-body of another object, or a part of another body; nullptr when it is free.
  [[nodiscard]] const char* ownedElsewhere() const;

  /// 1 / m, or 0 for a fixed body.
  [[nodiscard]] real inverseMass() const { return fixed ? real(0) : 1 / m; }
  /// 1 / I, or 0 for a fixed body.
  [[nodiscard]] real inverseInertia() const { return fixed ? real(0) : 1 / I; }

  /// Adds @p force applied at @p worldPoint to the accumulators (force and its torque).
  void applyForce(Vector2 force, Vector2 worldPoint);
  /// A point given in the body frame, in world coordinates.
  [[nodiscard]] Vector2 toWorld(Vector2 localPoint) const { return r + localPoint.rotated(alpha); }
  /// A world point in the body frame.
  [[nodiscard]] Vector2 toLocal(Vector2 worldPoint) const {
    return (worldPoint - r).rotated(-alpha);
  }
  /// Velocity of the body's material point at @p worldPoint.
  [[nodiscard]] Vector2 velocityAt(Vector2 worldPoint) const {
    return v + cross(omega, worldPoint - r);
  }

 protected:
  /// @param mass quasistatic mass, @param momentOfInertia about the centre of mass.
  /// Subclasses validate them, naming their own fields.
  PhysicalObject(real mass, real momentOfInertia) : m(mass), I(momentOfInertia) {}

  /// Makes @p primitive part of this body's collision geometry.
  void addPrimitive(Primitive& primitive) { primitives_.push_back(&primitive); }

  /// Hands @p body to this object until registration, when the world registers it right
  /// after this object and takes ownership (how an agent brings its several bodies along).
  /// @throws InvalidArgument naming "PhysicalObject.addSubBody.body" if it is null or owned
  /// elsewhere (ownedElsewhere()); such a body is then left to its owner, not destroyed.
  template <class T>
  T& addSubBody(std::unique_ptr<T> body) {
    T* added = body.get();
    adoptSubBody(std::unique_ptr<PhysicalObject>(std::move(body)));
    return *added;
  }

  /// Called once the object is registered with @p simulator (agents that need the time step
  /// or the world keep a reference). Must not throw.
  virtual void onRegistered(Simulator& simulator) noexcept;

 private:
  /// True when the force and torque accumulators are exactly +0 (not -0, not NaN).
  [[nodiscard]] bool unpushed() const {
    using Bits = std::conditional_t<sizeof(real) == 8, std::uint64_t, std::uint32_t>;
    return (std::bit_cast<Bits>(externalForce.x) | std::bit_cast<Bits>(externalForce.y) |
            std::bit_cast<Bits>(externalTorque)) == 0;
  }

  /// The default computeDerivativesWithoutContacts() in the gravity field @p gravity (finite,
  /// not zero, no component -0): `v = F / m + gravity` for a movable body, `omega` as without
  /// the field. Simulator::advanceTime() runs it inline for the core shapes while a field is
  /// set, and the default hook otherwise, so a world without gravity computes exactly what it
  /// did before the field existed (`F / m + 0` would turn a velocity -0 into +0).
  /// False for a pushed body (see velocitiesFromAccumulators()).
  bool computeDerivativesInField(Vector2 gravity) {
    return velocitiesFromAccumulators<true>(gravity);
  }

  /// The default hook's body, without (@p InField false: @p gravity is not read) or with the
  /// gravity field @p gravity added to a movable body's velocity. One body for both, the field's
  /// addition compiled out of the default hook: the same instructions and bits as before.
  /// False when the body was pushed (or has no positive mass or inertia): its velocity is then
  /// its own, not the field's.
  template <bool InField>
  bool velocitiesFromAccumulators([[maybe_unused]] Vector2 gravity) {
    if (unpushed() && m > 0 && I > 0) [[likely]] {
      // Unpushed (most bodies at rest): +0 divided by a positive mass is +0, so the three
      // divisions are skipped with the same result, bit for bit, fixed or not; and the
      // accumulators already hold +0, so they need no reset ([[likely]]: GCC put this path
      // out of line, a jump more for each body at rest). In a field, +0 / m + gravity is
      // gravity, bit for bit (no component -0): a body that only its weight pushes (most of a
      // pile) needs no division either.
      if constexpr (InField)
        v = fixed ? Vector2{} : gravity;
      else
        v = {};
      omega = 0;
      return true;
    }
    velocitiesFromPushes<InField>(gravity);
    return false;
  }
  /// velocitiesFromAccumulators() for a pushed body, out of line: the simulator's loop over the
  /// bodies, mostly unpushed, then keeps to the few instructions of the test (inline, the
  /// divisions' loads merged with the test's, which then went through the stack).
  template <bool InField>
  THYRIX_NO_INLINE void velocitiesFromPushes([[maybe_unused]] Vector2 gravity) {
    if (fixed) {
      v = {};
      omega = 0;
    } else {
      if constexpr (InField)
        v = externalForce / m + gravity;
      else
        v = externalForce / m;
      omega = externalTorque / I;
    }
    externalForce = {};
    externalTorque = 0;
  }

  void adoptSubBody(std::unique_ptr<PhysicalObject> body);

  friend class World;
  friend class Simulator;
  friend class Primitive;  // keeps sensing_, rigid_ and the direction cache
  std::vector<Primitive*> primitives_;
  std::vector<std::unique_ptr<PhysicalObject>> subBodies_;  // handed to the world on registration
  // Who owns this object besides the unique_ptr it came in, so that a second owner is refused.
  World* world_ = nullptr;                   // the world it is registered with
  const PhysicalObject* carrier_ = nullptr;  // the object whose sub-body it is, until registered
  std::uint32_t index_ = 0;                  // in its world's objects, once registered
};

}  // namespace thyrix
