#include <ThyrixLite/AngularCoverage.h>
#include <Tools/MathTools.h>

#include <algorithm>
#include <cmath>

namespace thyrix {
namespace {

AngularExtent wholeCircle() {
  AngularExtent extent;
  extent.wholeCircle = true;
  extent.count = 1;
  extent.intervals[0] = {-pi<real>, pi<real>};
  return extent;
}

/// Half the angle subtended by a disk of @p radius whose centre is @p distance away
/// (`distance > radius`; rounding is clamped so the result is at most pi / 2).
real halfAngle(real radius, real distance) {
  return std::asin(std::min(real(1), radius / distance));
}

/// The angle from @p from to @p to, in [-pi, pi].
real angleBetween(Vector2 from, Vector2 to) { return std::atan2(cross(from, to), dot(from, to)); }

}  // namespace

AngularExtent splitAtPi(real begin, real end) {
  AngularExtent extent;
  if (!(begin <= end)) return extent;  // reversed or NaN: nothing
  const real twoPi = 2 * pi<real>;
  if (!(end - begin < twoPi)) return wholeCircle();
  const real middle = (begin + end) / 2;
  if (middle < -pi<real> || middle > pi<real>) {
    const real shift = twoPi * std::round(middle / twoPi);
    begin -= shift;
    end -= shift;
  }
  if (begin < -pi<real>) {
    extent.count = 2;
    extent.intervals[0] = {std::min(begin + twoPi, pi<real>), pi<real>};
    extent.intervals[1] = {-pi<real>, std::max(end, -pi<real>)};
  } else if (end > pi<real>) {
    extent.count = 2;
    extent.intervals[0] = {std::min(begin, pi<real>), pi<real>};
    extent.intervals[1] = {-pi<real>, std::max(end - twoPi, -pi<real>)};
  } else {
    extent.count = 1;
    extent.intervals[0] = {begin, end};
  }
  return extent;
}

AngularExtent diskExtent(Vector2 eye, Vector2 reference, Vector2 centre, real radius) {
  const Vector2 toCentre = centre - eye;
  const real distanceSquared = toCentre.lengthSquared();
  if (distanceSquared <= radius * radius) return wholeCircle();
  const real half = halfAngle(radius, std::sqrt(distanceSquared));
  const real direction = angleBetween(reference, toCentre);
  return splitAtPi(direction - half, direction + half);
}

AngularExtent diskExtent(Vector2 eye, real reference, Vector2 centre, real radius) {
  return diskExtent(eye, Vector2{std::cos(reference), std::sin(reference)}, centre, radius);
}

AngularExtent capsuleExtent(Vector2 eye, Vector2 reference, Vector2 p0, Vector2 p1, real radius) {
  const Vector2 to0 = p0 - eye;
  const Vector2 to1 = p1 - eye;
  const real distance0Squared = to0.lengthSquared();
  const real distance1Squared = to1.lengthSquared();
  const real radiusSquared = radius * radius;
  // Inside or touching: within radius of the segment, that is of an end, or of the segment's
  // interior (the squared distance to the axis is cross^2 / |axis|^2; no division needed).
  if (distance0Squared <= radiusSquared || distance1Squared <= radiusSquared) return wholeCircle();
  const Vector2 axis = p1 - p0;
  const real along = -dot(to0, axis);  // eye's projection on the axis, times |axis|
  const real axisSquared = axis.lengthSquared();
  if (along > 0 && along < axisSquared && square(cross(to0, axis)) <= radiusSquared * axisSquared)
    return wholeCircle();
  const real half0 = halfAngle(radius, std::sqrt(distance0Squared));
  const real half1 = halfAngle(radius, std::sqrt(distance1Squared));
  // Angles relative to the direction of p0, then shifted: the eye is outside the convex
  // capsule, so the two end disks lie within less than pi of each other and their extreme
  // tangents bound the capsule's arc.
  const real direction0 = angleBetween(reference, to0);
  const real direction1 = angleBetween(to0, to1);
  const real begin = std::min(-half0, direction1 - half1);
  const real end = std::max(half0, direction1 + half1);
  return splitAtPi(direction0 + begin, direction0 + end);
}

AngularExtent capsuleExtent(Vector2 eye, real reference, Vector2 p0, Vector2 p1, real radius) {
  return capsuleExtent(eye, Vector2{std::cos(reference), std::sin(reference)}, p0, p1, radius);
}

void AngularCoverage::merge() {
  if (merged_) return;
  merged_ = true;
  if (intervals_.empty()) return;
  std::sort(intervals_.begin(), intervals_.end(),
            [](const AngularInterval& a, const AngularInterval& b) { return a.begin < b.begin; });
  std::size_t last = 0;  // the union so far ends with intervals_[last]
  for (std::size_t i = 1; i < intervals_.size(); ++i) {
    if (intervals_[i].begin <= intervals_[last].end) {  // overlaps or touches: extend
      intervals_[last].end = std::max(intervals_[last].end, intervals_[i].end);
    } else {
      intervals_[++last] = intervals_[i];
    }
  }
  intervals_.resize(last + 1);
}

real AngularCoverage::covered(real begin, real end) const {
  if (!(begin < end)) return 0;
  // The union is sorted and disjoint, so the ends are sorted too: skip those before begin.
  auto it = std::partition_point(intervals_.begin(), intervals_.end(),
                                 [begin](const AngularInterval& i) { return i.end <= begin; });
  real total = 0;
  for (; it != intervals_.end() && it->begin < end; ++it)
    total += std::min(it->end, end) - std::max(it->begin, begin);
  return total;
}

void AngularCoverage::coveredFractions(real begin, real width, std::span<real> fractions) const {
  std::fill(fractions.begin(), fractions.end(), real(0));
  const std::size_t count = fractions.size();
  if (count == 0 || !(width > 0)) return;
  const auto bound = [&](std::size_t i) { return begin + static_cast<real>(i) * width; };
  for (const AngularInterval& interval : intervals_) {
    // First bin that may overlap: the estimate is widened by one bin against rounding, and
    // every overlap is computed exactly from the bin's bounds, so an estimate off by one is
    // harmless.
    const real estimate = std::floor((interval.begin - begin) / width);
    std::size_t i = 0;
    if (estimate >= 1) {
      if (estimate > static_cast<real>(count)) continue;
      i = static_cast<std::size_t>(estimate) - 1;
    }
    for (; i < count; ++i) {
      const real low = bound(i);
      if (low >= interval.end) break;
      const real overlap = std::min(interval.end, bound(i + 1)) - std::max(interval.begin, low);
      if (overlap > 0) fractions[i] += overlap;
    }
  }
  for (std::size_t i = 0; i < count; ++i) {
    if (fractions[i] > 0)
      fractions[i] = std::min(real(1), fractions[i] / (bound(i + 1) - bound(i)));
  }
}

}  // namespace thyrix
