#include <Agents/PacEater.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace thyrix {

PacEater::PacEater(Pac& pac, const PhysicalObject& target) : pac_(&pac), target_(&target) {}

void PacEater::setTarget(const PhysicalObject& target) {
  target_ = &target;
  phase_ = Phase::Opening;
  stalled_ = 0;
}

void PacEater::drive(real forwardCommand, real turnCommand, real mouthCommand) {
  // Differential drive: turning left (counter-clockwise) pushes the right half forward and the
  // left half back. Each side's signed command splits into its forward and backward effector.
  const real left = std::clamp(forwardCommand - turnCommand, real(-1), real(1));
  const real right = std::clamp(forwardCommand + turnCommand, real(-1), real(1));
  const auto effectors = pac_->effectors();
  effectors[Pac::leftForward] = std::max(left, real(0));
  effectors[Pac::leftBackward] = std::max(-left, real(0));
  effectors[Pac::rightForward] = std::max(right, real(0));
  effectors[Pac::rightBackward] = std::max(-right, real(0));
  effectors[Pac::mouth] = mouthCommand;
}

void PacEater::step() {
  const auto sensors = pac_->sensors();
  const Vector2 local = pac_->toLocal(target_->r);  // in the ring's frame, x along the heading
  const bool inside = pac_->contains(target_->r);
  if (phase_ == Phase::Opening && sensors[Pac::mouthSensor] >= real(0.9))
    phase_ = Phase::Approaching;
  // Inside but stalled (a full ring, a wall ahead): close on it where it is.
  stalled_ = phase_ == Phase::Approaching && inside && sensors[Pac::forwardSensor] < real(0.05)
                 ? stalled_ + 1
                 : 0;
  if (phase_ == Phase::Approaching && inside && (local.x < 0 || stalled_ >= 50))
    phase_ = Phase::Closing;
  if (phase_ == Phase::Closing && sensors[Pac::mouthSensor] <= real(0.05)) phase_ = Phase::Carrying;

  switch (phase_) {
    case Phase::Opening:
      drive(0, 0, 1);
      break;
    case Phase::Approaching: {
      if (inside) {  // through the mouth: straight on until the back of the ring reaches it
        drive(1, 0, 1);
        break;
      }
      // Turn toward the target at full rate beyond about 20 degrees off the heading, and slow
      // down when it is off the heading, so that it meets the open mouth rather than a mouth
      // circle; back off a little when it is well off the heading, so that a wall or an object
      // touching the ring does not block the turn.
      const real bearing = std::atan2(local.y, local.x);
      drive(std::clamp(1 - std::abs(bearing) / real(0.5), real(-0.3), real(1)),
            std::clamp(3 * bearing, real(-1), real(1)), 1);
      break;
    }
    case Phase::Closing:
      drive(0, 0, 0);
      break;
    case Phase::Carrying:
      drive(1, 0, 0);
      break;
  }
}

void PacEater::saveState(StateRecord& record) const {
  record.addWord(static_cast<std::uint64_t>(phase_));
  record.addInteger(stalled_);
}

void PacEater::restoreState(StateRecord::Reader& reader) {
  const std::uint64_t phase = reader.word();
  if (phase > static_cast<std::uint64_t>(Phase::Carrying))
    throw std::runtime_error("WorldState: PacEater's phase " + std::to_string(phase) +
                             " does not exist");
  phase_ = static_cast<Phase>(phase);
  stalled_ = static_cast<int>(reader.integer());
}

}  // namespace thyrix
