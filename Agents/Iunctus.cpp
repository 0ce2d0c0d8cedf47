#include <Agents/Iunctus.h>

#include <ThyrixLite/GUI.h>
#include <Tools/MathTools.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace thyrix {
namespace {

real unit(real x) { return std::clamp(x, real(0), real(1)); }

ArticulatedLimb makeLimb(const IunctusParameters& p) {
  // Attached at the top of the base, pointing up (q0 = pi/2): the limb starts open.
  ArticulatedLimb limb({0, p.baseRadius});
  limb.addLink(-1, p.linkLength, p.linkRadius, p.linkMass, pi<real> / 2);
  limb.addLink(0, p.linkLength, p.linkRadius, p.linkMass, 0);
  limb.addLink(1, p.linkLength, p.linkRadius, p.linkMass, 0);
  for (int i = 0; i < 3; ++i) {
    const auto k = static_cast<std::size_t>(i);
    limb.setLimits(i, p.qMin[k], p.qMax[k]);
  }
  return limb;
}

}  // namespace

Iunctus::Iunctus(std::unique_ptr<Controller> controller, const Parameters& parameters)
    : ArticulatedAgentQuasistatic(
          {ArticulatedBasePart::circle(parameters.baseRadius, parameters.baseMass)},
          {makeLimb(parameters)}),
      parameters_(parameters),
      controller_(std::move(controller)) {
  auto& body = static_cast<Circle&>(basePart(0));
  // Sensor 0 centred on forward (the base's x axis).
  body.setTactileSensors(8, -pi<real> / 8, parameters.tactileSaturation);
  body.color = colors::yellow;
  for (int i = 0; i < jointCount; ++i) {
    linkShape(i).setTactileSensors(2, 1, parameters.tactileSaturation);
    linkShape(i).color = colors::yellow;
    // Hold the initial (open) pose until told otherwise.
    effectors_[static_cast<std::size_t>(firstServo + i)] = servoActivation(i, jointAngle(i));
  }
  jointColor = colors::brown;
}

Vector2 Iunctus::heading() const { return {std::cos(alpha), std::sin(alpha)}; }

real Iunctus::servoActivation(int i, real q) const {
  const auto k = static_cast<std::size_t>(i);
  return unit((q - parameters_.qMin[k]) / (parameters_.qMax[k] - parameters_.qMin[k]));
}

bool Iunctus::encloses(Vector2 p) const {
  // Even-odd rule on the polygon base centre, joint 0, joint 1, joint 2, tip.
  const std::array<Vector2, 5> polygon{r, jointPosition(0), jointPosition(1), jointPosition(2),
                                       linkTip(2)};
  bool inside = false;
  for (std::size_t a = 0, b = polygon.size() - 1; a < polygon.size(); b = a++) {
    const Vector2 pa = polygon[a];
    const Vector2 pb = polygon[b];
    if ((pa.y > p.y) != (pb.y > p.y) && p.x < (pb.x - pa.x) * (p.y - pa.y) / (pb.y - pa.y) + pa.x)
      inside = !inside;
  }
  return inside;
}

void Iunctus::readSensors() {
  for (int i = 0; i < jointCount; ++i)
    sensors_[static_cast<std::size_t>(i)] = servoActivation(i, jointAngle(i));
  const auto baseTouch = basePart(0).tactileActivations();
  std::copy(baseTouch.begin(), baseTouch.end(), sensors_.begin() + firstBaseTouch);
  for (int i = 0; i < jointCount; ++i) {
    const auto touch = linkShape(i).tactileActivations();
    std::copy(touch.begin(), touch.end(), sensors_.begin() + firstLinkTouch + i * touchPerLink);
  }
  real held = 0;
  for (const ContactInfo& contact : contacts()) {
    const PhysicalObject* other = contact.other;
    if (other != nullptr && other != this && !other->fixed && encloses(other->r)) held = 1;
  }
  sensors_[heldSensor] = held;
  for (real& s : sensors_) s = unit(s);
}

void Iunctus::applyEffectors() {
  for (real& e : effectors_) e = unit(e);
  externalForce +=
      heading() * (parameters_.maxForce * (effectors_[forward] - effectors_[backward]));
  externalTorque += parameters_.maxTorque * (effectors_[turnLeft] - effectors_[turnRight]);
  for (int i = 0; i < jointCount; ++i) {
    const auto k = static_cast<std::size_t>(i);
    const real target = parameters_.qMin[k] + effectors_[static_cast<std::size_t>(firstServo + i)] *
                                                  (parameters_.qMax[k] - parameters_.qMin[k]);
    setServoTarget(i, target, parameters_.servoGain);
  }
}

void Iunctus::control() {
  readSensors();
  if (controller_) controller_->control(sensors_, effectors_);
  applyEffectors();
}

void Iunctus::draw(GUI& gui) const {
  ArticulatedAgentQuasistatic::draw(gui);
  gui.drawLine(r, r + heading() * parameters_.baseRadius, colors::black);
}

void Iunctus::saveState(StateRecord& record) const {
  ArticulatedAgentQuasistatic::saveState(record);
  record.add(std::span<const real>(sensors_));
  record.add(std::span<const real>(effectors_));
  record.add(controller_ != nullptr);
  if (controller_) controller_->saveState(record);
}

void Iunctus::restoreState(StateRecord::Reader& reader) {
  ArticulatedAgentQuasistatic::restoreState(reader);
  reader.reals(sensors_);
  reader.reals(effectors_);
  if (reader.flag() != (controller_ != nullptr))
    throw std::runtime_error("WorldState: the Iunctus's controller is in one world, not the other");
  if (controller_) controller_->restoreState(reader);
}

}  // namespace thyrix
