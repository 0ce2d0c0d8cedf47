// Rest by structure (Simulator::restSkipping): bodies at rest are left out of the phases that
// would not change them, and contacts between them build no row. It must be exact: with rest
// on and off, every pose, velocity, contact and force is the same, bit for bit, at every step,
// whatever wakes the bodies. And a world at rest must cost nothing per body at rest: the
// simulator's own counts of what it visited say so (never a time).

#include <Agents/IunctusSimulator.h>
#include <Agents/PacEatingSimulator.h>
#include <Agents/PacSimulator.h>
#include <Agents/SpherusSimulator.h>
#include <Controller/RandomController.h>
#include <Scenes.h>
#include <ThyrixLite/Border.h>
#include <ThyrixLite/CappedRectangle.h>
#include <ThyrixLite/Circle.h>
#include <ThyrixLite/Elastoid.h>
#include <ThyrixLite/InvalidArgument.h>
#include <ThyrixLite/Simulator.h>
#include <Tools/MTRandom.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace thyrix {
namespace {

/// FNV-1a over the bits of everything a step leaves: every object's pose, velocities and
/// pending force and torque; every contact (shapes, feature, point, normal, depth, force); each
/// object's own list of contacts with their forces.
class Hash {
 public:
  void add(const void* data, std::size_t size) {
    const auto* bytes = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < size; ++i) value_ = (value_ ^ bytes[i]) * 1099511628211ull;
  }
  void add(real x) { add(&x, sizeof x); }
  void add(Vector2 v) {
    add(v.x);
    add(v.y);
  }
  void add(std::uint32_t x) { add(&x, sizeof x); }
  [[nodiscard]] std::uint64_t value() const { return value_; }

 private:
  std::uint64_t value_ = 14695981039346656037ull;
};

std::uint64_t worldHash(const Simulator& simulator) {
  Hash hash;
  for (const PhysicalObject& object : simulator.objects) {
    hash.add(object.r);
    hash.add(object.alpha);
    hash.add(object.v);
    hash.add(object.omega);
    hash.add(object.externalForce);
    hash.add(object.externalTorque);
    for (const Primitive* part : object.primitives()) {
      hash.add(part->r);
      hash.add(part->alpha);
    }
    for (const ContactInfo& info : object.contacts()) {
      hash.add(info.p);
      hash.add(info.force);
    }
  }
  for (const GlobalContactInfo& c : simulator.contacts) {
    hash.add(c.shapeA);
    hash.add(c.shapeB);
    hash.add(c.feature);
    hash.add(c.point);
    hash.add(c.normal);
    hash.add(c.depth);
    hash.add(c.force);
  }
  return hash.value();
}

using Factory = std::function<std::unique_ptr<Simulator>()>;
/// What a test does to a world before step @p step (the same to both worlds).
using Intervention = std::function<void(Simulator&, int step)>;

/// What the world with rest visited at each step: bodies in phases 5 and 8, contacts left out.
struct Visited {
  std::vector<std::size_t> awake;
  std::vector<std::size_t> left;
  [[nodiscard]] std::size_t totalAwake() const {
    std::size_t sum = 0;
    for (const std::size_t n : awake) sum += n;
    return sum;
  }
  [[nodiscard]] std::size_t totalLeft() const {
    std::size_t sum = 0;
    for (const std::size_t n : left) sum += n;
    return sum;
  }
};

/// Runs the world of @p make with rest on and off side by side for @p steps steps, each
/// preceded by @p intervene, and checks that they agree bit for bit after every step.
Visited expectSameRun(const Factory& make, int steps, const Intervention& intervene,
                      ContactSolverKind solver) {
  std::unique_ptr<Simulator> resting = make();
  std::unique_ptr<Simulator> plain = make();
  resting->restSkipping = true;
  plain->restSkipping = false;
  resting->setContactSolver(solver);
  plain->setContactSolver(solver);
  Visited visited;
  for (int step = 0; step < steps; ++step) {
    intervene(*resting, step);
    intervene(*plain, step);
    resting->advanceTime();
    plain->advanceTime();
    visited.awake.push_back(resting->statistics().awakeBodies);
    visited.left.push_back(resting->statistics().restingContacts);
    EXPECT_EQ(plain->statistics().awakeBodies, plain->objects.size());
    EXPECT_EQ(plain->statistics().restingContacts, 0u);
    if (worldHash(*resting) != worldHash(*plain)) {
      ADD_FAILURE() << "rest on and off differ after step " << step;
      return visited;
    }
  }
  return visited;
}

