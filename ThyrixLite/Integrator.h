#pragma once
/// @file Integrator.h
/// @brief Advances positions from velocities.

#include <ThyrixLite/ObjectList.h>

#include <cstdint>
#include <span>

namespace thyrix {

/// Explicit Euler: every object's `integrate(dt)` moves it by its velocity over @p dt
/// (`r += v dt`, `alpha += omega dt` for a rigid body). Under `F = m v` this is exact for the
/// step's constant velocity; agents with internal state override `integrate`.
class Integrator {
 public:
  /// Calls `integrate(dt)` on each object in registration order.
  void integrate(const ObjectList& objects, real dt) const;
  /// The same, but given the increasing indices of the objects that are *not* moved by
  /// PhysicalObject::integrate (@p customObjects, called virtually), the others are moved by it
  /// directly, without a virtual call (the core shapes, which do not override it).
  void integrateExcept(const ObjectList& objects, std::span<const std::uint32_t> customObjects,
                       real dt) const;
};

}  // namespace thyrix
