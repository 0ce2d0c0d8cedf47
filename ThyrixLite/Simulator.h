#pragma once
/// @file Simulator.h
/// @brief Time stepping of a World: contacts, the contact LCP, control and integration.

#include <ThyrixLite/BaraffSolver.h>
#include <ThyrixLite/BroadPhase.h>
#include <ThyrixLite/ContactSolver.h>
#include <ThyrixLite/GaussSeidelSolver.h>
#include <ThyrixLite/Integrator.h>
#include <ThyrixLite/Islands.h>
#include <ThyrixLite/MultiBodyObject.h>
#include <ThyrixLite/ObjectList.h>
#include <ThyrixLite/Primitive.h>
#include <ThyrixLite/World.h>
#include <ThyrixLite/WorldState.h>

#include <algorithm>
#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace thyrix {

struct Manifold;
struct ManifoldPoint;

/// What the last step did, for monitoring and benchmarks.
struct StepStatistics {
  std::size_t contacts = 0;           ///< contact points detected
  std::size_t reusedContacts = 0;     ///< of which kept from the last step (rest skipping)
  std::size_t islands = 0;            ///< islands built (none when no contact needed a force)
  std::size_t solvedIslands = 0;      ///< islands whose contacts needed forces
  std::size_t gaussSeidelSweeps = 0;  ///< sweeps summed over the islands Gauss-Seidel solved
  std::size_t baraffPivots = 0;       ///< pivots summed over the islands Baraff solved
  /// Islands Baraff was given and could not finish (a singular clamped block, contradictory
  /// targets, too many pivots): Gauss-Seidel solved them.
  std::size_t baraffFallbacks = 0;
  /// Islands of rigid bodies with more than ContactSolverSettings::baraffMaxIslandContacts
  /// contacts: Gauss-Seidel solved them although Baraff was chosen (0 with Gauss-Seidel chosen).
  std::size_t baraffOversizedIslands = 0;
  /// Detections run again because the solve moved a shape past a border that detection had
  /// not reached (Simulator::advanceTime()); 0 in almost every step.
  std::size_t redetections = 0;
  /// Equal parts the step was run in, each detected, solved and integrated on its own, because
  /// the solve moved a point of a shape farther than its radius in one step
  /// (Simulator::advanceTime()); 1 in almost every step.
  std::size_t substeps = 1;
  /// Bodies that phases 5 and 8 visited: every object, but with Simulator::restSkipping on and
  /// no gravity field only the awake ones (the users' guide, "Rest"); bodies at rest cost
  /// nothing there.
  std::size_t awakeBodies = 0;
  /// Contacts between two bodies at rest that the solve left out (no row; force 0).
  std::size_t restingContacts = 0;
};

/// A World that advances in time with quasistatic dynamics.
///
/// One call of advanceTime() runs, in order (docs/Design.md section 3):
/// 1. erase the last step's contacts; 2. detectContacts(); 3. indexContacts();
/// 4. applyMouseForce(); 5. computeDerivativesWithoutContacts() (each object's, in the gravity
/// field);
/// 6. solveContacts(); 7. each object's control(); 8. integrator().integrate() (explicit
/// Euler unless setIntegrator() replaced it); then World::advanceTime() counts the step.
/// In a world of core shapes only, integrated by explicit Euler, a step whose solve would move
/// a point of a shape farther than the shape's radius is run instead in equal substeps (phases
/// 2 and 6 and 8 each, from the same free velocities) short enough that each moves every point
/// by at most half its radius: contacts are linear in the motion, which an arc of a turning
/// capsule or a Gauss-Seidel error of a light body follows only for small motions
/// (StepStatistics::substeps; the users' guide, "Walls"). The phases run by hand never divide a
/// step; the same as advanceTime() wherever no step is divided.
/// advanceTime() runs phase 3 only when an object's list is first read
/// (PhysicalObject::contacts()), during the step or after it: a step in which nothing reads
/// the lists pays nothing for them, and the lists read are those phase 3 in its place gives.
/// The phases are public so that a program can run its own variant of the step. A subclass
/// that adds per-step logic (a scripted controller, fitness bookkeeping) overrides
/// advanceTime() and calls Simulator::advanceTime() from it: console loops and GUIWx's
/// simulation thread call advanceTime() alike, so the logic runs wherever the world is stepped.
///
/// A simulator owns everything it uses (no global state): worlds in different threads are
/// independent, and the same scene gives bit-identical runs.
class Simulator : public World {
 public:
  /// A simulator stepped by @p timestep seconds (World::timestep()).
  /// @throws InvalidArgument naming "World.timestep" unless positive and finite
  explicit Simulator(real timestep = real(0.01));

  /// This step's contacts (kept until the next step starts, for drawing).
  ContactList contacts;

  /// Advances the world by one time step: the eight phases, then World::advanceTime().
  /// @throws InvalidArgument naming the field ("Circle.externalForce", say) and, in the
  /// message, the object's index, if checkInputs is set and an object's `r`, `alpha`,
  /// `externalForce` or `externalTorque` is not finite; the world is then left as it was.
  void advanceTime() override;

  /// Replaces the integrator that moves the objects in phase 8 (explicit Euler, Integrator
  /// itself, by default) with @p integrator, from the next step on. The default Euler runs
  /// its loop without a virtual call per object; any other integrator is called once per step
  /// through Integrator::integrate().
  /// @throws InvalidArgument naming "Simulator.setIntegrator.integrator" if it is null (the
  ///         integrator is then unchanged)
  void setIntegrator(std::unique_ptr<Integrator> integrator);
  /// The integrator of phase 8.
  [[nodiscard]] Integrator& integrator() { return *integrator_; }
  /// The integrator of phase 8, read-only.
  [[nodiscard]] const Integrator& integrator() const { return *integrator_; }

