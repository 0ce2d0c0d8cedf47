#include <ThyrixLite/InvalidArgument.h>
#include <ThyrixLite/Primitive.h>
#include <ThyrixLite/VisualSensor.h>
#include <Tools/MathTools.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <string>
#include <type_traits>

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

/// True if a disk at @p offset from the eye, of @p radius, lies entirely outside the field of
/// view of edges @p rightEdge and @p leftEdge around @p view (conservative: a false answer does
/// not mean the disk is seen). @p convexField: the field is at most pi wide.
bool diskOutside(Vector2 offset, real radius, Vector2 view, Vector2 rightEdge, Vector2 leftEdge,
                 bool convexField) {
  // Entirely clockwise of the right edge's line, counter-clockwise of the left edge's line,
  // or behind the eye. A field of view of at most pi is the intersection of the two edges'
  // half-planes (and lies in front of the eye): outside either one is outside the field. A
  // wider field is the union of the two: the disk must be outside both.
  const bool right = cross(rightEdge, offset) < -radius;
  const bool left = cross(leftEdge, offset) > radius;
  if (convexField) return right || left || dot(view, offset) < -radius;
  return right && left;
}

/// The same for the capsule of end-cap centres at @p offset0 and @p offset1 from the eye.
bool capsuleOutside(Vector2 offset0, Vector2 offset1, real radius, Vector2 view, Vector2 rightEdge,
                    Vector2 leftEdge, bool convexField) {
  // The capsule is the convex hull of its end disks: it lies in a half-plane if both do.
  const bool right = cross(rightEdge, offset0) < -radius && cross(rightEdge, offset1) < -radius;
  const bool left = cross(leftEdge, offset0) > radius && cross(leftEdge, offset1) > radius;
  if (convexField)
    return right || left || (dot(view, offset0) < -radius && dot(view, offset1) < -radius);
  return right && left;
}

/// The cosine and sine of an angle.
struct CosSin {
  real c;
  real s;
};

/// std::cos and std::sin of @p angle, remembered for the last angle (per thread): the eyes of
/// an agent often sit on bodies turned alike (Spherus turns both its circles to its heading),
/// and libm's sincos costs as much as the culling of a small world. The angle is compared bit
/// for bit (0 and -0 have sines of different signs).
CosSin cosSin(real angle) {
  using Bits = std::conditional_t<sizeof(real) == 8, std::uint64_t, std::uint32_t>;
  struct Memo {
    Bits angle;
    CosSin value;
  };
  thread_local Memo memo{std::bit_cast<Bits>(real(0)), {1, 0}};  // cos 0 and sin 0, exactly
  const Bits bits = std::bit_cast<Bits>(angle);
  if (bits != memo.angle) memo = {bits, {std::cos(angle), std::sin(angle)}};
  return memo.value;
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
  // The arithmetic of AngularCoverage::coveredFractions(begin, width, ...), so the fractions
  // are the same bit for bit.
  bounds_.resize(static_cast<std::size_t>(pixelCount) + 1);
  for (int i = 0; i <= pixelCount; ++i)
    bounds_[static_cast<std::size_t>(i)] = -halfField_ + static_cast<real>(i) * pixelAngle_;
}

bool VisualSensor::partsChanged() const {
  for (const auto& [object, parts] : partCounts_)
    if (object->primitives().size() != parts) return true;
  return false;
}

