#pragma once
/// @file AngularCoverage.h
/// @brief Angular extents of disks and capsules seen from a point, and the union of angular
/// intervals (the geometry of the visual sensor; no objects involved).
///
/// Angles are in radians, counter-clockwise, measured from a reference direction (for the
/// visual sensor: its view direction), and lie within [-pi, pi]. An arc that crosses the
/// direction opposite to the reference (the angle +-pi) is split into two intervals: an arc
/// running from `b` to `e` with `b < -pi` becomes `[b + 2 pi, pi]` and `[-pi, e]`; one with
/// `e > pi` becomes `[b, pi]` and `[-pi, e - 2 pi]` (see splitAtPi()).

#include <ThyrixLite/ThyrixParameters.h>
#include <ThyrixLite/Vector2.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <span>
#include <vector>

namespace thyrix {

/// A closed arc of directions `[begin, end]` (rad), relative to a reference direction, with
/// `-pi <= begin <= end <= pi`.
struct AngularInterval {
  real begin = 0;  ///< clockwise-most angle (rad)
  real end = 0;    ///< counter-clockwise-most angle (rad)
};

/// The directions in which a shape is seen from an eye: one interval, or two when the shape
/// straddles the direction opposite to the reference (angle +-pi).
struct AngularExtent {
  /// True when every direction is covered: the eye is inside or touching the shape (or the arc
  /// spans 2 pi or more). `intervals[0]` is then `[-pi, pi]` and `count` is 1.
  bool wholeCircle = false;
  /// Number of valid intervals: 1, or 2 for an arc split at +-pi.
  int count = 0;
  /// The arc, split at +-pi; only the first `count` entries are meaningful.
  std::array<AngularInterval, 2> intervals{};

  /// The valid intervals.
  [[nodiscard]] std::span<const AngularInterval> pieces() const {
    return {intervals.data(), static_cast<std::size_t>(count)};
  }
};

/// Half the angle subtended by a disk of @p radius whose centre is @p distance away
/// (`distance > radius`; rounding is clamped so the result is at most pi / 2).
inline real halfAngle(real radius, real distance) {
  return std::asin(std::min(real(1), radius / distance));
}

/// The angle from direction @p from to direction @p to, in [-pi, pi].
inline real angleBetween(Vector2 from, Vector2 to) {
  return std::atan2(cross(from, to), dot(from, to));
}

/// The arc of directions from angle @p begin to angle @p end (`begin <= end`, any real values)
/// as intervals within [-pi, pi]: the arc is first shifted by a multiple of 2 pi so that its
/// middle lies in [-pi, pi], then split at +-pi if it crosses it. An arc of 2 pi or more gives
/// the whole circle.
AngularExtent splitAtPi(real begin, real end);

/// The directions in which the disk of @p centre and @p radius is seen from @p eye, relative to
/// the unit vector @p reference: the arc `phi -+ asin(radius / d)` around the direction `phi` of
/// the centre at distance `d`. The whole circle if `d <= radius` (eye inside or touching).
AngularExtent diskExtent(Vector2 eye, Vector2 reference, Vector2 centre, real radius);

/// As diskExtent() above, with the reference direction given as an angle (rad).
AngularExtent diskExtent(Vector2 eye, real reference, Vector2 centre, real radius);

/// The directions in which the capsule of end-cap centres @p p0, @p p1 and radius @p radius is
/// seen from @p eye, relative to the unit vector @p reference. The capsule is the convex hull of
/// its two end disks, so its arc runs from the clockwise-most tangent of the two end disks to
/// the counter-clockwise-most one (less than pi wide). The whole circle if the eye is within
/// @p radius of the segment p0 p1 (inside or touching).
AngularExtent capsuleExtent(Vector2 eye, Vector2 reference, Vector2 p0, Vector2 p1, real radius);

/// As capsuleExtent() above, with the reference direction given as an angle (rad).
AngularExtent capsuleExtent(Vector2 eye, real reference, Vector2 p0, Vector2 p1, real radius);

/// The union of a set of angular intervals, and how much of a range it covers, counting
/// overlapping intervals once.
///
/// Use: clear(), add() the intervals (or addExtent() the extents), merge(), then query covered() or
/// coveredFractions(). The buffer keeps its capacity across clear(), so once it has held the
/// largest set (or after reserve()) nothing is allocated.
class AngularCoverage {
 public:
  /// Makes room for @p count intervals.
  void reserve(std::size_t count) { intervals_.reserve(count); }
  /// Removes every interval, keeping the capacity.
  void clear() {
    intervals_.clear();
    merged_ = true;
  }
  /// Adds the interval [@p interval.begin, @p interval.end]; empty or reversed ones are ignored.
  void add(AngularInterval interval) {
    if (!(interval.begin < interval.end)) return;
    intervals_.push_back(interval);
    merged_ = false;
  }
  /// Adds every piece of @p extent.
  void addExtent(const AngularExtent& extent) {
    for (const AngularInterval& piece : extent.pieces()) add(piece);
  }

  /// Replaces the intervals by their union: sorted by begin, disjoint (overlapping or touching
  /// intervals are merged). Allocates nothing.
  void merge();

  /// True once merge() has run since the last add().
  [[nodiscard]] bool merged() const { return merged_; }
  /// The intervals: after merge(), their union, sorted and disjoint.
  [[nodiscard]] std::span<const AngularInterval> intervals() const { return intervals_; }

  /// The total angle (rad) of [@p begin, @p end] covered by the union. Call merge() first.
  [[nodiscard]] real covered(real begin, real end) const;

  /// The covered fraction, in [0, 1], of each of `fractions.size()` consecutive bins of width
  /// @p width, bin i spanning `[begin + i width, begin + (i + 1) width]`: one sweep over the
  /// union and the bins. A bin covered entirely gets exactly 1. Call merge() first.
  void coveredFractions(real begin, real width, std::span<real> fractions) const;

  /// As coveredFractions() above, with the bins' bounds precomputed: bin i spans
  /// `[bounds[i], bounds[i + 1]]`, so @p bounds (increasing) has one entry more than
  /// @p fractions (otherwise every fraction is 0). With `bounds[i] = begin + i * width` the
  /// fractions are the same bit for bit; a caller with fixed bins saves their computation.
  void coveredFractions(std::span<const real> bounds, std::span<real> fractions) const;

 private:
  std::vector<AngularInterval> intervals_;
  bool merged_ = true;
};

}  // namespace thyrix