  /// Whether advanceTime() first checks that every object's `r`, `alpha`, `externalForce` and
  /// `externalTorque` are finite (values written between steps), so that a NaN is refused
  /// instead of spreading. On by default in Debug builds of Thyrix, off in Release.
  bool checkInputs;

  /// Phase 1: erases the last step's contacts (kept until now so a GUI can draw them).
  void eraseContacts();
  /// Phase 2: updates bounding boxes, finds the contacts (broad then narrow phase).
  /// Appends to `contacts`: call eraseContacts() first when running phases by hand. (Only a
  /// step with one detection into an empty list, then a solve, leaves its contacts for the
  /// next step's rest skipping and warm start.)
  void detectContacts();
  /// Phase 3: lists each contact in its two objects' PhysicalObject::contacts() (with the
  /// contacts' forces, 0 until solveContacts() gives them, which it then gives the lists too).
  /// advanceTime() does not call it: the first read of a list after the contacts changed
  /// does. Each ContactInfo's `p` is relative to the reference point its body was detected at.
  void indexContacts();
  /// Phase 4: while dragging, adds the force that pulls the grabbed point to the mouse.
  void applyMouseForce();
  /// Phase 5: each object's velocities without contacts, in registration order (an Elastoid
  /// pushes its bodies, registered after it, before they compute theirs): its
  /// PhysicalObject::computeDerivativesWithoutContacts(), in the gravity field (setGravity()).
  void computeDerivativesWithoutContacts() {
    // Inline, so that advanceTime() runs a world without gravity as it did before the field
    // existed: one test per step, then the same loop (out of line, it cost the arena
    // benchmark 12 instructions a step). The core shapes' hooks are called without a virtual
    // call, in runs between the other objects (no flag to test per object).
    // (The bodies that move otherwise than the field are noted on their rare path, for
    // outranMargins().)
    freeRunners_.clear();
    if (hasGravity_) {
      computeDerivativesInGravity();
      return;
    }
    forEachInRuns(
        objects, customObjects_,
        [this](PhysicalObject& object) {
          if (!object.velocitiesFromAccumulators<false>({})) [[unlikely]]
            noteFreeMotion(object);
        },
        [this](PhysicalObject& object) {
          object.computeDerivativesWithoutContacts();
          if (!object.primitives().empty()) noteFreeMotion(object);  // (an elastoid has none)
        });
  }
  /// Phase 6: contact forces (the chosen solver, island by island), then final velocities;
  /// the tactile sensors then read the forces. In a world without articulated agents, where the
  /// solved velocities would carry an end of a shape past a border that was out of its reach at
  /// detection, the contacts are detected again (phase 2, and 3 if they were listed) with
  /// margins that cover the step's motion, and solved again from the free velocities, up to 4
  /// times (StepStatistics::redetections; the users' guide, "Walls").
  void solveContacts();

  /// Rest (exact, on by default): a shape whose pose did not change since the last
  /// detection keeps its geometry and box, and two such shapes keep the last detection's
  /// contacts instead of being tested again; a body at rest (docs/UsersGuide.md, "Rest") is
  /// not visited by phases 5 and 8, and the contacts between bodies at rest build no row. The
  /// results are bit-identical either way; turn it off only to compare.
  bool restSkipping = true;

  /// Wakes @p object for the next step: needed only after a hook (control(), say) wrote the
  /// velocity `v` or `omega` of another object at rest, which the step's integration would
  /// otherwise not see (every other write between steps, to a pose, force, torque, velocity,
  /// `fixed` or `collisionGroup`, wakes the body by itself). Harmless on a body awake.
  /// @throws InvalidArgument naming "Simulator.wake.object" if it is not registered here
  void wake(PhysicalObject& object);

  /// Reference mode (off by default): every cache and shortcut kept only for speed is off, and
  /// each step runs the plain algorithm of the users' guide: every shape placed from its pose
  /// (no rest: every body visited, every contact a row; no fast paths for circles, composed bodies
  /// or runs of links), every pair of grid boxes tested (no choice among broad-phase strategies, no
  /// memory of the last call), every border tested against every shape (no reach words), every pair
  /// through the narrow phase's general functions (no batch of circles, no reach test before them),
  /// the last step's forces found by a scan (no lookups by cursor, chain or index), every contact
  /// turned into a row (no judgment of a step that needs no force), the objects' contact lists made
  /// before the solve, every object's control() and updateSensors() called, and phase 8 through
  /// Integrator::integrate() (no loop without virtual calls). The results are bit-identical to
  /// the default mode's, step by step: the mode is the oracle the tests compare the shortcuts
  /// with, and a shortcut added later must be off in it too, its plain form run instead
  /// (tested: ReferenceModeTest).
  /// It may be turned on or off between any two steps; it is much slower (quadratic in the
  /// shapes).
  bool referenceMode = false;

  /// Sizes the per-step buffers for up to @p count contacts (and, with articulated agents
  /// registered, islands of up to 256 rows), so that steps with no more contacts than that
  /// allocate nothing. Without it the buffers grow to the largest count
  /// seen (geometrically), after which steps allocate nothing either.
  void reserveContacts(std::size_t count);

  /// Sets the world's gravity field @p gravity (m/s), {0, 0} by default: from the next step on,
  /// every movable object of quasistatic mass `m` feels its weight `m * gravity` at its centre
  /// of mass, as if it were added to `externalForce` before each step, so a free body falls at
  /// the velocity `gravity`. (Under `F = m v` a field is a velocity, not an acceleration: to
  /// match a Newtonian world with gravitational acceleration `a` and linear damping `d` (1/s),
  /// use `gravity = a / d`; a = 10 m/s^2 and d = 10 /s give a fall at 1 m/s.)
  ///
  /// Fixed objects feel nothing. The core shapes (Circle, CappedRectangle, Border,
  /// ComposedPhysicalObject) move at `externalForce / m + gravity`, computed in the same pass
  /// as their velocities; other objects get PhysicalObject::applyWeight() just before their
  /// computeDerivativesWithoutContacts(), which adds `m * gravity` to `externalForce` (an
  /// articulated agent weighs each link, and its base unless fixed, at its own centre of mass;
  /// an Elastoid weighs nothing itself, its bodies are weighed as objects). The two agree up
  /// to the rounding of `(F + m g) / m`; exactly for a mass that is a power of two (both are
  /// then `F / m + g` rounded once), not for every mass with `(m g) / m == g`. A zero field
  /// (either sign of zero) adds nothing: the steps compute exactly what they compute without
  /// it.
  /// @throws InvalidArgument naming "Simulator.setGravity.gravity" unless both coordinates are
  ///         finite (the field is then unchanged)
  void setGravity(Vector2 gravity);
  /// The gravity field (m/s); a coordinate set to -0 reads +0.
  [[nodiscard]] Vector2 gravity() const { return gravity_; }

