#pragma once
/// @file TactileSensors.h
/// @brief Touch sensors splitting a primitive's outline into sectors.

#include <ThyrixLite/StateRecord.h>
#include <ThyrixLite/Vector2.h>

#include <span>
#include <vector>

namespace thyrix {

/// The tactile sensors of one primitive (docs/Agents.md, "Touch: tactile sensors"). Each sensor
/// covers a sector of the outline; its activation is `min(1, sum of the contact-force magnitudes in
/// the sector / saturation)`, refreshed every step once the contact forces are known.
///
/// Layouts, in the primitive's own frame:
/// - circle: `count` sectors of `2 pi / count`, sensor k covering the angles
///   `[start + k 2pi/count, start + (k+1) 2pi/count)`;
/// - capped rectangle (axis along x, half length l): counter-clockwise from the corner
///   (-l, -R): `perSide` sensors along the lower side (left to right), `perCap` over the
///   right cap (from -90 to +90 degrees), `perSide` along the upper side (right to left), and
///   `perCap` over the left cap (from 90 to 270 degrees): `2 (perSide + perCap)` in all.
class TactileSensors {
 public:
  /// No sensors.
  TactileSensors() = default;
  /// Circle layout. @throws InvalidArgument naming the field for a count < 1, a non-finite
  /// start angle or a saturation that is not positive and finite.
  static TactileSensors circle(int count, real startAngle, real saturation);
  /// Capped-rectangle layout. @throws InvalidArgument naming the field for counts < 0, no
  /// sensor at all, or a bad saturation.
  static TactileSensors cappedRectangle(int perSide, int perCap, real saturation);

  /// True when there is at least one sensor.
  [[nodiscard]] bool enabled() const { return !activations_.empty(); }
  /// The activations, each in [0, 1].
  [[nodiscard]] std::span<const real> activations() const { return activations_; }
  /// The force that saturates a sensor.
  [[nodiscard]] real saturation() const { return saturation_; }

  /// The sensor under a contact at @p localPoint (primitive frame) of a circle.
  [[nodiscard]] int circleSector(Vector2 localPoint) const;
  /// The sensor under a contact at @p localPoint of a capped rectangle of half length @p l.
  [[nodiscard]] int cappedRectangleSector(Vector2 localPoint, real l) const;

  /// The middle of sensor @p k on the outline of a circle of @p radius (primitive frame).
  [[nodiscard]] Vector2 circleSectorMiddle(int k, real radius) const;
  /// The middle of sensor @p k on the outline of a capped rectangle (primitive frame).
  [[nodiscard]] Vector2 cappedRectangleSectorMiddle(int k, real l, real R) const;

  /// Starts a step: all sums to zero.
  void clear() {
    if (touched_) clearSums();
  }
  /// Adds a contact force of magnitude @p force to sensor @p sector.
  void add(int sector, real force) {
    activations_[static_cast<std::size_t>(sector)] += force;
    touched_ = true;
  }
  /// Ends a step: sums become activations, `min(1, sum / saturation)`.
  void finish() {
    if (touched_) finishSums();
  }

  /// Appends the sums or activations and whether any is touched to @p record.
  void saveState(StateRecord& record) const;
  /// Reads back what saveState() appended.
  void restoreState(StateRecord::Reader& reader);

 private:
  void clearSums();
  void finishSums();

  std::vector<real> activations_;  // force sums during a step, activations after finish()
  real saturation_ = 1;
  real startAngle_ = 0;
  int perSide_ = 0;
  int perCap_ = 0;
  // False while every activation is +0 (since the construction or clear()): most sensors are
  // touched by nothing in most steps, and then clear() and finish() have nothing to change
  // (min(1, +0 / saturation) is +0).
  bool touched_ = false;
};

}  // namespace thyrix
