#include <ThyrixLite/InvalidArgument.h>
#include <ThyrixPro/ArticulatedBody.h>
#include <ThyrixPro/SpatialAlgebra.h>

#include <algorithm>
#include <climits>
#include <cmath>
#include <string>
#include <utility>

// The quasistatic articulated-body algorithm (Featherstone 2008, chapter 7; ALGORITHMS.md
// section 2) with every body's spatial quantities expressed about its frame origin (the base's
// centre of mass, or the link's joint) in *world-aligned* axes. The algorithm holds in any
// coordinates as long as each quantity is expressed consistently (Featherstone 2008 uses body
// coordinates); world axes make every parent-to-child transform X_i a pure translation, keep
// the revolute joint's motion subspace S_i = (1, 0, 0) in every frame (the joint's axis passes
// through the frame origin), and give world velocities and take world forces with no rotation.
//
// With velocities in place of accelerations and no velocity-product terms, the equation of
// motion of body i is f_i = D_i v_i - f_ext,i, where f_i is the force its parent transmits
// through joint i (ALGORITHMS.md section 2). The articulated-body equation
// f_i = D^A_i v_i + p^A_i (Featherstone 2008, chapter 7, with v for a and no velocity-product
// terms) is built leaves to root, and then the joint rates follow root to leaves.

namespace thyrix {

namespace {

/// @p v turned by the angle whose (cos, sin) is @p axis.
constexpr Vector2 rotate(Vector2 axis, Vector2 v) {
  return {axis.x * v.x - axis.y * v.y, axis.y * v.x + axis.x * v.y};
}

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
  for (int i = 0; i < linkCount(); ++i) links_[i].validate(i);

  // Every work array is sized here, once: the passes below only overwrite them.
  const std::size_t n = links_.size();
  parentSlot_.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const int slot = links_[i].parent + 1;  // the base, -1, is at slot 0
    parentSlot_[i] = static_cast<std::size_t>(slot);
  }
  q_.assign(n, 0);
  origin_.assign(n + 1, Vector2{});
  angle_.assign(n + 1, 0);
  axis_.assign(n + 1, Vector2{1, 0});
  comOffset_.assign(n + 1, Vector2{});
  articulatedInertia_.assign(n + 1, SymmetricMatrix3{});
  bias_.assign(n + 1, Vector3{});
  originVelocity_.assign(n + 1, Vector3{});
  shift_.assign(n, Vector2{});
  jointForceDirection_.assign(n, Vector3{});
  inverseJointInertia_.assign(n, 0);
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
  if (out.velocities.size() != origin_.size() || out.jointRates.size() != q_.size())
    throw InvalidArgument("ArticulatedBody.Output",
                          "must be sized for " + std::to_string(linkCount()) + " links");
  if (!baseFixed_) {
    basePosition_ += out.linearVelocity(base) * dt;
    baseAngle_ += out.angularVelocity(base) * dt;
  }
  for (std::size_t i = 0; i < q_.size(); ++i) q_[i] += out.jointRates[i] * dt;
  forwardKinematics();
}

// --- kinematics ------------------------------------------------------------------------------

void ArticulatedBody::forwardKinematics() {
  // Parents come before children, so one sweep in index order finds every parent's pose ready
  // (the regular numbering of a kinematic tree, Featherstone 2008, chapter 4). Each body's
  // axis (cos, sin) is kept, so a link costs one cos and one sin.
  origin_[0] = basePosition_;
  angle_[0] = baseAngle_;
  axis_[0] = {std::cos(baseAngle_), std::sin(baseAngle_)};
  comOffset_[0] = {};
  for (std::size_t i = 0; i < links_.size(); ++i) {
    const ArticulatedLink& l = links_[i];
    const std::size_t p = parentSlot_[i];
    const std::size_t self = i + 1;
    const Vector2 shift = rotate(axis_[p], l.jointPosition);
    shift_[i] = shift;
    origin_[self] = origin_[p] + shift;
    const real a = angle_[p] + q_[i];
    angle_[self] = a;
    axis_[self] = {std::cos(a), std::sin(a)};
    comOffset_[self] = rotate(axis_[self], l.centerOfMass);
  }
  // Everything that depends on the configuration is now out of date.
  inertiasStale_ = true;
}

// --- articulated inertias ---------------------------------------------------------------------

void ArticulatedBody::startArticulatedInertias() {
  // Each body's own inertia about its frame origin (ALGORITHMS.md section 2); the inward pass
  // then adds its children's articulated terms.
  articulatedInertia_[0] = SymmetricMatrix3::diagonal(baseInertia_, baseMass_, baseMass_);
  for (std::size_t i = 0; i < links_.size(); ++i)
    articulatedInertia_[i + 1] =
        spatialInertia(links_[i].mass, links_[i].inertia, comOffset_[i + 1]);
}