  /// Chooses the method that solves the contact LCP (Baraff by default).
  void setContactSolver(ContactSolverKind kind) { solverKind_ = kind; }
  /// The method that solves the contact LCP.
  [[nodiscard]] ContactSolverKind contactSolver() const { return solverKind_; }
  /// Solver tuning, readable and writable.
  ContactSolverSettings& solverSettings() { return settings_; }
  /// Solver tuning, read-only.
  [[nodiscard]] const ContactSolverSettings& solverSettings() const { return settings_; }
  /// What the last step did.
  [[nodiscard]] const StepStatistics& statistics() const { return statistics_; }

  /// Grabs @p object at @p grabPoint (world coordinates); a part grabs its whole body.
  /// @throws InvalidArgument naming "Simulator.startDrag.object" if the object is not in this
  ///         world or has no shape of its own (an Elastoid: drag one of its bodies), or
  ///         "Simulator.startDrag.grabPoint" if the point is not finite
  void startDrag(PhysicalObject& object, Vector2 grabPoint);
  /// Moves the mouse target to @p target (world coordinates).
  /// @throws InvalidArgument naming "Simulator.dragTo.target" if it is not finite
  void dragTo(Vector2 target);
  /// Releases the grabbed object.
  void stopDrag() { dragged_ = nullptr; }
  /// The grabbed body, or nullptr.
  [[nodiscard]] PhysicalObject* draggedObject() const { return dragged_; }
  /// Fraction of the distance to the mouse that a free dragged point covers per step, in (0, 1].
  real dragResponse = real(0.5);
  /// Longest step of the dragged point, as a fraction of the dragged body's smallest radius:
  /// a far mouse pulls the body at a bounded speed, so it cannot jump through other objects.
  real dragMaxStepFraction = real(0.2);

  /// Everything that can change the next step, as one value (WorldState): restoring it,
  /// into this world or into one built the same way, then stepping gives the same steps, bit
  /// for bit, as stepping on from here.
  [[nodiscard]] WorldState saveState() const;
  /// Puts the world in @p state, as saveState() made it; the caches rest skipping, the broad
  /// phase and the contact lookups keep are rebuilt by the next step.
  /// @throws InvalidArgument naming "WorldState" and saying what differs if the state was saved
  ///         from a world of another make-up (other objects, types, shapes, agents), or if a
  ///         part of it does not fit this world; the world is then unchanged
  void restoreState(const WorldState& state);

 protected:
  void prepareRegistration(std::span<PhysicalObject* const> added) override;
  void completeRegistration(PhysicalObject& object, std::size_t index) noexcept override;
  /// Appends to @p record the state of a subclass's own (fitness counts, a script's phase),
  /// for saveState(); the default has none.
  virtual void saveOwnState(StateRecord& /*record*/) const {}
  /// Reads back what saveOwnState() appended, for restoreState(); it may throw (the world is
  /// then put back as it was).
  virtual void restoreOwnState(StateRecord::Reader& /*reader*/) {}

 private:
  /// A primitive as the collision pipeline sees it.
  struct Shape {
    Primitive* primitive;
    PhysicalObject* object;  // its body
    std::uint32_t body;      // index in objects
    std::uint32_t group;     // the body's collisionGroup, as of the last detection
    ShapeType type;
    bool movable;  // the body's, as of the last detection
  };
  /// World geometry of a shape this step: circle centre in p0; capsule ends p0, p1;
  /// half-plane point p0 and normal p1.
  struct ShapeGeometry {
    Vector2 p0;
    Vector2 p1;
    real radius;
    real margin;      // speculativeFraction * radius
    real travel = 0;  // speculativeTravel * the last step's displacement (0 at rest)
  };

  /// What detection remembers of a body, to notice that it moved or changed its filters.
  struct BodyState {
    static constexpr std::uint32_t unknown = 2;  // `fixed` before the body's first detection
    PhysicalObject* object = nullptr;            // the body
    Vector2 r;
    real alpha = 0;
    std::uint32_t group = 0;        // collisionGroup
    std::uint32_t fixed = unknown;  // 1 if fixed, else 0
    std::uint32_t firstShape = 0;   // its shapes are firstShape, firstShape + 1, ...
    std::uint32_t shapeCount = 0;
    bool movable = false;
    bool standalone = false;        // the body is its one primitive
    bool standaloneCircle = false;  // ... and that is a circle
    bool custom = false;            // its hooks are its own (called through virtual calls)
    // Never at rest: its own hooks may move it, or it is a sub-body its owner's hooks push.
    bool alwaysAwake = false;
    // Standalone, or no shape: at rest, only its sensors to note. As registered: then kept by
    // updateGeometry in filterKey, as a byte that is 1 while the body travels.
    bool restsCheaply = false;
    // `fixed`, no sensing_, whether it travels and `group` laid out as the body's bytes from its
    // `fixed` on (see updateGeometry): its filters, sensors and rest checked in one word. (All
    // ones before the first detection: never matches.)
    std::uint64_t filterKey = ~std::uint64_t{0};
  };
  /// The pose of a primitive its geometry was computed from (not kept for a standalone
  /// circle, whose body's pose says it), its capsule half axis, and its half length (fixed at
  /// construction: copied here so a moved shape reads one record).
  struct ShapePose {
    Vector2 r;
    real alpha = 0;
    Vector2 axis;
    real halfLength = 0;
  };

