#pragma once
/// @file Pac.h
/// @brief Pac: a ring of circles joined by elastic links, with a mouth through which it eats
/// objects and carries them inside its body (docs/Agents.md, "The example: Pac").

#include <Controller/Controller.h>
#include <ThyrixLite/Circle.h>
#include <ThyrixLite/Elastoid.h>
#include <ThyrixLite/VisualSensor.h>

#include <array>
#include <cmath>
#include <memory>
#include <span>
#include <utility>
#include <vector>

namespace thyrix {

/// The numbers that make a Pac. The defaults give a ring of 0.9 m across (1.2 m with the
/// circles) whose mouth, fully open, lets through a circle of up to 0.2 m radius, and whose
/// inside holds a circle of up to 0.3 m radius.
///
/// The links apply their forces all at once, each as if alone (ElasticLink), so a shape too
/// stiff for the time step overshoots, oscillates and blows up. With every pair linked the
/// stiffest mode relaxes by about `dt * circleCount * k / (mass + 2 dt k)` per step, with
/// `k = crossStiffness` and `dt` the time step; keep it below about 1.5 (it is 1.15 at the
/// defaults with dt = 0.01 s, 1.9 with dt = 0.02 s, the longest step the defaults take; at
/// 0.03 s the ring blows up). The softest mode bounds the deformation: pressed on a wall by its
/// own push, the default ring stays within 10% of its radius.
///
/// It lives at namespace scope, not inside Pac, because a nested struct with member
/// initializers cannot serve as a default argument inside its own class.
struct PacParameters {
  int circleCount = 10;      ///< circles in the ring, at least 5
  real radius = real(0.15);  ///< radius of each circle (m)
  real mass = 1;             ///< quasistatic mass of each circle (N s/m)
  /// Distance of the circle centres from the ring's centre, mouth closed (m). Keep the chord
  /// `2 ringRadius sin(pi / circleCount)` below `2 radius`: neighbours then overlap (they pass
  /// through each other) and nothing slips between them.
  real ringRadius = real(0.45);
  /// Distance between the centres of the two mouth circles with the mouth fully open (m); at
  /// least the closed chord `2 ringRadius sin(pi / circleCount)`, less than
  /// `(circleCount - 1)` times it. The gap left for food is this minus `2 radius`.
  real mouthWidth = real(0.7);
  /// Each circle is linked to the next `crossLinkSpan` circles along the ring: 1 links only
  /// neighbours (a floppy ring), `circleCount / 2` links every pair (the stiffest shape).
  int crossLinkSpan = 5;
  real ringStiffness = 30;     ///< stiffness of the links between neighbours, mouth included (N/m)
  real crossStiffness = 15;    ///< stiffness of the other links (N/m)
  real maxForce = real(0.5);   ///< force on each circle at full locomotion activation (N)
  real tactileSaturation = 1;  ///< contact force that saturates a touch sensor (N)
};

/// Pac: `circleCount` circles on a ring, consecutive ones joined by elastic links and every
/// circle cross-linked to the next few, so the ring keeps its shape while it pushes and is
/// pushed. The link between the last and the first circle is the mouth, centred on the heading.
///
/// The shape is commanded as a whole: for a mouth activation `m`, the circles sit on a circle
/// with every neighbour chord at its closed length and the mouth chord growing from that length
/// (`m = 0`) to `mouthWidth` (`m = 1`), the angle of each non-mouth gap shrinking linearly in
/// `m`. Every link's rest length is its length in that shape, so the cross-links spanning the
/// mouth let it open and the rest of the ring swells to match. Links are virtual: objects in the
/// mouth or inside pass through them, and collide only with the circles.
///
/// Circles are numbered counter-clockwise from the mouth: circle 0 is the left mouth circle,
/// circle `circleCount - 1` the right one. Pac's own pose (`r`, `alpha`, read by heading() and
/// toLocal()) is the ring's centre and heading, fitted each step to the circles' positions: the
/// rotation and translation that best map the commanded shape onto them (least squares).
///
/// Effectors (5, each in [0, 1]; Pac clamps them each step, NaN to 0):
///   0 left forward, 1 left backward, 2 right forward, 3 right backward: each circle of the left
///   (right) half of the ring is pushed along the heading with `(forward - backward) * maxForce`
///   (the back circle of an odd ring takes the mean of both sides); equal sides drive straight,
///   opposite sides turn in place, as Spherus's rockets;
///   4 mouth: 0 closed, 1 fully open.
/// Sensors (`11 + circleCount`, each in [0, 1]):
///   0 something inside: the summed activations of the circles' inner halves (the half facing the
///     ring's centre), capped at 1;
///   1 mouth opening: `(mouth chord - closed chord) / (mouthWidth - closed chord)`, clamped;
///   2 forward and 3 backward speed of the ring's centre along the heading, as a fraction of
///     `maxForce / mass`;
///   4-10 seven visual pixels of 15 degrees (105 degrees centred on the heading, infinite range),
///     from the rightmost, seen from an eye just ahead of the closed mouth
///     (`ringRadius + radius` from the centre);
///   11 .. 10 + circleCount: the outer half of each circle, from circle 0 counter-clockwise.
class Pac : public Elastoid {
 public:
  using Parameters = PacParameters;         ///< the agent's sizes and strengths
  static constexpr int effectorCount = 5;   ///< number of effectors
  static constexpr int leftForward = 0;     ///< effector: left half forward
  static constexpr int leftBackward = 1;    ///< effector: left half backward
  static constexpr int rightForward = 2;    ///< effector: right half forward
  static constexpr int rightBackward = 3;   ///< effector: right half backward
  static constexpr int mouth = 4;           ///< effector: mouth opening
  static constexpr int insideSensor = 0;    ///< sensor: something inside
  static constexpr int mouthSensor = 1;     ///< sensor: mouth opening
  static constexpr int forwardSensor = 2;   ///< sensor: forward speed
  static constexpr int backwardSensor = 3;  ///< sensor: backward speed
  static constexpr int firstPixel = 4;      ///< sensor: the rightmost visual pixel
  static constexpr int pixelCount = 7;      ///< visual pixels
  static constexpr int firstTouch = firstPixel + pixelCount;  ///< sensor: circle 0's outer half

