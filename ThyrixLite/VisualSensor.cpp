#include <ThyrixLite/InvalidArgument.h>
#include <ThyrixLite/Primitive.h>
#include <ThyrixLite/VisualSensor.h>
#include <Tools/MathTools.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace thyrix {
namespace {

/// Checks the constructor's arguments, naming the first bad one.
void validateSensor(Vector2 localPosition, real localDirection, int pixelCount, real pixelAngle) {
  if (pixelCount < 1)
    throw InvalidArgument("VisualSensor.pixelCount",
                          "must be at least 1 (got " + std::to_string(pixelCount) + ")");
  requirePositive(pixelAngle, "VisualSensor.pixelAngle");
  // 2 pi / n times n may round above 2 pi: allow a few units of rounding.
  const real field = static_cast<real>(pixelCount) * pixelAngle;
  if (!(field <= 2 * pi<real> * (1 + 8 * realEpsilon)))
    throw InvalidArgument(
        "VisualSensor.pixelAngle",
        "times VisualSensor.pixelCount must be at most 2 pi (got " + std::to_string(field) + ")");
  requireFinite(localPosition, "VisualSensor.localPosition");
  requireFinite(localDirection, "VisualSensor.localDirection");
}

/// @p v rotated by the angle whose cosine and sine are @p c and @p s.
Vector2 rotate(Vector2 v, real c, real s) { return {c * v.x - s * v.y, s * v.x + c * v.y}; }

}  // namespace

VisualSensor::VisualSensor(const PhysicalObject& body, Vector2 localPosition, real localDirection,
                           int pixelCount, real pixelAngle)
    : body_(&body) {
  validateSensor(localPosition, localDirection, pixelCount, pixelAngle);
  localPosition_ = localPosition;
  localDirection_ = localDirection;
  localView_ = {std::cos(localDirection), std::sin(localDirection)};
  pixelCount_ = pixelCount;
  pixelAngle_ = pixelAngle;
  halfField_ = static_cast<real>(pixelCount) * pixelAngle / 2;
  cosHalfField_ = std::cos(halfField_);
  sinHalfField_ = std::sin(halfField_);
  activations_.assign(static_cast<std::size_t>(pixelCount), real(0));
}

real VisualSensor::viewDirection() const { return wrapAngle(body_->alpha + localDirection_); }

std::pair<real, real> VisualSensor::pixelBounds(int i) const {
  if (i < 0 || i >= pixelCount_)
    throw InvalidArgument(
        "VisualSensor.pixelBounds.i",
        "must be in [0, " + std::to_string(pixelCount_) + ") (got " + std::to_string(i) + ")");
  const real first = viewDirection() - halfField_;
  return {first + static_cast<real>(i) * pixelAngle_,
          first + static_cast<real>(i + 1) * pixelAngle_};
}

bool VisualSensor::outside(Vector2 offset, real radius, Vector2 view, Vector2 rightEdge,
                           Vector2 leftEdge) const {
  // Entirely clockwise of the right edge's line, counter-clockwise of the left edge's line,
  // or behind the eye. A field of view of at most pi is the intersection of the two edges'
  // half-planes (and lies in front of the eye): outside either one is outside the field. A
  // wider field is the union of the two: the disk must be outside both.
  const bool right = cross(rightEdge, offset) < -radius;
  const bool left = cross(leftEdge, offset) > radius;
  if (halfField_ <= pi<real> / 2) return right || left || dot(view, offset) < -radius;
  return right && left;
}

bool VisualSensor::outside(Vector2 offset0, Vector2 offset1, real radius, Vector2 view,
                           Vector2 rightEdge, Vector2 leftEdge) const {
  // The capsule is the convex hull of its end disks: it lies in a half-plane if both do.
  const bool right = cross(rightEdge, offset0) < -radius && cross(rightEdge, offset1) < -radius;
  const bool left = cross(leftEdge, offset0) > radius && cross(leftEdge, offset1) > radius;
  if (halfField_ <= pi<real> / 2)
    return right || left || (dot(view, offset0) < -radius && dot(view, offset1) < -radius);
  return right && left;
}

void VisualSensor::update(const ObjectList& objects) {
  // The body's pose: one cosine and sine for the eye, the view and the field's edges.
  const real c = std::cos(body_->alpha);
  const real s = std::sin(body_->alpha);
  const Vector2 eye = body_->r + rotate(localPosition_, c, s);
  const Vector2 view = rotate(localView_, c, s);
  const Vector2 rightEdge = rotate(view, cosHalfField_, -sinHalfField_);
  const Vector2 leftEdge = rotate(view, cosHalfField_, sinHalfField_);

  coverage_.clear();
  if (objects.size() != objectsSized_) {  // the world has grown: at most two pieces a primitive
    std::size_t primitives = 0;
    for (const PhysicalObject& object : objects) primitives += object.primitives().size();
    coverage_.reserve(2 * primitives);
    objectsSized_ = objects.size();
  }
  for (const PhysicalObject& object : objects) {
    for (const Primitive* primitive : object.primitives()) {
      if (&primitive->owner() == body_) continue;
      AngularExtent extent;
      switch (primitive->shapeType()) {
        case ShapeType::HalfPlane:
          continue;
        case ShapeType::Circle: {
          const real radius = primitive->radius();
          if (outside(primitive->r - eye, radius, view, rightEdge, leftEdge)) continue;
          extent = diskExtent(eye, view, primitive->r, radius);
          break;
        }
        case ShapeType::Capsule: {
          const real radius = primitive->radius();
          const real halfLength = primitive->halfLength();
          // The bounding disk first, before the trigonometry of the end points.
          if (outside(primitive->r - eye, radius + halfLength, view, rightEdge, leftEdge)) continue;
          const Vector2 axis{halfLength * std::cos(primitive->alpha),
                             halfLength * std::sin(primitive->alpha)};
          const Vector2 p0 = primitive->r - axis;
          const Vector2 p1 = primitive->r + axis;
          if (outside(p0 - eye, p1 - eye, radius, view, rightEdge, leftEdge)) continue;
          extent = capsuleExtent(eye, view, p0, p1, radius);
          break;
        }
      }
      if (extent.wholeCircle) {
        std::fill(activations_.begin(), activations_.end(), real(1));
        return;
      }
      for (const AngularInterval& piece : extent.pieces())
        coverage_.add(
            AngularInterval{std::max(piece.begin, -halfField_), std::min(piece.end, halfField_)});
    }
  }
  coverage_.merge();
  coverage_.coveredFractions(-halfField_, pixelAngle_, activations_);
}

}  // namespace thyrix
