#pragma once
/// @file ArticulatedAgentBase.h
/// @brief An articulated agent as a simulated object: a base of circles and capsules with limbs
/// of capsule links, its effectors (joint torques, servos, forces on links), proprioception,
/// joint limits, self-collision rules and drawing; the dynamics are in a subclass.

#include <ThyrixLite/CappedRectangle.h>
#include <ThyrixLite/Circle.h>
#include <ThyrixLite/Color.h>
#include <ThyrixLite/ColorDefinitions.h>
#include <ThyrixLite/MultiBodyObject.h>
#include <ThyrixLite/Primitive.h>
#include <ThyrixLite/ThyrixParameters.h>
#include <ThyrixLite/Vector2.h>
#include <ThyrixLite/Vector3.h>
#include <ThyrixPro/ArticulatedBody.h>
#include <ThyrixPro/ArticulatedComponent.h>
#include <ThyrixPro/ArticulatedLimb.h>
#include <ThyrixPro/LinkContactInfo.h>

#include <cmath>
#include <cstddef>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace thyrix {

/// One collision shape of an articulated agent's base, a circle or a capsule, placed in the
/// frame the base is described in (like ComposedPhysicalObject's parts). The base is rigid: its
/// parts never move relative to each other.
struct ArticulatedBasePart {
  ShapeType type = ShapeType::Circle;  ///< Circle or Capsule
  real radius = 1;                     ///< circle radius, or capsule half width R (m)
  real halfLength = 0;                 ///< capsule half length l (m); unused for a circle
  real mass = 1;                       ///< quasistatic mass (N s/m)
  Vector2 position;                    ///< centre, in the base's description frame (m)
  real angle = 0;                      ///< capsule axis angle in that frame (rad)

  /// A circle of @p radius and @p mass centred at @p position.
  static ArticulatedBasePart circle(real radius, real mass, Vector2 position = {});
  /// A capsule of half length @p halfLength, radius @p radius and @p mass centred at
  /// @p position, its axis turned by @p angle.
  static ArticulatedBasePart capsule(real halfLength, real radius, real mass, Vector2 position = {},
                                     real angle = 0);

  /// Checks the fields of part @p index.
  /// @throws InvalidArgument naming "ArticulatedBasePart.type" unless Circle or Capsule,
  /// ".radius", ".mass" (and ".halfLength" for a capsule) unless positive and finite,
  /// ".position" or ".angle" unless finite
  void validate(std::size_t index) const;
};

/// The part of an articulated agent that does not depend on the law of motion: its bodies and
/// shapes, its effectors and sensors, its joint limits and which of its shapes may collide.
/// ArticulatedAgentQuasistatic adds the dynamics (the quasistatic articulated-body algorithm);
/// it is the only one in ThyrixPro, which has no classical (inertial) variant.
///
/// **Bodies.** Body -1 (ArticulatedBody::base) is the base, a rigid set of circles and capsules
/// (ArticulatedBasePart); bodies 0 .. linkCount() - 1 are the links, limb after limb in the
/// order the limbs are given, each limb's links in its own order (ArticulatedLimb). Each link
/// is one capsule from its joint to its tip.
///
/// **Frames.** The base's parts and the limbs' attachments are described in one frame, as for
/// a ComposedPhysicalObject; the base's centre of mass sits at centreOfMassOffset() in it. The
/// agent's `r` is the base's centre of mass (world, m) and `alpha` the base's angle: set them
/// before registering, or call setPose() at any time. Joint angles are relative to the parent's
/// axis (ArticulatedLimb), counter-clockwise, in radians, and are not wrapped.
///
/// **Effectors**, applied in every step until changed: joint torques (setJointTorque()), and
/// joint angle servos (setServoTarget()), solved implicitly so that any gain is stable at the
/// simulator's time step. **Accumulators**, used by the next step and then reset, like a
/// PhysicalObject's: `externalForce` and `externalTorque` (on the base, at its centre of mass;
/// applyForce() works as for any body) and applyLinkForce().
///
/// **Proprioception:** jointAngle(), jointRate(), the poses and velocities of every body, the
/// last limit torques, and each body's contact list, joint limits included (linkContacts()).
/// Like the setters, every accessor checks its index: InvalidArgument naming
/// "ArticulatedAgentBase.joint", ".body" or ".linkContact.k".
///
/// **Contacts.** Every shape collides with other objects. Two of the agent's own bodies collide
/// unless they are neighbours (selfCollides()). The base's parts never collide with each other.
///
/// The agent owns its shapes (ArticulatedComponent) and places them itself from the forward
/// kinematics; subclasses must not add primitives of their own (validate() refuses them).
class ArticulatedAgentBase : public MultiBodyObject {
 public:
  /// The body index of the base.
  static constexpr int base = ArticulatedBody::base;

