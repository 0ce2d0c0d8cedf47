#pragma once
/// @file ArticulatedBody.h
/// @brief A floating base with a tree of links on revolute joints under quasistatic dynamics,
/// solved in O(N) by the quasistatic articulated-body algorithm, with Kokkevis test forces for
/// building contact and joint-limit constraint matrices.

#include <ThyrixLite/SymmetricMatrix3.h>
#include <ThyrixLite/ThyrixParameters.h>
#include <ThyrixLite/Vector2.h>
#include <ThyrixLite/Vector3.h>
#include <ThyrixPro/ArticulatedLink.h>
#include <Tools/Wide.h>

#include <bit>
#include <cstddef>
#include <cstdint>
#include <span>
#include <type_traits>
#include <vector>

namespace thyrix {

/// A rigid base (mass m0, moment of inertia I0 about its centre of mass, pose x, y, theta) and
/// a tree of ArticulatedLink on revolute joints, moving by the quasistatic law `D u = F`
/// (docs/Design.md section 4): velocities, not accelerations, are proportional to forces.
///
/// **Bodies** are numbered like ArticulatedLink::parent: `-1` (ArticulatedLink::base) is the
/// base and `0 .. linkCount() - 1` are the links. Arrays over all bodies hold the base first:
/// body `b` is at slot `b + 1`.
///
/// **Frames and units.** Everything given or returned is in world coordinates unless stated.
/// The base frame has its origin at the base's centre of mass and is turned by baseAngle().
/// Link i's frame has its origin at its joint and its x axis along the link, turned by
/// `q_i` from its parent's frame; angles are counter-clockwise (rad).
///
/// **Spatial vectors** are planar, ordered *(angular, x, y)* (see SpatialAlgebra.h):
/// - a body velocity is `(omega, vx, vy)`: the angular velocity and the linear velocity of the
///   body's *centre of mass*, world axes;
/// - an external wrench is `(torque, fx, fy)`: the force in world axes and the torque about the
///   body's *centre of mass* (a force f at a world point p gives the torque
///   `cross(p - centerOfMass(b), f)`; spatialForceAt(f, p, centerOfMass(b)) builds it).
///
/// **Joint torques.** `tau_i > 0` turns link i counter-clockwise relative to its parent: it
/// acts as `+tau_i` on link i and `-tau_i` on the parent, so it is the generalized force of
/// `qdot_i`.
///
/// **The law solved.** With generalized velocities `u = (v_base, omega_base, qdot)` and the
/// Jacobian J from u to every body's (centre-of-mass velocity, omega),
/// `(J^T D J + C) u = J^T F + (0, 0, 0, tau)`, D = diag(m, m, I) per body and
/// C = diag(0, 0, 0, c) the joint damping (setJointDamping(), zero by default). solve() computes
/// u in O(N) by the articulated-body algorithm with velocities in place of accelerations and no
/// velocity-product terms (Featherstone 2008, chapter 7: section 7.3 and Table 7.1, p. 132;
/// docs/Algorithms.md section 2).
///
/// **Joint damping.** A joint torque `-c_i qdot_i` opposing the joint's own rate enters the
/// joint equation as `(d_i + c_i) qdot_i = u_i - U_i^T X_i v_parent`, so it is solved implicitly in
/// the same O(N) passes with `d_i + c_i` in place of `d_i` (also in what the joint passes to its
/// parent). This is how an agent makes a position servo `tau = k (q* - q - dt qdot)` stable for
/// any gain k: `c_i = k dt`, and `k (q* - q)` is an ordinary torque.
///
/// **Use.** Set the state (setBasePose(), setJointAngles()), then solve() for the velocities
/// from torques and external wrenches. A contact solver then builds its constraint matrix K a
/// column at a time with respond() (one TestForce per constraint) and velocityAlong(): the
/// articulated inertias depend on the configuration only, so they are computed once and every
/// test force costs one bias pass and one outward pass (Kokkevis 2004; docs/Algorithms.md section
/// 3). Move the state with integrate().
///
/// All work arrays are sized at construction: solve(), respond() and the kinematics allocate
/// nothing once the Output passed in has been sized (makeOutput()).
class ArticulatedBody {
 public:
  /// The body index of the base.
  static constexpr int base = ArticulatedLink::base;

