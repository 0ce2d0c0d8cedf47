// The simulator as a whole: determinism, piles without overlap, mouse dragging, and the
// bookkeeping of contacts between the global list and the objects' lists.

#include "TestTolerances.h"
#include "support/SolverCases.h"

#include <Scenes.h>
#include <ThyrixLite/Border.h>
#include <ThyrixLite/CappedRectangle.h>
#include <ThyrixLite/Circle.h>
#include <ThyrixLite/Simulator.h>
#include <Tools/MTRandom.h>

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <span>
#include <vector>

namespace thyrix {
namespace {

using test::solverName;

/// 30 bodies (circles and capsules, radii 0.2 to 0.3) on a loose grid without overlap in a
/// 6 x 6 box.
std::vector<PhysicalObject*> addCornerPile(Simulator& simulator, std::uint32_t seed) {
  MTRandom random(seed);
  scenes::addWalls(simulator, 6, 6);
  std::vector<PhysicalObject*> bodies;
  for (int i = 0; i < 30; ++i) {
    PhysicalObject* body;
    if (i % 4 == 3)
      body = &simulator.registerObject(
          std::make_unique<CappedRectangle>(real(0.3), real(0.2), real(1.5)));
    else
      body = &simulator.registerObject(std::make_unique<Circle>(
          static_cast<real>(random.uniform(0.2, 0.3)), static_cast<real>(random.uniform(0.5, 2))));
    body->r = {real(0.8) + real(0.95) * static_cast<real>(i % 5),
               real(0.5) + real(0.95) * static_cast<real>(i / 5)};
    body->alpha = static_cast<real>(random.uniform(-1.5, 1.5));
    bodies.push_back(body);
  }
  return bodies;
}

class SimulatorTest : public ::testing::TestWithParam<ContactSolverKind> {};

TEST_P(SimulatorTest, SameSceneGivesBitIdenticalRuns) {
  std::uint64_t hashes[2];
  for (std::uint64_t& hash : hashes) {
    Simulator simulator;
    simulator.setContactSolver(GetParam());
    const auto bodies = addCornerPile(simulator, 7);
    MTRandom random(3);
    for (int step = 0; step < 500; ++step) {
      for (PhysicalObject* body : bodies)
        body->externalForce = {static_cast<real>(random.uniform(-2, 2)),
                               static_cast<real>(random.uniform(-2, 2))};
      simulator.advanceTime();
    }
    hash = scenes::stateHash(simulator);
  }
  EXPECT_EQ(hashes[0], hashes[1]);
}

TEST_P(SimulatorTest, PilePushedIntoCornerNeverOverlapsBeyondTolerance) {
  Simulator simulator;
  simulator.setContactSolver(GetParam());
  const auto bodies = addCornerPile(simulator, 11);
  // A free body moves at 1 m/s: 5% of the smallest radius per step. Overlap then comes only
  // from the first-order error of sliding around curved surfaces, which the correction bounds.
  real worst = 0;
  for (int step = 0; step < 2000; ++step) {
    scenes::push(bodies, {real(-0.6), real(-0.8)});
    simulator.advanceTime();
    worst = std::max(worst, scenes::largestOverlap(simulator));
  }
  // The smallest radius is 0.2: overlap stays under 1% of it.
  EXPECT_LT(worst, real(0.002));
  // And the pile is packed into the corner: everyone moved down-left and stopped.
  for (PhysicalObject* body : bodies) {
    EXPECT_LT(body->v.length(), real(0.05));
    EXPECT_GE(body->boxMin.x, -real(0.002));
    EXPECT_GE(body->boxMin.y, -real(0.002));
  }
}

TEST_P(SimulatorTest, DragPullsBodyToMouseAndStopsOnRelease) {
  Simulator simulator;
  simulator.setContactSolver(GetParam());
  auto& capsule =
      simulator.registerObject(std::make_unique<CappedRectangle>(real(1), real(0.2), real(2)));
  const Vector2 grab{real(0.8), 0};  // near one end: pulling turns the body too
  simulator.startDrag(capsule, grab);
  const Vector2 mouse{3, 2};
  simulator.dragTo(mouse);
  for (int step = 0; step < 400; ++step) simulator.advanceTime();
  const Vector2 grabbedNow = capsule.toWorld(Vector2{real(0.8), 0});
  EXPECT_LT(distance(grabbedNow, mouse), real(1e-3));
  simulator.stopDrag();
  EXPECT_EQ(simulator.draggedObject(), nullptr);
  const Vector2 released = capsule.r;
  simulator.advanceTime();
  EXPECT_EQ(capsule.v, Vector2{});
  EXPECT_EQ(capsule.omega, 0);
  EXPECT_EQ(capsule.r, released);
}

TEST_P(SimulatorTest, DraggedBodyPushesOthersAndIsStoppedByBorders) {
  Simulator simulator;
  simulator.setContactSolver(GetParam());
  simulator.registerObject(std::make_unique<Border>(Vector2{5, 0}, Vector2{-1, 0}));
  auto& dragged = simulator.registerObject(std::make_unique<Circle>(real(0.5), real(1)));
  auto& pushed = simulator.registerObject(std::make_unique<Circle>(real(0.5), real(1)));
  pushed.r = {real(1.5), 0};
  simulator.startDrag(dragged, {0, 0});
  simulator.dragTo({10, 0});  // beyond the wall at x = 5
  for (int step = 0; step < 1000; ++step) simulator.advanceTime();
  EXPECT_NEAR(pushed.r.x, real(4.5), real(0.01)) << "pushed against the wall";
  EXPECT_NEAR(dragged.r.x, real(3.5), real(0.01)) << "held off by the pushed circle";
}

TEST_P(SimulatorTest, ContactsAreIndexedInBothObjectsWithOpposedNormalsAndForces) {
  Simulator simulator;
  simulator.setContactSolver(GetParam());
  const auto bodies = addCornerPile(simulator, 5);
  for (int step = 0; step < 300; ++step) {
    scenes::push(bodies, {-1, -1});
    simulator.advanceTime();
  }
  ASSERT_FALSE(simulator.contacts.empty());
  std::size_t listed = 0;
  for (const PhysicalObject& object : simulator.objects) {
    for (const ContactInfo& info : object.contacts()) {
      ++listed;
      const GlobalContactInfo& global = simulator.contacts[info.index];
      ASSERT_TRUE(global.objectA == &object || global.objectB == &object);
      const bool isA = global.objectA == &object;
      EXPECT_EQ(info.other, isA ? global.objectB : global.objectA);
      EXPECT_EQ(info.normal, isA ? -global.normal : global.normal);
      EXPECT_EQ(info.force, global.force);
      EXPECT_EQ(info.point, global.point);
    }
  }
  EXPECT_EQ(listed, 2 * simulator.contacts.size());
  // The quasistatic law holds per body with the contact forces: push + contacts = D u.
  for (PhysicalObject* body : bodies) {
    Vector2 net = Vector2{-1, -1} * body->m;
    real torque = 0;
    const Vector2 centreWhenSolved = body->r - body->v * simulator.timestep();
    for (const ContactInfo& info : body->contacts()) {
      net += info.normal * info.force;
      torque += cross(info.point - centreWhenSolved, info.normal * info.force);
    }
    const real tolerance = test::isFloat ? real(1e-3) : real(1e-6);
    EXPECT_NEAR(net.x, body->m * body->v.x, tolerance);
    EXPECT_NEAR(net.y, body->m * body->v.y, tolerance);
    EXPECT_NEAR(torque, body->I * body->omega, tolerance);
  }
}

/// Each object's `contacts` lists, in order, every contact of `simulator.contacts` it is in
/// (once per side), as seen from its side.
void expectContactListsMatch(const Simulator& simulator) {
  for (std::size_t i = 0; i < simulator.objects.size(); ++i) {
    const PhysicalObject& object = simulator.objects[i];
    std::size_t next = 0;
    for (std::uint32_t k = 0; k < simulator.contacts.size(); ++k) {
      const GlobalContactInfo& global = simulator.contacts[k];
      for (const bool sideA : {true, false}) {
        if ((sideA ? global.bodyA : global.bodyB) != i) continue;
        ASSERT_LT(next, object.contacts().size()) << "object " << i << ", contact " << k;
        const ContactInfo& info = object.contacts()[next++];
        EXPECT_EQ(info.index, k);
        EXPECT_EQ(info.other, sideA ? global.objectB : global.objectA);
        EXPECT_EQ(info.primitive, sideA ? global.primitiveA : global.primitiveB);
        EXPECT_EQ(info.normal, sideA ? -global.normal : global.normal);
      }
    }
    EXPECT_EQ(next, object.contacts().size()) << "object " << i;
  }
}

// The objects' lists follow the contacts whatever phases a program runs by hand: detection
// counts each object's contacts as it appends them, for indexContacts.
TEST(Simulator, ContactListsFollowThePhasesRunByHand) {
  Simulator simulator;
  const auto bodies = addCornerPile(simulator, 7);
  for (int step = 0; step < 100; ++step) {
    scenes::push(bodies, {-1, -1});
    simulator.advanceTime();
  }
  expectContactListsMatch(simulator);
  simulator.indexContacts();  // again: the same lists
  expectContactListsMatch(simulator);
  const std::size_t before = simulator.contacts.size();
  ASSERT_GT(before, 10u);
  simulator.detectContacts();  // appended to the list (most contacts twice)
  EXPECT_GT(simulator.contacts.size(), before);
  simulator.indexContacts();
  expectContactListsMatch(simulator);
  simulator.eraseContacts();
  for (const PhysicalObject& object : simulator.objects) EXPECT_TRUE(object.contacts().empty());
  simulator.detectContacts();  // detected, not indexed, erased: nothing left of its counts
  simulator.eraseContacts();
  simulator.detectContacts();
  simulator.indexContacts();
  expectContactListsMatch(simulator);
  // An object registered between detection and indexing, touching one already there.
  simulator.eraseContacts();
  simulator.detectContacts();
  auto& added = simulator.registerObject(std::make_unique<Circle>(real(0.3), real(1)));
  added.r = bodies[0]->r;
  simulator.indexContacts();
  expectContactListsMatch(simulator);
  simulator.detectContacts();
  simulator.indexContacts();
  expectContactListsMatch(simulator);
  EXPECT_FALSE(added.contacts().empty());
  for (int step = 0; step < 5; ++step) simulator.advanceTime();
  expectContactListsMatch(simulator);
}

/// One step of @p simulator through its public phases, in the users' guide's order.
void stepByHand(Simulator& simulator) {
  simulator.eraseContacts();
  simulator.detectContacts();
  simulator.indexContacts();
  simulator.applyMouseForce();
  simulator.computeDerivativesWithoutContacts();
  simulator.solveContacts();
  for (PhysicalObject& object : simulator.objects) object.control();
  simulator.integrator().integrate(simulator, simulator.timestep());
}

// In a world of core shapes, advanceTime() lists the contacts after the solve: the objects
// and their lists end each step as with the phases run by hand in their documented order.
// (The pile starts in deep overlaps, which its first step, moving shapes farther than their
// radius, runs in substeps: the phases by hand never divide a step, so that step is run by
// advanceTime() in both, and every later one must be undivided.)
TEST_P(SimulatorTest, AdvanceTimeEndsAsThePhasesInOrder) {
  Simulator stepped;
  Simulator byHand;
  for (Simulator* simulator : {&stepped, &byHand}) {
    simulator->setContactSolver(GetParam());
    simulator->setGravity({0, -1});
  }
  const auto bodies = scenes::addMixedPile(stepped, 80, 5);
  const auto handBodies = scenes::addMixedPile(byHand, 80, 5);
  stepped.advanceTime();
  byHand.advanceTime();
  for (int step = 1; step < 200; ++step) {
    scenes::push(bodies, {-1, 0});
    scenes::push(handBodies, {-1, 0});
    stepped.advanceTime();
    ASSERT_EQ(stepped.statistics().substeps, 1u) << "step " << step;
    stepByHand(byHand);
  }
  ASSERT_GE(stepped.contacts.size(), 64u);
  ASSERT_EQ(stepped.objects.size(), byHand.objects.size());
  for (std::size_t i = 0; i < stepped.objects.size(); ++i) {
    const PhysicalObject& a = stepped.objects[i];
    const PhysicalObject& b = byHand.objects[i];
    EXPECT_EQ(a.r, b.r) << "object " << i;
    EXPECT_EQ(a.v, b.v) << "object " << i;
    ASSERT_EQ(a.contacts().size(), b.contacts().size()) << "object " << i;
    for (std::size_t j = 0; j < a.contacts().size(); ++j) {
      const ContactInfo& x = a.contacts()[j];
      const ContactInfo& y = b.contacts()[j];
      EXPECT_EQ(x.index, y.index);
      EXPECT_EQ(x.point, y.point);
      EXPECT_EQ(x.normal, y.normal);
      EXPECT_EQ(x.depth, y.depth);
      EXPECT_EQ(x.force, y.force);
    }
  }
  expectContactListsMatch(stepped);
}

/// Expects the contact lists of @p a and @p b, worlds of the same scene, equal in every field
/// (the objects and primitives compared by their positions in their worlds).
void expectSameContactLists(const Simulator& a, const Simulator& b) {
  const auto position = [](const Simulator& simulator, const PhysicalObject* object) {
    for (std::size_t i = 0; i < simulator.objects.size(); ++i)
      if (&simulator.objects[i] == object) return i;
    return simulator.objects.size();
  };
  ASSERT_EQ(a.objects.size(), b.objects.size());
  for (std::size_t i = 0; i < a.objects.size(); ++i) {
    const std::span<ContactInfo> x = a.objects[i].contacts();
    const std::span<ContactInfo> y = b.objects[i].contacts();
    ASSERT_EQ(x.size(), y.size()) << "object " << i;
    for (std::size_t j = 0; j < x.size(); ++j) {
      EXPECT_EQ(x[j].index, y[j].index);
      EXPECT_EQ(position(a, x[j].other), position(b, y[j].other));
      EXPECT_EQ(position(a, x[j].primitive), position(b, y[j].primitive));
      EXPECT_EQ(position(a, x[j].otherPrimitive), position(b, y[j].otherPrimitive));
      EXPECT_EQ(x[j].p, y[j].p) << "object " << i << ", contact " << j;
      EXPECT_EQ(x[j].point, y[j].point);
      EXPECT_EQ(x[j].n, y[j].n);
      EXPECT_EQ(x[j].sigma, y[j].sigma);
      EXPECT_EQ(x[j].normal, y[j].normal);
      EXPECT_EQ(x[j].depth, y[j].depth);
      EXPECT_EQ(x[j].force, y[j].force);
      EXPECT_EQ(x[j].type, y[j].type);
    }
  }
}

// advanceTime() lists the contacts only when a list is read: read after the step, when phase
// 8 has moved the bodies, the lists are those phase 3 gave in its place (the phases by hand),
// p relative to where each body was detected, not to where it went.
TEST_P(SimulatorTest, ListsReadAfterTheStepAreThoseOfPhaseThree) {
  Simulator stepped;
  Simulator byHand;
  for (Simulator* simulator : {&stepped, &byHand}) {
    simulator->setContactSolver(GetParam());
    simulator->setGravity({0, -1});
  }
  const auto bodies = scenes::addMixedPile(stepped, 80, 5);
  const auto handBodies = scenes::addMixedPile(byHand, 80, 5);
  stepped.advanceTime();  // (its deep overlaps are run in substeps: see the test above)
  byHand.advanceTime();
  std::size_t moved = 0;
  for (int step = 1; step < 100; ++step) {
    scenes::push(bodies, {-1, 0});
    scenes::push(handBodies, {-1, 0});
    stepped.advanceTime();
    ASSERT_EQ(stepped.statistics().substeps, 1u) << "step " << step;
    stepByHand(byHand);
    if (step % 33 != 0) continue;  // read now and then: each read lists that step's contacts
    expectSameContactLists(stepped, byHand);
    for (const PhysicalObject& object : stepped.objects)
      for (const ContactInfo& info : object.contacts())
        moved += info.p != info.point - object.r ? 1 : 0;  // (the same operation as phase 3's)
  }
  expectSameContactLists(stepped, byHand);
  EXPECT_GT(moved, 0u) << "no body moved after its detection: p's origin was not tested";
}

/// A circle whose hook reads its contacts before the solve, if told to.
class EarlyReader : public Circle {
 public:
  using Circle::Circle;
  bool reads = false;
  std::size_t seen = 0;  ///< contacts it saw (forces not yet solved)
  void computeDerivativesWithoutContacts() override {
    if (reads) seen += contacts().size();
    Circle::computeDerivativesWithoutContacts();
  }
};

// A list read by a hook before the solve is given the solve's forces: after the step, every
// list is the one a world whose hook reads nothing lists when read.
TEST_P(SimulatorTest, ListsReadBeforeTheSolveEndTheStepAsListsReadAfterIt) {
  Simulator reading;
  Simulator quiet;
  std::vector<EarlyReader*> readers;
  for (Simulator* simulator : {&reading, &quiet}) {
    simulator->setContactSolver(GetParam());
    addCornerPile(*simulator, 3);
    auto& reader = simulator->registerObject(std::make_unique<EarlyReader>(real(0.3), real(1)));
    reader.r = {real(5.4), real(5.4)};
    readers.push_back(&reader);
  }
  readers[0]->reads = true;
  for (int step = 0; step < 200; ++step) {
    for (EarlyReader* reader : readers) reader->externalForce = {-1, -1};
    reading.advanceTime();
    quiet.advanceTime();
    ASSERT_EQ(scenes::stateHash(reading), scenes::stateHash(quiet)) << "step " << step;
    if (step % 50 == 49) expectSameContactLists(reading, quiet);
  }
  EXPECT_GT(readers[0]->seen, 0u);
  real force = 0;
  for (const ContactInfo& info : readers[0]->contacts()) force += info.force;
  EXPECT_GT(force, 0) << "pushed into the pile";
}

/// A circle of radius 0.1 pushed onto a floor at 4 m/s (0.04 m, 40% of its radius, per step),
/// its heights chosen so that no step ends exactly on the floor: its largest overlap, and the
/// detections run again over its steps.
struct FastCircle {
  real overlap = 0;
  std::size_t redetections = 0;
};
FastCircle fastCircleOnFloor(ContactSolverKind solver, real speculativeTravel) {
  Simulator simulator(real(0.01));
  simulator.setContactSolver(solver);
  simulator.solverSettings().speculativeTravel = speculativeTravel;
  simulator.registerObject(std::make_unique<Border>(Vector2{0, 0}, Vector2{0, 1}));
  auto& circle = simulator.registerObject(std::make_unique<Circle>(real(0.1), real(1)));
  circle.r = {0, real(0.7234)};
  FastCircle result;
  for (int step = 0; step < 30; ++step) {
    circle.externalForce = {0, -4};
    simulator.advanceTime();
    result.overlap = std::max(result.overlap, real(0.1) - circle.r.y);
    result.redetections += simulator.statistics().redetections;
  }
  EXPECT_NEAR(circle.r.y, real(0.1), real(1e-3)) << "the circle rests on the floor";
  return result;
}

TEST_P(SimulatorTest, AFastBodyIsStoppedAtTheSurfaceByItsTravelMargin) {
  // Its margin grows by what it travelled in the last step, so the floor's contact is seen a
  // step before it would be crossed: no overlap at any step, and no detection run again.
  const FastCircle travelling = fastCircleOnFloor(GetParam(), 1);
  EXPECT_LT(travelling.overlap, test::isFloat ? real(1e-4) : real(1e-9));
  EXPECT_EQ(travelling.redetections, 0u);
  // With the narrow margin alone (10% of the radius) the floor is out of reach in the step that
  // would sink it in by 17% of its radius: the check of its free motion detects that step again,
  // and it stops at the surface all the same.
  const FastCircle narrow = fastCircleOnFloor(GetParam(), 0);
  EXPECT_LT(narrow.overlap, test::isFloat ? real(1e-4) : real(1e-9));
  EXPECT_GE(narrow.redetections, 1u);
}

INSTANTIATE_TEST_SUITE_P(BothSolvers, SimulatorTest,
                         ::testing::Values(ContactSolverKind::Baraff,
                                           ContactSolverKind::GaussSeidel),
                         solverName);

TEST(Simulator, ContactIdentityIsStableWhileTheSameFeaturesTouch) {
  Simulator simulator;
  simulator.registerObject(std::make_unique<Border>(Vector2{0, 0}, Vector2{0, 1}));
  auto& capsule =
      simulator.registerObject(std::make_unique<CappedRectangle>(real(1), real(0.2), real(1)));
  capsule.r = {0, real(0.2)};
  capsule.externalForce = {1, -1};
  simulator.advanceTime();
  ASSERT_EQ(simulator.contacts.size(), 2u);
  const auto first = simulator.contacts[0];
  const auto second = simulator.contacts[1];
  EXPECT_NE(first.feature, second.feature);
  for (int step = 0; step < 10; ++step) {
    capsule.externalForce = {1, -1};
    simulator.advanceTime();
    ASSERT_EQ(simulator.contacts.size(), 2u);
    EXPECT_EQ(simulator.contacts[0].shapeA, first.shapeA);
    EXPECT_EQ(simulator.contacts[0].shapeB, first.shapeB);
    EXPECT_EQ(simulator.contacts[0].feature, first.feature);
    EXPECT_EQ(simulator.contacts[1].feature, second.feature);
  }
}

TEST(Simulator, StepCountTimeAndTimestep) {
  Simulator simulator(real(0.02));
  EXPECT_EQ(simulator.timestep(), real(0.02));
  for (int i = 0; i < 5; ++i) simulator.advanceTime();
  EXPECT_EQ(simulator.stepCount(), 5u);
  EXPECT_NEAR(simulator.time(), 0.1, 1e-6);
}

TEST(Simulator, FixedBodiesNeverMove) {
  Simulator simulator;
  auto& wall = simulator.registerObject(std::make_unique<Circle>(real(1), real(1)));
  wall.fixed = true;
  auto& ball = simulator.registerObject(std::make_unique<Circle>(real(0.5), real(1)));
  ball.r = {real(1.5), 0};
  for (int step = 0; step < 20; ++step) {
    wall.externalForce = {5, 5};
    ball.externalForce = {-3, 0};
    simulator.advanceTime();
  }
  EXPECT_EQ(wall.r, Vector2{});
  EXPECT_EQ(wall.v, Vector2{});
  EXPECT_EQ(wall.externalForce, Vector2{});  // used up by the step, fixed or not
  EXPECT_GE(ball.r.x, real(1.5) - test::loose);
}

/// A circle with its own step hooks: in phase 5 it pushes two other bodies, and it counts
/// its integrations (the simulator runs such objects through their virtual hooks, in
/// registration order among the core shapes it runs directly).
class Pusher : public Circle {
 public:
  Pusher(PhysicalObject& before, PhysicalObject& after)
      : Circle(real(0.1), real(1)), before_(before), after_(after) {}
  void computeDerivativesWithoutContacts() override {
    before_.externalForce += Vector2{1, 0};
    after_.externalForce += Vector2{0, 1};
    Circle::computeDerivativesWithoutContacts();
  }
  void integrate(real dt) override {
    ++integrations;
    Circle::integrate(dt);
  }
  int integrations = 0;