  // --- description ---------------------------------------------------------------------------

  /// The number of links (joints).
  [[nodiscard]] int linkCount() const { return body_.linkCount(); }
  /// The parent body of body @p b: -1 (the base) for a link on the base; -2 for the base.
  [[nodiscard]] int parent(int b) const { return body_.parent(b); }
  /// The articulated body: the tree, its state and the algorithm (read-only).
  [[nodiscard]] const ArticulatedBody& articulatedBody() const { return body_; }
  /// The capsule of link @p i: set its colours or tactile sensors here.
  [[nodiscard]] CappedRectangle& linkShape(int i) const { return *linkShapes_[joint(i)]; }
  /// The number of the base's parts.
  [[nodiscard]] std::size_t basePartCount() const { return baseParts_.size(); }
  /// Part @p k of the base, in the order given: a Circle or a CappedRectangle.
  [[nodiscard]] Primitive& basePart(std::size_t k) const { return *baseParts_[k]; }
  /// The base's centre of mass in the frame its parts were described in (m).
  [[nodiscard]] Vector2 centreOfMassOffset() const { return centreOffset_; }
  /// The agent's body that @p primitive (one of this agent's primitives) belongs to: -1 the
  /// base, else a link index. O(1).
  [[nodiscard]] static int bodyOf(const Primitive& primitive) {
    return articulatedBodyOf(primitive);
  }

  // --- state ---------------------------------------------------------------------------------

  /// Places the base's centre of mass at @p position with angle @p angle (also `r` and
  /// `alpha`) and every shape with it; the joint angles are kept.
  /// @throws InvalidArgument naming "ArticulatedAgentBase.position" or ".angle" unless finite
  void setPose(Vector2 position, real angle);
  /// Sets the angle of joint @p i (rad) and places the shapes (a kinematic jump, for set-up).
  /// @throws InvalidArgument naming "ArticulatedAgentBase.joint" unless @p i is a joint, or
  /// "ArticulatedAgentBase.q" unless @p q is finite
  void setJointAngle(int i, real q);

  // --- effectors -----------------------------------------------------------------------------

  /// Sets the torque of joint @p i (N m), held in every step until changed; positive turns
  /// link i counter-clockwise relative to its parent (and the parent the other way).
  /// @throws InvalidArgument naming "ArticulatedAgentBase.joint" or ".jointTorque" (not finite)
  void setJointTorque(int i, real torque);
  /// The torque set on joint @p i (N m), without the servo's.
  [[nodiscard]] real jointTorque(int i) const { return jointTorques_[joint(i)]; }
  /// Sets every joint torque to zero.
  void clearJointTorques();