  /// computeDerivativesWithoutContacts() with a gravity field that is not zero.
  void computeDerivativesInGravity();
  void updateGeometry();
  // Reference mode (SimulatorReference.cpp): the plain algorithm in place of each cache.
  /// updateGeometry() without caches: every body's shapes placed from their poses.
  void updateGeometryPlainly();
  /// Every pair of overlapping grid boxes into pairs_, by first then second box.
  void findPairsPlainly();
  /// Every border tested against every grid shape, border by border, in slot order.
  void findBorderContactsPlainly();
  /// The force the last step's contact with @p contact's identity ended with, or 0: a scan.
  [[nodiscard]] real previousForcePlainly(const GlobalContactInfo& contact) const;
  /// Makes the next detection recompute what rest skipping, the border reach words and the broad
  /// phase keep from earlier detections (after a restore, or steps in reference mode).
  void forgetCaches();
  bool cachesForgotten_ = false;  // steps ran in reference mode: forgetCaches() before the next
  /// updateGeometry for a body that changed (its collision filters with @p newFilters), or
  /// that has several shapes (whose poses are then compared one by one).
  void updateBody(std::uint32_t index, bool changed, bool newFilters);
  /// updateBody for a standalone circle whose filters did not change (@p changed: its pose did).
  void updateMovedCircle(BodyState& state, bool changed);
  /// updateBody's loop over the shapes of a body that is not its one primitive (@p known:
  /// detected before, as of the start of updateBody).
  void updateComposedBody(const BodyState& state, bool changed, bool known);
  void addCachedBox(std::uint32_t shape, Vector2& boxMin, Vector2& boxMax) const;
  /// Whether @p object has tactile sensors or is rigidly attached (sensing_ || rigid_).
  static bool sensingOrRigid(const PhysicalObject& object);
  /// The 8 bytes of @p object from its `fixed` on as one word (BodyState::filterKey's layout).
  static std::uint64_t filterBytes(const PhysicalObject& object);
  /// addCachedBox for a circle or capsule of geometry @p geometry.
  static void addGeometryBox(const ShapeGeometry& geometry, Vector2& boxMin, Vector2& boxMax);
  void updateShape(std::uint32_t shape, bool poseKnown, bool standalone, Vector2& boxMin,
                   Vector2& boxMax);
  /// updateShape for a circle at centre @p r; @return its travel.
  real updateCircle(std::uint32_t shape, Vector2 r, bool poseKnown, Vector2& boxMin,
                    Vector2& boxMax);
  /// The grid arrays a shape's update writes, and the travel factor: read once by
  /// updateComposedBody for all its shapes (a byte store, as to shapeMoved_, may alias anything,
  /// so members would be read again after each).
  struct GridTargets {
    const std::uint32_t* slots;  // gridSlot_
    std::uint64_t* movedBits;    // gridMovedBits_
    BoundingBox* boxes;          // gridBoxes_
    real travelFactor;           // geometryTravel_
  };
  [[nodiscard]] GridTargets gridTargets() {
    return {gridSlot_.data(), gridMovedBits_.data(), gridBoxes_.data(), geometryTravel_};
  }
  /// updateShape for a capsule, @p primitive its primitive.
  void updateCapsule(std::uint32_t shape, Primitive& primitive, ShapePose& pose,
                     ShapeGeometry& geometry, bool poseKnown, const GridTargets& grid,
                     Vector2& boxMin, Vector2& boxMax);
  /// updateCapsule once the half axis @p axis is known, for the pose (@p r, @p alpha).
  void placeCapsule(std::uint32_t shape, Vector2 r, real alpha, Vector2 axis, ShapePose& pose,
                    ShapeGeometry& geometry, bool poseKnown, const GridTargets& grid,
                    Vector2& boxMin, Vector2& boxMax);
  /// placeCapsule without the grid's moved bit (the caller's), its grid box @p gridBox.
  void placeLinkCapsule(Vector2 r, real alpha, Vector2 axis, ShapePose& pose,
                        ShapeGeometry& geometry, bool poseKnown, real travelFactor,
                        BoundingBox& gridBox, Vector2& boxMin, Vector2& boxMax);
  /// updateComposedBody's loop body for shape @p shape, once a shape of its body moved, in
  /// general (the loop does a chain's links and the unmoved shapes itself).
  void updateComposedShape(std::uint32_t shape, bool changed, bool poseKnown, Vector2& boxMin,
                           Vector2& boxMax);
  /// Sorts pairs_ by first, then second box (BroadPhase's order up to its all-pairs limit).
  void sortPairs();
  std::vector<std::uint32_t> pairStart_;  // sortPairs(): each first box's place
  std::vector<BoxPair> sortedPairs_;      // sortPairs()' output, swapped with pairs_
  /// Phase 2's pairs of grid shapes (reused, batched or tested), then the borders' contacts.
  void detectPairs(bool reuse);
  /// addContacts() through the narrow phase's general functions only (reference mode).
  void addContactsPlainly(std::uint32_t shapeA, std::uint32_t shapeB);
  void findBorderContacts(bool reuse);
  /// The pairs of border @p border with the grid shapes @p first + i for each bit i of @p bits
  /// (shapes in its reach): reused if @p reuse (the border's reach is remembered) and neither
  /// shape moved, else detected.
  void addBorderPairs(std::uint32_t border, std::size_t first, std::uint64_t bits, bool reuse);
  /// Border @p k's reach bits over @p words words of shapes: every shape's retested if the
  /// border moved, else the moved shapes'.
  void findBorderReach(std::size_t k, std::size_t words, bool borderMoved);
  /// findBorderReach for all borders at once, none of which moved; false (nothing done) when
  /// a border moved or there are more than a few.
  bool findBorderReachTogether(std::size_t words);
  /// Puts the pair's shapes in the narrow phase's order (the lower ShapeType first); false if
  /// they may not touch (both fixed, one collision group, or parts of one body kept apart).
  bool orderAndFilter(std::uint32_t& shapeA, std::uint32_t& shapeB) const;
  /// The speculative margin of a pair in that order: a half-plane takes its shape's, two shapes
  /// the smaller, and both add what they travelled in the last step.
  real pairMargin(std::uint32_t shapeA, std::uint32_t shapeB) const;
  void addContacts(std::uint32_t shapeA, std::uint32_t shapeB);
  /// Two circles that addContacts would test exactly, as it would (A first).
  /// Plain numbers, no Vector2: a batch on the stack is then not zeroed at every detection
  /// (which cost a small world 9% of its step).
  struct CirclePair {
    real centreAx;
    real centreAy;
    real centreBx;
    real centreBy;
    real radiusA;
    real radiusB;
    real margin;
    std::uint32_t shapeA;
    std::uint32_t shapeB;
  };
  static constexpr std::size_t circleBatch = 64;  // CirclePairs kept before they are tested
  /// addContacts' tests for two circles before the exact one (whether shapes of one body
  /// may touch is settled by the caller); true if it is to be run. @p pair is filled then, and
  /// also when only the distance rules the pair out (so a caller may keep it without a branch).
  bool circlesInReach(std::uint32_t shapeA, std::uint32_t shapeB, CirclePair& pair) const;
  /// addContacts' exact test and contacts for each of @p pairs, in order.
  void addCirclePairs(std::span<const CirclePair> pairs);
  /// Appends a contact of shapes @p shapeA and @p shapeB per point of @p manifold.
  void appendContacts(std::uint32_t shapeA, std::uint32_t shapeB, const Manifold& manifold);
  /// Appends the contact of shapes @p shapeA and @p shapeB at @p point along @p normal (the
  /// caller notes it: noteContactPair()).
  void appendContact(std::uint32_t shapeA, std::uint32_t shapeB, const ManifoldPoint& point,
                     Vector2 normal);
  /// Appends the last detection's contacts of shapes @p shapeA and @p shapeB, of two bodies,
  /// shape A the one addContacts() would take first (rest skipping: neither moved), to the
  /// run of reused contacts (flushReused() appends it to `contacts`).
  void reusePair(std::uint32_t shapeA, std::uint32_t shapeB);
  /// Appends the run of reused contacts, previousContacts_[reusedBegin_, reusedEnd_), to
  /// `contacts` (before any other contact is appended, and when the detection ends).
  void flushReused();
  /// flushReused() for a run of at least one contact.
  void appendReused();
  std::uint32_t reusedBegin_ = 0;
  std::uint32_t reusedEnd_ = 0;
  void indexPreviousContacts();
  // Each contact's pair as detection appended it, and, in a list longer than
  // scannedListLength, the pairs of each shape A chained in list order (noteContactPair(),
  // chainFirstPairs()): the next step finds a pair's contacts from them without sorting the
  // list (a short list is scanned). Kept for `contacts` and, swapped with it, for
  // previousContacts_.
  struct ContactPair {
    std::uint64_t key;      // pairKey()
    std::uint32_t nextOfA;  // first contact of the next pair with the same shape A, or noPair
  };
  static constexpr std::uint32_t noPair = ~0u;
  /// A pair of shapes as one number, ordered by shape A, then shape B.
  static std::uint64_t pairKey(std::uint32_t shapeA, std::uint32_t shapeB) {
    return std::uint64_t{shapeA} << 32 | shapeB;
  }
  struct PairChain {          // one shape's pairs as shape A in one list
    std::uint32_t first = 0;  // first contact of its first pair
    std::uint32_t last = 0;   // first contact of its last pair
    // Its pair count, and in the top two bits, once looked at (sortedRun()): 1 when its
    // contacts are consecutive in the list, by increasing shape B (a border's: its pairs are
    // visited in the shapes' order), 2 when not.
    std::uint32_t pairsAndRun = 0;
    std::uint32_t stamp = 0;  // the list's stamp when valid
  };
  /// Notes, for the next step's lookups by pair (SimulatorPreviousContacts.cpp), the contact at
  /// @p position in `contacts`, of shapes @p shapeA and @p shapeB (@p first: its pair's first
  /// point), in @p notes (from notesFor()).
  void noteContactPair(ContactPair* notes, std::uint32_t position, std::uint32_t shapeA,
                       std::uint32_t shapeB, bool first);
  /// noteContactPair()'s chaining of a pair's first contact, at @p position (from
  /// scannedListLength on).
  void chainPair(ContactPair* notes, std::uint32_t position, std::uint32_t shapeA);
  /// A list of up to this many contacts has no chains (its lookups scan it); a longer one
  /// has its first pairs chained when its detection ends.
  static constexpr std::size_t scannedListLength = 16;
  /// Chains the pairs of this detection (from position @p start) that chainPair() left out.
  void chainFirstPairs(std::uint32_t start);
  /// The notes of `contacts`, with room for @p count contacts.
  ContactPair* notesFor(std::size_t count);
  /// Positions [begin, end) in previousContacts_: a pair's contacts, consecutive in a list.
  struct PreviousRange {
    std::uint32_t begin;
    std::uint32_t end;
  };
  /// Where in previousContacts_ the last step's contacts between @p shapeA and @p shapeB
  /// are (in their order of detection).
  PreviousRange previousContactsOf(std::uint32_t shapeA, std::uint32_t shapeB) {
    // Inline: pairs come in nearly the last step's order, so the pair's contacts usually
    // begin where the last pair's ended (a pair's contacts are consecutive; the cursor is
    // 0 or the end of a pair's, so a pair found there begins there). Else a search.
    const std::uint64_t key = pairKey(shapeA, shapeB);
    const ContactPair* const list = previousPairs_.data();
    const std::size_t count = previousCount_;
    std::size_t first = previousCursor_;
    std::size_t last = first + 1;  // (past the contact found at the cursor)
    if (!(first < count && list[first].key == key)) {
      first = findPreviousPair(key, shapeA);
      last = first;
    }
    while (last < count && list[last].key == key) ++last;
    // (A pair in reach without contacts leaves the cursor where the next pair's may begin.)
    if (last != first) previousCursor_ = last;
    return {static_cast<std::uint32_t>(first), static_cast<std::uint32_t>(last)};
  }
  /// previousContactsOf() when the pair's contacts do not begin at previousCursor_: the
  /// first of them, or previousContacts_.size() if none.
  std::size_t findPreviousPair(std::uint64_t key, std::uint32_t shapeA);
  /// Whether @p chain, shape @p shapeA's in previousContacts_, is a sorted run (PairChain);
  /// the answer is kept in the chain.
  bool sortedRun(PairChain& chain, std::uint32_t shapeA);
  /// Advances listStamp_ for a new detection.
  void nextListStamp();
  /// The force the last step's contact with @p contact's identity (shapes and feature) ended
  /// with, or 0, when it is not at the warm start's first guess @p hint (solveContacts(): the
  /// contact after the last found). Looks just after and before the guess, at @p position,
  /// @p contact's own place in `contacts`, then searches; @p hint is left just past the
  /// contact found (or unchanged).
  [[nodiscard]] real searchPreviousForce(const GlobalContactInfo& contact, std::size_t position,
                                         std::size_t& hint);
  void clearContactLists();
  /// Solves @p island, a rigid island one of whose contacts does not hold without force.
  void solveIsland(std::span<const std::uint32_t> island);
  /// solveContacts() once: @return true if it stopped short, its velocities carrying a shape
  /// past a border unseen (only if @p mayRedetect), leaving the objects' free velocities.
  bool solveOnce(bool mayRedetect);
  /// solveOnce() with the rows of every contact, or (@p filtered) without those of contacts
  /// between bodies at rest that hold at zero velocities; @p partial is set, and nothing
  /// written, when an island of a filtered pass needs a force and reaches a body at rest
  /// (which is then woken).
  bool solvePass(bool mayRedetect, bool filtered, bool& partial);
  /// The most filtered passes of one solve (solveOnce()), each waking more bodies at rest.
  static constexpr int maxRestPasses = 4;
  std::vector<std::uint32_t> activeRows_;  // a filtered pass's rows' contacts, by row
  bool rowsFiltered_ = false;              // rows_ are a filtered pass's (row k: activeRows_[k])
  /// The length of the step or substep being solved: timestep() but within stepInParts().
  [[nodiscard]] real solveStep() const { return substep_ > 0 ? substep_ : timestep(); }
  void solveGeneralIsland(std::span<const std::uint32_t> island);
  /// Shape @p shape is a circle that is its own body (not a part of a composed body): its
  /// contacts' normals go through its centre. Reads the shape table, not the objects.
  [[nodiscard]] bool centredCircle(std::uint32_t shape, const Primitive* primitive,
                                   const PhysicalObject* object) const {
    return shapes_[shape].type == ShapeType::Circle && primitive == object;
  }
  [[nodiscard]] bool movable(std::uint32_t body) const {
    return multiBodies_[body] != nullptr || !objects[body].fixed;
  }
  void updateTactileSensors();
  // SimulatorContainment.cpp: whether this step's velocities carry an end of a shape past a
  // border it was out of reach of at detection: the solve's (bodies_) for the @p moved bodies,
  // the free ones for every other movable body (those the last solve did not touch: its stamp
  // is not theirs); the detection again, with margins that cover this step's motion.
  [[nodiscard]] bool outranMargins(std::span<const std::uint32_t> moved) const;
  // outranMargins() of a solve that built no row: no call when no body moves otherwise than
  // the field and there is none.
  [[nodiscard]] bool freeMotionOutranMargins() const {
    return (!freeRunners_.empty() || hasGravity_) && outranMargins({});
  }
  // Lists @p object in freeRunners_ if its free velocity (pushed, or its own hook's) may move
  // a point of it farther than the least margin in the step.
  void noteFreeMotion(const PhysicalObject& object);
  // Whether an end of a shape of @p body, moving at @p v, @p omega, crosses such a border.
  [[nodiscard]] bool endsOutranMargins(std::uint32_t body, Vector2 v, real omega) const;
  [[nodiscard]] bool crossesUnseenBorder(std::uint32_t shape, Vector2 end, Vector2 displacement,
                                         real reach) const;
  void widenMargins();
  void redetect();
  // After Gauss-Seidel: the bodies of @p island whose wall contacts it left violated by more
  // than their margin in the step get those contacts solved alone (holdAtWalls()).
  void holdWalls(std::span<const std::uint32_t> island);
  void holdAtWalls(std::span<const std::uint32_t> island, std::uint32_t body);
  // Into how many equal parts this solve's motion (bodies_) of the @p moved bodies must be
  // divided so that no point of a shape moves farther than half its radius in one; 1 if none
  // moves farther than its radius.
  [[nodiscard]] std::uint32_t partsNeeded(std::span<const std::uint32_t> moved) const;
  // Phases 2, 6 and 8 again in parts_ equal substeps from the free velocities, each divided
  // further where its solve asks, up to maxSubsteps in all; phase 3 after the last.
  void stepInParts();
  [[nodiscard]] static bool immovable(const SolverBody& body) {
    return body.inverseMass == 0 && body.inverseInertia == 0;
  }
  /// Throws InvalidArgument for the first object whose pose or accumulators are not finite.
  void checkFinite() const;
  /// The make-up a state must have been saved from: object types and shapes, a line each.
  [[nodiscard]] std::string makeUp() const;
  /// restoreState() once the make-up is known to match (may throw half-way).
  void applyState(const WorldState& state);
  /// Makes @p list this step's contacts, as a detection (@p complete) and a solve (@p solved)
  /// would have left them, with the notes the next step's lookups by pair read.
  void restoreContacts(std::vector<GlobalContactInfo> list, bool complete, bool solved);

