#include <ThyrixLite/GUI.h>
#include <ThyrixLite/InvalidArgument.h>
#include <ThyrixLite/Simulator.h>
#include <ThyrixPro/ArticulatedAgentBase.h>
#include <Tools/Wide.h>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <string>
#include <type_traits>
#include <utility>

namespace thyrix {

// --- ArticulatedBasePart ---------------------------------------------------------------------

ArticulatedBasePart ArticulatedBasePart::circle(real radius, real mass, Vector2 position) {
  ArticulatedBasePart part;
  part.type = ShapeType::Circle;
  part.radius = radius;
  part.mass = mass;
  part.position = position;
  return part;
}

ArticulatedBasePart ArticulatedBasePart::capsule(real halfLength, real radius, real mass,
                                                 Vector2 position, real angle) {
  ArticulatedBasePart part;
  part.type = ShapeType::Capsule;
  part.radius = radius;
  part.halfLength = halfLength;
  part.mass = mass;
  part.position = position;
  part.angle = angle;
  return part;
}

void ArticulatedBasePart::validate(std::size_t index) const {
  const std::string where = " of base part " + std::to_string(index);
  auto positive = [&](real value, const char* field) {
    if (!(value > 0) || !std::isfinite(value))
      throw InvalidArgument(
          field, "must be positive and finite" + where + " (got " + std::to_string(value) + ")");
  };
  if (type != ShapeType::Circle && type != ShapeType::Capsule)
    throw InvalidArgument("ArticulatedBasePart.type", "must be Circle or Capsule" + where);
  positive(radius, "ArticulatedBasePart.radius");
  if (type == ShapeType::Capsule) positive(halfLength, "ArticulatedBasePart.halfLength");
  positive(mass, "ArticulatedBasePart.mass");
  requireFinite(position, "ArticulatedBasePart.position");
  requireFinite(angle, "ArticulatedBasePart.angle");
}

// --- construction ----------------------------------------------------------------------------

/// Everything computed from the description before any member is built, so that bad input
/// throws before the agent exists.
struct ArticulatedAgentBase::Layout {
  real mass = 0;
  real inertia = 0;
  Vector2 centre;  // the base's centre of mass in the description frame
  std::vector<ArticulatedLink> links;
  std::vector<real> radii;
  std::vector<real> angles;
};

ArticulatedAgentBase::Layout ArticulatedAgentBase::describe(
    const std::vector<ArticulatedBasePart>& baseParts, const std::vector<ArticulatedLimb>& limbs) {
  if (baseParts.empty())
    throw InvalidArgument("ArticulatedAgentBase.baseParts",
                          "must hold at least one circle or capsule");
  Layout layout;
  // The base is rigid: mass, centre of mass and inertia as for a ComposedPhysicalObject (the
  // parts' own inertias plus the parallel-axis terms).
  Vector2 weighted;
  for (std::size_t k = 0; k < baseParts.size(); ++k) {
    const ArticulatedBasePart& part = baseParts[k];
    part.validate(k);
    layout.mass += part.mass;
    weighted += part.position * part.mass;
  }
  layout.centre = weighted / layout.mass;
  for (const ArticulatedBasePart& part : baseParts) {
    const real own = part.type == ShapeType::Circle ? part.mass * part.radius * part.radius / 2
                                                    : CappedRectangle::momentOfInertia(
                                                          part.halfLength, part.radius, part.mass);
    layout.inertia += own + part.mass * (part.position - layout.centre).lengthSquared();
  }

  // The limbs' links, renumbered into one tree: limb after limb, so each limb's parents stay
  // earlier links and the tree has no loop. Root joints move from the attachment (description
  // frame) to the base frame, whose origin is the centre of mass.
  std::size_t total = 0;
  for (const ArticulatedLimb& limb : limbs) total += static_cast<std::size_t>(limb.linkCount());
  layout.links.reserve(total);
  layout.radii.reserve(total);
  layout.angles.reserve(total);
  for (const ArticulatedLimb& limb : limbs) {
    const int offset = static_cast<int>(layout.links.size());
    for (const ArticulatedLimb::Part& part : limb.parts()) {
      ArticulatedLink link = part.link;
      if (link.parent == ArticulatedLink::base) {
        link.jointPosition = limb.attachment() + link.jointPosition - layout.centre;
      } else {
        link.parent += offset;
      }
      link.validate(static_cast<int>(layout.links.size()));
      layout.links.push_back(link);
      layout.radii.push_back(part.radius);
      layout.angles.push_back(part.angle);
    }
  }
  return layout;
}

ArticulatedAgentBase::ArticulatedAgentBase(const std::vector<ArticulatedBasePart>& baseParts,
                                           const std::vector<ArticulatedLimb>& limbs)
    : ArticulatedAgentBase(baseParts, describe(baseParts, limbs)) {}

ArticulatedAgentBase::ArticulatedAgentBase(const std::vector<ArticulatedBasePart>& baseParts,
                                           Layout layout)
    : MultiBodyObject(layout.mass, layout.inertia),
      body_(layout.mass, layout.inertia, layout.links),
      velocities_(static_cast<int>(layout.links.size())),
      centreOffset_(layout.centre) {
  const std::size_t n = layout.links.size();
  jointTorques_.assign(n, 0);
  servoTargets_.assign(n, 0);
  servoGains_.assign(n, 0);
  servoTorques_.assign(n, 0);
  limitTorques_.assign(n, 0);
  linkWrenches_.assign(n + 1, Vector3{});
  bodyMasses_.reserve(n + 1);
  for (int b = base; b < static_cast<int>(n); ++b) bodyMasses_.push_back(body_.mass(b));
  linksWeighAlike_ = n > 0 && std::all_of(bodyMasses_.begin() + 1, bodyMasses_.end(),
                                          [&](real mass) { return mass == bodyMasses_[1]; });
  for (std::size_t i = 0; i < n; ++i)
    if (layout.links[i].hasLimits) limitedJoints_.push_back(static_cast<int>(i));

  // The shapes: each knows its body (ArticulatedComponent), and is attached without a fixed
  // pose (rigid = false): placeShapes() puts it where the kinematics say.
  baseParts_.reserve(baseParts.size());
  partPositions_.reserve(baseParts.size());
  partAngles_.reserve(baseParts.size());
  for (const ArticulatedBasePart& part : baseParts) {
    std::unique_ptr<Primitive> shape;
    if (part.type == ShapeType::Circle)
      shape = std::make_unique<ArticulatedComponent<Circle>>(base, part.radius, part.mass);
    else
      shape = std::make_unique<ArticulatedComponent<CappedRectangle>>(base, part.halfLength,
                                                                      part.radius, part.mass);
    const Vector2 local = part.position - centreOffset_;
    shape->attachTo(*this, local, part.angle, /*rigid=*/false);
    addPrimitive(*shape);
    partPositions_.push_back(local);
    partAngles_.push_back(part.angle);
    baseParts_.push_back(std::move(shape));
  }
  linkShapes_.reserve(n);
  linkHalfLengths_.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    auto shape = std::make_unique<ArticulatedComponent<CappedRectangle>>(
        static_cast<int>(i), layout.links[i].length / 2, layout.radii[i], layout.links[i].mass);
    shape->attachTo(*this, {}, 0, /*rigid=*/false);
    addPrimitive(*shape);
    linkHalfLengths_.push_back(shape->halfLength());
    linkShapes_.push_back(std::move(shape));
  }
  const auto bits = [](real value) {
    return std::bit_cast<std::conditional_t<sizeof(real) == 8, std::uint64_t, std::uint32_t>>(
        value);
  };
  capsulesCentredOnMass_ = true;
  for (std::size_t i = 0; i < n; ++i) {
    const Vector2 centre = layout.links[i].centerOfMass;
    capsulesCentredOnMass_ = capsulesCentredOnMass_ &&
                             bits(centre.x) == bits(linkHalfLengths_[i]) &&
                             bits(centre.y) == bits(real(0));
  }