  /// Drives joint @p i toward the angle @p target (rad) with the stiffness @p gain (N m/rad):
  /// the servo adds the torque `gain (target - q - dt qdot)` with `qdot` this step's final rate,
  /// solved implicitly (a joint damping `gain dt` in the articulated-body algorithm), so it is
  /// stable and does not overshoot for any gain. Held until clearServo().
  /// @throws InvalidArgument naming "ArticulatedAgentBase.joint", ".servoTarget" (not finite)
  /// or ".servoGain" (not positive and finite)
  void setServoTarget(int i, real target, real gain);
  /// Switches off the servo of joint @p i. @throws InvalidArgument naming
  /// "ArticulatedAgentBase.joint"
  void clearServo(int i);
  /// Whether joint @p i has a servo.
  [[nodiscard]] bool hasServo(int i) const { return servoGains_[joint(i)] > 0; }
  /// The servo target of joint @p i (rad); meaningful when hasServo().
  [[nodiscard]] real servoTarget(int i) const { return servoTargets_[joint(i)]; }
  /// The servo gain of joint @p i (N m/rad), 0 without a servo.
  [[nodiscard]] real servoGain(int i) const { return servoGains_[joint(i)]; }
  /// The torque the servo of joint @p i applied in the last step (N m), with the final rate:
  /// `gain (target - q - dt qdot)`, q the angle at the start of the step; 0 without a servo.
  [[nodiscard]] real servoTorque(int i) const { return servoTorques_[joint(i)]; }

  /// Adds the world force @p force (N) applied at the world point @p worldPoint on body @p b
  /// (-1 the base, else a link) for the next step; reset after it, like `externalForce`.
  /// @throws InvalidArgument naming "ArticulatedAgentBase.body" unless a body of this agent,
  /// or ".force" / ".worldPoint" unless finite
  void applyLinkForce(int b, Vector2 force, Vector2 worldPoint) {
    // Inline: a program applying weights calls it for every link in every step. The messages
    // are built out of line, only when a check fails.
    if (b < base || b >= linkCount() || !std::isfinite(force.x) || !std::isfinite(force.y) ||
        !std::isfinite(worldPoint.x) || !std::isfinite(worldPoint.y)) [[unlikely]]
      refuseLinkForce(b, force, worldPoint);
    if (b != base) touchLinkWrenches();
    // A wrench about the body's centre of mass, as ArticulatedBody::solve() takes it.
    Vector3& wrench = linkWrenches_[index(b + 1)];
    wrench.x += cross(worldPoint - body_.centerOfMass(b), force);
    wrench.y += force.x;
    wrench.z += force.y;
  }
  /// Adds the world force @p force (N) applied at the centre of mass of body @p b (-1 the base,
  /// else a link) for the next step; reset after it, like `externalForce`. A weight, say: no
  /// moment, and the pose is not read, so it is cheaper than
  /// `applyLinkForce(b, force, centerOfMass(b))`, which gives the same bits while the pose is
  /// finite (its lever arm is then (+0, +0); with a non-finite pose that call throws for
  /// ".worldPoint", this one does not look).
  /// @throws InvalidArgument naming "ArticulatedAgentBase.body" unless a body of this agent,
  /// or ".force" unless finite
  void applyLinkForceAtCenterOfMass(int b, Vector2 force) {
    if (b < base || b >= linkCount() || !std::isfinite(force.x) || !std::isfinite(force.y))
        [[unlikely]]
      refuseLinkForce(b, force, Vector2{});
    if (b != base) touchLinkWrenches();
    Vector3& wrench = linkWrenches_[index(b + 1)];
    wrench.x += cross(Vector2{}, force);
    wrench.y += force.x;
    wrench.z += force.y;
  }
  /// Adds the world force @p force (N) at the centre of mass of every link (the base excepted)
  /// for the next step, as applyLinkForceAtCenterOfMass(i, force) for each link i would (the
  /// same bits): the weight of links of equal mass, say. The base's own weight goes to
  /// `externalForce` or applyLinkForceAtCenterOfMass(base, ...).
  /// @throws InvalidArgument naming "ArticulatedAgentBase.force" unless finite (nothing added)
  void applyForceAtEveryLinkCenterOfMass(Vector2 force);

  // --- proprioception and poses --------------------------------------------------------------