  std::unique_ptr<Integrator> integrator_;  // never null
  bool eulerIntegrator_ = true;             // integrator_ is exactly Integrator: its fast loop
  Vector2 gravity_;                         // no component -0 (setGravity())
  bool hasGravity_ = false;                 // gravity_ is not {0, 0}
  ContactSolverKind solverKind_ = ContactSolverKind::Baraff;
  ContactSolverSettings settings_;
  StepStatistics statistics_;

  std::vector<Shape> shapes_;
  std::vector<ShapeGeometry> geometry_;
  std::vector<std::uint32_t> borderShapes_;    // half-planes: tested against every shape
  std::vector<std::uint32_t> gridShapes_;      // the others, in the broad phase
  std::vector<Primitive*> sensingPrimitives_;  // primitives with tactile sensors, this step
  std::vector<BoundingBox> gridBoxes_;
  std::vector<BoxPair> pairs_;
  BroadPhase broadPhase_;
  // Rest skipping (SimulatorContacts.cpp): what the last detection saw.
  std::vector<BodyState> bodyStates_;
  std::vector<ShapePose> shapePoses_;
  std::vector<std::uint8_t> shapeMoved_;      // per shape: geometry recomputed this detection
  std::vector<std::uint32_t> gridSlot_;       // per shape: its index in gridShapes_
  std::vector<std::uint64_t> gridMovedBits_;  // a bit per grid shape: moved this detection
  std::vector<std::uint64_t> borderReach_;    // per border, a bit per grid shape behind it
  std::vector<std::uint32_t> pendingBodies_;  // updateGeometry: bodies for its second loop
  // The sweep's extents of grid slots 0 to gridExtentsCount_ - 1, gathered in slot order by
  // updateGeometry as it computed their boxes (runs of links): the broad phase's when they
  // cover every grid shape.
  SweepAndPrune::Extents gridExtents_;
  std::uint32_t gridExtentsCount_ = 0;
  /// Adds the grid boxes from slot gridExtentsCount_ to @p slot - 1 to gridExtents_.
  void gatherExtentsUpTo(std::uint32_t slot);
  std::size_t reachShapes_ = 0;  // grid shapes borderReach_ was computed for
  // Pairs of one body's shapes that never touch, which the broad phase's sweep leaves out
  // (updateNeverPaired(), SimulatorContacts.cpp).
  struct NeverPaired {
    std::vector<std::uint64_t> bits;  // per grid shape, or none while no body has two
    std::size_t objects = 0;          // the objects the bits cover (registration appends)
    // The multi-body objects' indices, with the SelfCollisionFilter::stamp() the bits follow.
    std::vector<std::pair<std::uint32_t, std::uint64_t>> rules;
  };
  NeverPaired neverPaired_;
  void updateNeverPaired();
  void markNeverPaired(std::uint32_t body);
  std::vector<GlobalContactInfo> previousContacts_;  // the last detection's contacts
  // The pairs noted for `contacts` and, swapped with it, for previousContacts_ (as many as
  // the list's contacts are valid: the buffers only grow).
  std::vector<ContactPair> contactPairs_;
  std::vector<ContactPair> previousPairs_;
  std::vector<PairChain> pairChains_;
  std::vector<PairChain> previousChains_;
  std::uint32_t listStamp_ = 0;          // of the detection appending to `contacts`
  std::uint32_t previousListStamp_ = 0;  // of previousContacts_'s detection
  // A shape with many pairs whose contacts are not one sorted run (PairChain) is looked up in
  // an index built when first needed: a counting sort by shape A, then B for large groups.
  std::vector<std::uint32_t> previousStart_;       // counting sort by shape A: offsets
  std::vector<std::uint32_t> previousOrder_;       // by shape A (then B if many): positions
  std::vector<std::uint64_t> previousSortedKeys_;  // each previousOrder_ entry's shapes, A then B
  std::size_t previousCursor_ = 0;                 // previousContacts_ after the last pair found
  // previousContacts_.size() as of the last detection (no contact to look up before one): a
  // lookup's bound without a division by the size of a contact.
  std::size_t previousCount_ = 0;
  real geometryFraction_ = 0;      // speculativeFraction the cached margins were computed with
  real geometryTravel_ = 0;        // speculativeTravel the cached travels were computed with
  bool contactsComplete_ = false;  // `contacts` holds exactly one detection's contacts
  bool previousValid_ = false;     // previousContacts_ is the last detection's, complete
  bool previousIndexed_ = false;   // previousOrder_ and previousSortedKeys_ are up to date
  bool contactsSolved_ = false;    // the solver wrote the forces of `contacts`
  bool previousSolved_ = false;    // previousContacts_ carries its solve's forces (warm start)
  // Core shapes only (no object's own hooks, no articulated agent): nothing between the
  // phases reads or moves the objects, so a step may be divided (stepInParts()).
  bool listsAfterSolve() const { return customObjects_.empty() && !hasMultiBodies_; }
  // The objects that do not keep PhysicalObject's step hooks, in registration order (the
  // others' hooks are called without virtual calls).
  std::vector<std::uint32_t> customObjects_;

