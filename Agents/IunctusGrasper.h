#pragma once
/// @file IunctusGrasper.h
/// @brief A scripted behaviour: an Iunctus opens its limb, approaches an object, curls the limb
/// around it and carries it a set distance.

#include <Agents/Iunctus.h>

#include <Controller/Controller.h>

namespace thyrix {

/// Drives an Iunctus through its effectors, to catch one circular object and carry it. Like
/// PacEater it reads the world directly (the agent's pose and joint angles, the target's
/// position), not the sensors: a script for tests and demonstrations, not a controller to
/// evolve. Either install it as the agent's controller (Iunctus::setController(), as
/// IunctusSimulator::useGrasper() does; it then runs in phase 7 of every step), or leave the
/// agent without a controller and call step() before each Simulator::advanceTime(). The phases:
/// 1. Opening: limb to the open pose (pi/2, 0, 0), standing still, until every joint is within
///    0.05 rad of it;
/// 2. Approaching: turning and driving so that the target comes to rest at the grip point
///    (gripPoint, in the base's frame), in the box the closed limb will enclose, until it is
///    within 0.03 m of it;
/// 3. Closing: holding the base's place and heading, the servo targets moving from the open
///    to the closed pose (0, -pi/2, -pi/2) at closingRate, until the targets are there and every
///    joint has stopped (rate below 0.01 rad/s) for 20 steps: closed, or curled onto the target;
/// 4. Carrying: limb closed, driving straight ahead (holding the heading) until the target has
/// moved carryDistance
///    from where it was when carrying began;
/// 5. Holding: limb closed, standing still (done() is true).
class IunctusGrasper : public Controller {
 public:
  /// The steps of the script, in order.
  enum class Phase { Opening, Approaching, Closing, Carrying, Holding };

  /// Where the target should be, in the base's frame (x forward), before the limb closes (m):
  /// in the box of the closed limb, clear of the base and of every link's sweep.
  static constexpr Vector2 gripPoint{real(0.6), real(-0.12)};

  /// Catches @p target with @p agent and carries it @p carryDistance (m); both must outlive
  /// the script.
  /// How fast the servo targets move while closing (rad/s).
  static constexpr real closingRate = real(0.5);

  /// A script for @p agent that catches @p target and carries it @p carryDistance (m).
  IunctusGrasper(Iunctus& agent, const PhysicalObject& target, real carryDistance = 2);

  /// Advances the script and writes the agent's effectors for the next step.
  void step();
  /// As the agent's controller: step(); @p effectors must be the agent's (they are written
  /// through it), and the sensors are not read.
  void control(std::span<const real> sensors, std::span<real> effectors) override;

  /// The script's current phase.
  [[nodiscard]] Phase phase() const { return phase_; }
  /// True once the target has been carried the set distance.
  [[nodiscard]] bool done() const { return phase_ == Phase::Holding; }
  /// The target's position when carrying began.
  [[nodiscard]] Vector2 carryStart() const { return carryStart_; }

  /// Appends the phase, the still count, the carry start, the closing pose and the hold.
  void saveState(StateRecord& record) const override;
  /// Reads back what saveState() appended.
  /// @throws std::runtime_error for a phase that does not exist
  void restoreState(StateRecord::Reader& reader) override;

 private:
  void drive(real forwardCommand, real turnCommand, const real (&pose)[3]);
  [[nodiscard]] bool reached(const real (&pose)[3]) const;

  Iunctus* agent_;
  const PhysicalObject* target_;
  real carryDistance_;
  Phase phase_ = Phase::Opening;
  int still_ = 0;  // steps with every joint at rest while closing
  Vector2 carryStart_;
  real pose_[3];          // the servo targets while closing (rad)
  Vector2 holdPosition_;  // where the base stays while closing
  real holdHeading_ = 0;
};

}  // namespace thyrix