  /// A unit generalized force of one constraint: a unit force at a world point along a world
  /// direction on one body (a contact), or a torque on one joint (a joint limit). It is also
  /// the constraint's Jacobian row J_c: velocityAlong() reads `J_c u`, so respond() to test
  /// force j read with velocityAlong() of constraint i is `K_ij = J_i (J^T D J)^-1 J_j^T`.
  struct TestForce {
    /// What the force is.
    enum class Kind : std::uint8_t {
      PointForce,  ///< `direction` applied at `point` on body `index` (-1 the base)
      JointTorque  ///< `torque` on joint `index` (+ on the link, - on its parent)
    };
    Kind kind = Kind::PointForce;  ///< what the force is
    int index = base;              ///< the body (PointForce) or the joint, i.e. link (JointTorque)
    Vector2 point;                 ///< PointForce: world point of application (m)
    Vector2 direction;             ///< PointForce: world force per unit magnitude (a unit normal)
    real torque = 1;  ///< JointTorque: torque per unit magnitude: 1 (lower limit), -1 (upper)

    /// A unit force along @p direction at the world point @p point on @p body (-1 the base).
    static constexpr TestForce atPoint(int body, Vector2 point, Vector2 direction) {
      return {Kind::PointForce, body, point, direction, 1};
    }
    /// A torque @p torque (1 by default) on joint @p joint.
    static constexpr TestForce onJoint(int joint, real torque = 1) {
      return {Kind::JointTorque, joint, {}, {}, torque};
    }
  };

  /// The velocities computed by solve() and respond(); size it once with makeOutput().
  struct Output {
    /// Per body, base first (body b at slot b + 1): `(omega, vx, vy)`, the angular velocity and
    /// the velocity of the centre of mass, world axes.
    std::vector<Vector3> velocities;
    /// Per joint: `qdot_i` (rad/s).
    std::vector<real> jointRates;

    /// An output for @p linkCount links, all zero.
    explicit Output(int linkCount = 0) { resize(linkCount); }
    /// Resizes for @p linkCount links; allocates only when growing past the capacity.
    void resize(int linkCount);
    /// Sets every velocity and rate to zero.
    void setZero();
    /// Adds @p scale times @p other (same size): responses add up, being linear in the forces.
    void addScaled(const Output& other, real scale);

    /// The spatial velocity `(omega, vx, vy)` of body @p b (-1 the base) at its centre of mass.
    [[nodiscard]] const Vector3& velocity(int b) const { return velocities[b + 1]; }
    /// The angular velocity of body @p b (rad/s).
    [[nodiscard]] real angularVelocity(int b) const { return velocities[b + 1].x; }
    /// The velocity of the centre of mass of body @p b (m/s).
    [[nodiscard]] Vector2 linearVelocity(int b) const {
      return {velocities[b + 1].y, velocities[b + 1].z};
    }
    /// The rate of joint @p i (rad/s).
    [[nodiscard]] real jointRate(int i) const { return jointRates[i]; }
  };

  /// A base of quasistatic mass @p baseMass (N s/m) and moment of inertia @p baseInertia
  /// (N m s) about its centre of mass, with @p links; the pose and joint angles start at zero.
  /// @throws InvalidArgument naming "ArticulatedBody.baseMass" or ".baseInertia" unless
  /// positive and finite, or the first bad field of a link (ArticulatedLink::validate())
  ArticulatedBody(real baseMass, real baseInertia, std::vector<ArticulatedLink> links);

  // --- description ---------------------------------------------------------------------------

  /// The number of links N (joints).
  [[nodiscard]] int linkCount() const { return static_cast<int>(q_.size()); }
  /// The links, in index order.
  [[nodiscard]] std::span<const ArticulatedLink> links() const { return links_; }
  /// Link @p i. @throws InvalidArgument naming "ArticulatedBody.link" unless @p i is a link.
  [[nodiscard]] const ArticulatedLink& link(int i) const { return links_[checked(i)]; }
  /// The parent of body @p b (-1 for a link on the base; the base has none and gives -2).
  [[nodiscard]] int parent(int b) const { return b == base ? base - 1 : links_[b].parent; }
  /// The quasistatic mass of body @p b (-1 the base).
  [[nodiscard]] real mass(int b) const { return b == base ? baseMass_ : links_[b].mass; }
  /// The moment of inertia of body @p b (-1 the base) about its centre of mass.
  [[nodiscard]] real inertia(int b) const { return b == base ? baseInertia_ : links_[b].inertia; }

