#include <Agents/Spherus.h>

#include <ThyrixLite/GUI.h>
#include <ThyrixLite/World.h>
#include <Tools/MathTools.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace thyrix {
namespace {

constexpr int contactSensors = 8;
constexpr int pixels = 7;
constexpr real pixelAngle = pi<real> / 12;  // 15 degrees

real unit(real x) { return std::clamp(x, real(0), real(1)); }

}  // namespace

Spherus::Spherus(std::unique_ptr<Controller> controller, const Parameters& parameters)
    : parameters_(parameters),
      controller_(std::move(controller)),
      left_(&addBody(std::make_unique<Circle>(parameters.radius, parameters.mass))),
      right_(&addBody(std::make_unique<Circle>(parameters.radius, parameters.mass))),
      link_(&addLink(*left_, {}, *right_, {}, parameters.linkLength, parameters.linkStiffness)),
      eyes_{VisualSensor(*left_, {}, 0, pixels, pixelAngle),
            VisualSensor(*right_, {}, 0, pixels, pixelAngle)} {
  for (Circle* circle : {left_, right_}) {
    // Sensor 0 centred on forward (the circle's x axis once aligned to the heading).
    circle->setTactileSensors(contactSensors, -pi<real> / contactSensors,
                              parameters.tactileSaturation);
    circle->color = colors::yellow;
  }
  effectors_[4] = unit(parameters.linkLength / parameters.maxLinkLength);
  place({0, 0}, pi<real> / 2);
}

void Spherus::place(Vector2 centre, real heading) {
  const Vector2 forwardDirection{std::cos(heading), std::sin(heading)};
  const Vector2 along{forwardDirection.y, -forwardDirection.x};  // left to right
  const real half = link_->restLength() / 2;
  left_->r = centre - along * half;
  right_->r = centre + along * half;
  left_->alpha = right_->alpha = heading;
}

Vector2 Spherus::forward() const { return (right_->r - left_->r).normalized().perpendicular(); }

void Spherus::updateSensors(const World& world) {
  // A circle's orientation has no effect on its physics (its contacts are frictionless and
  // pass through its centre): turn both frames to the heading so the sensors follow it.
  const Vector2 f = forward();
  if (f.lengthSquared() > 0) left_->alpha = right_->alpha = std::atan2(f.y, f.x);
  for (VisualSensor& eye : eyes_) eye.update(world.objects);
}

void Spherus::readSensors(Vector2 f) {
  const real fullSpeed = parameters_.maxForce / parameters_.mass;
  const Circle* circles[2] = {left_, right_};
  for (int c = 0; c < 2; ++c) {
    real* out = &sensors_[static_cast<std::size_t>(c * sensorsPerCircle)];
    // Copies of the constructor's counts, known here: a few moves, no memmove call. (The
    // circles are public: tactile sensors set again to another count copy what fits.)
    const auto touch = circles[c]->tactileActivations();
    if (touch.size() == std::size_t{contactSensors}) {
      for (int i = 0; i < contactSensors; ++i) out[i] = touch[i];
    } else {
      std::copy_n(touch.begin(), std::min(touch.size(), std::size_t{contactSensors}), out);
    }
    const real* const seen = eyes_[c].activations().data();  // the eye's own pixel count
    for (int i = 0; i < pixels; ++i) out[contactSensors + i] = seen[i];
    const real speed = dot(circles[c]->v, f) / fullSpeed;
    out[contactSensors + pixels] = unit(speed);
    out[contactSensors + pixels + 1] = unit(-speed);
  }
  // The link's anchors are the circles' centres: its length without ElasticLink::length()'s
  // two rotations of a zero anchor (a cosine and a sine each), the same value bit for bit
  // while the circles' angles are finite (a rotation by a NaN angle made it NaN).
  sensors_[sensorCount - 1] = unit((right_->r - left_->r).length() / parameters_.maxLinkLength);
}

void Spherus::applyEffectors(Vector2 f) {
  for (real& e : effectors_) e = unit(e);
  left_->externalForce += f * (parameters_.maxForce * (effectors_[0] - effectors_[1]));
  right_->externalForce += f * (parameters_.maxForce * (effectors_[2] - effectors_[3]));
  link_->setRestLength(effectors_[4] * parameters_.maxLinkLength);
}

void Spherus::control() {
  // The circles do not move between reading the sensors and applying the effectors: one
  // forward direction (a square root and a division) serves both.
  const Vector2 f = forward();
  readSensors(f);
  if (controller_) controller_->control(sensors_, effectors_);
  applyEffectors(f);
}

void Spherus::draw(GUI& gui) const {
  Elastoid::draw(gui);
  const Vector2 c = centre();
  gui.drawLine(c, c + forward() * parameters_.radius, colors::black);
}

void Spherus::saveState(StateRecord& record) const {
  Elastoid::saveState(record);
  record.add(std::span<const real>(sensors_));
  record.add(std::span<const real>(effectors_));
  record.add(controller_ != nullptr);
  if (controller_) controller_->saveState(record);
}

void Spherus::restoreState(StateRecord::Reader& reader) {
  Elastoid::restoreState(reader);
  reader.reals(sensors_);
  reader.reals(effectors_);
  if (reader.flag() != (controller_ != nullptr))
    throw std::runtime_error("WorldState: the Spherus's controller is in one world, not the other");
  if (controller_) controller_->restoreState(reader);
}

}  // namespace thyrix
