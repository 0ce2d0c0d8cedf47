#include <Agents/IunctusGrasper.h>

#include <Tools/MathTools.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace thyrix {
namespace {

constexpr real openPose[3] = {pi<real> / 2, 0, 0};
constexpr real closedPose[3] = {0, -pi<real> / 2, -pi<real> / 2};

}  // namespace

IunctusGrasper::IunctusGrasper(Iunctus& agent, const PhysicalObject& target, real carryDistance)
    : agent_(&agent), target_(&target), carryDistance_(carryDistance) {
  std::copy(std::begin(openPose), std::end(openPose), std::begin(pose_));
}

void IunctusGrasper::drive(real forwardCommand, real turnCommand, const real (&pose)[3]) {
  const auto effectors = agent_->effectors();
  const real f = std::clamp(forwardCommand, real(-1), real(1));
  const real t = std::clamp(turnCommand, real(-1), real(1));
  effectors[Iunctus::forward] = std::max(f, real(0));
  effectors[Iunctus::backward] = std::max(-f, real(0));
  effectors[Iunctus::turnLeft] = std::max(t, real(0));
  effectors[Iunctus::turnRight] = std::max(-t, real(0));
  for (int i = 0; i < Iunctus::jointCount; ++i)
    effectors[static_cast<std::size_t>(Iunctus::firstServo + i)] =
        agent_->servoActivation(i, pose[i]);
}

bool IunctusGrasper::reached(const real (&pose)[3]) const {
  for (int i = 0; i < Iunctus::jointCount; ++i)
    if (std::abs(agent_->jointAngle(i) - pose[i]) > real(0.05)) return false;
  return true;
}

void IunctusGrasper::control(std::span<const real>, std::span<real>) { step(); }

void IunctusGrasper::step() {
  // The target in the base's frame (x forward).
  const Vector2 h = agent_->heading();
  const Vector2 d = target_->r - agent_->r;
  const Vector2 local{dot(d, h), dot(d, h.perpendicular())};

  if (phase_ == Phase::Opening && reached(openPose)) phase_ = Phase::Approaching;
  if (phase_ == Phase::Approaching && distance(local, gripPoint) < real(0.03)) {
    phase_ = Phase::Closing;
    still_ = 0;
    holdPosition_ = agent_->r;
    holdHeading_ = agent_->alpha;
  }
  if (phase_ == Phase::Closing &&
      std::equal(std::begin(pose_), std::end(pose_), std::begin(closedPose))) {
    bool resting = true;
    for (int i = 0; i < Iunctus::jointCount; ++i)
      resting = resting && std::abs(agent_->jointRate(i)) < real(0.01);
    still_ = resting ? still_ + 1 : 0;
    if (still_ >= 20) {
      phase_ = Phase::Carrying;
      carryStart_ = target_->r;
      holdHeading_ = agent_->alpha;
    }
  }
  if (phase_ == Phase::Carrying && distance(target_->r, carryStart_) >= carryDistance_)
    phase_ = Phase::Holding;

  switch (phase_) {
    case Phase::Opening:
      drive(0, 0, openPose);
      break;
    case Phase::Approaching: {
      // Turn so that the target lies on the grip point's bearing, and close the distance to
      // the grip point's range; slowly near it so as to stop there without touching the target.
      const real bearingError = std::atan2(local.y, local.x) - std::atan2(gripPoint.y, gripPoint.x);
      const real rangeError = local.length() - gripPoint.length();
      drive(std::clamp(2 * rangeError, real(-0.5), real(0.5)) *
                std::max(real(0), 1 - 2 * std::abs(bearingError)),
            3 * bearingError, openPose);
      break;
    }
    case Phase::Closing: {
      // Move the commanded pose toward the closed one at closingRate, so the servos turn the
      // joints slowly: the joint torques also turn the (floating) base the other way, and a
      // slow limb needs small torques, which the base's own effectors can hold against. The
      // base holds its place and heading meanwhile, so the target stays in the closing box.
      const real most = closingRate * agent_->timestep();
      for (int i = 0; i < Iunctus::jointCount; ++i)
        pose_[i] += std::clamp(closedPose[i] - pose_[i], -most, most);
      const Vector2 back = holdPosition_ - agent_->r;
      drive(4 * dot(back, h), 4 * (holdHeading_ - agent_->alpha), pose_);
      break;
    }
    case Phase::Carrying:
      // The target pushed off the base's axis turns it: hold the heading to carry it straight.
      drive(1, 4 * (holdHeading_ - agent_->alpha), closedPose);
      break;
    case Phase::Holding:
      drive(0, 0, closedPose);
      break;
  }
}

void IunctusGrasper::saveState(StateRecord& record) const {
  record.addWord(static_cast<std::uint64_t>(phase_));
  record.addInteger(still_);
  record.add(carryStart_);
  for (const real angle : pose_) record.add(angle);
  record.add(holdPosition_);
  record.add(holdHeading_);
}

void IunctusGrasper::restoreState(StateRecord::Reader& reader) {
  const std::uint64_t phase = reader.word();
  if (phase > static_cast<std::uint64_t>(Phase::Holding))
    throw std::runtime_error("WorldState: IunctusGrasper's phase " + std::to_string(phase) +
                             " does not exist");
  phase_ = static_cast<Phase>(phase);
  still_ = static_cast<int>(reader.integer());
  carryStart_ = reader.vector();
  for (real& angle : pose_) angle = reader.value();
  holdPosition_ = reader.vector();
  holdHeading_ = reader.value();
}

}  // namespace thyrix
