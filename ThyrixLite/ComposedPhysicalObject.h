#pragma once
/// @file ComposedPhysicalObject.h
/// @brief One rigid body made of several circles and capped rectangles.

#include <ThyrixLite/Primitive.h>

#include <memory>
#include <vector>

namespace thyrix {

/// A rigid body made of primitives at fixed relative positions and angles. Its mass is the
/// sum of the parts' masses, its centre of mass their weighted mean, and its moment of inertia
/// the parts' own plus the parallel-axis terms. A contact on any part acts on the whole body;
/// each part keeps its own tactile sensors.
///
/// Parts are placed in a fixed building frame; `r` is the centre of mass, which sits at
/// centreOfMassOffset() in that frame. Adding a part moves `r` with the centre of mass while
/// the parts already placed stay where they are. Add the parts first, then set `r` and `alpha`.
class ComposedPhysicalObject : public PhysicalObject {
 public:
  ComposedPhysicalObject();

  /// Adds @p part at @p relativePosition and @p relativeAngle in the body's frame and returns
  /// it. @throws InvalidArgument naming "ComposedPhysicalObject.part" (null, a border, or
  /// owned elsewhere: a part of a body, registered, a sub-body; PhysicalObject::ownedElsewhere),
  /// ".relativePosition" or ".relativeAngle" (not finite); the body is then unchanged, and a
  /// part owned elsewhere is left to its owner, not destroyed.
  template <class T>
  T& add(std::unique_ptr<T> part, Vector2 relativePosition, real relativeAngle = 0) {
    T* added = part.get();  // not dereferenced before addPart has refused a null part
    addPart(std::unique_ptr<Primitive>(std::move(part)), relativePosition, relativeAngle);
    return *added;
  }

  /// The centre of mass in the building frame the parts were placed in.
  [[nodiscard]] Vector2 centreOfMassOffset() const { return centreOffset_; }
  /// Number of parts.
  [[nodiscard]] std::size_t partCount() const { return parts_.size(); }

  void validate() const override;
  void draw(GUI& gui) const override;
  [[nodiscard]] std::string typeName() const override { return "ComposedPhysicalObject"; }

 private:
  void addPart(std::unique_ptr<Primitive> part, Vector2 relativePosition, real relativeAngle);

  std::vector<std::unique_ptr<Primitive>> parts_;
  Vector2 centreOffset_;  // centre of mass in the building frame
};

}  // namespace thyrix