  setSelfCollisionRules();

  // As for a ComposedPhysicalObject, the description frame starts at the world origin, so the
  // base's centre of mass is at centreOffset_ until the agent is moved.
  body_.setJointAngles(layout.angles);
  body_.setBasePose(centreOffset_, 0);
  placeShapes();
}

void ArticulatedAgentBase::onRegistered(Simulator& simulator) noexcept {
  simulator_ = &simulator;
  // validate() has checked r and alpha: the pose set before registration is taken here.
  body_.setBasePose(r, alpha);
  placeShapes();
}

real ArticulatedAgentBase::timestep() const {
  return simulator_ != nullptr ? simulator_->timestep() : real(0);
}

// --- state -----------------------------------------------------------------------------------

void ArticulatedAgentBase::placeShapes() {
  for (std::size_t i = 0; i < linkShapes_.size(); ++i) {
    const int link = static_cast<int>(i);
    placeLinkShape(i, body_.centerOfMass(link), body_.angle(link), body_.axis(link));
  }
  placeBase();
}

void ArticulatedAgentBase::placeBase() {
  const real baseAngle = body_.baseAngle();
  for (std::size_t k = 0; k < baseParts_.size(); ++k) {
    Primitive& part = *baseParts_[k];
    part.r = body_.toWorld(base, partPositions_[k]);
    part.alpha = baseAngle + partAngles_[k];
  }
  r = body_.basePosition();
  alpha = baseAngle;
}