  /// A Pac driven by @p controller (it may be null: the effectors then stay as set through
  /// effectors(), e.g. by a program or a script driving it), mouth closed, centred at the origin
  /// and facing +x.
  /// @throws InvalidArgument naming "Pac.circleCount", "Pac.ringRadius", "Pac.mouthWidth",
  ///         "Pac.crossLinkSpan", "Pac.maxForce" or "Pac.tactileSaturation"; Circle and
  ///         ElasticLink check the radius, mass and stiffnesses
  explicit Pac(std::unique_ptr<Controller> controller = nullptr, const Parameters& = {});

  /// Puts the ring's centre at @p centre, facing @p heading (radians), in the commanded shape
  /// (mouth closed until a step has applied another mouth effector).
  void place(Vector2 centre, real heading);

  /// Number of sensors, `11 + circleCount`.
  [[nodiscard]] int sensorCount() const { return static_cast<int>(sensors_.size()); }
  /// The original spellings of sensorCount and effectorCount: any use fails to compile,
  /// naming them (ThyrixLite/Renamed.h).
  static renamed::nSensors_is_now_sensorCount nSensors;
  static renamed::nEffectors_is_now_effectorCount nEffectors;  ///< see nSensors
  /// The sensor activations of the last step.
  [[nodiscard]] std::span<const real> sensors() const { return sensors_; }
  /// The effector activations, written by the controller each step (or by hand without one).
  [[nodiscard]] std::span<real> effectors() { return effectors_; }
  /// The effector activations, read-only.
  [[nodiscard]] std::span<const real> effectors() const { return effectors_; }
  /// The controller, or null.
  [[nodiscard]] Controller* controller() const { return controller_.get(); }

  /// The circles, counter-clockwise from the left mouth circle.
  [[nodiscard]] std::span<Circle* const> circles() const { return circles_; }
  /// The link between the last and the first circle, whose rest length opens the mouth.
  [[nodiscard]] ElasticLink& mouthLink() const { return *links()[mouthLinkIndex()]; }
  /// The centroid of the circle centres, now.
  [[nodiscard]] Vector2 centre() const;
  /// The heading (rad), as fitted at the start of the last step (or by place()).
  [[nodiscard]] real heading() const { return alpha; }
  /// The unit vector of heading().
  [[nodiscard]] Vector2 forward() const { return {std::cos(alpha), std::sin(alpha)}; }
  /// True if @p point lies inside the polygon of the circle centres (even-odd rule).
  [[nodiscard]] bool contains(Vector2 point) const;
  /// The distance between the mouth circles' centres when closed: the ring's chord (m).
  [[nodiscard]] real closedChord() const { return chord_; }
  /// The commanded shape: circle centres in Pac's frame, for the current mouth command.
  [[nodiscard]] std::span<const Vector2> shape() const { return shape_; }
  /// The numbers this Pac was made with.
  [[nodiscard]] const Parameters& parameters() const { return parameters_; }
  /// The eye, attached to Pac's own pose (the fitted ring frame), looking along the heading.
  [[nodiscard]] const VisualSensor& eye() const { return eye_; }

  /// Phase 2: fits the pose, turns each circle's frame outward (so its touch sensors split
  /// inner and outer halves) and updates the eye.
  void updateSensors(const World& world) override;
  /// Phase 7: sensors -> controller -> locomotion forces and link rest lengths for the next step.
  void control() override;
  /// Elastoid::saveState(), then the sensor and effector activations and the controller's state
  /// (Controller::saveState()).
  void saveState(StateRecord& record) const override;
  /// Reads back what saveState() appended.
  void restoreState(StateRecord::Reader& reader) override;
  /// Draws the ring outline (the cross-links would hide the inside), the mouth link, the
  /// heading and the eye.
  void draw(GUI& gui) const override;
  [[nodiscard]] std::string typeName() const override { return "Pac"; }

 private:
  [[nodiscard]] std::size_t mouthLinkIndex() const {
    return static_cast<std::size_t>(parameters_.circleCount - 1);
  }
  void setShape(real mouthActivation);
  void fitPose();
  void orientCircles();
  void readSensors();
  void applyEffectors();

  Parameters parameters_;
  std::unique_ptr<Controller> controller_;
  real chord_ = 0;      // neighbour chord (m)
  real closedGap_ = 0;  // angle between neighbours, mouth closed (rad)
  real openGap_ = 0;    // angle between non-mouth neighbours, mouth fully open (rad)
  std::vector<Circle*> circles_;
  std::vector<std::pair<int, int>> linkEnds_;  // circles joined by each link, in link order
  std::vector<Vector2> shape_;                 // commanded circle centres, Pac's frame
  Vector2 shapeCentroid_;                      // centroid of shape_
  real shapeMouth_ = -1;                       // mouth activation shape_ was made for
  VisualSensor eye_;
  std::vector<real> sensors_;
  std::array<real, effectorCount> effectors_{};
};

}  // namespace thyrix