/// A walled 10 m arena of up to @p count circles placed at random (most touch nothing), a row
/// of circles at rest against the top wall, an Elastoid agent of two circles, a few capsules
/// resting on the floor.
std::unique_ptr<Simulator> crowdedArena(int count) {
  auto simulator = std::make_unique<Simulator>(real(0.01));
  scenes::addWalls(*simulator, 10, 10);
  auto agent = std::make_unique<Elastoid>();
  Circle& left = agent->addBody(std::make_unique<Circle>(real(0.3), real(1)));
  Circle& right = agent->addBody(std::make_unique<Circle>(real(0.3), real(1)));
  left.r = {real(4.6), real(5)};
  right.r = {real(5.4), real(5)};
  agent->addLink(left, {}, right, {}, real(0.8), real(200));
  simulator->registerObject(std::move(agent));
  for (int i = 0; i < 4; ++i) {
    auto& capsule = simulator->registerObject(
        std::make_unique<CappedRectangle>(real(0.4), real(0.15), real(1)));
    capsule.r = {real(1 + 2.5 * i), real(0.2)};  // touching the floor: resting contacts
    capsule.alpha = real(0.01);
  }
  // A row of circles along the top wall, each in its neighbours' margins and the wall's.
  for (int i = 0; i < 24; ++i) {
    auto& circle = simulator->registerObject(std::make_unique<Circle>(real(0.195), real(1)));
    circle.r = {real(0.25) + real(0.4) * static_cast<real>(i), real(9.8)};
  }
  scenes::addRandomCircles(*simulator, count, real(0.15), real(9.4), 3);
  return simulator;
}

/// Pushes the agent (objects 4 and 5, its circles) along a slowly turning direction.
void pushAgent(Simulator& simulator, int step) {
  const real angle = real(0.003) * static_cast<real>(step);
  const Vector2 push{2 * std::cos(angle), 2 * std::sin(angle)};
  simulator.objects[5].externalForce += push;
  simulator.objects[6].externalForce += push;
}

class RestOnOff : public testing::TestWithParam<ContactSolverKind> {};

TEST_P(RestOnOff, CrowdedArenaPushedByAnAgent) {
  const Visited visited =
      expectSameRun([] { return crowdedArena(160); }, 1500, pushAgent, GetParam());
  // Most of the crowd rests: far fewer bodies visited than the objects at every step.
  EXPECT_LT(visited.totalAwake(), 1500u * 40u);
  EXPECT_GT(visited.totalLeft(), 0u);
}

TEST_P(RestOnOff, WritesBetweenStepsWakeTheBodies) {
  // Forces, torques, poses, velocities, `fixed` and the collision group written by hand to
  // bodies at rest; a drag; bodies registered into the crowd, one onto another.
  MTRandom random(17);
  std::vector<std::uint32_t> picks;  // among the capsules and circles (from object 7 on)
  for (int i = 0; i < 64; ++i) picks.push_back(random.integer(1000000));
  const auto intervene = [&picks](Simulator& simulator, int step) {
    pushAgent(simulator, step);
    const std::size_t pick = picks[static_cast<std::size_t>(step / 25) % 64];
    PhysicalObject& body = simulator.objects[7 + pick % 100];
    switch (step % 25) {
      case 3:
        body.externalForce += Vector2{real(3), real(-1)};
        break;
      case 6:
        body.externalTorque += real(2);
        break;
      case 9:
        body.r += Vector2{real(0.02), 0};
        break;
      case 10:
        body.alpha += real(0.5);
        break;
      case 12:
        body.v = {real(0.5), 0};  // between steps: the next phase 5 recomputes it
        break;
      case 14:
        body.fixed = !body.fixed;
        break;
      case 16:
        body.collisionGroup = body.collisionGroup == 0 ? 7 : 0;
        break;
      case 18:
        simulator.startDrag(body, body.r + Vector2{real(0.1), 0});
        simulator.dragTo(body.r + Vector2{1, 1});
        break;
      case 22:
        simulator.stopDrag();
        break;
      default:
        break;
    }
    if (step == 700 || step == 900) {  // a new circle over a body at rest, overlapping it
      auto& added = simulator.registerObject(std::make_unique<Circle>(real(0.25), real(1)));
      added.r = simulator.objects[40].r + Vector2{real(0.1), 0};
    }
  };
  expectSameRun([] { return crowdedArena(150); }, 1200, intervene, GetParam());
}