void ArticulatedAgentBase::setPose(Vector2 position, real angle) {
  requireFinite(position, "ArticulatedAgentBase.position");
  requireFinite(angle, "ArticulatedAgentBase.angle");
  body_.setBasePose(position, angle);
  placeShapes();
}

void ArticulatedAgentBase::checkJoint(int i) const {
  if (i < 0 || i >= linkCount())
    throw InvalidArgument(
        "ArticulatedAgentBase.joint",
        "must be in [0, " + std::to_string(linkCount()) + ") (got " + std::to_string(i) + ")");
}

void ArticulatedAgentBase::setJointAngle(int i, real q) {
  checkJoint(i);
  requireFinite(q, "ArticulatedAgentBase.q");
  body_.setJointAngle(i, q);
  placeShapes();
}

// --- effectors -------------------------------------------------------------------------------

void ArticulatedAgentBase::setJointTorque(int i, real torque) {
  checkJoint(i);
  requireFinite(torque, "ArticulatedAgentBase.jointTorque");
  jointTorques_[index(i)] = torque;
}

void ArticulatedAgentBase::clearJointTorques() {
  std::fill(jointTorques_.begin(), jointTorques_.end(), real(0));
}

void ArticulatedAgentBase::setServoTarget(int i, real target, real gain) {
  checkJoint(i);
  requireFinite(target, "ArticulatedAgentBase.servoTarget");
  requirePositive(gain, "ArticulatedAgentBase.servoGain");
  servoTargets_[index(i)] = target;
  if (servoGains_[index(i)] == 0) ++servoCount_;
  servoGains_[index(i)] = gain;
  servosChanged_ = true;
}

void ArticulatedAgentBase::clearServo(int i) {
  checkJoint(i);
  if (servoGains_[index(i)] > 0) --servoCount_;
  servoGains_[index(i)] = 0;
  servosChanged_ = true;
}

namespace {

/// Adds (@p torque, @p forceOf(k)) to the wrench k of the @p count wrenches from @p wrenches
/// on, each wrench's force as one pair: the same additions. (GCC vectorizes the plain loop
/// across neighbouring wrenches, 24 bytes each, whose 16-byte loads then straddle the last
/// stores: a store-forwarding stall per link, slower than a call per link.)
template <class ForceOf>
void addToEachWrench(Vector3* wrenches, std::size_t count, real torque, ForceOf forceOf) {
  using Pair = simd::Wide<real, 2>;
  static_assert(std::is_standard_layout_v<Vector3> && sizeof(Vector3) == 3 * sizeof(real),
                "a wrench is read as its three coordinates");
  for (std::size_t k = 0; k < count; ++k) {
    auto* const w = reinterpret_cast<real*>(&wrenches[k]);
    w[0] += torque;
    const Vector2 force = forceOf(k);
    (Pair::load(w + 1) + simd::pair(force.x, force.y)).store(w + 1);
  }
}

}  // namespace

