#pragma once
/// @file VisualSensor.h
/// @brief An eye: a row of pixels rigidly attached to a body, each measuring how much of its
/// view angle the objects of the world cover.

#include <ThyrixLite/AngularCoverage.h>
#include <ThyrixLite/ObjectList.h>
#include <ThyrixLite/PhysicalObject.h>
#include <ThyrixLite/ThyrixParameters.h>
#include <ThyrixLite/Vector2.h>

#include <cstddef>
#include <span>
#include <utility>
#include <vector>

namespace thyrix {

/// A visual sensor (docs/Design.md section 4): an eye at a point of a body, looking along a
/// direction fixed in the body, with `pixelCount` pixels of `pixelAngle` radians side by side,
/// centred on the view direction. With `d` the world view direction, `n` pixels of width `w`,
/// pixel i sees the directions `[d - n w / 2 + i w, d - n w / 2 + (i + 1) w]`: pixel 0 is the
/// clockwise-most (rightmost) and the indices increase counter-clockwise.
///
/// A pixel's activation is the fraction of its angle covered by the circles and capsules
/// (CappedRectangle) of the world, in [0, 1]; overlapping objects count once. Borders are not
/// seen, nor the primitives of the sensor's own body. The range is infinite. An object that
/// contains or touches the eye covers every pixel.
///
/// The sensor reads the primitives' world pose (`r`, `alpha`) as it is when update() runs; for
/// the parts of a composed body the simulator keeps it current. update() lists the circles and
/// capsules of the objects (and sizes its buffers for them: two intervals and one culling slot
/// each) when it is given another object list, more objects, or a composed body among them has
/// gained parts, so it allocates nothing on later calls with the same objects. The sensor
/// refers to its body, which must outlive it, and to the primitives of the objects it last saw.
class VisualSensor {
 public:
  /// @param body the body the eye is attached to (it is not seen)
  /// @param localPosition the eye, in the body frame (m)
  /// @param localDirection the view direction, an angle in the body frame (rad)
  /// @param pixelCount number of pixels, at least 1
  /// @param pixelAngle angle each pixel covers (rad); all together at most 2 pi (rounding of
  ///        `2 pi / pixelCount` is accepted)
  /// @throws InvalidArgument naming "VisualSensor.pixelCount" (below 1),
  ///         "VisualSensor.pixelAngle" (not positive and finite, or pixels spanning more than
  ///         2 pi), "VisualSensor.localPosition" or "VisualSensor.localDirection" (not finite)
  VisualSensor(const PhysicalObject& body, Vector2 localPosition, real localDirection,
               int pixelCount, real pixelAngle);

  /// Recomputes every pixel's activation from the primitives of @p objects, seen from the
  /// body's current pose. Objects out of the field of view are culled without trigonometry;
  /// the others' angular extents are clipped to the field of view, merged into their union, and
  /// the pixels integrated over it in one sweep. The arcs are exactly capsuleExtent()'s and
  /// diskExtent()'s.
  void update(const ObjectList& objects);

  /// Activation of each pixel, in [0, 1], as of the last update() (zero before the first).
  [[nodiscard]] std::span<const real> activations() const { return activations_; }
  /// Number of pixels.
  [[nodiscard]] int pixelCount() const { return pixelCount_; }
  /// Angle each pixel covers (rad).
  [[nodiscard]] real pixelAngle() const { return pixelAngle_; }
  /// Angle all the pixels cover together, `pixelCount * pixelAngle` (rad).
  [[nodiscard]] real fieldOfView() const { return 2 * halfField_; }
  /// The eye's position in the body frame (m).
  [[nodiscard]] Vector2 localPosition() const { return localPosition_; }
  /// The view direction in the body frame (rad).
  [[nodiscard]] real localDirection() const { return localDirection_; }
  /// The body the eye is attached to.
  [[nodiscard]] const PhysicalObject& body() const { return *body_; }

  /// The eye's position in world coordinates, from the body's current pose (m).
  [[nodiscard]] Vector2 eyePosition() const { return body_->toWorld(localPosition_); }
  /// The view direction in world coordinates, from the body's current pose, in (-pi, pi] (rad).
  [[nodiscard]] real viewDirection() const;
  /// The world directions (rad) bounding pixel @p i, clockwise-most first, from the body's
  /// current pose: `viewDirection() - n w / 2 + i w` and `+ (i + 1) w` (not wrapped, so the
  /// second is always the larger), for drawing the pixels' rays.
  /// @throws InvalidArgument naming "VisualSensor.pixelBounds.i" unless 0 <= i < pixelCount()
  [[nodiscard]] std::pair<real, real> pixelBounds(int i) const;

 private:
  const PhysicalObject* body_;
  Vector2 localPosition_;
  real localDirection_;
  Vector2 localView_;  // unit vector of localDirection_
  int pixelCount_;
  real pixelAngle_;
  real halfField_;  // half the field of view
  real cosHalfField_;
  real sinHalfField_;
  /// A primitive that update()'s culling let through, its centre's offset from the eye, and
  /// for a circle the offset's squared length.
  struct Candidate {
    const Primitive* primitive;
    Vector2 offset;
    real distanceSquared;
  };

  std::vector<real> activations_;
  // The pixels' bounds relative to the view, -halfField_ + i pixelAngle_ for i in [0, n]:
  // fixed, so update() does not recompute them.
  std::vector<real> bounds_;
  AngularCoverage coverage_;
  std::vector<Candidate> candidates_;  // update()'s culled primitives, one slot per primitive
  // The circles and capsules of the objects update() last saw (borders are never seen), so the
  // culling walks one flat list instead of every object's primitives: collected again when the
  // objects are others, more, or a composed body among them has gained parts.
  std::vector<const Primitive*> primitives_;  // the circles, then the capsules
  std::size_t circleCount_ = 0;
  std::vector<std::pair<const PhysicalObject*, std::size_t>> partCounts_;  // composed bodies
  const ObjectList* objectsSeen_ = nullptr;
  std::size_t objectsSized_ = 0;

  /// True if a composed body has gained parts since collectPrimitives().
  [[nodiscard]] bool partsChanged() const;
  /// Collects the circles and capsules of @p objects into primitives_ and sizes the buffers.
  void collectPrimitives(const ObjectList& objects);
};

}  // namespace thyrix