TEST_P(RestOnOff, BallPushedIntoAHeapAtRest) {
  // Without gravity, a heap of circles in the corner, each within its neighbours' margins (at
  // rest from the start); a ball is driven into it, and the heap wakes ring by ring. (A heap
  // pushed together overlaps, and its overlaps shrink by a fraction per step: it would not be
  // at rest for thousands of steps.)
  const Factory heap = [] {
    auto simulator = std::make_unique<Simulator>(real(0.01));
    scenes::addWalls(*simulator, 6, 6);
    for (int i = 0; i < 60; ++i) {
      auto& circle = simulator->registerObject(std::make_unique<Circle>(real(0.25), real(1)));
      const real row = static_cast<real>(i / 10);
      circle.r = {real(0.255) + real(0.505) * static_cast<real>(i % 10) +
                      (i / 10 % 2 == 1 ? real(0.2525) : real(0)),
                  real(0.255) + real(0.44) * row};
    }
    auto& ball = simulator->registerObject(std::make_unique<Circle>(real(0.3), real(1)));
    ball.r = {real(5.5), real(5.5)};
    return simulator;
  };
  const auto intervene = [](Simulator& simulator, int step) {
    if (step >= 100 && step < 500)  // the ball into the heap at rest
      simulator.objects[simulator.objects.size() - 1].externalForce += {-2, -2};
  };
  const Visited visited = expectSameRun(heap, 800, intervene, GetParam());
  // Before the ball is pushed, after the first detections, the heap and the ball rest, and
  // every contact (neighbours, walls) is left out.
  for (std::size_t step = 3; step < 100; ++step) {
    EXPECT_EQ(visited.awake[step], 0u) << "step " << step;
    EXPECT_GT(visited.left[step], 100u) << "step " << step;
  }
  EXPECT_GT(visited.totalAwake(), 800u);  // and the ball woke some
}

TEST_P(RestOnOff, PileInGravityNeverRests) {
  // In a gravity field every movable body is pushed by its weight: rest leaves none out, and
  // the pile is the same.
  const Factory pile = [] {
    auto simulator = std::make_unique<Simulator>(real(1.0 / 60.0));
    simulator->setGravity({0, -1});
    scenes::addPile(*simulator, 100, 1);
    return simulator;
  };
  const Visited visited = expectSameRun(
      pile, 300, [](Simulator&, int) {}, GetParam());
  EXPECT_EQ(visited.totalAwake(), 300u * 103u);
  EXPECT_EQ(visited.totalLeft(), 0u);
}

TEST_P(RestOnOff, Spherus) {
  const Factory spherus = [] {
    SpherusSimulator::Options options;
    options.objects = 60;
    return std::make_unique<SpherusSimulator>(options, std::make_unique<RandomController>(7));
  };
  expectSameRun(
      spherus, 1500, [](Simulator&, int) {}, GetParam());
}

TEST_P(RestOnOff, Pac) {
  const Factory pac = [] {
    PacSimulator::Options options;
    return std::make_unique<PacSimulator>(options, std::make_unique<RandomController>(3, 5, 40),
                                          std::make_unique<RandomController>(4, 5, 40));
  };
  expectSameRun(
      pac, 800, [](Simulator&, int) {}, GetParam());
}

TEST_P(RestOnOff, PacEating) {
  const Factory pac = [] {
    PacSimulator::Options options;
    return std::make_unique<PacEatingSimulator>(options,
                                                std::make_unique<RandomController>(5, 5, 40));
  };
  expectSameRun(
      pac, 800, [](Simulator&, int) {}, GetParam());
}

TEST_P(RestOnOff, IunctusGrasping) {
  const Factory iunctus = [] {
    IunctusSimulator::Options options;
    options.objects = 4;
    auto simulator = std::make_unique<IunctusSimulator>(options, nullptr);
    simulator->useGrasper();
    return simulator;
  };
  expectSameRun(
      iunctus, 800, [](Simulator&, int) {}, GetParam());
}

TEST_P(RestOnOff, RestoredStateWakesEveryBody) {
  // A state saved with rest on, restored into both worlds (and into the one with rest on
  // again, after it went on): the steps after it agree.
  std::unique_ptr<Simulator> source = crowdedArena(100);
  source->setContactSolver(GetParam());
  for (int step = 0; step < 400; ++step) {
    pushAgent(*source, step);
    source->advanceTime();
  }
  const WorldState saved = source->saveState();
  const auto fromSaved = [&saved] {
    std::unique_ptr<Simulator> world = crowdedArena(100);
    world->restoreState(saved);
    return world;
  };
  expectSameRun(fromSaved, 400, pushAgent, GetParam());
  // The world that saved it, stepped on and then restored, against a fresh one restored.
  for (int step = 0; step < 50; ++step) source->advanceTime();
  source->restoreState(saved);
  std::unique_ptr<Simulator> plain = fromSaved();
  plain->restSkipping = false;
  plain->setContactSolver(GetParam());
  for (int step = 0; step < 300; ++step) {
    pushAgent(*source, step);
    pushAgent(*plain, step);
    source->advanceTime();
    plain->advanceTime();
    ASSERT_EQ(worldHash(*source), worldHash(*plain)) << "after step " << step;
  }
}