  std::vector<ContactInfo> objectContacts_;  // every object's contacts, object by object
  // Each object's contacts are counted as detection appends them (countContact()), each
  // object listed at its first: indexContacts() then needs no pass of its own to count.
  // objectContactCursor_ is zero for every object in neither countedObjects_ nor
  // listedObjects_ (outside indexContacts): a listed object's cursor is zeroed as its list
  // is cleared (clearContactLists(), before any counting: eraseContacts() and
  // indexContacts() clear the lists first).
  std::vector<std::uint32_t> objectContactCursor_;  // per object: its count, then a cursor
  std::vector<std::uint32_t> countedObjects_;       // the first countedCount_ have counts
  std::size_t countedCount_ = 0;  // (std::size_t: no alias of the uint32 entries it indexes)
  bool countsComplete_ = true;    // every contact of `contacts` is counted
  std::vector<std::uint32_t> listedObjects_;  // the first listedCount_ have `contacts` not empty
  std::size_t listedCount_ = 0;
  // The lists do not follow `contacts` (changed by a detection since): the first read of a list
  // (listContacts()) indexes them.
  bool listsPending_ = false;
  // The contacts were detected here (bodyStates_ holds the poses they were detected at), not
  // restored (their bodies' poses are then the objects' own).
  bool originsDetected_ = true;
  void listContacts() override;
  /// Counts a contact of bodies @p bodyA and @p bodyB (countedObjects_ has room for every
  /// object and one more).
  void countContact(std::uint32_t bodyA, std::uint32_t bodyB);
  /// Zeroes the counts, and sizes countedObjects_ for the objects.
  void resetCounts();
  /// Sizes countedObjects_ for the objects (one more than there are), if they grew.
  void fitCountedObjects() {
    if (countedObjects_.size() < objects.size() + 1) growCountedObjects();
  }
  void growCountedObjects();