  /// The angle of joint @p i (rad), not wrapped.
  [[nodiscard]] real jointAngle(int i) const { return body_.jointAngles()[joint(i)]; }
  /// All joint angles (rad).
  [[nodiscard]] std::span<const real> jointAngles() const { return body_.jointAngles(); }
  /// The rate of joint @p i in the last step (rad/s), contact forces and limits included.
  [[nodiscard]] real jointRate(int i) const { return velocities_.jointRates[joint(i)]; }
  /// The world position of the joint of link @p i (m).
  [[nodiscard]] Vector2 jointPosition(int i) const {
    checkJoint(i);
    return body_.origin(i);
  }
  /// The world position of the tip of link @p i (m).
  [[nodiscard]] Vector2 linkTip(int i) const {
    checkJoint(i);
    return body_.tip(i);
  }
  /// The world position of body @p b's centre of mass (m).
  [[nodiscard]] Vector2 centerOfMass(int b) const {
    checkBody(b);
    return body_.centerOfMass(b);
  }
  /// The world angle of body @p b's axis (rad): the base's angle, or a link's direction.
  [[nodiscard]] real bodyAngle(int b) const {
    checkBody(b);
    return body_.angle(b);
  }
  /// The velocity of body @p b's centre of mass in the last step (m/s).
  [[nodiscard]] Vector2 bodyVelocity(int b) const {
    checkBody(b);
    return velocities_.linearVelocity(b);
  }
  /// The angular velocity of body @p b in the last step (rad/s).
  [[nodiscard]] real bodyAngularVelocity(int b) const {
    checkBody(b);
    return velocities_.angularVelocity(b);
  }
  /// The velocity of the material point of body @p b at the world point @p point in the last
  /// step (m/s).
  [[nodiscard]] Vector2 pointVelocity(int b, Vector2 point) const {
    checkBody(b);
    return body_.pointVelocity(velocities_, b, point);
  }
  /// The torque the limits of joint @p i applied in the last step (N m): positive at the lower
  /// limit, negative at the upper, zero when neither acted. Its magnitude is the limit's LCP
  /// multiplier, never negative.
  [[nodiscard]] real limitTorque(int i) const { return limitTorques_[joint(i)]; }

  /// Contact @p k of this step's `contacts`, with the body it touches, its `p` relative to that
  /// body's centre of mass.
  [[nodiscard]] LinkContactInfo linkContact(std::size_t k) const;
  /// Body @p b's contact list of this step (-1 the base, else a link), as the original users'
  /// guide describes it (docs/PortingFromThyrix.md): its force contacts (linkContact(), in the
  /// order of `contacts`), then a torque contact for each joint at its limit between @p b and its
  /// parent or a child (limitTorque() not zero; LinkContactInfo). The view is valid until the next
  /// call of linkContacts() or the next step; a list no longer than any before it allocates
  /// nothing.
  /// @throws InvalidArgument naming "ArticulatedAgentBase.body" unless a body of this agent
  [[nodiscard]] std::span<const LinkContactInfo> linkContacts(int b);
  /// The sum of the magnitudes of this step's contact forces on body @p b (N).
  [[nodiscard]] real contactForceOn(int b) const;

  // --- joint limits --------------------------------------------------------------------------

  /// A joint gets its limit's constraint (a row of the contact LCP) when it could reach the
  /// limit this step, turning at its free rate or at its last step's rate, plus this margin
  /// (rad): a speculative limit, like a speculative contact, so that contact forces acting in
  /// the same step cannot push it across. 0.05 rad by default.
  real limitMargin = real(0.05);

  // --- MultiBodyObject and PhysicalObject ----------------------------------------------------