  /// A fixed base never moves (infinite mass): only the joints do. Off by default.
  [[nodiscard]] bool baseFixed() const { return baseFixed_; }
  /// Fixes or frees the base; the cached articulated inertias stay valid (the base's own
  /// articulated inertia is simply not used while it is fixed).
  void setBaseFixed(bool fixed) { baseFixed_ = fixed; }

  /// The damping `c_i` of joint @p i (N m s/rad): the joint feels the torque `-c_i qdot_i`,
  /// solved implicitly. Zero by default.
  /// @throws InvalidArgument naming "ArticulatedBody.link" unless @p i is a joint.
  [[nodiscard]] real jointDamping(int i) const { return jointDamping_[checked(i)]; }
  /// Sets the damping of joint @p i to @p damping (N m s/rad). The articulated inertias depend
  /// on it, so a change makes the next solve() or respond() recompute them; setting the same
  /// value again costs nothing.
  /// @throws InvalidArgument naming "ArticulatedBody.jointDamping" unless @p i is a joint and
  /// @p damping is finite and non-negative; the body is then unchanged
  void setJointDamping(int i, real damping);

  // --- state ---------------------------------------------------------------------------------

  /// The world position of the base's centre of mass, the base frame's origin (m).
  [[nodiscard]] Vector2 basePosition() const { return basePosition_; }
  /// The world angle of the base frame (rad).
  [[nodiscard]] real baseAngle() const { return baseAngle_; }
  /// The joint angles q (rad), one per link.
  [[nodiscard]] std::span<const real> jointAngles() const { return q_; }
  /// The angle of joint @p i (rad).
  /// @throws InvalidArgument naming "ArticulatedBody.link" unless @p i is a joint.
  [[nodiscard]] real jointAngle(int i) const { return q_[checked(i)]; }

  // Every setter below recomputes the kinematics (O(N)), so the pose accessors are always
  // current; the articulated inertias are recomputed lazily by the next solve() or respond().

  /// Places the base's centre of mass at @p position, its frame turned by @p angle.
  /// @throws InvalidArgument naming "ArticulatedBody.basePosition" or ".baseAngle" unless finite
  void setBasePose(Vector2 position, real angle);
  /// Sets the angle of joint @p i; O(N), so prefer setJointAngles() to set many.
  /// @throws InvalidArgument naming "ArticulatedBody.q" unless @p i is a joint and @p q finite
  void setJointAngle(int i, real q);
  /// Sets all joint angles. @throws InvalidArgument naming "ArticulatedBody.q" unless there are
  /// linkCount() of them, all finite; the state is then unchanged
  void setJointAngles(std::span<const real> q);
  /// Moves the state by @p out for @p dt (explicit Euler, like Integrator): the base's centre
  /// of mass by its velocity, the base angle by its angular velocity (unless the base is
  /// fixed), each `q_i` by `qdot_i`.
  /// @throws InvalidArgument naming "ArticulatedBody.Output" when @p out is not sized for this
  /// body
  void integrate(const Output& out, real dt);
  /// integrate(@p out, @p dt), calling `eachLink(i, centerOfMass(i), angle(i), axis(i))` for
  /// every link i, in index order, as soon as link i's pose is known (the accessors below give
  /// it then too). The calls come from within the kinematics' last loop over the links, with
  /// the pose at hand, so that a caller placing a shape on every link does so without a loop of
  /// its own.
  template <class EachLink>
  void integrate(const Output& out, real dt, EachLink&& eachLink) {
    moveBase(out, dt);
    anglesAndAxes(out.jointRates.data(), dt);
    if (allInChain_)
      linkOrigins<true>(eachLink);
    else
      linkOrigins<false>(eachLink);
  }

  // --- kinematics ----------------------------------------------------------------------------

