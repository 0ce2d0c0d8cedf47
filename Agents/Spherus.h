#pragma once
/// @file Spherus.h
/// @brief Spherus: two circles joined by a variable-length virtual link (docs/Agents.md, "The
/// example: Spherus").

#include <Controller/Controller.h>
#include <ThyrixLite/Circle.h>
#include <ThyrixLite/Elastoid.h>
#include <ThyrixLite/VisualSensor.h>

#include <array>
#include <memory>

namespace thyrix {

/// The numbers that make a Spherus.
struct SpherusParameters {
  real radius = real(0.25);     ///< radius of each circle (m)
  real mass = 1;                ///< quasistatic mass of each circle (N s/m)
  real maxForce = 1;            ///< force of a rocket at activation 1 (N)
  real maxLinkLength = 1;       ///< link rest length at activation 1 (m)
  real linkLength = real(0.6);  ///< initial distance between the circle centres (m)
  real linkStiffness = 20;      ///< link stiffness (N/m)
  real tactileSaturation = 1;   ///< contact force that saturates a contact sensor (N)
};

/// Spherus: a left and a right circle joined by a virtual link whose length it commands; it
/// moves like a two-wheeled robot with a rocket on each wheel, "forward" being perpendicular to
/// the link (the link direction, left to right, turned by +90 degrees).
///
/// Effectors (5, each in [0, 1]):
///   0 left forward rocket, 1 left backward rocket, 2 right forward, 3 right backward
///   (each pushes its circle with `value * maxForce` along -/+ forward), 4 link rest length
///   (`value * maxLinkLength`, an elastic force pulls toward it).
/// Sensors (35, each in [0, 1]), for the left circle then the right circle (17 each):
///   0-7 contact sensors of 45 degrees, counter-clockwise from the one centred on forward;
///   8-14 visual pixels of 15 degrees (105 degrees centred on forward, infinite range), from the
///   rightmost; 15 forward and 16 backward velocity, as a fraction of `maxForce / mass`;
///   then 34: the link length as a fraction of maxLinkLength.
class Spherus : public Elastoid {
 public:
  using Parameters = SpherusParameters;    ///< the agent's sizes and strengths
  static constexpr int effectorCount = 5;  ///< number of effectors
  static constexpr int sensorCount = 35;   ///< number of sensors
  /// The original spellings of sensorCount and effectorCount: any use fails to compile,
  /// naming them (ThyrixLite/Renamed.h).
  static renamed::nSensors_is_now_sensorCount nSensors;
  static renamed::nEffectors_is_now_effectorCount nEffectors;  ///< see nSensors
  static constexpr int sensorsPerCircle = 17;                  ///< contact 8, visual 7, velocity 2

  /// A Spherus driven by @p controller (it may be null: the effectors then stay as set by
  /// effectors(), e.g. by a program driving it directly).
  explicit Spherus(std::unique_ptr<Controller> controller = nullptr, const Parameters& = {});

  /// Puts the centre of the link at @p centre, facing @p heading (radians; forward direction).
  void place(Vector2 centre, real heading);

  /// The sensor activations of the last step.
  [[nodiscard]] std::span<const real> sensors() const { return sensors_; }
  /// The effector activations, written by the controller each step (or by hand without one).
  [[nodiscard]] std::span<real> effectors() { return effectors_; }
  /// The effector activations, read only.
  [[nodiscard]] std::span<const real> effectors() const { return effectors_; }
  /// The controller, or null.
  [[nodiscard]] Controller* controller() const { return controller_.get(); }

  /// The circle on the left of the forward direction.
  [[nodiscard]] Circle& leftCircle() const { return *left_; }
  /// The circle on the right of the forward direction.
  [[nodiscard]] Circle& rightCircle() const { return *right_; }
  /// The midpoint of the two circle centres.
  [[nodiscard]] Vector2 centre() const { return (left_->r + right_->r) * real(0.5); }
  /// The unit forward direction (perpendicular to the link).
  [[nodiscard]] Vector2 forward() const;
  /// The parameters it was built with.
  [[nodiscard]] const Parameters& parameters() const { return parameters_; }
  /// The eye of circle @p circle (0: left, 1: right).
  [[nodiscard]] const VisualSensor& eye(int circle) const { return eyes_[circle]; }

  [[nodiscard]] std::span<const VisualSensor> visualSensors() const override { return eyes_; }
  /// Phase 2: turns the circles' frames to the heading and updates the eyes.
  void updateSensors(const World& world) override;
  /// Phase 7: sensors -> controller -> rocket forces and link length for the next step.
  void control() override;
  /// Elastoid::saveState(), then the sensor and effector activations and the controller's state
  /// (Controller::saveState()).
  void saveState(StateRecord& record) const override;
  /// Reads back what saveState() appended.
  void restoreState(StateRecord::Reader& reader) override;
  void draw(GUI& gui) const override;
  [[nodiscard]] std::string typeName() const override { return "Spherus"; }

 private:
  /// Copies the sensor values, with the speeds along the forward direction @p f.
  void readSensors(Vector2 f);
  /// Clamps the effectors and applies them, the rockets along the forward direction @p f.
  void applyEffectors(Vector2 f);

  Parameters parameters_;
  std::unique_ptr<Controller> controller_;
  Circle* left_;
  Circle* right_;
  ElasticLink* link_;
  std::array<VisualSensor, 2> eyes_;
  std::array<real, sensorCount> sensors_{};
  std::array<real, effectorCount> effectors_{};
};

}  // namespace thyrix