  /// False for two shapes of the same body, for a link and its parent (the base included), and
  /// for two links on the same parent whose joints are closer than the sum of their radii (they
  /// overlap around the shared joint whatever their angles); true otherwise, e.g. for a
  /// folded chain touching itself or a leg touching the base it is not attached to. The rules
  /// are set once, when the agent is built, as its selfCollision() table, which the simulator
  /// reads; this answers from it for two of the agent's primitives.
  [[nodiscard]] bool selfCollides(const Primitive& a, const Primitive& b) const;
  /// The weight in the gravity field @p gravity (Simulator::setGravity()): each link, and the
  /// base unless the agent is `fixed`, gets `mass(b) * gravity` at its own centre of mass, the
  /// same bits as applyLinkForceAtCenterOfMass(b, mass(b) * gravity) for each body b (base
  /// first), without its checks (the simulator checked the field). One call per step. Links
  /// that weigh alike, with no force given to a link yet, keep their weight as one wrench
  /// (linkWeightKept_) that the solve takes for every link: no pass over the links.
  void applyWeight(Vector2 gravity) override;
  /// Also checks limitMargin (finite, non-negative) and that every primitive is the agent's own
  /// (an ArticulatedComponent).
  void validate() const override;
  /// PhysicalObject::saveState() (the base and the links' shapes), then the joint angles, the
  /// servos, the effector and last step's torques and rates, and the pending link wrenches.
  void saveState(StateRecord& record) const override;
  /// Reads back what saveState() appended; the servos' dampings are set again at the next step.
  void restoreState(StateRecord::Reader& reader) override;
  /// Draws the base's parts and the links' capsules, then each joint as a small circle.
  void draw(GUI& gui) const override;
  [[nodiscard]] std::string typeName() const override { return "ArticulatedAgentBase"; }

  /// Fill colour of the joints' circles.
  Color jointColor = colors::yellow;

 protected:
  /// An agent whose base is made of @p baseParts (at least one) and which carries @p limbs.
  /// @throws InvalidArgument naming "ArticulatedAgentBase.baseParts" when empty, the first bad
  /// field of a part (ArticulatedBasePart::validate()), or of a link (ArticulatedLink)
  ArticulatedAgentBase(const std::vector<ArticulatedBasePart>& baseParts,
                       const std::vector<ArticulatedLimb>& limbs);

  /// Keeps the simulator (for its time step) and places the shapes at `r`, `alpha`.
  void onRegistered(Simulator& simulator) noexcept override;

  /// The time step of the simulator the agent is registered with (s), 0 before registration.
  [[nodiscard]] real timestep() const;
  /// Places every shape from the articulated body's forward kinematics and copies the base's
  /// pose to `r` and `alpha`: placeLinkShape() of every link, then placeBase().
  void placeShapes();
  /// Places the base's shapes and copies the base's pose to `r` and `alpha`.
  void placeBase();
  /// Places link @p i's capsule, whose centre of mass the kinematics put at @p centerOfMass,
  /// its frame turned by @p angle with the axis @p axis (`(cos, sin)` of the angle): the
  /// capsule runs from the joint to the tip, its centre half way along the axis. Inline:
  /// ArticulatedBody::integrate() calls it for every link from within its kinematics' loop.
  void placeLinkShape(std::size_t i, Vector2 centerOfMass, real angle, Vector2 axis) {
    // The kinematics' (cos, sin) goes with the capsule, so the simulator does not compute them
    // again for its end points (Primitive::direction()). toWorld(link, (half length, 0)) is
    // origin + rotate(axis, (half length, 0)), and the kinematics computed the centre of mass as
    // origin + rotate(axis, centre of mass): the same bits when the two points are, without the
    // rotation again.
    const Vector2 centre = capsulesCentredOnMass_
                               ? centerOfMass
                               : body_.toWorld(static_cast<int>(i), {linkHalfLengths_[i], 0});
    linkShapes_[i]->place(centre, angle, axis);
  }
  /// `i` as an index, for the per-joint arrays.
  [[nodiscard]] static std::size_t index(int i) { return static_cast<std::size_t>(i); }
  /// Throws InvalidArgument naming "ArticulatedAgentBase.joint" unless @p i is a joint.
  void checkJoint(int i) const;
  /// `i` as an index, once checkJoint() has accepted it (the getters' check).
  [[nodiscard]] std::size_t joint(int i) const {
    checkJoint(i);
    return index(i);
  }
  /// Throws InvalidArgument naming "ArticulatedAgentBase.body" unless @p b is -1 (the base) or
  /// a link.
  void checkBody(int b) const;

