// Rest skipping: shapes that did not move keep their geometry, and pairs of them keep their
// contacts. It must be exact: the same contacts in the same order and the same trajectories as
// a simulator that tests everything at every step, whatever the user does between steps.

#include <Scenes.h>
#include <ThyrixLite/Border.h>
#include <ThyrixLite/CappedRectangle.h>
#include <ThyrixLite/Circle.h>
#include <ThyrixLite/ComposedPhysicalObject.h>
#include <ThyrixLite/Elastoid.h>
#include <ThyrixLite/Simulator.h>
#include <Tools/MTRandom.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <memory>
#include <vector>

namespace thyrix {
namespace {

/// A world of circles, capsules, composed bodies and an elastoid in a walled box; most bodies
/// rest unless pushed. @p extra more circles put it above the broad phase's all-pairs limit.
struct Scene {
  explicit Scene(bool restSkipping, int extra = 0) {
    simulator.restSkipping = restSkipping;
    scenes::addWalls(simulator, 8, 8);
    auto agent = std::make_unique<Elastoid>();
    Circle& left = agent->addBody(std::make_unique<Circle>(real(0.3), real(1)));
    Circle& right = agent->addBody(std::make_unique<Circle>(real(0.3), real(1)));
    left.r = {real(3.6), real(4)};
    right.r = {real(4.4), real(4)};
    agent->addLink(left, {}, right, {}, real(0.8), real(100));
    simulator.registerObject(std::move(agent));
    bodies = {&left, &right};
    MTRandom random(5);
    for (int i = 0; i < 12 + extra; ++i) {
      PhysicalObject* body;
      if (i % 4 == 1) {
        body = &simulator.registerObject(
            std::make_unique<CappedRectangle>(real(0.25), real(0.15), real(1)));
      } else if (i % 4 == 2) {
        auto composed = std::make_unique<ComposedPhysicalObject>();
        composed->add(std::make_unique<Circle>(real(0.15), real(1)), {real(-0.2), 0});
        composed->add(std::make_unique<CappedRectangle>(real(0.1), real(0.1), real(1)),
                      {real(0.2), 0}, real(0.5));
        body = &simulator.registerObject(std::move(composed));
      } else {
        body = &simulator.registerObject(std::make_unique<Circle>(real(0.2), real(1)));
      }
      const int columns = extra > 0 ? 12 : 4;
      const real pitch = extra > 0 ? real(0.6) : real(1.6);
      // The first row and column near the walls: resting contacts to keep.
      body->r = {real(0.3) + pitch * static_cast<real>(i % columns),
                 real(0.3) + pitch * static_cast<real>(i / columns)};
      body->alpha = static_cast<real>(random.uniform(-1, 1));
      bodies.push_back(body);
    }
  }
  Simulator simulator;
  std::vector<PhysicalObject*> bodies;  // the agent's two circles first
};

bool sameBits(real a, real b) { return std::memcmp(&a, &b, sizeof(real)) == 0; }

/// The two simulators found exactly the same contacts, in the same order.
void expectSameContacts(const Simulator& a, const Simulator& b, int step) {
  ASSERT_EQ(a.contacts.size(), b.contacts.size()) << "step " << step;
  for (std::size_t k = 0; k < a.contacts.size(); ++k) {
    const GlobalContactInfo& p = a.contacts[k];
    const GlobalContactInfo& q = b.contacts[k];
    SCOPED_TRACE(::testing::Message() << "step " << step << ", contact " << k);
    ASSERT_EQ(p.shapeA, q.shapeA);
    ASSERT_EQ(p.shapeB, q.shapeB);
    ASSERT_EQ(p.bodyA, q.bodyA);
    ASSERT_EQ(p.bodyB, q.bodyB);
    ASSERT_EQ(p.feature, q.feature);
    ASSERT_TRUE(sameBits(p.point.x, q.point.x) && sameBits(p.point.y, q.point.y));
    ASSERT_TRUE(sameBits(p.normal.x, q.normal.x) && sameBits(p.normal.y, q.normal.y));
    ASSERT_TRUE(sameBits(p.depth, q.depth));
    ASSERT_TRUE(sameBits(p.force, q.force));
  }
}

/// Runs both worlds side by side with the same pushes and the same interventions by hand, and
/// checks contacts and states at every step.
void runSideBySide(int extra) {
  Scene cached(true, extra);
  Scene plain(false, extra);
  MTRandom random(11);
  std::size_t contacts = 0;
  std::size_t reused = 0;
  for (int step = 0; step < 1500; ++step) {
    // The agent is always pushed, turning slowly; one other body now and then.
    const real angle = real(0.004) * static_cast<real>(step);
    const Vector2 push{std::cos(angle), std::sin(angle)};
    const auto poke = random.integer(static_cast<std::uint32_t>(cached.bodies.size()));
    const bool poking = step % 50 < 10;
    const Vector2 pokeForce{static_cast<real>(random.uniform(-2, 2)),
                            static_cast<real>(random.uniform(-2, 2))};
    const auto touched = random.integer(static_cast<std::uint32_t>(cached.bodies.size() - 2)) + 2;
    for (Scene* world : {&cached, &plain}) {
      Simulator& simulator = world->simulator;
      world->bodies[0]->externalForce += push;
      world->bodies[1]->externalForce += push;
      if (poking) world->bodies[poke]->externalForce += pokeForce;
      // What researchers do by hand between steps.
      PhysicalObject& body = *world->bodies[touched];
      switch (step % 300) {
        case 40:  // moved by setting r and alpha directly
          body.r += Vector2{real(0.05), real(-0.03)};
          body.alpha += real(0.2);
          break;
        case 60:  // one part of a composed body moved, then another turned, by hand
          world->bodies[4]->primitives()[0]->r += Vector2{real(0.3), real(0.1)};
          break;
        case 61:
          world->bodies[4]->primitives()[1]->alpha += real(0.3);
          break;
        case 90:  // a part of a composed body moved by hand (the simulator puts it back)
          for (Primitive* part : world->bodies[4]->primitives()) part->r += Vector2{real(0.5), 0};
          break;
        case 130:  // fixed, then free again
          body.fixed = true;
          break;
        case 131:
          body.fixed = false;
          break;
        case 170:  // made to pass through the agent for a while
          body.collisionGroup = world->bodies[0]->collisionGroup;
          break;
        case 220:
          body.collisionGroup = 0;
          break;
        case 250:  // a new margin
          simulator.solverSettings().speculativeFraction =
              step % 600 == 250 ? real(0.4) : real(0.25);
          break;
        case 260:  // margins that follow travel more, or not at all
          simulator.solverSettings().speculativeTravel = step % 600 == 260 ? real(2) : real(0);
          break;
        case 280:
          simulator.solverSettings().speculativeTravel = 1;
          break;
        default:
          break;
      }
      if (step == 700) {  // an object added between steps
        auto& added = simulator.registerObject(std::make_unique<Circle>(real(0.25), real(1)));
        added.r = {real(6.5), real(6.5)};
        world->bodies.push_back(&added);
      }
      simulator.advanceTime();
    }
    expectSameContacts(cached.simulator, plain.simulator, step);
    // The bodies' boxes too (a composed body's box is made of its parts' boxes).
    for (std::size_t i = 0; i < cached.simulator.objects.size(); ++i) {
      const PhysicalObject& a = cached.simulator.objects[i];
      const PhysicalObject& b = plain.simulator.objects[i];
      ASSERT_TRUE(sameBits(a.boxMin.x, b.boxMin.x) && sameBits(a.boxMin.y, b.boxMin.y) &&
                  sameBits(a.boxMax.x, b.boxMax.x) && sameBits(a.boxMax.y, b.boxMax.y))
          << "step " << step << ", object " << i;
    }
    ASSERT_EQ(scenes::stateHash(cached.simulator), scenes::stateHash(plain.simulator))
        << "step " << step;
    if (::testing::Test::HasFatalFailure()) return;
    contacts += cached.simulator.statistics().contacts;
    reused += cached.simulator.statistics().reusedContacts;
    EXPECT_EQ(plain.simulator.statistics().reusedContacts, 0u);
  }
  // The scene exercised both: contacts found anew and contacts kept.
  EXPECT_GT(contacts, 1000u);
  EXPECT_GT(reused, 100u);
  EXPECT_LT(reused, contacts);
}

TEST(RestSkipping, SameContactsAndStatesAsTestingEverything) { runSideBySide(0); }

TEST(RestSkipping, SameContactsAndStatesInTheGrid) { runSideBySide(60); }

// A crowd in motion: every word of 64 grid shapes moved, so the borders' reach is retested for
// all of them at once (a path of its own), with one border that is not axis-aligned. The same
// contacts as the per-shape test of a simulator without rest skipping.
TEST(RestSkipping, BordersMeetACrowdInMotionAsTestingEverything) {
  Simulator cached;
  Simulator plain;
  plain.restSkipping = false;
  std::vector<std::vector<Circle*>> crowds;
  for (Simulator* simulator : {&cached, &plain}) {
    simulator->registerObject(std::make_unique<Border>(Vector2{0, 0}, Vector2{0, 1}));
    simulator->registerObject(std::make_unique<Border>(Vector2{-1, 0}, Vector2{1, 0}));
    simulator->registerObject(
        std::make_unique<Border>(Vector2{12, 0}, Vector2{real(-0.8), real(0.6)}));
    std::vector<Circle*> crowd;
    MTRandom random(3);
    for (int i = 0; i < 200; ++i) {
      auto& circle = simulator->registerObject(std::make_unique<Circle>(real(0.3), real(1)));
      circle.r = {real(0.7) * static_cast<real>(i % 14),
                  real(0.5) + real(0.7) * static_cast<real>(i / 14) +
                      static_cast<real>(random.uniform(0, 0.1))};
      crowd.push_back(&circle);
    }
    crowds.push_back(crowd);
  }
  std::size_t borderContacts = 0;
  for (int step = 0; step < 150; ++step) {
    for (std::size_t w = 0; w < 2; ++w)
      for (Circle* circle : crowds[w]) circle->externalForce += Vector2{real(0.3), -2};
    cached.advanceTime();
    plain.advanceTime();
    expectSameContacts(cached, plain, step);
    if (::testing::Test::HasFatalFailure()) return;
    for (const GlobalContactInfo& contact : cached.contacts)
      borderContacts += contact.shapeA < 3 ? 1 : 0;
  }
  EXPECT_EQ(scenes::stateHash(cached), scenes::stateHash(plain));
  EXPECT_GT(borderContacts, 1000u) << "the crowd met the borders";
}

TEST(RestSkipping, ARestingBodyHitLaterMovesAndGetsItsContacts) {
  Simulator simulator;
  auto& pusher = simulator.registerObject(std::make_unique<Circle>(real(0.5), real(1)));
  auto& resting = simulator.registerObject(std::make_unique<Circle>(real(0.5), real(1)));
  pusher.r = {0, 0};
  resting.r = {3, 0};
  for (int step = 0; step < 50; ++step) simulator.advanceTime();  // both at rest a while
  EXPECT_EQ(resting.r.x, 3);
  EXPECT_TRUE(resting.contacts().empty());
  for (int step = 0; step < 400; ++step) {
    pusher.externalForce = {1, 0};
    simulator.advanceTime();
  }
  EXPECT_GT(resting.r.x, real(3.5)) << "the resting circle was pushed along";
  EXPECT_FALSE(resting.contacts().empty());
  EXPECT_GT(resting.contacts()[0].force, 0);
}

TEST(RestSkipping, ABodyMovedByHandIsNoticed) {
  Simulator simulator;
  simulator.registerObject(std::make_unique<Border>(Vector2{0, 0}, Vector2{0, 1}));
  auto& circle = simulator.registerObject(std::make_unique<Circle>(real(0.5), real(1)));
  auto& capsule =
      simulator.registerObject(std::make_unique<CappedRectangle>(real(1), real(0.2), real(1)));
  circle.r = {0, 5};
  capsule.r = {5, 5};
  for (int step = 0; step < 5; ++step) simulator.advanceTime();
  EXPECT_EQ(simulator.contacts.size(), 0u);

  circle.r = {0, real(0.45)};  // set directly: now it overlaps the floor
  simulator.advanceTime();
  ASSERT_EQ(simulator.contacts.size(), 1u);
  EXPECT_EQ(simulator.contacts[0].objectB, &circle);
  EXPECT_GT(circle.r.y, real(0.45)) << "pushed out of the floor";

  circle.r = {0, 5};  // lifted away: the contact goes
  simulator.advanceTime();
  EXPECT_EQ(simulator.contacts.size(), 0u);

  capsule.r = {5, real(1.1)};  // turned upright by hand: its end now reaches the floor
  capsule.alpha = real(1.5707963);
  simulator.advanceTime();
  ASSERT_EQ(simulator.contacts.size(), 1u);
  EXPECT_EQ(simulator.contacts[0].objectB, &capsule);
  EXPECT_LT(capsule.boxMin.y, real(0.1)) << "the box follows the new angle";
}

/// Hubs: big circles, registered after a ring of capsules around each, so that each hub is
/// shape A of many pairs (more than a short walk finds), with a floor under a row of circles.
/// Pokes move a few shapes, so the last step's contacts are looked up out of their order.
void runHubs(int hubs, bool gaussSeidel) {
  std::vector<std::unique_ptr<Simulator>> worlds;
  std::vector<std::vector<PhysicalObject*>> bodies(2);
  for (int w = 0; w < 2; ++w) {
    auto& simulator = *worlds.emplace_back(std::make_unique<Simulator>(real(1) / 60));
    simulator.restSkipping = w == 0;
    if (gaussSeidel) simulator.setContactSolver(ContactSolverKind::GaussSeidel);
    simulator.registerObject(std::make_unique<Border>(Vector2{0, 0}, Vector2{0, 1}));
    for (int i = 0; i < 24; ++i) {  // resting on the floor: a border's many pairs
      auto& circle = simulator.registerObject(std::make_unique<Circle>(real(0.2), real(1)));
      circle.r = {real(0.5) * static_cast<real>(i), real(0.19)};
      bodies[w].push_back(&circle);
    }
    constexpr int ring = 45;  // the capsules overlap their neighbours near the hub
    for (int h = 0; h < hubs; ++h) {
      for (int k = 0; k < ring; ++k) {
        const double angle = 2 * 3.14159265358979 * k / ring;
        auto& capsule = simulator.registerObject(
            std::make_unique<CappedRectangle>(real(0.3), real(0.15), real(1)));
        capsule.r = {static_cast<real>(5 + 7 * h + 2.42 * std::cos(angle)),
                     static_cast<real>(5 + 2.42 * std::sin(angle))};
        capsule.alpha = static_cast<real>(angle);
        bodies[w].push_back(&capsule);
      }
    }
    for (int h = 0; h < hubs; ++h) {
      auto& hub = simulator.registerObject(std::make_unique<Circle>(real(2), real(1)));
      hub.r = {static_cast<real>(5 + 7 * h), 5};
      bodies[w].push_back(&hub);
    }
  }
  MTRandom random(7);
  std::size_t reused = 0;
  for (int step = 0; step < 400; ++step) {
    const bool poking = step % 40 < 5;
    const auto poked = random.integer(static_cast<std::uint32_t>(bodies[0].size()));
    const Vector2 push{static_cast<real>(random.uniform(-3, 3)),
                       static_cast<real>(random.uniform(-3, 3))};
    for (int w = 0; w < 2; ++w) {
      if (poking) bodies[w][poked]->externalForce += push;
      if (step % 100 < 3) bodies[w].back()->externalForce += Vector2{real(0.3), real(0.1)};
      worlds[w]->advanceTime();
    }
    expectSameContacts(*worlds[0], *worlds[1], step);
    if (::testing::Test::HasFatalFailure()) return;
    reused += worlds[0]->statistics().reusedContacts;
  }
  EXPECT_EQ(scenes::stateHash(*worlds[0]), scenes::stateHash(*worlds[1]));
  EXPECT_GT(reused, 1000u);
}

// One hub among few boxes (tested pair by pair): its pairs come between its capsules' own, so
// its contacts are not together in the list. Several hubs in the grid: each hub's pairs are
// listed together (it is oversized).
TEST(RestSkipping, AShapeOfManyPairsKeepsItsContacts) {
  for (const bool gaussSeidel : {false, true}) {
    runHubs(1, gaussSeidel);
    runHubs(4, gaussSeidel);
  }
}

}  // namespace
}  // namespace thyrix
