#include <ThyrixLite/InvalidArgument.h>
#include <ThyrixPro/ArticulatedBody.h>
#include <ThyrixPro/CosSin.h>
#include <ThyrixPro/SpatialAlgebra.h>

#include <algorithm>
#include <climits>
#include <cmath>
#include <string>
#include <type_traits>
#include <utility>

// The quasistatic articulated-body algorithm (Featherstone 2008, chapter 7; docs/Algorithms.md
// section 2) with every body's spatial quantities expressed about its frame origin (the base's
// centre of mass, or the link's joint) in *world-aligned* axes. The algorithm holds in any
// coordinates as long as each quantity is expressed consistently (Featherstone 2008 uses body
// coordinates); world axes make every parent-to-child transform X_i a pure translation, keep
// the revolute joint's motion subspace S_i = (1, 0, 0) in every frame (the joint's axis passes
// through the frame origin), and give world velocities and take world forces with no rotation.
//
// With velocities in place of accelerations and no velocity-product terms, the equation of
// motion of body i is f_i = D_i v_i - f_ext,i, where f_i is the force its parent transmits
// through joint i (docs/Algorithms.md section 2). The articulated-body equation
// f_i = D^A_i v_i + p^A_i (Featherstone 2008, chapter 7, with v for a and no velocity-product
// terms) is built leaves to root, and then the joint rates follow root to leaves.

namespace thyrix {

namespace {

std::string sizeProblem(std::size_t expected, std::size_t got) {
  return "must have " + std::to_string(expected) + " entries or none (got " + std::to_string(got) +
         ")";
}

}  // namespace

// --- Output ----------------------------------------------------------------------------------

void ArticulatedBody::Output::resize(int linkCount) {
  velocities.resize(static_cast<std::size_t>(linkCount) + 1);
  jointRates.resize(static_cast<std::size_t>(linkCount));
}

void ArticulatedBody::Output::setZero() {
  std::fill(velocities.begin(), velocities.end(), Vector3{});
  std::fill(jointRates.begin(), jointRates.end(), real(0));
}

void ArticulatedBody::Output::addScaled(const Output& other, real scale) {
  for (std::size_t k = 0; k < velocities.size(); ++k) velocities[k] += other.velocities[k] * scale;
  for (std::size_t k = 0; k < jointRates.size(); ++k) jointRates[k] += other.jointRates[k] * scale;
}

// --- construction and state ------------------------------------------------------------------

ArticulatedBody::ArticulatedBody(real baseMass, real baseInertia,
                                 std::vector<ArticulatedLink> links)
    : baseMass_(baseMass), baseInertia_(baseInertia), links_(std::move(links)) {
  requirePositive(baseMass, "ArticulatedBody.baseMass");
  requirePositive(baseInertia, "ArticulatedBody.baseInertia");
  if (links_.size() >= static_cast<std::size_t>(INT_MAX))
    throw InvalidArgument("ArticulatedBody.links",
                          "must be fewer than INT_MAX (got " + std::to_string(links_.size()) + ")");
  // linkCount() counts the joint angles, which are sized below.
  for (std::size_t i = 0; i < links_.size(); ++i) links_[i].validate(static_cast<int>(i));

  // Every work array is sized here, once: the passes below only overwrite them.
  const std::size_t n = links_.size();
  parentSlot_.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const int slot = links_[i].parent + 1;  // the base, -1, is at slot 0
    parentSlot_[i] = static_cast<std::size_t>(slot);
  }
  // A link passes its terms through its parent's slot unless its parent is at slot i, the
  // body visited just after it (ArticulatedBodyPasses.cpp): link i - 1, or the base for link 0.
  gathers_.assign(n + 1, 0);
  for (std::size_t i = 0; i < n; ++i)
    if (parentSlot_[i] != i) gathers_[parentSlot_[i]] = 1;
  for (std::size_t slot = 0; slot <= n; ++slot)
    if (gathers_[slot] != 0) gatheringSlots_.push_back(slot);
  inChain_.assign(n, 0);
  for (std::size_t i = 0; i < n; ++i)
    inChain_[i] = parentSlot_[i] == i && gathers_[i + 1] == 0 ? 1 : 0;
  allInChain_ =
      std::all_of(inChain_.begin(), inChain_.end(), [](std::uint8_t c) { return c != 0; });
  q_.assign(n, 0);
  origin_.assign(n + 1, Vector2{});
  angle_.assign(n + 1, 0);
  axis_.assign(n + 1, Vector2{1, 0});
  comOffset_.assign(n + 1, Vector2{});
  placements_.resize(n);
  linkMasses_.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const ArticulatedLink& link = links_[i];
    placements_[i] = {link.jointPosition, link.centerOfMass};
    linkMasses_[i] = {link.mass, link.inertia + link.mass * link.centerOfMass.lengthSquared()};
  }
  articulatedInertia_.assign(n + 1, SymmetricMatrix3{});
  bias_.assign(n + 1, Vector3{});
  originVelocity_.assign(n + 1, Vector3{});
  shift_.assign(n, Vector2{});
  terms_.assign(n, JointTerms{});
  jointDamping_.assign(n, 0);
  jointTorque_.assign(n, 0);
  jointBias_.assign(n, 0);
  forwardKinematics();
}