  /// Computes every body's world pose and centre of mass from the state, root to leaves. The
  /// constructor and every state setter call it, so the accessors below are always current.
  void forwardKinematics();
  /// The world origin of body @p b's frame: the base's centre of mass, or link b's joint (m).
  [[nodiscard]] Vector2 origin(int b) const { return origin_[b + 1]; }
  /// The world angle of body @p b's frame (rad).
  [[nodiscard]] real angle(int b) const { return angle_[b + 1]; }
  /// The unit vector of body @p b's frame x axis in world axes: `(cos, sin)` of angle(b).
  [[nodiscard]] Vector2 axis(int b) const { return axis_[b + 1]; }
  /// The world position of body @p b's centre of mass (m).
  [[nodiscard]] Vector2 centerOfMass(int b) const { return origin_[b + 1] + comOffset_[b + 1]; }
  /// The world position of the point @p local of body @p b's frame (m).
  [[nodiscard]] Vector2 toWorld(int b, Vector2 local) const {
    const Vector2 a = axis_[b + 1];
    return origin_[b + 1] + Vector2{a.x * local.x - a.y * local.y, a.y * local.x + a.x * local.y};
  }
  /// The world position of link @p i's tip, `toWorld(i, link(i).tip())` (m).
  /// @throws InvalidArgument naming "ArticulatedBody.link" unless @p i is a link.
  [[nodiscard]] Vector2 tip(int i) const { return toWorld(i, links_[checked(i)].tip()); }

  // --- quasistatic articulated-body algorithm ------------------------------------------------

  /// The inward pass quantities that depend only on the configuration (Featherstone 2008,
  /// section 7.3): each body's articulated inertia `D^A_i` about its frame origin in world
  /// axes, `U_i = D^A_i S_i` and `d_i = S_i^T U_i` (plus the joint damping `c_i`). Cached:
  /// solve() and respond() recompute them, in the same sweep as their own inward pass, only
  /// when the state or a damping has changed since (solve() then stores only the base's
  /// `D^A`: see articulatedInertia()).
  void computeArticulatedInertias();

  /// The velocities from joint torques and external wrenches, in O(N).
  /// @param jointTorques `tau_i` per joint (N m), or empty for none
  /// @param externalWrenches `(torque about the centre of mass, fx, fy)` per body, world axes,
  ///        base first (body b at b + 1), linkCount() + 1 of them, or empty for none
  /// @param out the velocities of every body and the joint rates; resized if needed
  /// @throws InvalidArgument naming "ArticulatedBody.jointTorques" or ".externalWrenches" when
  ///         a span is neither empty nor of the right size
  void solve(std::span<const real> jointTorques, std::span<const Vector3> externalWrenches,
             Output& out);
  /// solve() with the wrench @p baseWrench on the base and the same @p linkWrench on every link
  /// (the weights of links of equal mass, say), as `(torque about the centre of mass, fx, fy)`:
  /// the same bits as solve() given an array of those wrenches, without one to fill and read.
  /// @throws InvalidArgument naming "ArticulatedBody.jointTorques" when @p jointTorques is
  ///         neither empty nor of the right size
  void solve(std::span<const real> jointTorques, const Vector3& baseWrench,
             const Vector3& linkWrench, Output& out);

  /// The velocities caused by one test force (Kokkevis): like solve() with that force alone,
  /// but reusing the cached articulated inertias, so it costs one bias pass and one outward
  /// pass, O(N). A column of the constraint matrix K is velocityAlong() of each constraint.
  /// @throws InvalidArgument naming "ArticulatedBody.TestForce.index" when out of range
  void respond(const TestForce& force, Output& out);
  /// The velocities caused by @p forces together, force k scaled by `magnitudes[k]` (all 1 when
  /// @p magnitudes is empty): by linearity, `u0 + respond(forces, f)` gives the velocities
  /// under contact forces f. Same cost as one respond().
  /// @throws InvalidArgument naming "ArticulatedBody.TestForce.index" when out of range, or
  ///         "ArticulatedBody.magnitudes" when neither empty nor one per force
  void respond(std::span<const TestForce> forces, std::span<const real> magnitudes, Output& out);

  /// The world velocity of the material point of body @p b (-1 the base) at the world point
  /// @p point, in @p out: `v_com + omega x (point - centerOfMass(b))` (m/s).
  [[nodiscard]] Vector2 pointVelocity(const Output& out, int b, Vector2 point) const;
  /// The velocity conjugate to @p constraint, `J_c u`: for a PointForce the velocity of its
  /// point on its body along its direction; for a JointTorque `torque * qdot_index`.
  [[nodiscard]] real velocityAlong(const Output& out, const TestForce& constraint) const;
  /// The rate of joint @p i in @p out (rad/s).
  [[nodiscard]] static real jointRate(const Output& out, int i) { return out.jointRates[i]; }
  /// An Output sized for this body, all zero.
  [[nodiscard]] Output makeOutput() const { return Output(linkCount()); }

