#pragma once
/// @file Iunctus.h
/// @brief Iunctus: an articulated agent (ThyrixPro) with a round body and a three-link limb on
/// servos that catches and holds a circular object.

#include <Controller/Controller.h>
#include <ThyrixPro/ArticulatedAgentQuasistatic.h>

#include <array>
#include <memory>

namespace thyrix {

/// The numbers that make an Iunctus.
struct IunctusParameters {
  real baseRadius = real(0.3);   ///< radius of the round base (m)
  real baseMass = 5;             ///< quasistatic mass of the base (N s/m)
  real linkLength = real(0.85);  ///< length of each of the three links, joint to tip (m)
  real linkRadius = real(0.05);  ///< half width of the links' capsules (m)
  real linkMass = real(0.2);     ///< quasistatic mass of each link (N s/m)
  real maxForce = 5;             ///< forward or backward force on the base at activation 1 (N)
  real maxTorque = 2;            ///< turning torque on the base at activation 1 (N m)
  real servoGain = 20;           ///< stiffness of the joint servos (N m/rad)
  real tactileSaturation = 1;    ///< contact force that saturates a touch sensor (N)
  std::array<real, 3> qMin{real(-0.3), real(-1.8), real(-1.8)};  ///< joint lower limits (rad)
  std::array<real, 3> qMax{real(1.8), real(0.3), real(0.3)};     ///< joint upper limits (rad)
};

/// Iunctus ("joined"): a round base facing its x axis ("forward") with one limb of three
/// capsule links attached at the top of the base (the point at +90 degrees from forward). Each
/// joint has a servo and joint limits. With the joint angles (0, -pi/2, -pi/2) the limb forms
/// a box in front of the base (link 0 forward, link 1 down across the front, link 2 back under
/// it toward the base): an object in that box is enclosed by the limb and the base, which is how
/// it holds things with frictionless contacts. With (pi/2, 0, 0) the limb points up, out of the
/// way, and the front is open.
///
/// Effectors (7, each in [0, 1]):
///   0 forward and 1 backward force on the base (`value * maxForce` along -/+ forward, at its
///   centre of mass), 2 counter-clockwise and 3 clockwise torque on the base
///   (`value * maxTorque`), 4-6 the servo targets of joints 0-2, mapped linearly from [0, 1] to
///   the joint's range [qMin, qMax].
/// Sensors (30, each in [0, 1]):
///   0-2 the joint angles, normalised to their ranges ((q - qMin) / (qMax - qMin), clamped);
///   3-10 touch on the base, 8 sensors of 45 degrees counter-clockwise from the one centred on
///   forward; 11-28 touch on the links, 6 per link (link 0 first), each link's sensors
///   numbered as a CappedRectangle's with 2 per side and 1 per cap (TactileSensors): the side
///   on the link's right first, from joint to tip, the tip cap, the left side from tip to
///   joint, the joint cap; 29 something held: 1 when a movable object touches the agent and its
///   centre is inside the polygon of the base's centre, the joints and the limb's tip.
class Iunctus : public ArticulatedAgentQuasistatic {
 public:
  using Parameters = IunctusParameters;    ///< the agent's sizes and strengths
  static constexpr int effectorCount = 7;  ///< number of effectors
  static constexpr int sensorCount = 30;   ///< number of sensors
  /// The original spellings of sensorCount and effectorCount: any use fails to compile,
  /// naming them (ThyrixLite/Renamed.h).
  static renamed::nSensors_is_now_sensorCount nSensors;
  static renamed::nEffectors_is_now_effectorCount nEffectors;  ///< see nSensors
  static constexpr int jointCount = 3;                         ///< links (and joints) of the limb
  // Effector and sensor indices, as documented above.
  static constexpr int forward = 0;          ///< effector: forward force
  static constexpr int backward = 1;         ///< effector: backward force
  static constexpr int turnLeft = 2;         ///< effector: counter-clockwise torque
  static constexpr int turnRight = 3;        ///< effector: clockwise torque
  static constexpr int firstServo = 4;       ///< effector: servo target of joint 0
  static constexpr int firstBaseTouch = 3;   ///< sensor: first touch sensor of the base
  static constexpr int firstLinkTouch = 11;  ///< sensor: first touch sensor of link 0
  static constexpr int touchPerLink = 6;     ///< touch sensors per link
  static constexpr int heldSensor = 29;      ///< sensor: something held

  /// An Iunctus driven by @p controller (it may be null: the effectors then stay as set through
  /// effectors(), e.g. by IunctusGrasper). Its limb starts open, at (pi/2, 0, 0), with the
  /// servo effectors set to hold it there.
  explicit Iunctus(std::unique_ptr<Controller> controller = nullptr, const Parameters& = {});

  /// Puts the base's centre at @p centre, facing @p heading (rad).
  void place(Vector2 centre, real heading) { setPose(centre, heading); }

  /// The sensor activations of the last step.
  [[nodiscard]] std::span<const real> sensors() const { return sensors_; }
  /// The effector activations, written by the controller each step (or by hand without one).
  [[nodiscard]] std::span<real> effectors() { return effectors_; }
  /// The effector activations, read only.
  [[nodiscard]] std::span<const real> effectors() const { return effectors_; }
  /// Replaces the controller (null: driven by hand through effectors()).
  void setController(std::unique_ptr<Controller> controller) {
    controller_ = std::move(controller);
  }
  /// The controller, or null.
  [[nodiscard]] Controller* controller() const { return controller_.get(); }
  /// The parameters it was built with.
  [[nodiscard]] const Parameters& parameters() const { return parameters_; }

  /// The unit forward direction (the base's x axis).
  [[nodiscard]] Vector2 heading() const;
  /// The servo effector value that commands the angle @p q (rad) of joint @p i.
  [[nodiscard]] real servoActivation(int i, real q) const;
  /// Whether the world point @p p is inside the polygon of the base's centre, the joints and
  /// the limb's tip (the region the curled limb encloses).
  [[nodiscard]] bool encloses(Vector2 p) const;

  /// Phase 7: sensors -> controller -> base force and torque, servo targets for the next step.
  void control() override;
  /// ArticulatedAgentQuasistatic::saveState(), then the sensor and effector activations and the
  /// controller's state (Controller::saveState()).
  void saveState(StateRecord& record) const override;
  /// Reads back what saveState() appended.
  void restoreState(StateRecord::Reader& reader) override;
  void draw(GUI& gui) const override;
  [[nodiscard]] std::string typeName() const override { return "Iunctus"; }
  /// The simulator's time step (s), 0 before registration.
  [[nodiscard]] real timestep() const { return ArticulatedAgentQuasistatic::timestep(); }

 private:
  void readSensors();
  void applyEffectors();

  Parameters parameters_;
  std::unique_ptr<Controller> controller_;
  std::array<real, sensorCount> sensors_{};
  std::array<real, effectorCount> effectors_{};
};

}  // namespace thyrix