 private:
  PhysicalObject& before_;
  PhysicalObject& after_;
};

TEST(Simulator, OwnHooksRunInRegistrationOrderAmongTheCoreShapes) {
  // A push in phase 5 reaches a body registered after the pusher in the same step, and one
  // registered before it in the next step; every object is integrated once per step.
  Simulator simulator(real(0.5));
  std::vector<Circle*> circles;
  std::vector<Pusher*> pushers;
  const auto addCircle = [&](real x) {
    circles.push_back(&simulator.registerObject(std::make_unique<Circle>(real(0.1), real(2))));
    circles.back()->r = {x, 0};
  };
  const auto addPusher = [&](Circle& before, Circle& after, real x) {
    pushers.push_back(&simulator.registerObject(std::make_unique<Pusher>(before, after)));
    pushers.back()->r = {x, 5};
  };
  addCircle(0);                // object 0
  addCircle(1);                // 1
  circles.push_back(nullptr);  // (filled below: the pushers need it first)
  auto third = std::make_unique<Circle>(real(0.1), real(2));
  auto fourth = std::make_unique<Circle>(real(0.1), real(2));
  addPusher(*circles[1], *third, 2);  // 2: pushes object 1 (before) and 3 (after)
  circles[2] = &simulator.registerObject(std::move(third));  // 3
  circles[2]->r = {3, 0};
  addPusher(*circles[2], *fourth, 4);  // 4: pushes object 3 (before) and 5 (after)
  circles.push_back(&simulator.registerObject(std::move(fourth)));  // 5
  circles[3]->r = {5, 0};
  simulator.advanceTime();
  EXPECT_EQ(circles[0]->r, (Vector2{0, 0}));
  // Pushed by a later object: not moved yet, the push kept for the next step.
  EXPECT_EQ(circles[1]->r, (Vector2{1, 0}));
  EXPECT_EQ(circles[1]->externalForce, (Vector2{1, 0}));
  // Pushed by an earlier object (v = F / m), then by a later one (kept).
  EXPECT_EQ(circles[2]->v, (Vector2{0, real(0.5)}));
  EXPECT_EQ(circles[2]->r, (Vector2{3, real(0.25)}));
  EXPECT_EQ(circles[2]->externalForce, (Vector2{1, 0}));
  EXPECT_EQ(circles[3]->r, (Vector2{5, real(0.25)}));
  EXPECT_EQ(circles[3]->externalForce, Vector2{});
  simulator.advanceTime();
  EXPECT_EQ(circles[1]->r, (Vector2{real(1.25), 0}));
  EXPECT_EQ(circles[2]->r, (Vector2{real(3.25), real(0.5)}));
  EXPECT_EQ(circles[3]->r, (Vector2{5, real(0.5)}));
  for (const Pusher* pusher : pushers) EXPECT_EQ(pusher->integrations, 2);
}

}  // namespace
}  // namespace thyrix