  /// The cached articulated inertia `D^A` of body @p b (-1 the base) about its frame origin,
  /// world axes, ordered (angular, x, y). A link's is valid after computeArticulatedInertias()
  /// (or a respond() that found the inertias out of date) until the next change of the state or
  /// of a damping, and not updated by solve(), which keeps only the base's (a chain's solve
  /// needs no other).
  [[nodiscard]] const SymmetricMatrix3& articulatedInertia(int b) const {
    return articulatedInertia_[b + 1];
  }

 private:
  /// The external wrenches of a solve (as solve() takes them): one per body, the same on every
  /// link, or none.
  struct Wrenches {
    const Vector3* perBody = nullptr;  ///< body slot s's at s, or null
    bool uniform = false;              ///< perBody null: `base` on the base, `link` on each link
    Vector3 base;
    Vector3 link;
    /// Whether there are wrenches at all.
    [[nodiscard]] bool any() const { return perBody != nullptr || uniform; }
    /// The wrench on the body at @p slot (when any()).
    [[nodiscard]] const Vector3& at(std::size_t slot) const {
      if (perBody != nullptr) return perBody[slot];
      return slot == 0 ? base : link;
    }
  };
  /// integrate()'s check of @p out and move of the base.
  void moveBase(const Output& out, real dt);
  /// The first two sweeps of forwardKinematics(): every body's angle, then its axis; with
  /// @p rates (not null) integrate()'s move of the joints too, `q_i += rates[i] dt`.
  void anglesAndAxes(const real* rates, real dt);
  /// The last sweep of forwardKinematics(): every link's origin and centre-of-mass offset,
  /// calling @p eachLink as integrate() says once link i's pose is stored. @p plainChain is
  /// allInChain_: every parent is then at slot i, carried in registers, with no slot to test.
  template <bool plainChain, class EachLink>
  void linkOrigins(EachLink&& eachLink) {
    origin_[0] = basePosition_;
    comOffset_[0] = {};
    if constexpr (plainChain) {
      plainChainLinkOrigins(eachLink);
      return;
    }
    Vector2 parentOrigin = basePosition_;
    Vector2 parentAxis = axis_[0];
    for (std::size_t i = 0; i < links_.size(); ++i) {
      if constexpr (!plainChain) {
        const std::size_t p = parentSlot_[i];
        if (p != i) {
          parentOrigin = origin_[p];
          parentAxis = axis_[p];
        }
      }
      const LinkPlacement& l = placements_[i];
      const Vector2 shift = rotated(parentAxis, l.jointPosition);
      shift_[i] = shift;
      parentOrigin += shift;
      origin_[i + 1] = parentOrigin;
      parentAxis = axis_[i + 1];
      const Vector2 offset = rotated(parentAxis, l.centerOfMass);
      comOffset_[i + 1] = offset;
      eachLink(i, parentOrigin + offset, angle_[i + 1], parentAxis);
    }
  }
  /// linkOrigins<true>()'s loop (a plain chain), each vector's two coordinates at once. Each
  /// rotation as rotated() computes it: (a.x, a.y) v.x plus (-a.y, a.x) v.y, where
  /// a.x v.x + (-a.y) v.y has the bits of a.x v.x - a.y v.y (a product with a negated factor
  /// is the negated product, and x + (-y) is x - y). The turned axis (-a.y, a.x) serves the
  /// link's centre of mass and its child's joint.
  template <class EachLink>
  void plainChainLinkOrigins(EachLink& eachLink) {
    using Pair = simd::Wide<real, 2>;
    static_assert(std::is_standard_layout_v<Vector2> && sizeof(Vector2) == sizeof(Pair),
                  "vectors are read and written as their coordinates");
    const auto pairOf = [](const Vector2& v) { return Pair::load(&v.x); };
    // Stored as a whole Vector2 (std::bit_cast), not through a real*: a vector store may alias
    // anything, and GCC then reads the caller's fields again at every link.
    const auto vectorOf = [](Pair pair) { return std::bit_cast<Vector2>(pair); };
    const Pair negateLow = simd::pair(real(-0.0), real(0.0));
    const auto turned = [&](Pair a) { return flipSigns(simd::swapped(a), negateLow); };
    const auto turn = [](Pair a, Pair aTurned, Pair v) {
      return a * simd::lows(v, v) + aTurned * simd::highs(v, v);
    };
    const LinkPlacement* const placements = placements_.data();
    const Vector2* const axes = axis_.data() + 1;  // link i's at i, as below
    const real* const angles = angle_.data() + 1;
    Vector2* const origins = origin_.data() + 1;
    Vector2* const offsets = comOffset_.data() + 1;
    Vector2* const shifts = shift_.data();
    Pair parentOrigin = pairOf(basePosition_);
    Pair parentAxis = pairOf(axis_[0]);
    Pair parentTurned = turned(parentAxis);
    const std::size_t n = links_.size();
    for (std::size_t i = 0; i < n; ++i) {
      const Pair shift = turn(parentAxis, parentTurned, pairOf(placements[i].jointPosition));
      shifts[i] = vectorOf(shift);
      parentOrigin = parentOrigin + shift;
      origins[i] = vectorOf(parentOrigin);
      parentAxis = pairOf(axes[i]);
      parentTurned = turned(parentAxis);
      const Pair offset = turn(parentAxis, parentTurned, pairOf(placements[i].centerOfMass));
      offsets[i] = vectorOf(offset);
      eachLink(i, vectorOf(parentOrigin + offset), angles[i], vectorOf(parentAxis));
    }
  }
  /// @p v turned by the angle whose (cos, sin) is @p axis.
  static constexpr Vector2 rotated(Vector2 axis, Vector2 v) {
    return {axis.x * v.x - axis.y * v.y, axis.y * v.x + axis.x * v.y};
  }
  /// Throws InvalidArgument naming "ArticulatedBody.jointTorques" unless @p jointTorques is
  /// empty or has a torque per joint.
  void checkTorques(std::span<const real> jointTorques) const;
  void checkTestForce(const TestForce& force) const;
  /// @p i as an index; throws InvalidArgument naming "ArticulatedBody.link" unless a link.
  [[nodiscard]] std::size_t checked(int i) const {
    if (i < 0 || i >= linkCount()) refuseLink(i);
    return static_cast<std::size_t>(i);
  }
  [[noreturn]] void refuseLink(int i) const;
  void depositTestForce(const TestForce& force, real magnitude);
  /// Link @p i's step of the inward inertia pass, given its articulated inertia @p da: sets
  /// terms_[i] and returns the inertia it passes to its parent (about the parent's origin).
  template <bool damped>
  SymmetricMatrix3 articulateJoint(std::size_t i, const SymmetricMatrix3& da);
  /// Link @p i's step of the inward bias pass, given its bias @p pa and its joint torque
  /// @p tau: sets u_i and returns the bias it passes to its parent (about the parent's origin).
  Vector3 passBias(std::size_t i, const Vector3& pa, real tau);
  /// inwardPass<true, false, false>()'s loop over a plain chain (allInChain_), with or
  /// without @p wrenches, in pairs, re-associated for shorter dependency chains (so not
  /// chainStep's last bits): leaves the terms it carries to the base in @p inertiaCarried and
  /// @p biasCarried.
  void plainChainInwardPass(const Wrenches& wrenches, const real* torques,
                            SymmetricMatrix3& inertiaCarried, Vector3& biasCarried);
  /// The inward sweep, leaves to root: the bias pass from @p wrenches (as solve() takes
  /// them, or none), the joint torques @p torques (one per joint), the forces already in
  /// bias_, and the articulated inertias too when @p withInertias, with the joint damping when
  /// @p damped (else all c_i are zero). When @p general every body's bias_ slot is read
  /// (respond()'s test forces) and every articulated inertia stored; otherwise only the slots
  /// that gather the terms of children (gathers_) are read (the others are not), and only the
  /// base's inertia is kept.
  template <bool withInertias, bool damped, bool general>
  void inwardPass(const Wrenches& wrenches, const real* torques);
  /// Zeroes the slots of @p perBody (bias_ or articulatedInertia_) that gather the terms of
  /// children (gathers_): the only ones an inward pass without deposits reads.
  template <class T>
  void clearGatheringSlots(std::vector<T>& perBody) const {
    for (const std::size_t slot : gatheringSlots_) perBody[slot] = T{};
  }
  /// The bias pass (leaves to root) from @p wrenches (or none), the joint torques
  /// @p torques, the forces in bias_ (in every slot when @p general, see inwardPass()), with
  /// the articulated inertias if they are stale, then the outward pass (root to leaves),
  /// writing @p out.
  template <bool general>
  void biasAndOutwardPasses(const Wrenches& wrenches, const real* torques, Output& out);
  /// solve()'s passes, @p jointTorques already checked (checkTorques()).
  void solveWith(std::span<const real> jointTorques, const Wrenches& wrenches, Output& out);

