// Pac: its sensor and effector layout, its shape, and eating as docs/Agents.md describes it.
// This executable links support/AllocationCounter.cpp to count allocations (as AllocationTest
// does); the count is read around the steps under test only.

#include "TestTolerances.h"
#include "support/AllocationCounter.h"

#include <Agents/PacEater.h>
#include <Agents/PacSimulator.h>
#include <Controller/RandomController.h>
#include <Scenes.h>
#include <ThyrixLite/Circle.h>
#include <ThyrixLite/InvalidArgument.h>
#include <Tools/MathTools.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <new>

namespace thyrix {
namespace {

/// Winding number of the polygon of the ring's circle centres around @p point, summed from the
/// angles the edges subtend: non-zero inside. Independent of Pac::contains (a crossing test).
bool insideRing(const Pac& pac, Vector2 point) {
  real turn = 0;
  const auto circles = pac.circles();
  for (std::size_t i = 0; i < circles.size(); ++i) {
    const Vector2 a = circles[i]->r - point;
    const Vector2 b = circles[(i + 1) % circles.size()]->r - point;
    turn += std::atan2(cross(a, b), dot(a, b));
  }
  return std::abs(turn) > pi<real>;
}

/// The largest difference between a circle's distance to the centroid and the ring radius.
real radialError(const Pac& pac) {
  const Vector2 c = pac.centre();
  real worst = 0;
  for (const Circle* circle : pac.circles())
    worst = std::max(worst, std::abs(distance(circle->r, c) - pac.parameters().ringRadius));
  return worst;
}

/// An arena without food and with both Pacs driven by hand: Pac 0 at (2, 4) facing +x, Pac 1
/// at (6, 4) facing -x.
struct HandDriven {
  explicit HandDriven(ContactSolverKind solver = ContactSolverKind::Baraff)
      : simulator(options(), nullptr, nullptr) {
    simulator.setContactSolver(solver);
  }
  static PacSimulator::Options options() {
    PacSimulator::Options o;
    o.food = 0;
    return o;
  }
  Circle& addFood(Vector2 at) {
    auto& food = simulator.registerObject(std::make_unique<Circle>(real(0.12), real(0.5)));
    food.r = at;
    return food;
  }
  void step(std::array<real, 5> effectors) {
    std::copy(effectors.begin(), effectors.end(), pac().effectors().begin());
    simulator.advanceTime();
  }
  void run(int steps, std::array<real, 5> effectors) {
    for (int i = 0; i < steps; ++i) step(effectors);
  }
  Pac& pac() { return simulator.pac(0); }
  PacSimulator simulator;
};

TEST(Pac, HasFiveEffectorsAndTwentyOneSensorsAllInUnitRangeOverALongRandomRun) {
  PacSimulator::Options options;
  options.seed = 5;
  PacSimulator simulator(options, std::make_unique<RandomController>(7),
                         std::make_unique<RandomController>(8));
  for (int p = 0; p < 2; ++p) {
    ASSERT_EQ(simulator.pac(p).sensors().size(), 21u);
    ASSERT_EQ(simulator.pac(p).sensorCount(), Pac::firstTouch + 10);
    ASSERT_EQ(simulator.pac(p).effectors().size(), 5u);
  }
  std::array<bool, 4> fired{};  // touch, sight, mouth opening, forward speed
  for (int step = 0; step < 20000; ++step) {
    simulator.advanceTime();
    for (int p = 0; p < 2; ++p) {
      const Pac& pac = simulator.pac(p);
      for (const real s : pac.sensors()) ASSERT_TRUE(s >= 0 && s <= 1) << "step " << step;
      for (const real e : pac.effectors()) ASSERT_TRUE(e >= 0 && e <= 1);
      for (int k = 0; k < 10; ++k) fired[0] |= pac.sensors()[Pac::firstTouch + k] > 0;
      for (int k = 0; k < Pac::pixelCount; ++k) fired[1] |= pac.sensors()[Pac::firstPixel + k] > 0;
      fired[2] |= pac.sensors()[Pac::mouthSensor] > real(0.5);
      fired[3] |= pac.sensors()[Pac::forwardSensor] > real(0.2);
    }
  }
  EXPECT_TRUE(fired[0]) << "the touch sensors fired at some point";
  EXPECT_TRUE(fired[1]) << "the eye saw something";
  EXPECT_TRUE(fired[2]) << "the mouth opened";
  EXPECT_TRUE(fired[3]) << "Pac moved forward";
  for (const PhysicalObject& object : simulator.objects) {
    if (object.fixed) continue;
    EXPECT_TRUE(object.r.x > 0 && object.r.x < 8 && object.r.y > 0 && object.r.y < 8)
        << "nothing escapes the arena";
  }
  for (int p = 0; p < 2; ++p)
    EXPECT_LT(radialError(simulator.pac(p)), real(0.5)) << "no ring was torn apart";
}

TEST(Pac, EqualSidesDriveStraightAndOppositeSidesTurnInPlace) {
  HandDriven straight;
  const Vector2 start = straight.pac().centre();
  straight.run(100, {1, 0, 1, 0, 0});
  // Every circle pushed with 0.5 N, mass 1: 0.5 m/s along +x. Effectors act from the next step
  // on: 99 of the 100 steps move, 0.495 m.
  EXPECT_NEAR(straight.pac().centre().x, start.x + real(0.495), real(1e-3));
  EXPECT_NEAR(straight.pac().centre().y, start.y, real(1e-3));
  EXPECT_NEAR(straight.pac().sensors()[Pac::forwardSensor], 1, real(1e-3));
  EXPECT_EQ(straight.pac().sensors()[Pac::backwardSensor], 0);
  EXPECT_LT(radialError(straight.pac()), real(1e-3)) << "a uniform push does not deform";

  HandDriven turn;
  turn.run(100, {0, 1, 1, 0, 0});  // left half back, right half forward: turns left
  EXPECT_NEAR(distance(turn.pac().centre(), start), 0, real(1e-3)) << "turns in place";
  EXPECT_GT(turn.pac().heading(), real(0.4));
  EXPECT_LT(radialError(turn.pac()), real(0.03));
}

TEST(Pac, OddRingOfSevenCirclesDrivesStraightAndOpensItsMouth) {
  // On its own in a world with no walls: the back circle (on the axis) takes the mean push.
  PacParameters parameters;
  parameters.circleCount = 7;
  parameters.crossLinkSpan = 3;
  parameters.ringRadius = real(0.33);
  Simulator simulator;
  Pac& pac = simulator.registerObject(std::make_unique<Pac>(nullptr, parameters));
  ASSERT_EQ(pac.sensorCount(), Pac::firstTouch + 7);
  pac.place({1, 2}, pi<real> / 2);
  const Vector2 start = pac.centre();
  for (int step = 0; step < 100; ++step) {
    const std::array<real, 5> e{1, 0, 1, 0, 1};
    std::copy(e.begin(), e.end(), pac.effectors().begin());
    simulator.advanceTime();
  }
  EXPECT_NEAR(pac.heading(), pi<real> / 2, real(1e-3));
  EXPECT_NEAR(pac.centre().x, start.x, real(1e-3));
  EXPECT_GT(pac.centre().y, start.y + real(0.45));
  EXPECT_NEAR(pac.mouthLink().length(), parameters.mouthWidth, real(0.02));
}

TEST(Pac, ClosedRingKeepsItsShapeWhilePushedAgainstAWallAndTurning) {
  HandDriven pac;
  pac.pac().place({real(1.5), 4}, pi<real>);  // facing the wall at x = 0, 0.9 m away
  real worst = 0;
  for (int step = 0; step < 600; ++step) {
    pac.step({1, 0, 1, 0, 0});
    worst = std::max(worst, radialError(pac.pac()));
  }
  EXPECT_LT(pac.pac().centre().x, real(0.62)) << "pressed on the wall";
  for (int step = 0; step < 600; ++step) {
    pac.step({1, 0, 0, real(0.5), 0});  // turning while pressing on the wall
    worst = std::max(worst, radialError(pac.pac()));
  }
  // The front circles carry the push of all ten (5 N) against the wall.
  EXPECT_LT(worst, real(0.1) * pac.pac().parameters().ringRadius);
  EXPECT_LT(pac.pac().mouthLink().length(), pac.pac().closedChord() + real(0.01))
      << "the closed mouth stays closed";
}

TEST(Pac, ClosedRingsKeepTheirShapeWhenTwoPacsPushHeadOn) {
  HandDriven pacs;
  Pac& other = pacs.simulator.pac(1);
  real worst = 0;
  real furthest = 0;  // Pac 0's largest x
  for (int step = 0; step < 1000; ++step) {
    // Pac 1 pushes harder (both halves at 1 against Pac 0's 0.5), so the pair drifts toward -x.
    std::fill(other.effectors().begin(), other.effectors().end(), real(0));
    other.effectors()[Pac::leftForward] = other.effectors()[Pac::rightForward] = 1;
    pacs.step({real(0.5), 0, real(0.5), 0, 0});
    worst = std::max({worst, radialError(pacs.pac()), radialError(other)});
    furthest = std::max(furthest, pacs.pac().centre().x);
  }
  EXPECT_LT(distance(pacs.pac().centre(), other.centre()), real(1.25)) << "they met";
  EXPECT_LT(pacs.pac().centre().x, furthest - real(0.3)) << "Pac 0 was pushed back";
  EXPECT_LT(worst, real(0.1) * pacs.pac().parameters().ringRadius);
}

TEST(Pac, OpeningTheMouthWidensTheGapBetweenTheMouthCircles) {
  HandDriven pac;
  const Circle& left = *pac.pac().circles().front();
  const Circle& right = *pac.pac().circles().back();
  const real closed = distance(left.r, right.r);
  EXPECT_NEAR(closed, pac.pac().closedChord(), test::tight);
  pac.run(100, {0, 0, 0, 0, 1});
  const real open = distance(left.r, right.r);
  EXPECT_NEAR(open, pac.pac().parameters().mouthWidth, real(0.02));
  EXPECT_GT(open - 2 * left.radius(), 2 * real(0.12) + real(0.1))
      << "a food circle of radius 0.12 passes with room to spare";
  EXPECT_GT(pac.pac().sensors()[Pac::mouthSensor], real(0.95));
  // The mouth opens symmetrically about the heading, which does not change.
  EXPECT_NEAR(pac.pac().heading(), 0, real(1e-3));
  pac.run(100, {0, 0, 0, 0, 0});
  EXPECT_NEAR(distance(left.r, right.r), closed, real(1e-3));
  EXPECT_LT(pac.pac().sensors()[Pac::mouthSensor], real(0.01));
}

TEST(Pac, TouchSensorsTellInsideFromOutsideAndTheEyeSeesAhead) {
  HandDriven pac;
  Circle& food = pac.addFood(pac.pac().centre());  // inside the ring
  auto& ahead = pac.simulator.registerObject(std::make_unique<Circle>(real(0.3), real(1)));
  ahead.r = pac.pac().centre() + Vector2{2, 0};
  pac.run(100, {1, 0, 1, 0, 0});  // the back of the ring reaches the food and pushes it
  auto s = pac.pac().sensors();
  EXPECT_GT(s[Pac::insideSensor], real(0.1));
  for (int k = 0; k < 10; ++k) EXPECT_EQ(s[Pac::firstTouch + k], 0) << "outer half " << k;
  EXPECT_GT(s[Pac::firstPixel + 3], real(0.5)) << "the middle pixel sees the circle ahead";
  EXPECT_EQ(s[Pac::firstPixel], 0);
  EXPECT_EQ(s[Pac::firstPixel + 6], 0);
  EXPECT_TRUE(insideRing(pac.pac(), food.r));
  pac.run(300, {1, 0, 1, 0, 0});  // now pushing the circle ahead with the closed mouth
  s = pac.pac().sensors();
  EXPECT_GT(s[Pac::firstTouch] + s[Pac::firstTouch + 9], 0) << "the mouth circles feel it";
}

class PacEating : public testing::TestWithParam<ContactSolverKind> {};

TEST_P(PacEating, OpenMouthEatsTheFoodWhichStaysInsideWhileCarried) {
  // Food ahead, off the heading to both sides and at several distances: Pac opens its mouth,
  // steers onto it, closes its mouth once it is inside, then carries it 1.5 m straight and
  // 1 m along a curve.
  for (const real bearing : {real(-0.4), real(0), real(0.25)}) {
    for (const real range : {real(1), real(1.8)}) {
      SCOPED_TRACE(testing::Message() << "bearing " << bearing << " range " << range);
      HandDriven pac(GetParam());
      const Vector2 start = pac.pac().centre();
      Circle& food = pac.addFood(start + Vector2{std::cos(bearing), std::sin(bearing)} * range);
      PacEater eater(pac.pac(), food);
      int steps = 0;
      bool sawOpen = false;
      for (; !eater.done() && steps < 2000; ++steps) {
        eater.step();
        pac.simulator.advanceTime();
        sawOpen |= pac.pac().sensors()[Pac::mouthSensor] > real(0.9);
      }
      ASSERT_TRUE(eater.done()) << "phase " << static_cast<int>(eater.phase());
      EXPECT_TRUE(sawOpen);
      EXPECT_TRUE(insideRing(pac.pac(), food.r)) << "eaten";
      EXPECT_LT(pac.pac().sensors()[Pac::mouthSensor], real(0.05)) << "mouth closed";

      const Vector2 eatenAt = pac.pac().centre();
      bool felt = false;
      int carried = 0;
      while (distance(pac.pac().centre(), eatenAt) < real(1.5) && carried < 1000) {
        eater.step();  // carrying: straight ahead, mouth closed
        pac.simulator.advanceTime();
        ASSERT_TRUE(insideRing(pac.pac(), food.r)) << "after " << carried << " steps";
        felt |= pac.pac().sensors()[Pac::insideSensor] > 0;
        ++carried;
      }
      EXPECT_TRUE(felt) << "something inside";
      real travelled = 0;
      for (int step = 0; step < 1000 && travelled < 1; ++step) {
        const Vector2 before = pac.pac().centre();
        pac.step({real(0.6), 0, 1, 0, 0});  // a left curve
        travelled += distance(pac.pac().centre(), before);
        ASSERT_TRUE(insideRing(pac.pac(), food.r)) << "on the curve";
      }
      EXPECT_GE(travelled, 1);
      EXPECT_TRUE(pac.pac().contains(food.r)) << "Pac::contains agrees";
    }
  }
}

TEST_P(PacEating, ClosedMouthPushesTheFoodInsteadOfEatingIt) {
  HandDriven pac(GetParam());
  const Vector2 start = pac.pac().centre();
  Circle& food = pac.addFood(start + Vector2{1, 0});
  for (int step = 0; step < 500; ++step) {  // 2.5 m at 0.5 m/s
    pac.step({1, 0, 1, 0, 0});
    ASSERT_FALSE(insideRing(pac.pac(), food.r)) << "step " << step;
  }
  EXPECT_GT(food.r.x, start.x + real(2)) << "pushed ahead";
  EXPECT_NEAR(food.r.y, start.y, real(0.05)) << "held in the notch between the mouth circles";
  EXPECT_GT(pac.pac().sensors()[Pac::firstPixel + 3], real(0.9)) << "right in front";
}

INSTANTIATE_TEST_SUITE_P(Solvers, PacEating,
                         testing::Values(ContactSolverKind::Baraff, ContactSolverKind::GaussSeidel),
                         [](const testing::TestParamInfo<ContactSolverKind>& solver) {
                           return solver.param == ContactSolverKind::Baraff ? "Baraff"
                                                                            : "GaussSeidel";
                         });

TEST(Pac, BadParametersAreRefusedNamingTheField) {
  const auto field = [](PacParameters p) -> std::string {
    try {
      Pac pac(nullptr, p);
    } catch (const InvalidArgument& error) {
      return error.field();
    }
    return "";
  };
  PacParameters p;
  p.circleCount = 4;
  EXPECT_EQ(field(p), "Pac.circleCount");
  p = {};
  p.mouthWidth = real(0.2);  // narrower than the closed chord
  EXPECT_EQ(field(p), "Pac.mouthWidth");
  p = {};
  p.crossLinkSpan = 6;
  EXPECT_EQ(field(p), "Pac.crossLinkSpan");
  p = {};
  p.radius = -1;
  EXPECT_EQ(field(p), "Circle.radius");
  p = {};
  p.crossLinkSpan = 1;  // a ring alone is allowed, if floppy
  EXPECT_EQ(field(p), "");
}

TEST(Pac, StepsWithoutAllocatingOnceWarmedUp) {
  const long start = test::allocationCount();
  PacSimulator::Options options;
  options.seed = 3;
  PacSimulator simulator(options, std::make_unique<RandomController>(3),
                         std::make_unique<RandomController>(4));
  simulator.reserveContacts(200);
  for (int step = 0; step < 100; ++step) simulator.advanceTime();
  const long before = test::allocationCount();
  ASSERT_GT(before, start) << "building the world allocates: the counter counts";
  for (int step = 0; step < 5000; ++step) simulator.advanceTime();  // mouths open and close
  EXPECT_EQ(test::allocationCount() - before, 0);
}

TEST(Pac, SameSeedSameTrajectory) {
  for (const ContactSolverKind solver :
       {ContactSolverKind::Baraff, ContactSolverKind::GaussSeidel}) {
    std::uint64_t hashes[2];
    for (std::uint64_t& hash : hashes) {
      PacSimulator::Options options;
      options.seed = 11;
      PacSimulator simulator(options, std::make_unique<RandomController>(11),
                             std::make_unique<RandomController>(12));
      simulator.setContactSolver(solver);
      for (int step = 0; step < 3000; ++step) simulator.advanceTime();
      hash = scenes::stateHash(simulator);
    }
    EXPECT_EQ(hashes[0], hashes[1]);
  }
}

}  // namespace
}  // namespace thyrix
