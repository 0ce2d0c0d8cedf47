#pragma once
/// @file Integrator.h
/// @brief Advances positions from velocities: the last phase of a Simulator's step, replaceable.

#include <ThyrixLite/ObjectList.h>

#include <cstdint>
#include <span>

namespace thyrix {

class Simulator;

/// How a Simulator moves its objects in phase 8 of a step, from the velocities the step gave
/// them: a strategy the simulator calls once per step (Simulator::setIntegrator()).
///
/// This class is explicit Euler, the default: each object's PhysicalObject::integrate(dt) moves
/// it by its velocity over the step (`r += v dt`, `alpha += omega dt` for a rigid body; agents
/// with internal state override it). Under `F = m v` this is exact while the velocity stays
/// constant over the step. Derive from it to integrate otherwise: override integrateObject() to
/// move each object differently, or integrate() to replace the whole phase (a higher-order
/// method evaluates the velocities at other poses with the simulator's public phases,
/// Simulator::detectContacts() to Simulator::solveContacts(), then sets the poses itself).
class Integrator {
 public:
  Integrator() = default;
  Integrator(const Integrator&) = delete;
  Integrator& operator=(const Integrator&) = delete;
  virtual ~Integrator() = default;

  /// Phase 8: moves every object of @p simulator over @p dt (s): integrateObject() for each,
  /// in registration order.
  virtual void integrate(Simulator& simulator, real dt);
  /// Moves @p object over @p dt (s) from its velocities: its PhysicalObject::integrate(dt).
  virtual void integrateObject(PhysicalObject& object, real dt);

  /// What this class's integrate() does to @p objects, given the increasing indices of those
  /// that override PhysicalObject::integrate (@p customObjects, called virtually): the others
  /// are moved by PhysicalObject::integrate directly, without a virtual call (the core shapes).
  /// The simulator's phase 8 while its integrator is this class itself.
  static void integrateExcept(const ObjectList& objects,
                              std::span<const std::uint32_t> customObjects, real dt);
};

}  // namespace thyrix