  ArticulatedBody body_;  ///< the tree, its state and the algorithm
  /// The velocities of the last step (those without contacts until the contacts are solved).
  ArticulatedBody::Output velocities_;
  std::vector<real> jointTorques_;  ///< the effector torques, per joint (N m)
  std::vector<real> servoTargets_;  ///< per joint (rad)
  std::vector<real> servoGains_;    ///< per joint (N m/rad), 0: no servo
  int servoCount_ = 0;              ///< how many joints have a servo
  bool servosChanged_ = false;      ///< a servo was set or cleared since the last step
  std::vector<real> servoTorques_;  ///< the servo torques of the last step (N m)
  std::vector<real> limitTorques_;  ///< the limit torques of the last step (N m)
  std::vector<LinkContactInfo> linkContactList_;  ///< linkContacts()' list, reused
  /// The wrenches of applyLinkForce() per body, base first (body b at b + 1), about each centre
  /// of mass: `(torque, fx, fy)`. The links' lack the weight while applyWeight() keeps it
  /// (linkWeightKept_): code that reads or writes a link's wrench here other than through
  /// applyLinkForce() and its kin calls touchLinkWrenches() first.
  std::vector<Vector3> linkWrenches_;
  /// The joints that have limits, in index order.
  std::vector<int> limitedJoints_;
  /// Each body's quasistatic mass, base first (body b at b + 1), side by side for applyWeight().
  std::vector<real> bodyMasses_;
  /// Every link has the same mass (and there is one): applyWeight() computes one weight.
  bool linksWeighAlike_ = false;
  /// No link's wrench in linkWrenches_ has been given anything since the last solve (they are
  /// zero; the base's may not be).
  bool linkWrenchesClear_ = true;
  /// applyWeight() found the links' wrenches clear and their weights equal: it kept the wrench
  /// each would have, `(0, 0, 0)` plus the weight, in linkWeight_ rather than adding it to
  /// every one (a pass over the links), and the solve takes it as every link's wrench
  /// (ArticulatedBody::solve() with a link wrench), the same bits.
  bool linkWeightKept_ = false;
  Vector3 linkWeight_;  ///< see linkWeightKept_
  /// Before a link's wrench in linkWrenches_ is given a force or read (other than by the solve
  /// that takes the kept weight): adds the weight applyWeight() kept, if it did, to every
  /// link's (the additions in the order applyWeight() would have made them), and notes that
  /// the links' wrenches are no longer clear.
  void touchLinkWrenches() {
    if (linkWeightKept_) [[unlikely]]
      addKeptLinkWeight();
    linkWrenchesClear_ = false;
  }
  /// touchLinkWrenches()'s addition of the kept weight.
  void addKeptLinkWeight();

 private:
  struct Layout;
  ArticulatedAgentBase(const std::vector<ArticulatedBasePart>& baseParts, Layout layout);
  static Layout describe(const std::vector<ArticulatedBasePart>& baseParts,
                         const std::vector<ArticulatedLimb>& limbs);
  /// Fills selfCollision_ with the rules selfCollides() describes.
  void setSelfCollisionRules();
  /// Throws the InvalidArgument that applyLinkForce() owes for these arguments, if any.
  void refuseLinkForce(int b, Vector2 force, Vector2 worldPoint) const;

  std::vector<std::unique_ptr<Primitive>> baseParts_;
  std::vector<Vector2> partPositions_;  ///< each base part's centre relative to the centre of mass
  std::vector<real> partAngles_;        ///< each base part's angle in the base frame
  std::vector<std::unique_ptr<ArticulatedComponent<CappedRectangle>>> linkShapes_;
  /// Each link capsule's half length (fixed), kept here so that placeShapes() only writes to
  /// the shapes, which lie apart in memory, and reads nothing from them.
  std::vector<real> linkHalfLengths_;
  /// Every link's centre of mass is its capsule's centre, (half length, +0) in the link frame
  /// bit for bit (ArticulatedLink::capsule()): placeShapes() then takes the kinematics'
  /// centres of mass, computed by the same operations on the same values.
  bool capsulesCentredOnMass_ = false;
  Vector2 centreOffset_;
  const Simulator* simulator_ = nullptr;
};

}  // namespace thyrix