void VisualSensor::collectPrimitives(const ObjectList& objects) {
  primitives_.clear();
  partCounts_.clear();
  for (const PhysicalObject& object : objects) {
    const auto parts = object.primitives();
    // A circle or capsule is its own single primitive for good; any other object (a composed
    // body) may gain parts: its count is checked on each update().
    if (!(parts.size() == 1 && parts[0] == &object))
      partCounts_.emplace_back(&object, parts.size());
  }
  // The circles first, then the capsules, so the culling knows each one's type.
  for (const ShapeType type : {ShapeType::Circle, ShapeType::Capsule}) {
    for (const PhysicalObject& object : objects)
      for (const Primitive* primitive : object.primitives())
        if (primitive->shapeType() == type) primitives_.push_back(primitive);
    if (type == ShapeType::Circle) circleCount_ = primitives_.size();
  }
  // At most two pieces of arc a primitive.
  coverage_.reserve(2 * primitives_.size());
  candidates_.resize(primitives_.size());
  objectsSeen_ = &objects;
  objectsSized_ = objects.size();
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

void VisualSensor::update(const ObjectList& objects) {
  // The body's pose: one cosine and sine for the eye, the view and the field's edges.
  const auto [c, s] = cosSin(body_->alpha);
  const Vector2 eye = body_->r + rotate(localPosition_, c, s);
  const Vector2 view = rotate(localView_, c, s);
  const Vector2 rightEdge = rotate(view, cosHalfField_, -sinHalfField_);
  const Vector2 leftEdge = rotate(view, cosHalfField_, sinHalfField_);

  coverage_.clear();
  if (&objects != objectsSeen_ || objects.size() != objectsSized_ || partsChanged())
    collectPrimitives(objects);
  const PhysicalObject* const self = body_;
  const real halfField = halfField_;
  const bool convexField = halfField <= pi<real> / 2;
  // An arc is at most pi wide (half of it asin(...) <= pi / 2), so it spans at most
  // [-3 pi / 2, 3 pi / 2] unwrapped: in a field of half width below pi / 2 (with a wide margin
  // for rounding) its wrapped image never reaches the field, and a disk's arc needs no split.
  const bool narrow = halfField < real(0.45) * pi<real>;

  // Pass 1, the culling of every circle and capsule, calls no function: the loop keeps the eye,
  // the view and the edges in registers (a call clobbers every floating-point register). The
  // primitives that may be seen are written to candidates_ (one slot per primitive).
  // In a narrow field (a compile-time variant, not a test per primitive) a circle is culled by
  // the two edges alone: those it keeps that diskOutside() would cull lie entirely behind the
  // eye (dot(view, offset) < -radius), their arcs more than pi / 2 from the view, so more than
  // 0.05 pi outside the field: clipping empties them, and the pixels are the same (but one of
  // them must not be taken for a disk containing the eye).
  // The circles and the capsules are culled by two instances of one loop (no test of the type).
  std::size_t count = 0;
  const auto cull = [&](auto narrowField, auto circles, std::span<const Primitive* const> list) {
    constexpr ShapeType type = decltype(circles)::value ? ShapeType::Circle : ShapeType::Capsule;
    Candidate* const out = candidates_.data();
    for (const Primitive* primitive : list) {
      // A capsule is culled by its bounding disk here, by its end disks in pass 2.
      real radius = primitive->radius();
      if (type != ShapeType::Circle) radius += primitive->halfLength();
      const Vector2 offset = primitive->r - eye;
      if constexpr (decltype(narrowField)::value) {
        // Clockwise of the right edge's line or counter-clockwise of the left one's, by more
        // than the radius (cross(offset, rightEdge) is -cross(rightEdge, offset) exactly).
        if (cross(offset, rightEdge) > radius || cross(leftEdge, offset) > radius) continue;
        // A capsule keeps the general test (pass 2 works from its end disks).
        if (type != ShapeType::Circle && dot(view, offset) < -radius) continue;
      } else {
        if (diskOutside(offset, radius, view, rightEdge, leftEdge, convexField)) continue;
      }
      // The body's own primitives usually contain the eye and pass, so they are excluded after
      // the test (here, not in collectPrimitives(): a primitive may be attached to another
      // owner at any time).
      if (&primitive->owner() == self) continue;
      // A disk that contains (or touches) the eye covers every pixel, whatever else is seen
      // (diskExtent()'s test, with the same arithmetic): the rest of the pass is not needed,
      // and pass 2 sees no such disk.
      real distanceSquared = 0;
      if (type == ShapeType::Circle) {
        distanceSquared = offset.lengthSquared();
        if (distanceSquared <= radius * radius) {
          // Rounding can put a disk that touches the eye entirely behind it, where
          // diskOutside() culls it: so does the narrow variant.
          if constexpr (decltype(narrowField)::value)
            if (dot(view, offset) < -radius) continue;
          return false;
        }
      }
      out[count++] = Candidate{primitive, offset, distanceSquared};
    }
    return true;
  };
  std::size_t circleCandidates = 0;  // candidates_[0, circleCandidates) are circles
  const auto cullAll = [&](auto narrowField) {
    const std::span<const Primitive* const> all = primitives_;
    if (!cull(narrowField, std::true_type{}, all.first(circleCount_))) return false;
    circleCandidates = count;
    return cull(narrowField, std::false_type{}, all.subspan(circleCount_));
  };
  if (!(narrow ? cullAll(std::true_type{}) : cullAll(std::false_type{}))) {
    std::fill(activations_.begin(), activations_.end(), real(1));
    return;
  }

  // Pass 2: the arcs of the candidates, clipped to the field. The union does not depend on
  // the order in which they are added.
  // Adds @p extent clipped to the field; false when it is the whole circle.
  const auto addExtent = [&](const AngularExtent& extent) {
    if (extent.wholeCircle) return false;
    for (const AngularInterval& piece : extent.pieces())
      coverage_.add(
          AngularInterval{std::max(piece.begin, -halfField), std::min(piece.end, halfField)});
    return true;
  };
  // Adds a candidate's arc; false when the eye is inside (or touching) it: every pixel sees it.
  // The circle candidates come first (pass 1 culls the circles first): @p circle is known.
  const auto addArc = [&](const Candidate& candidate, auto narrowField, auto circle) {
    const Primitive* const primitive = candidate.primitive;
    const real radius = primitive->radius();
    if constexpr (decltype(circle)::value) {
      if constexpr (!decltype(narrowField)::value)
        return addExtent(diskExtent(eye, view, primitive->r, radius));
      // diskExtent() and splitAtPi() inlined with the same arithmetic, bit for bit: in a
      // field narrower than pi the pieces splitAtPi() makes of an arc crossing +-pi (or its
      // shift of an arc whose rounded middle passes +-pi) lie outside the field, so clipping
      // the unsplit arc gives the same intervals (VisualSensorTest's
      // MatchesTheExtentFunctionsBitForBit checks). Pass 1 found the eye outside the disk.
      const real half = halfAngle(radius, std::sqrt(candidate.distanceSquared));
      const real direction = angleBetween(view, candidate.offset);
      coverage_.add(AngularInterval{std::max(direction - half, -halfField),
                                    std::min(direction + half, halfField)});
      return true;
    } else {
      const real halfLength = primitive->halfLength();  // a capsule
      const Vector2 axis{halfLength * std::cos(primitive->alpha),
                         halfLength * std::sin(primitive->alpha)};
      const Vector2 p0 = primitive->r - axis;
      const Vector2 p1 = primitive->r + axis;
      if (capsuleOutside(p0 - eye, p1 - eye, radius, view, rightEdge, leftEdge, convexField))
        return true;
      return addExtent(capsuleExtent(eye, view, p0, p1, radius));
    }
  };
  const auto addArcs = [&](auto narrowField) {
    for (std::size_t k = 0; k < circleCandidates; ++k)
      if (!addArc(candidates_[k], narrowField, std::true_type{})) return false;
    for (std::size_t k = circleCandidates; k < count; ++k)
      if (!addArc(candidates_[k], narrowField, std::false_type{})) return false;
    return true;
  };
  if (!(narrow ? addArcs(std::true_type{}) : addArcs(std::false_type{}))) {
    std::fill(activations_.begin(), activations_.end(), real(1));
    return;
  }
  coverage_.merge();
  coverage_.coveredFractions(bounds_, activations_);
}

}  // namespace thyrix