inline void ArticulatedBody::articulateLink(std::size_t i) {
  // Featherstone 2008, section 7.3 and Table 7.1: U_i = I^A_i S_i, d_i = S_i^T U_i, and the
  // parent receives I^a_i = X_i^T (I^A_i - U_i U_i^T / d_i) X_i. A damped joint (torque
  // -c_i qdot_i) has S_i^T f_i = tau_i - c_i qdot_i, so its rate solves
  // (d_i + c_i) qdot_i = u_i - U_i^T v'_i and d_i + c_i replaces d_i in both places.
  const SymmetricMatrix3& da = articulatedInertia_[i + 1];
  // S = (1, 0, 0) picks the first column and the top-left entry.
  const Vector3 u{da.xx, da.xy, da.xz};
  const real c = jointDamping_[i];
  const real inverseD = 1 / (da.xx + c);
  jointForceDirection_[i] = u;
  inverseJointInertia_[i] = inverseD;
  // The first row of I^A - U U^T / (d + c) is U^T (1 - d / (d + c)) = U^T c / (d + c): zero
  // for an undamped joint, which transmits no moment about its own axis; a damped joint
  // passes that fraction of its stiffness on. Written this way the undamped row is exactly
  // zero, not a difference of equal numbers.
  SymmetricMatrix3 transmitted;
  transmitted.xx = u.x * c * inverseD;
  transmitted.xy = u.y * c * inverseD;
  transmitted.xz = u.z * c * inverseD;
  transmitted.yy = da.yy - u.y * u.y * inverseD;
  transmitted.yz = da.yz - u.y * u.z * inverseD;
  transmitted.zz = da.zz - u.z * u.z * inverseD;
  SymmetricMatrix3& parent = articulatedInertia_[parentSlot_[i]];
  parent = parent + translateInertiaBack(transmitted, shift_[i]);
}

inline void ArticulatedBody::passBias(std::size_t i) {
  // Table 7.1, second loop: u_i = tau_i - S_i^T p^A_i, and the parent receives
  // p^a_i = X_i^T (p^A_i + U_i u_i / (d_i + c_i)).
  const Vector3& pa = bias_[i + 1];
  const real ui = jointTorque_[i] - pa.x;
  jointBias_[i] = ui;
  const Vector3 passed = pa + jointForceDirection_[i] * (ui * inverseJointInertia_[i]);
  bias_[parentSlot_[i]] += translateForceBack(passed, shift_[i]);
}

void ArticulatedBody::computeArticulatedInertias() {
  startArticulatedInertias();
  // Leaves to root: reverse index order visits children before parents.
  for (std::size_t i = links_.size(); i-- > 0;) articulateLink(i);
  inertiasStale_ = false;
}

// --- solve and respond -----------------------------------------------------------------------

void ArticulatedBody::solve(std::span<const real> jointTorques,
                            std::span<const Vector3> externalWrenches, Output& out) {
  if (!jointTorques.empty() && jointTorques.size() != q_.size())
    throw InvalidArgument("ArticulatedBody.jointTorques",
                          sizeProblem(q_.size(), jointTorques.size()));
  if (!externalWrenches.empty() && externalWrenches.size() != origin_.size())
    throw InvalidArgument("ArticulatedBody.externalWrenches",
                          sizeProblem(origin_.size(), externalWrenches.size()));
  out.resize(linkCount());

  // p^A_i starts as -f_ext,i about the frame origin (Table 7.1 without the v x* I v term): the
  // wrench is given about the centre of mass, so its force adds the moment c x f.
  if (externalWrenches.empty()) {
    std::fill(bias_.begin(), bias_.end(), Vector3{});
  } else {
    for (std::size_t b = 0; b < bias_.size(); ++b)
      bias_[b] = -translateForceBack(externalWrenches[b], comOffset_[b]);
  }
  if (jointTorques.empty())
    std::fill(jointTorque_.begin(), jointTorque_.end(), real(0));
  else
    std::copy(jointTorques.begin(), jointTorques.end(), jointTorque_.begin());
  biasAndOutwardPasses(out);
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
  biasAndOutwardPasses(out);
}

void ArticulatedBody::biasAndOutwardPasses(Output& out) {
  // Leaves to root. The articulated inertias and the bias forces are both built from the
  // leaves, and link i's bias needs only its own U_i and d_i: when the configuration has
  // changed, one sweep does both, so the two dependency chains (each link waits for its
  // children) run side by side instead of one after the other.
  if (inertiasStale_) {
    startArticulatedInertias();
    for (std::size_t i = links_.size(); i-- > 0;) {
      articulateLink(i);
      passBias(i);
    }
    inertiasStale_ = false;
  } else {
    for (std::size_t i = links_.size(); i-- > 0;) passBias(i);
  }

  // The free-floating base: nothing acts on it from outside the tree, so 0 = D^A_0 v_0 + p^A_0
  // (Featherstone 2008, chapter 9, free-floating bases, with v for a). D^A_0 is symmetric
  // positive definite: the base's own inertia is, and every child adds a positive
  // semi-definite term.
  Vector3 v0{};
  if (!baseFixed_) v0 = articulatedInertia_[0].solve(-bias_[0]);
  originVelocity_[0] = v0;
  out.velocities[0] = v0;  // the base frame's origin is its centre of mass

  // Outward pass, root to leaves (Table 7.1, third loop): v'_i = X_i v_parent,
  // qdot_i = (u_i - U_i^T v'_i) / (d_i + c_i), v_i = v'_i + S_i qdot_i.
  for (std::size_t i = 0; i < links_.size(); ++i) {
    const std::size_t self = i + 1;
    Vector3 v = translateMotion(originVelocity_[parentSlot_[i]], shift_[i]);
    const real qdot = (jointBias_[i] - jointForceDirection_[i].dot(v)) * inverseJointInertia_[i];
    v.x += qdot;
    originVelocity_[self] = v;
    out.jointRates[i] = qdot;
    // The centre of mass moves with the body point there: v_O + omega x c.
    out.velocities[self] = translateMotion(v, comOffset_[self]);
  }
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
