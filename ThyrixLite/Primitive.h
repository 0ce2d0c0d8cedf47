#pragma once
/// @file Primitive.h
/// @brief The base of the collision shapes: Circle, CappedRectangle and Border.

#include <ThyrixLite/PhysicalObject.h>
#include <ThyrixLite/TactileSensors.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <utility>

namespace thyrix {

/// The kinds of primitive, in the order the narrow phase pairs them (the lower kind is A).
enum class ShapeType : std::uint8_t {
  HalfPlane = 0,  ///< a Border
  Circle = 1,     ///< a Circle
  Capsule = 2,    ///< a CappedRectangle
};

/// A primitive shape. It is a body of its own when registered alone; inside a composed body it
/// is a part, placed at `localPosition` and `localAngle` in its owner's frame, and its own
/// `r` and `alpha` follow the owner (the simulator updates them each step).
class Primitive : public PhysicalObject {
 public:
  /// The kind of shape.
  [[nodiscard]] ShapeType shapeType() const { return shapeType_; }
  /// Circle radius, or capsule half width R; 0 for a border.
  [[nodiscard]] real radius() const { return radius_; }
  /// Capsule half length l of the central segment; 0 for other shapes.
  [[nodiscard]] real halfLength() const { return halfLength_; }

  /// The body this primitive moves with: itself, or the composed body it is part of.
  [[nodiscard]] PhysicalObject& owner() const { return *owner_; }
  /// Position in the owner's frame (zero for a standalone primitive).
  [[nodiscard]] Vector2 localPosition() const { return localPosition_; }
  /// Orientation in the owner's frame (zero for a standalone primitive).
  [[nodiscard]] real localAngle() const { return localAngle_; }

  /// Places this primitive in @p owner's frame (used by composed bodies when adding a part).
  /// With @p rigid false the primitive only belongs to the owner, which places it itself (the
  /// links of an articulated agent, see MultiBodyObject).
  void attachTo(PhysicalObject& owner, Vector2 localPosition, real localAngle, bool rigid = true) {
    owner_ = &owner;
    localPosition_ = localPosition;
    localAngle_ = localAngle;
    rigid_ = rigid;
  }
  /// True when the primitive keeps a fixed pose in its owner's frame.
  [[nodiscard]] bool rigidlyAttached() const { return rigid_; }
  /// The tactile sensors of this primitive (none unless set up; see Circle and CappedRectangle).
  [[nodiscard]] const TactileSensors& tactileSensors() const { return tactile_; }
  /// Shortcut for `tactileSensors().activations()`.
  [[nodiscard]] std::span<const real> tactileActivations() const { return tactile_.activations(); }
  /// Adds a contact force of magnitude @p force at @p worldPoint to the sensor under it.
  void touch(Vector2 worldPoint, real force);

  /// The unit vector of the primitive's x axis, `(cos alpha, sin alpha)`: a capsule's axis.
  /// Cached with the angle it belongs to, so it costs a cosine and a sine only when `alpha`
  /// has changed since the last call or place().
  [[nodiscard]] Vector2 direction() {
    if (alpha != directionAngle_) {
      direction_ = {std::cos(alpha), std::sin(alpha)};
      directionAngle_ = alpha;
    }
    return direction_;
  }
  /// Sets `r` to @p position and `alpha` to @p angle, whose `(cos, sin)` the caller already
  /// has as @p direction (an owner placing its parts from its own kinematics): direction()
  /// then returns it without recomputing it.
  void place(Vector2 position, real angle, Vector2 direction) {
    r = position;
    alpha = angle;
    direction_ = direction;
    directionAngle_ = angle;
  }

  /// PhysicalObject::saveState(), then the cached direction (an owner's kinematics may have
  /// set it with other bits than a cosine would give) and the tactile sensors' sums.
  void saveState(StateRecord& record) const override;
  /// Reads back what saveState() appended.
  void restoreState(StateRecord::Reader& reader) override;

  /// Moves `r` and `alpha` to follow the owner (no-op for a standalone primitive).
  void followOwner() {
    if (owner_ == this || !rigid_) return;
    r = owner_->toWorld(localPosition_);
    alpha = owner_->alpha + localAngle_;
  }

 protected:
  /// A primitive of @p type with its size, mass and moment of inertia (checked by the shape
  /// classes, which name their own fields).
  Primitive(ShapeType type, real radius, real halfLength, real mass, real momentOfInertia)
      : PhysicalObject(mass, momentOfInertia),
        shapeType_(type),
        radius_(radius),
        halfLength_(halfLength) {
    addPrimitive(*this);
  }

 private:
  friend class Simulator;  // clears and finishes the sensors around each solve

  // What a link's step writes and reads (pose, flags, direction) in one 64-byte line of an
  // object that starts a line, in double (offsetof: conditionally supported on a class with
  // virtual functions, and so by GCC and Clang, which warn).
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Winvalid-offsetof"
  static_assert(sizeof(real) != 8 ||
                (offsetof(PhysicalObject, direction_) / 64 ==
                     (offsetof(PhysicalObject, collisionGroup) + 3) / 64 &&
                 offsetof(PhysicalObject, direction_) < offsetof(PhysicalObject, r) &&
                 offsetof(PhysicalObject, r) < offsetof(PhysicalObject, directionAngle_) &&
                 offsetof(PhysicalObject, directionAngle_) < offsetof(PhysicalObject, sensing_) &&
                 offsetof(PhysicalObject, rigid_) < offsetof(PhysicalObject, collisionGroup)));
#pragma GCC diagnostic pop

  // (Its direction cache and rigid_ are PhysicalObject's, next to the pose: see there.) First
  // what followOwner() reads. The sensors are read only when sensing_ says so.
  ShapeType shapeType_;
  PhysicalObject* owner_ = this;
  Vector2 localPosition_;
  real localAngle_ = 0;

 protected:
  /// Gives the primitive @p sensors (the shape classes set them up; none by default).
  void installTactileSensors(TactileSensors sensors) {
    tactile_ = std::move(sensors);
    sensing_ = tactile_.enabled();
  }

 private:
  TactileSensors tactile_;
  real radius_;
  real halfLength_;
};

}  // namespace thyrix
