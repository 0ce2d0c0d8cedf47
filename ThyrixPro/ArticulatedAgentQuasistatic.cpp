#include <ThyrixPro/ArticulatedAgentQuasistatic.h>
#include <Tools/ProcessorFeatures.h>

#include <algorithm>
#include <cmath>
#include <utility>

namespace thyrix {

ArticulatedAgentQuasistatic::ArticulatedAgentQuasistatic(
    const std::vector<ArticulatedBasePart>& baseParts, const std::vector<ArticulatedLimb>& limbs)
    : ArticulatedAgentBase(baseParts, limbs),
      free_(linkCount()),
      response_(linkCount()),
      torques_(index(linkCount()), 0),
      lastRates_(index(linkCount()), 0) {
  // Room for a few constraints per body; more only grows the buffer to the largest count seen.
  tests_.reserve(index(2 * linkCount() + 8));
}

void ArticulatedAgentQuasistatic::computeDerivativesWithoutContacts() {
  // `r` and `alpha` are public: follow a move made by hand (the contacts of this step were
  // found at the old place; the next step's are right).
  if ((r != body_.basePosition() || alpha != body_.baseAngle()) && std::isfinite(r.x) &&
      std::isfinite(r.y) && std::isfinite(alpha))
    setPose(r, alpha);
  body_.setBaseFixed(fixed);

  // The servo tau = k (q* - q - dt qdot) with the step's final qdot, solved implicitly: the
  // damping c = k dt joins d_i in the articulated-body algorithm (ArticulatedBody), and
  // k (q* - q) is an ordinary torque. The joint's equation becomes (d + k dt) qdot = k (q* - q)
  // + ..., which cannot overshoot, whatever k (docs/Algorithms.md section 2, pitfalls). The damping
  // is constant between changes of the servos (or of the time step): it is set only then, and
  // only where it differs, since a change costs the body a new inertia pass.
  const real dt = timestep();
  if (servosChanged_ || dt != dampingTimestep_) {
    for (int i = 0; i < linkCount(); ++i) {
      const real damping = servoGains_[index(i)] * dt;
      if (body_.jointDamping(i) != damping) body_.setJointDamping(i, damping);
    }
    servosChanged_ = false;
    dampingTimestep_ = dt;
  }
  std::span<const real> torques = jointTorques_;
  if (servoCount_ > 0) {
    for (int i = 0; i < linkCount(); ++i) {
      const std::size_t j = index(i);
      const real gain = servoGains_[j];
      torques_[j] = jointTorques_[j];
      if (gain > 0) torques_[j] += gain * (servoTargets_[j] - body_.jointAngles()[j]);
    }
    torques = torques_;
  }
  // The base's force acts at its centre of mass, as for any PhysicalObject (applyForce() has put
  // the moment of an off-centre force in externalTorque). The accumulated wrenches are handed
  // to the solve as they are, and cleared after it.
  linkWrenches_[0] += Vector3{externalTorque, externalForce.x, externalForce.y};

  // The free velocities are solved straight into the final ones: until the contact solver says
  // otherwise (it leaves an agent without constraints alone), they are the same, and
  // applyConstraintForces() saves them before changing them. The last step's rates are kept
  // for the limits (a swap of buffers, not a copy).
  std::swap(lastRates_, velocities_.jointRates);
  if (linkWeightKept_)  // every link's wrench is the weight applyWeight() kept
    body_.solve(torques, linkWrenches_[0], linkWeight_, velocities_);
  else
    body_.solve(torques, linkWrenches_, velocities_);
  freeSaved_ = false;
  v = velocities_.linearVelocity(base);
  omega = velocities_.angularVelocity(base);

  externalForce = {};
  externalTorque = 0;
  if (linkWrenchesClear_)
    linkWrenches_[0] = Vector3{};  // the links' are still zero
  else
    std::fill(linkWrenches_.begin(), linkWrenches_.end(), Vector3{});
  linkWrenchesClear_ = true;
  linkWeightKept_ = false;
  if (limitsActed_) {
    std::fill(limitTorques_.begin(), limitTorques_.end(), real(0));
    limitsActed_ = false;
  }
}

const ArticulatedBody::Output& ArticulatedAgentQuasistatic::freeVelocities() const {
  return freeSaved_ ? free_ : velocities_;
}

ArticulatedBody::TestForce ArticulatedAgentQuasistatic::toTestForce(const UnitForce& force) const {
  if (force.primitive == nullptr)
    return ArticulatedBody::TestForce::onJoint(force.joint, force.torque);
  return ArticulatedBody::TestForce::atPoint(bodyOf(*force.primitive), force.point,
                                             force.direction);
}

void ArticulatedAgentQuasistatic::convert(std::span<const UnitForce> forces) {
  tests_.clear();
  for (const UnitForce& force : forces) tests_.push_back(toTestForce(force));
}

real ArticulatedAgentQuasistatic::velocityAlong(const UnitForce& force) const {
  return body_.velocityAlong(freeVelocities(), toTestForce(force));
}

void ArticulatedAgentQuasistatic::responseMatrix(std::span<const UnitForce> forces,
                                                 std::span<real> matrix) {
  convert(forces);
  const std::size_t n = tests_.size();
  // Column j: the response to unit force j alone, read by every constraint (Kokkevis). The
  // articulated inertias are computed once (by the first respond()) and reused for every column.
  for (std::size_t j = 0; j < n; ++j) {
    body_.respond(tests_[j], response_);
    for (std::size_t i = 0; i < n; ++i)
      matrix[i * n + j] = body_.velocityAlong(response_, tests_[i]);
  }
  // K = J (J^T D J)^-1 J^T is symmetric; the columns agree with the rows only to round-off.
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j) {
      const real mean = (matrix[i * n + j] + matrix[j * n + i]) / 2;
      matrix[i * n + j] = mean;
      matrix[j * n + i] = mean;
    }
}