void ArticulatedAgentBase::applyForceAtEveryLinkCenterOfMass(Vector2 force) {
  if (!std::isfinite(force.x) || !std::isfinite(force.y)) [[unlikely]]
    refuseLinkForce(base, force, Vector2{});
  touchLinkWrenches();
  // The torque, the same for every link, as applyLinkForceAtCenterOfMass() computes it.
  addToEachWrench(linkWrenches_.data() + 1, linkWrenches_.size() - 1, cross(Vector2{}, force),
                  [force](std::size_t) { return force; });
}

void ArticulatedAgentBase::applyWeight(Vector2 gravity) {
  // applyLinkForceAtCenterOfMass(b, m_b g)'s operations. Its torque cross((0, 0), m_b g) is a
  // zero whose sign follows the signs of m_b g's coordinates, which are g's (m_b > 0): the
  // same bits for every body, cross((0, 0), g), computed once.
  const real torque = cross(Vector2{}, gravity);
  // The weights of the bodies from @p masses on: body k's m_k g.
  const auto weightsOf = [gravity](const real* masses) {
    return [masses, gravity](std::size_t k) { return masses[k] * gravity; };
  };
  if (!fixed)  // a fixed base weighs nothing
    addToEachWrench(linkWrenches_.data(), 1, torque, weightsOf(bodyMasses_.data()));
  const std::size_t links = linkWrenches_.size() - 1;
  if (linksWeighAlike_) {  // one weight for all (a uniform chain), without a multiplication each
    const Vector2 weight = bodyMasses_[1] * gravity;
    const auto theWeight = [weight](std::size_t) { return weight; };
    if (linkWrenchesClear_ && !linkWeightKept_) {
      // Every link's wrench is zero: keep the one they would all become.
      Vector3 wrench{};
      addToEachWrench(&wrench, 1, torque, theWeight);
      linkWeight_ = wrench;
      linkWeightKept_ = true;
      return;
    }
    touchLinkWrenches();
    addToEachWrench(linkWrenches_.data() + 1, links, torque, theWeight);
  } else {
    touchLinkWrenches();
    addToEachWrench(linkWrenches_.data() + 1, links, torque, weightsOf(bodyMasses_.data() + 1));
  }
}

void ArticulatedAgentBase::addKeptLinkWeight() {
  // Each link's wrench is zero: it becomes the kept one, as applyWeight()'s additions made it.
  std::fill(linkWrenches_.begin() + 1, linkWrenches_.end(), linkWeight_);
  linkWeightKept_ = false;
}

void ArticulatedAgentBase::refuseLinkForce(int b, Vector2 force, Vector2 worldPoint) const {
  checkBody(b);
  requireFinite(force, "ArticulatedAgentBase.force");
  requireFinite(worldPoint, "ArticulatedAgentBase.worldPoint");
}

// --- proprioception --------------------------------------------------------------------------

void ArticulatedAgentBase::checkBody(int b) const {
  if (b < base || b >= linkCount())
    throw InvalidArgument(
        "ArticulatedAgentBase.body",
        "must be in [-1, " + std::to_string(linkCount()) + ") (got " + std::to_string(b) + ")");
}

LinkContactInfo ArticulatedAgentBase::linkContact(std::size_t k) const {
  const std::span<const ContactInfo> list = contacts();
  if (k >= list.size())
    throw InvalidArgument("ArticulatedAgentBase.linkContact.k",
                          "must be below the " + std::to_string(list.size()) +
                              " contacts of this step (got " + std::to_string(k) + ")");
  LinkContactInfo info;
  static_cast<ContactInfo&>(info) = list[k];
  info.body = bodyOf(*info.primitive);
  info.p = info.point - centerOfMass(info.body);
  return info;
}