INSTANTIATE_TEST_SUITE_P(Solvers, RestOnOff,
                         testing::Values(ContactSolverKind::Baraff, ContactSolverKind::GaussSeidel),
                         [](const testing::TestParamInfo<ContactSolverKind>& solver) {
                           return solver.param == ContactSolverKind::Baraff ? "Baraff"
                                                                            : "GaussSeidel";
                         });

/// A row of @p count circles touching each other's margins on the floor of a walled box, at
/// rest from the start (nothing pushes them).
std::unique_ptr<Simulator> restingRow(int count) {
  auto simulator = std::make_unique<Simulator>(real(0.01));
  scenes::addWalls(*simulator, real(0.5) * static_cast<real>(count) + 1, 4);
  for (int i = 0; i < count; ++i) {
    auto& circle = simulator->registerObject(std::make_unique<Circle>(real(0.24), real(1)));
    circle.r = {real(0.75) + real(0.5) * static_cast<real>(i), real(0.25)};
  }
  return simulator;
}

TEST(Rest, BodiesAtRestAreNotVisited) {
  constexpr int count = 1000;
  std::unique_ptr<Simulator> simulator = restingRow(count);
  // The first step detects every body (registration wakes it); then nothing moves.
  simulator->advanceTime();
  EXPECT_EQ(simulator->statistics().awakeBodies, simulator->objects.size());
  simulator->advanceTime();
  ASSERT_GT(simulator->contacts.size(), std::size_t{count});  // neighbours and the floor
  for (int step = 0; step < 5; ++step) {
    simulator->advanceTime();
    EXPECT_EQ(simulator->statistics().awakeBodies, 0u);
    EXPECT_EQ(simulator->statistics().restingContacts, simulator->contacts.size());
    EXPECT_EQ(simulator->statistics().islands, 0u);  // no row built
  }
  // One body pushed: it alone is visited in that step, and its contacts alone are rows.
  PhysicalObject& pushed = simulator->objects[4 + count / 2];
  pushed.externalForce = {0, real(0.5)};
  simulator->advanceTime();
  EXPECT_EQ(simulator->statistics().awakeBodies, 1u);
  EXPECT_GE(simulator->statistics().restingContacts, simulator->contacts.size() - 4);
  EXPECT_GT(pushed.r.y, real(0.25));
  // Unpushed, it stops at once (F = m v), is looked at while its margin narrows, then rests.
  int steps = 0;
  do {
    simulator->advanceTime();
    ++steps;
  } while (simulator->statistics().awakeBodies != 0 && steps < 10);
  EXPECT_LE(steps, 3);
  // With rest off every body is visited at every step.
  simulator->restSkipping = false;
  simulator->advanceTime();
  EXPECT_EQ(simulator->statistics().awakeBodies, simulator->objects.size());
  EXPECT_EQ(simulator->statistics().restingContacts, 0u);
}

/// A circle whose control() (phase 7) sets another body's velocity, and wakes it: the
/// integration (phase 8) then moves that body, as it would with rest off.
class Kicker : public Circle {
 public:
  Kicker(Simulator& simulator, PhysicalObject& target)
      : Circle(real(0.2), real(1)), simulator_(simulator), target_(target) {}
  void control() override {
    if (++calls_ % 50 != 0) return;
    target_.v = {real(0.7), real(0.2)};
    simulator_.wake(target_);
  }

 private:
  Simulator& simulator_;
  PhysicalObject& target_;
  int calls_ = 0;
};

TEST(Rest, WakeMakesAVelocityWrittenInAHookMove) {
  const Factory kicked = [] {
    std::unique_ptr<Simulator> simulator = restingRow(10);
    auto& kicker =
        simulator->registerObject(std::make_unique<Kicker>(*simulator, simulator->objects[8]));
    kicker.r = {1, 3};
    return simulator;
  };
  for (const ContactSolverKind solver : {ContactSolverKind::Baraff, ContactSolverKind::GaussSeidel})
    expectSameRun(
        kicked, 400, [](Simulator&, int) {}, solver);
  std::unique_ptr<Simulator> simulator = kicked();
  const Vector2 before = simulator->objects[8].r;
  for (int step = 0; step < 60; ++step) simulator->advanceTime();
  EXPECT_GT(simulator->objects[8].r.x, before.x);  // kicked at step 50

  Circle outside(real(0.2), real(1));
  try {
    simulator->wake(outside);
    ADD_FAILURE() << "an object of no world was woken";
  } catch (const InvalidArgument& error) {
    EXPECT_EQ(error.field(), "Simulator.wake.object");
  }
}

}  // namespace
}  // namespace thyrix