  std::vector<SolverBody> bodies_;  // valid for the bodies of this step's rows only
  std::vector<std::uint8_t> movable_;
  std::vector<std::uint32_t> touched_;       // bodies of this step's rows (movable rigid first)
  std::vector<std::uint64_t> touchedStamp_;  // stamp_ when a row last touched a body
  std::uint64_t stamp_ = 0;
  std::vector<ContactConstraint> rows_;
  Islands islands_;
  BaraffSolver baraff_;
  GaussSeidelSolver gaussSeidel_;

  // Multi-body objects (articulated agents): their islands are solved on an explicit matrix.
  std::vector<MultiBodyObject*> multiBodies_;  // per object, null for a rigid body
  bool hasMultiBodies_ = false;
  std::vector<MultiBodyObject::InternalConstraint> internal_;  // this step's joint limits
  std::vector<std::uint32_t> internalOwner_;                   // their objects
  struct Side {  // one multi-body side of a row of a general island
    std::uint32_t owner;
    std::uint32_t row;  // position in the island
    MultiBodyObject::UnitForce force;
  };
  std::vector<Side> sides_;
  std::vector<std::uint32_t> sideOrder_;  // sides_ sorted by owner
  std::vector<MultiBodyObject::UnitForce> ownerForces_;
  std::vector<real> ownerMagnitudes_;
  std::vector<std::uint32_t> ownerRows_;
  std::vector<real> denseMatrix_;
  std::vector<real> denseSlack_;
  std::vector<real> denseForces_;
  std::vector<real> response_;