  real baseMass_;
  real baseInertia_;
  bool baseFixed_ = false;
  std::vector<ArticulatedLink> links_;
  // Copies of the fields of links_ that the kinematics and the passes read, packed: they read
  // 32 and 16 bytes a link instead of lines of 88-byte links (the chain's arrays fill about
  // the L2 cache).
  /// Where a link sits in its frames: what linkOrigins() reads.
  struct LinkPlacement {
    Vector2 jointPosition;  ///< ArticulatedLink::jointPosition
    Vector2 centerOfMass;   ///< ArticulatedLink::centerOfMass
  };
  /// A link's quasistatic mass and inertia: what the inward pass reads.
  struct LinkMass {
    real mass = 0;  ///< ArticulatedLink::mass
    /// I + m |c|^2, the inertia about the joint (c = ArticulatedLink::centerOfMass): |c| does
    /// not change as the link turns, so it is computed once, not in every inertia pass.
    real inertiaAboutJoint = 0;
  };
  std::vector<LinkPlacement> placements_;  ///< per link
  std::vector<LinkMass> linkMasses_;       ///< per link

  Vector2 basePosition_;
  real baseAngle_ = 0;
  std::vector<real> q_;  ///< joint angles

  bool inertiasStale_ = true;  ///< the state changed since computeArticulatedInertias()

