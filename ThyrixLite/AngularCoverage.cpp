#include <ThyrixLite/AngularCoverage.h>
#include <Tools/MathTools.h>

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace thyrix {
namespace {

AngularExtent wholeCircle() {
  AngularExtent extent;
  extent.wholeCircle = true;
  extent.count = 1;
  extent.intervals[0] = {-pi<real>, pi<real>};
  return extent;
}

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
  AngularInterval* const first = intervals_.data();
  AngularInterval* const last = first + intervals_.size();
  if (first == last) return;
  // A sensor sees a handful of intervals at a time: an insertion sort does them with a fraction
  // of std::sort's overhead (an interval already after its predecessor is not moved). The order
  // of equal begins does not matter: an interval beginning where the previous one begins always
  // joins it, so the union is the same.
  if (intervals_.size() <= 16) {
    for (AngularInterval* i = first + 1; i != last; ++i) {
      if (!(i->begin < i[-1].begin)) continue;
      const AngularInterval moved = *i;
      AngularInterval* j = i;
      do {
        *j = j[-1];
        --j;
      } while (j != first && moved.begin < j[-1].begin);
      *j = moved;
    }
  } else {
    std::sort(first, last,
              [](const AngularInterval& a, const AngularInterval& b) { return a.begin < b.begin; });
  }
  AngularInterval* end = first;  // the union so far ends with *end
  for (const AngularInterval* i = first + 1; i != last; ++i) {
    if (i->begin <= end->end) {  // overlaps or touches: extend
      end->end = std::max(end->end, i->end);
    } else {
      *++end = *i;
    }
  }
  intervals_.erase(intervals_.begin() + (end - first) + 1, intervals_.end());  // shrinks only
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

namespace {

/// coveredFractions() of the sorted union @p intervals over the bins whose bounds @p bound(i)
/// gives (bin i spans [bound(i), bound(i + 1)], increasing).
template <class Bound>
void fractionsOfBins(std::span<const AngularInterval> intervals, const Bound& bound,
                     std::span<real> fractions) {
  std::fill(fractions.begin(), fractions.end(), real(0));
  const std::size_t count = fractions.size();
  // One sweep: the union is sorted, so the first bin an interval may overlap never lies before
  // the previous interval's (unsorted intervals, merge() not called, restart from bin 0). A bin
  // skipped ends at or before the interval's begin, so its overlap would not be positive: each
  // bin receives the same overlaps in the same order as when every bin is tried.
  std::size_t first = 0;
  real previousBegin = bound(0);
  for (const AngularInterval& interval : intervals) {
    if (interval.begin < previousBegin) first = 0;
    previousBegin = interval.begin;
    while (first < count && bound(first + 1) <= interval.begin) ++first;
    for (std::size_t i = first; i < count; ++i) {
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

}  // namespace

void AngularCoverage::coveredFractions(real begin, real width, std::span<real> fractions) const {
  if (fractions.empty() || !(width > 0)) {
    std::fill(fractions.begin(), fractions.end(), real(0));
    return;
  }
  // Through a signed index: converting a size_t to floating point takes several instructions
  // on x86-64, a signed integer one (same value).
  const auto bound = [&](std::size_t i) {
    return begin + static_cast<real>(static_cast<std::ptrdiff_t>(i)) * width;
  };
  fractionsOfBins(intervals_, bound, fractions);
}

void AngularCoverage::coveredFractions(std::span<const real> bounds,
                                       std::span<real> fractions) const {
  if (fractions.empty() || bounds.size() != fractions.size() + 1) {
    std::fill(fractions.begin(), fractions.end(), real(0));
    return;
  }
  if (!merged_) {  // unsorted: the sweep over the intervals, which restarts when needed
    fractionsOfBins(
        intervals_, [bounds](std::size_t i) { return bounds[i]; }, fractions);
    return;
  }
  // The union is sorted and disjoint, so the bins and the intervals advance together: bin by
  // bin, skip the intervals that end at or before the bin, sum the overlaps of those that begin
  // before its end. Each bin sums the same overlaps in the same order as fractionsOfBins(), from
  // zero (those it skips as not positive are zero here: the ends are sorted too, so every
  // interval summed ends after the bin's start), so the fractions are the same bit for bit.
  const std::size_t count = fractions.size();
  const AngularInterval* interval = intervals_.data();
  const AngularInterval* const last = interval + intervals_.size();
  for (std::size_t i = 0; i < count; ++i) {
    const real low = bounds[i];
    const real high = bounds[i + 1];
    while (interval != last && interval->end <= low) ++interval;
    real sum = 0;
    for (const AngularInterval* j = interval; j != last && j->begin < high; ++j)
      sum += std::min(j->end, high) - std::max(j->begin, low);
    fractions[i] = sum > 0 ? std::min(real(1), sum / (high - low)) : real(0);
  }
}

}  // namespace thyrix