  // Rest (advanceTime()): the bodies awake in this step, in registration order, then those
  // the solve set moving; the rest keep v = 0 and no pending force, so phases 5 and 8 would
  // leave them as they are. Listed by updateGeometry as it compares the bodies.
  std::vector<std::uint32_t> awake_;
  std::size_t awakeCount_ = 0;
  std::vector<std::uint64_t> awakeStamp_;  // per body: awakeNow_ while listed in awake_
  std::uint64_t awakeNow_ = 0;
  std::size_t registrationFirst_ = 0;  // the object registered first of those being registered
  // awake_ is this step's and phases 5 and 8 may keep to it (no gravity field: a body at
  // rest in one is pushed by its weight; nor when every body was updated anyway).
  bool awakeValid_ = false;
  bool stepping_ = false;  // within advanceTime()
  /// Lists body @p index in awake_ unless it is already.
  void listAwake(std::uint32_t index) {
    if (awakeStamp_[index] == awakeNow_) return;
    awakeStamp_[index] = awakeNow_;
    awake_[awakeCount_++] = index;
  }
  /// The index of @p object in `objects`, or objects.size() if it is not registered here.
  [[nodiscard]] std::size_t indexOf(const PhysicalObject& object) const;
  /// Phase 5 for the bodies of awake_ only (the others' hooks would change nothing).
  void computeAwakeDerivatives();
  /// Phase 8 (explicit Euler) for the bodies of awake_ only.
  void integrateAwake(real dt);

  PhysicalObject* dragged_ = nullptr;
  std::uint32_t draggedIndex_ = 0;  // its index in objects
  real dragMaxStep_ = 0;            // metres per step, from the dragged body's size
  Vector2 dragLocalPoint_;
  Vector2 dragTarget_;

  // Containment (SimulatorContainment.cpp), read off the common path: kept last, after the
  // members every step reads.
  // The most detections solveContacts() runs again in one step (each widens the margins to four
  // times the motion of the last solve, which the new contacts mostly slow down).
  static constexpr std::size_t maxRedetections = 4;
  bool widening_ = false;  // this detection recomputes every shape, with widenMargins()' margins
  bool marginsWidened_ = false;  // the margins are widenMargins()': the next detection resets them
  real smallestRadius_ = realMax;  // of the shapes other than borders registered so far
  // This step's bodies whose free velocity is not the field's and may move a point farther
  // than the least margin (noteFreeMotion()).
  std::vector<std::uint32_t> freeRunners_;
  // The most substeps a step is divided into (stepInParts()).
  static constexpr std::uint32_t maxSubsteps = 64;
  bool mayDivide_ = false;   // the solve may ask for the step to be divided (advanceTime())
  std::uint32_t parts_ = 1;  // the substeps the last solve asked for (1: none)
  real substep_ = 0;         // the substep being run, 0 outside stepInParts()
  struct StepStart {         // an object's pose and free velocities at the start of a divided step
    Vector2 r;
    real alpha = 0;
    Vector2 v;
    real omega = 0;
  };
  std::vector<StepStart> stepStarts_;  // every object's, saved for the substeps
};

}  // namespace thyrix
