#pragma once
/// @file PacEater.h
/// @brief A scripted behaviour: a Pac opens its mouth, advances onto an object, closes its mouth
/// on it and carries it away.

#include <Agents/Pac.h>

namespace thyrix {

/// Drives a Pac that has no controller through its effectors, to eat one object. It reads the
/// world directly (the Pac's fitted pose and the target's position), not the Pac's sensors:
/// it is a script for tests and demonstrations, not a controller to evolve. Call step() before
/// each Simulator::advanceTime() (PacEatingSimulator does, in its own advanceTime()). The phases:
/// 1. Opening: mouth open, no locomotion, until the mouth sensor reads at least 0.9;
/// 2. Approaching: mouth open, steering toward the target and advancing (slower when it is off
///    the heading, backing off when it is far off), until the target's centre is inside the
///    ring and behind its centre, or inside and Pac stalled for 50 steps (a full ring, a wall);
/// 3. Closing: mouth closed, standing still, until the mouth sensor reads at most 0.05;
/// 4. Carrying: mouth closed, driving straight ahead (done() is true from here on).
class PacEater {
 public:
  /// The steps of the script, in order.
  enum class Phase { Opening, Approaching, Closing, Carrying };

  /// Eats @p target with @p pac; both must outlive the script.
  PacEater(Pac& pac, const PhysicalObject& target);

  /// Starts over (from Opening) with another target.
  void setTarget(const PhysicalObject& target);
  /// Advances the script and writes the Pac's effectors for the next step.
  void step();

  /// The current phase.
  [[nodiscard]] Phase phase() const { return phase_; }
  /// True once the target is inside and the mouth closed.
  [[nodiscard]] bool done() const { return phase_ == Phase::Carrying; }
  /// The target.
  [[nodiscard]] const PhysicalObject& target() const { return *target_; }

  /// Appends the phase and the steps stalled (the target is saved by the script's owner).
  void saveState(StateRecord& record) const;
  /// Reads back what saveState() appended.
  /// @throws std::runtime_error for a phase that does not exist
  void restoreState(StateRecord::Reader& reader);

 private:
  void drive(real forwardCommand, real turnCommand, real mouthCommand);

  Pac* pac_;
  const PhysicalObject* target_;
  Phase phase_ = Phase::Opening;
  int stalled_ = 0;  // steps spent inside the target without moving forward
};

}  // namespace thyrix