void ArticulatedAgentQuasistatic::applyConstraintForces(std::span<const UnitForce> forces,
                                                        std::span<const real> magnitudes) {
  convert(forces);
  // The responses are linear in the forces: one pass with every force scaled gives their sum.
  body_.respond(tests_, magnitudes, response_);
  if (!freeSaved_) {
    // The first change of this step's velocities: keep the free ones, which velocityAlong()
    // reads and to which a later call adds its response again.
    std::copy(velocities_.velocities.begin(), velocities_.velocities.end(),
              free_.velocities.begin());
    std::copy(velocities_.jointRates.begin(), velocities_.jointRates.end(),
              free_.jointRates.begin());
    freeSaved_ = true;
  }
  std::copy(free_.velocities.begin(), free_.velocities.end(), velocities_.velocities.begin());
  std::copy(free_.jointRates.begin(), free_.jointRates.end(), velocities_.jointRates.begin());
  velocities_.addScaled(response_, 1);
  v = velocities_.linearVelocity(base);
  omega = velocities_.angularVelocity(base);
  for (std::size_t k = 0; k < forces.size(); ++k) {
    if (forces[k].primitive != nullptr) continue;
    limitTorques_[index(forces[k].joint)] += forces[k].torque * magnitudes[k];
    limitsActed_ = true;
  }
}

void ArticulatedAgentQuasistatic::collectInternalConstraints(real dt,
                                                             std::vector<InternalConstraint>& out) {
  for (const int i : limitedJoints_) {
    const ArticulatedLink& link = body_.links()[index(i)];
    const real q = body_.jointAngles()[index(i)];
    // How far the joint may turn this step toward each limit: by its free rate, or by its last
    // step's rate (contacts may keep driving it, and their forces are not known yet), plus the
    // margin. A row that turns out not to be needed costs one LCP row and gets no torque.
    const real freeRate = freeVelocities().jointRate(i);
    const real lastRate = lastRates_[index(i)];
    const real down = dt * std::max({real(0), -freeRate, -lastRate}) + limitMargin;
    const real up = dt * std::max({real(0), freeRate, lastRate}) + limitMargin;
    if (q - link.qMin <= down) out.push_back({{nullptr, {}, {}, i, 1}, (link.qMin - q) / dt});
    if (link.qMax - q <= up) out.push_back({{nullptr, {}, {}, i, -1}, (q - link.qMax) / dt});
  }
}

void ArticulatedAgentQuasistatic::integrate(real dt) {
  // The servos' torques with the final rates, for proprioception, before q moves; once more
  // after the last servo is cleared, which sets them all to zero.
  if (servoCount_ > 0 || servoTorquesSet_) {
    for (int i = 0; i < linkCount(); ++i) {
      const std::size_t j = index(i);
      servoTorques_[j] = servoGains_[j] * (servoTargets_[j] - body_.jointAngles()[j] -
                                           dt * velocities_.jointRates[j]);
    }
    servoTorquesSet_ = servoCount_ > 0;
  }
  // A fixed base stays put. The links' shapes are placed as the kinematics reach them.
  const auto run = [this, dt] {
    body_.integrate(velocities_, dt,
                    [this](std::size_t i, Vector2 centerOfMass, real angle, Vector2 axis) {
                      placeLinkShape(i, centerOfMass, angle, axis);
                    });
  };
#if defined(THYRIX_AVX_DISPATCH)
  // With AVX the same loop in VEX form (flatten: the kinematics inlined into it): the same
  // operations, so the same bits, without SSE2's register copies and its broadcasts read from
  // memory. 128-bit vectors for GCC: with 256 it merges each capsule's direction and position
  // into one store, built on the stack. (Clang ignores a target with that option.)
#if defined(__clang__)
  const auto runAvx = [&run]() __attribute__((target("avx"), flatten)) { run(); };
#else
  const auto runAvx = [&run]() __attribute__((target("avx,prefer-vector-width=128"), flatten)) {
    run();
  };
#endif
  if (processorHasAvx())
    runAvx();
  else
    run();
#else
  run();
#endif
  placeBase();
}

void ArticulatedAgentQuasistatic::saveState(StateRecord& record) const {
  ArticulatedAgentBase::saveState(record);
  record.add(std::span<const real>(lastRates_));
  record.add(freeSaved_);
  for (const Vector3& velocity : free_.velocities) {
    record.add(velocity.x);
    record.add(velocity.y);
    record.add(velocity.z);
  }
  record.add(std::span<const real>(free_.jointRates));
  record.add(limitsActed_);
  record.add(servoTorquesSet_);
}

void ArticulatedAgentQuasistatic::restoreState(StateRecord::Reader& reader) {
  ArticulatedAgentBase::restoreState(reader);
  reader.reals(lastRates_);
  freeSaved_ = reader.flag();
  for (Vector3& velocity : free_.velocities) {
    velocity.x = reader.value();
    velocity.y = reader.value();
    velocity.z = reader.value();
  }
  reader.reals(free_.jointRates);
  limitsActed_ = reader.flag();
  servoTorquesSet_ = reader.flag();
}

}  // namespace thyrix