void ArticulatedBody::setBasePose(Vector2 position, real angle) {
  requireFinite(position, "ArticulatedBody.basePosition");
  requireFinite(angle, "ArticulatedBody.baseAngle");
  basePosition_ = position;
  baseAngle_ = angle;
  forwardKinematics();
}

void ArticulatedBody::refuseLink(int i) const {
  throw InvalidArgument(
      "ArticulatedBody.link",
      "index must be in [0, " + std::to_string(linkCount()) + ") (got " + std::to_string(i) + ")");
}

void ArticulatedBody::setJointAngle(int i, real q) {
  if (i < 0 || i >= linkCount())
    throw InvalidArgument("ArticulatedBody.q", "index must be in [0, " +
                                                   std::to_string(linkCount()) + ") (got " +
                                                   std::to_string(i) + ")");
  requireFinite(q, "ArticulatedBody.q");
  q_[i] = q;
  forwardKinematics();
}

void ArticulatedBody::setJointDamping(int i, real damping) {
  if (i < 0 || i >= linkCount())
    throw InvalidArgument("ArticulatedBody.jointDamping", "index must be in [0, " +
                                                              std::to_string(linkCount()) +
                                                              ") (got " + std::to_string(i) + ")");
  if (!(damping >= 0) || !std::isfinite(damping))
    throw InvalidArgument("ArticulatedBody.jointDamping",
                          "must be finite and non-negative (got " + std::to_string(damping) + ")");
  real& c = jointDamping_[static_cast<std::size_t>(i)];
  if (c == damping) return;
  if (c == 0) ++dampedJoints_;
  if (damping == 0) --dampedJoints_;
  c = damping;
  inertiasStale_ = true;  // d_i + c_i enters D^A of every ancestor
}

void ArticulatedBody::setJointAngles(std::span<const real> q) {
  if (q.size() != q_.size())
    throw InvalidArgument("ArticulatedBody.q", "must have " + std::to_string(q_.size()) +
                                                   " entries (got " + std::to_string(q.size()) +
                                                   ")");
  for (const real value : q) requireFinite(value, "ArticulatedBody.q");
  std::copy(q.begin(), q.end(), q_.begin());
  forwardKinematics();
}

void ArticulatedBody::integrate(const Output& out, real dt) {
  integrate(out, dt, [](std::size_t, Vector2, real, Vector2) {});
}

void ArticulatedBody::moveBase(const Output& out, real dt) {
  if (out.velocities.size() != origin_.size() || out.jointRates.size() != q_.size())
    throw InvalidArgument("ArticulatedBody.Output",
                          "must be sized for " + std::to_string(linkCount()) + " links");
  if (!baseFixed_) {
    basePosition_ += out.linearVelocity(base) * dt;
    baseAngle_ += out.angularVelocity(base) * dt;
  }
}

// --- kinematics ------------------------------------------------------------------------------

void ArticulatedBody::forwardKinematics() {
  // Parents come before children, so sweeps in index order find every parent's pose ready
  // (the regular numbering of a kinematic tree, Featherstone 2008, chapter 4). Three sweeps:
  // the angles (a chain of additions), their axes (cos, sin) all at once (cosSin(), a loop
  // that vectorizes: no call per link), then the origins and centre-of-mass offsets. The
  // parent's angle, origin and axis are carried in registers when it is the body just visited
  // (slot i, the usual case within a limb), as in the articulated-body passes: each link waits
  // for its parent's, and a round trip through memory would lengthen the chain.
  anglesAndAxes(nullptr, 0);
  const auto nothing = [](std::size_t, Vector2, real, Vector2) {};
  if (allInChain_)
    linkOrigins<true>(nothing);
  else
    linkOrigins<false>(nothing);
}

void ArticulatedBody::anglesAndAxes(const real* rates, real dt) {
  angle_[0] = baseAngle_;
  real parentAngle = baseAngle_;
  bool kernelTakesAll = cosSinKernelTakes(baseAngle_);
  // In two copies, with and without integrate()'s move of the joints (q_i += qdot_i dt, in
  // the same pass).
  const auto sweep = [&](auto moving) {
    // (A plain chain, allInChain_, has every parent at slot i: no slot to test.)
    for (std::size_t i = 0; i < links_.size(); ++i) {
      if (!allInChain_) {
        const std::size_t p = parentSlot_[i];
        if (p != i) parentAngle = angle_[p];
      }
      if constexpr (decltype(moving)::value) q_[i] += rates[i] * dt;
      parentAngle += q_[i];
      angle_[i + 1] = parentAngle;
      kernelTakesAll &= cosSinKernelTakes(parentAngle);
    }
  };
  if (rates != nullptr)
    sweep(std::true_type{});
  else
    sweep(std::false_type{});
  if (kernelTakesAll)
    cosSinKernel(angle_, axis_);
  else
    cosSin(angle_, axis_);
  // Everything that depends on the configuration is now out of date.
  inertiasStale_ = true;
}