  // Per body, slot b + 1 (base first); world axes.
  std::vector<Vector2> origin_;     ///< frame origin: base centre of mass or joint
  std::vector<real> angle_;         ///< frame angle
  std::vector<Vector2> axis_;       ///< (cos, sin) of the frame angle: the frame's x axis
  std::vector<Vector2> comOffset_;  ///< centre of mass minus frame origin
  std::vector<SymmetricMatrix3> articulatedInertia_;  ///< D^A about the frame origin
  std::vector<Vector3> bias_;                         ///< p^A about the frame origin
  /// The spatial velocity at the frame origin, kept for the bodies whose slot gathers (gathers_)
  std::vector<Vector3> originVelocity_;

  // Per link (joint) i.
  std::vector<std::size_t> parentSlot_;  ///< the parent's slot in the per-body arrays
  /// Per body slot: 1 when some child passes its terms through the slot (a child that is not
  /// the next link, e.g. at a fork or on the base) rather than in registers; a chain has none.
  std::vector<std::uint8_t> gathers_;
  std::vector<std::size_t> gatheringSlots_;  ///< the slots whose gathers_ is 1, in order
  /// Per link: 1 when its parent is at slot i (the link before it, or the base for link 0) and
  /// its own slot gathers nothing: the inward pass's terms then stay in registers.
  std::vector<std::uint8_t> inChain_;
  bool allInChain_ = false;     ///< every inChain_ is 1: a plain chain on the base
  std::vector<Vector2> shift_;  ///< origin minus the parent's origin: X_i is a pure translation
  /// Per joint, the coefficients the inertia pass leaves for the bias and outward passes:
  /// Table 7.1's U_i and d_i folded with X_i (see ArticulatedBody.cpp for the algebra).
  struct JointTerms {
    real inverseD = 0;  ///< 1 / (d_i + c_i), d_i = S_i^T D^A_i S_i
    real alpha = 0;     ///< (c_i - g_i) / (d_i + c_i), g_i = r_i x (linear part of U_i)
    real gamma = 0;     ///< (d_i + g_i) / (d_i + c_i)
    Vector2 beta;       ///< the linear part of U_i = D^A_i S_i, over d_i + c_i
  };
  std::vector<JointTerms> terms_;   ///< per joint, from the inertia pass
  std::vector<real> jointDamping_;  ///< c_i, the implicit joint damping
  std::size_t dampedJoints_ = 0;    ///< how many c_i are not zero
  std::vector<real> jointTorque_;   ///< tau_i for respond()'s pass (solve() reads its own)
  std::vector<real> jointBias_;     ///< u_i = tau_i - S_i^T p^A_i
};

}  // namespace thyrix
