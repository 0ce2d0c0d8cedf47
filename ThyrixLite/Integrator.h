#pragma once
/// @file Integrator.h
/// @brief Advances positions from velocities.

#include <ThyrixLite/ObjectList.h>

namespace thyrix {

/// Explicit Euler: every object's `integrate(dt)` moves it by its velocity over @p dt
/// (`r += v dt`, `alpha += omega dt` for a rigid body). Under `F = m v` this is exact for the
/// step's constant velocity; agents with internal state override `integrate`.
class Integrator {
 public:
  /// Calls `integrate(dt)` on each object in registration order.
  void integrate(const ObjectList& objects, real dt) const;
};

}  // namespace thyrix