std::span<const LinkContactInfo> ArticulatedAgentBase::linkContacts(int b) {
  if (b < base || b >= linkCount())
    throw InvalidArgument(
        "ArticulatedAgentBase.body",
        "must be in [-1, " + std::to_string(linkCount()) + ") (got " + std::to_string(b) + ")");
  linkContactList_.clear();
  const std::span<const ContactInfo> list = contacts();
  for (std::size_t k = 0; k < list.size(); ++k)
    if (bodyOf(*list[k].primitive) == b) linkContactList_.push_back(linkContact(k));
  // A limit's torque acts on its joint's link and, reversed, on the link's parent.
  const auto primitiveOf = [this](int body) -> Primitive* {
    return body == base ? baseParts_.front().get() : linkShapes_[index(body)].get();
  };
  for (const int joint : limitedJoints_) {
    const real torque = limitTorques_[index(joint)];
    const int parentBody = parent(joint);
    if (torque == 0 || (b != joint && b != parentBody)) continue;
    const ArticulatedLink& link = body_.links()[index(joint)];
    const real q = jointAngle(joint);
    LinkContactInfo info;
    info.index = ContactInfo::noIndex;
    info.other = this;
    info.primitive = primitiveOf(b);
    info.otherPrimitive = primitiveOf(b == joint ? parentBody : joint);
    info.point = jointPosition(joint);
    info.p = info.point - centerOfMass(b);
    info.n = {0, 0};
    info.normal = {0, 0};
    // Positive torque: the lower limit holds the link; the parent feels the opposite.
    info.sigma = (torque > 0) == (b == joint) ? real(1) : real(-1);
    info.depth = torque > 0 ? link.qMin - q : q - link.qMax;
    info.force = std::abs(torque);
    info.type = ContactType::Torque;
    info.body = b;
    linkContactList_.push_back(info);
  }
  return linkContactList_;
}

real ArticulatedAgentBase::contactForceOn(int b) const {
  checkBody(b);
  real sum = 0;
  for (const ContactInfo& c : contacts())
    if (bodyOf(*c.primitive) == b) sum += c.force;
  return sum;
}

// --- collisions, validation, drawing ---------------------------------------------------------

void ArticulatedAgentBase::setSelfCollisionRules() {
  // Part 0 is the base (all its primitives: one rigid body), part i + 1 link i; the primitives
  // are the base's parts, then the links, in that order (the constructor added them so).
  const auto partOf = [](int b) { return static_cast<std::uint32_t>(b + 1); };
  const int n = linkCount();
  std::vector<std::uint32_t> parts(baseParts_.size(), partOf(base));
  for (int i = 0; i < n; ++i) parts.push_back(partOf(i));
  std::vector<std::pair<std::uint32_t, std::uint32_t>> apart;
  // A joint's two bodies overlap around it by construction (a capsule's cap covers its joint).
  for (int i = 0; i < n; ++i) apart.emplace_back(partOf(i), partOf(parent(i)));
  // Siblings on one joint point (a fork at a parent's tip, or links on the base at one point)
  // overlap there at every angle. The links grouped by parent (counting sort), then each
  // group's pairs: a fork has a few children.
  std::vector<int> childStart(index(n) + 2, 0);
  for (int i = 0; i < n; ++i) ++childStart[index(parent(i) + 2)];
  for (std::size_t p = 1; p < childStart.size(); ++p) childStart[p] += childStart[p - 1];
  std::vector<int> children(index(n));
  std::vector<int> fill(childStart.begin(), childStart.end() - 1);
  for (int i = 0; i < n; ++i) children[index(fill[index(parent(i) + 1)]++)] = i;
  for (std::size_t p = 0; p + 1 < childStart.size(); ++p) {
    for (int x = childStart[p]; x < childStart[p + 1]; ++x) {
      for (int y = x + 1; y < childStart[p + 1]; ++y) {
        const int a = children[index(x)];
        const int b = children[index(y)];
        const Vector2 gap = body_.link(a).jointPosition - body_.link(b).jointPosition;
        const real reach = linkShapes_[index(a)]->radius() + linkShapes_[index(b)]->radius();
        if (gap.lengthSquared() < reach * reach) apart.emplace_back(partOf(a), partOf(b));
      }
    }
  }
  selfCollision_.assign(parts, apart);
}

