#pragma once
/// @file CappedRectangle.h
/// @brief A capsule: a rectangle capped by two half-disks.

#include <ThyrixLite/Primitive.h>

namespace thyrix {

/// A rectangle of length 2 l and width 2 R with a half-disk of radius R on each end, of uniform
/// density. At `alpha = 0` its long axis lies along x, centred on `r`: the end-cap centres are
/// `r -/+ (l, 0)`.
///
/// Aligned to a cache line (64 bytes): what every step writes and reads of an articulated
/// agent's link, its pose, flags and direction, then lies in one line of the object, never two.
class alignas(64) CappedRectangle : public Primitive {
 public:
  /// @param l half length of the straight part
  /// @param R half width (the caps' radius)
  /// @param mass quasistatic mass (N s/m)
  /// @throws InvalidArgument naming "CappedRectangle.l", ".R" or ".mass" unless positive and finite
  /// (the mass with a finite inverse too)
  CappedRectangle(real l, real R, real mass);

  /// Moment of inertia of a uniform capsule about its centre.
  static real momentOfInertia(real l, real R, real mass);

  /// World position of end-cap centre 0 (`-l` along the axis) or 1 (`+l`).
  [[nodiscard]] Vector2 endPoint(int end) const;

  /// Puts @p perSide touch sensors on each straight side and @p perCap on each end cap,
  /// numbered counter-clockwise from the lower-left corner (see TactileSensors); a sensor
  /// saturates at a summed contact force of @p saturation. @throws InvalidArgument.
  void setTactileSensors(int perSide, int perCap, real saturation);

  void draw(GUI& gui) const override;
  [[nodiscard]] std::string typeName() const override { return "CappedRectangle"; }
};

}  // namespace thyrix