// --- solve and respond -----------------------------------------------------------------------

void ArticulatedBody::solve(std::span<const real> jointTorques,
                            std::span<const Vector3> externalWrenches, Output& out) {
  checkTorques(jointTorques);
  if (!externalWrenches.empty() && externalWrenches.size() != origin_.size())
    throw InvalidArgument("ArticulatedBody.externalWrenches",
                          sizeProblem(origin_.size(), externalWrenches.size()));
  Wrenches wrenches;
  wrenches.perBody = externalWrenches.empty() ? nullptr : externalWrenches.data();
  solveWith(jointTorques, wrenches, out);
}

void ArticulatedBody::solve(std::span<const real> jointTorques, const Vector3& baseWrench,
                            const Vector3& linkWrench, Output& out) {
  checkTorques(jointTorques);
  solveWith(jointTorques, Wrenches{nullptr, true, baseWrench, linkWrench}, out);
}

void ArticulatedBody::solveWith(std::span<const real> jointTorques, const Wrenches& wrenches,
                                Output& out) {
  out.resize(linkCount());

  // The inward pass adds the wrenches to the bias terms as it visits the bodies.
  // Only the slots that gather children's terms are read (gathers_); the torques are read
  // where they are.
  clearGatheringSlots(bias_);
  const real* torques = jointTorques.data();
  if (jointTorques.empty()) {
    std::fill(jointTorque_.begin(), jointTorque_.end(), real(0));
    torques = jointTorque_.data();
  }
  biasAndOutwardPasses<false>(wrenches, torques, out);
}

void ArticulatedBody::checkTorques(std::span<const real> jointTorques) const {
  if (!jointTorques.empty() && jointTorques.size() != q_.size())
    throw InvalidArgument("ArticulatedBody.jointTorques",
                          sizeProblem(q_.size(), jointTorques.size()));
}

void ArticulatedBody::checkTestForce(const TestForce& force) const {
  const int low = force.kind == TestForce::Kind::PointForce ? base : 0;
  if (force.index < low || force.index >= linkCount())
    throw InvalidArgument("ArticulatedBody.TestForce.index",
                          "must be in [" + std::to_string(low) + ", " +
                              std::to_string(linkCount()) + ") (got " +
                              std::to_string(force.index) + ")");
}

void ArticulatedBody::depositTestForce(const TestForce& force, real magnitude) {
  if (force.kind == TestForce::Kind::PointForce) {
    const int slot = force.index + 1;
    bias_[slot] -= spatialForceAt(force.direction * magnitude, force.point, origin_[slot]);
  } else {
    jointTorque_[static_cast<std::size_t>(force.index)] += force.torque * magnitude;
  }
}

void ArticulatedBody::respond(const TestForce& force, Output& out) {
  respond(std::span<const TestForce>(&force, 1), {}, out);
}

void ArticulatedBody::respond(std::span<const TestForce> forces, std::span<const real> magnitudes,
                              Output& out) {
  if (!magnitudes.empty() && magnitudes.size() != forces.size())
    throw InvalidArgument("ArticulatedBody.magnitudes",
                          sizeProblem(forces.size(), magnitudes.size()));
  for (const TestForce& force : forces) checkTestForce(force);
  // The articulated inertias do not depend on the forces (Kokkevis 2004): only the bias terms
  // are recomputed, from the test forces alone (and the inertias once, if stale).
  out.resize(linkCount());
  std::fill(bias_.begin(), bias_.end(), Vector3{});
  std::fill(jointTorque_.begin(), jointTorque_.end(), real(0));
  for (std::size_t k = 0; k < forces.size(); ++k)
    depositTestForce(forces[k], magnitudes.empty() ? real(1) : magnitudes[k]);
  biasAndOutwardPasses<true>(Wrenches{}, jointTorque_.data(), out);
}

// --- reading velocities ----------------------------------------------------------------------

Vector2 ArticulatedBody::pointVelocity(const Output& out, int b, Vector2 point) const {
  return out.linearVelocity(b) + cross(out.angularVelocity(b), point - centerOfMass(b));
}

real ArticulatedBody::velocityAlong(const Output& out, const TestForce& constraint) const {
  if (constraint.kind == TestForce::Kind::PointForce)
    return constraint.direction.dot(pointVelocity(out, constraint.index, constraint.point));
  return constraint.torque * out.jointRates[static_cast<std::size_t>(constraint.index)];
}

}  // namespace thyrix