bool ArticulatedAgentBase::selfCollides(const Primitive& a, const Primitive& b) const {
  return selfCollision_.partsMayTouch(static_cast<std::uint32_t>(bodyOf(a) + 1),
                                      static_cast<std::uint32_t>(bodyOf(b) + 1));
}

void ArticulatedAgentBase::validate() const {
  MultiBodyObject::validate();
  if (!(limitMargin >= 0) || !std::isfinite(limitMargin))
    throw InvalidArgument(typeName() + ".limitMargin", "must be finite and non-negative (got " +
                                                           std::to_string(limitMargin) + ")");
  // articulatedBodyOf() relies on every primitive being one of the agent's own components.
  for (const Primitive* primitive : primitives()) {
    const bool own =
        dynamic_cast<const ArticulatedComponent<Circle>*>(primitive) != nullptr ||
        dynamic_cast<const ArticulatedComponent<CappedRectangle>*>(primitive) != nullptr;
    if (!own)
      throw InvalidArgument(typeName() + ".primitives",
                            "must all be the agent's own shapes (ArticulatedComponent); "
                            "subclasses must not add primitives");
  }
}

void ArticulatedAgentBase::draw(GUI& gui) const {
  for (const auto& part : baseParts_) part->draw(gui);
  for (const auto& shape : linkShapes_) shape->draw(gui);
  // Joints on top, half a link wide, so the tree's structure reads at a glance.
  for (int i = 0; i < linkCount(); ++i)
    gui.drawCircle(body_.origin(i), linkShapes_[index(i)]->radius() / 2, body_.angle(i), jointColor,
                   outlineColor);
}

namespace {

void addOutput(StateRecord& record, const ArticulatedBody::Output& output) {
  for (const Vector3& velocity : output.velocities) {
    record.add(velocity.x);
    record.add(velocity.y);
    record.add(velocity.z);
  }
  record.add(std::span<const real>(output.jointRates));
}

void readOutput(StateRecord::Reader& reader, ArticulatedBody::Output& output) {
  for (Vector3& velocity : output.velocities) {
    velocity.x = reader.value();
    velocity.y = reader.value();
    velocity.z = reader.value();
  }
  reader.reals(output.jointRates);
}

}  // namespace

void ArticulatedAgentBase::saveState(StateRecord& record) const {
  PhysicalObject::saveState(record);
  record.add(body_.basePosition());
  record.add(body_.baseAngle());
  record.add(body_.jointAngles());
  addOutput(record, velocities_);
  for (const auto* values :
       {&jointTorques_, &servoTargets_, &servoGains_, &servoTorques_, &limitTorques_})
    record.add(std::span<const real>(*values));
  record.addInteger(servoCount_);
  for (const Vector3& wrench : linkWrenches_) {
    record.add(wrench.x);
    record.add(wrench.y);
    record.add(wrench.z);
  }
  record.add(linkWrenchesClear_);
  record.add(linkWeightKept_);
  record.add(linkWeight_.x);
  record.add(linkWeight_.y);
  record.add(linkWeight_.z);
}

void ArticulatedAgentBase::restoreState(StateRecord::Reader& reader) {
  PhysicalObject::restoreState(reader);
  const Vector2 basePosition = reader.vector();
  const real baseAngle = reader.value();
  std::vector<real> q(body_.jointAngles().size());
  reader.reals(q);
  body_.setBasePose(basePosition, baseAngle);
  body_.setJointAngles(q);
  readOutput(reader, velocities_);
  for (auto* values :
       {&jointTorques_, &servoTargets_, &servoGains_, &servoTorques_, &limitTorques_})
    reader.reals(*values);
  servoCount_ = static_cast<int>(reader.integer());
  for (Vector3& wrench : linkWrenches_) {
    wrench.x = reader.value();
    wrench.y = reader.value();
    wrench.z = reader.value();
  }
  linkWrenchesClear_ = reader.flag();
  linkWeightKept_ = reader.flag();
  linkWeight_.x = reader.value();
  linkWeight_.y = reader.value();
  linkWeight_.z = reader.value();
  servosChanged_ = true;  // the dampings follow the restored gains
}

}  // namespace thyrix
