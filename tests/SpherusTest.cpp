// Spherus: its sensor and effector layout, and the behaviours docs/Agents.md describes.

#include "TestTolerances.h"

#include <Agents/SpherusSimulator.h>
#include <Controller/RandomController.h>
#include <Scenes.h>
#include <ThyrixLite/Circle.h>
#include <ThyrixLite/InvalidArgument.h>

#include <gtest/gtest.h>

#include <array>
#include <cmath>

namespace thyrix {
namespace {

/// An empty arena (no obstacles) with a Spherus driven by hand, facing +y at the centre.
struct HandDriven {
  HandDriven() : simulator(options(), nullptr) {}
  static SpherusSimulator::Options options() {
    SpherusSimulator::Options o;
    o.objects = 0;
    return o;
  }
  void run(int steps, std::array<real, 5> effectors) {
    for (int i = 0; i < steps; ++i) {
      std::copy(effectors.begin(), effectors.end(), spherus().effectors().begin());
      simulator.advanceTime();
    }
  }
  Spherus& spherus() { return simulator.spherus(); }
  SpherusSimulator simulator;
};

TEST(Spherus, HasFiveEffectorsAndThirtyFiveSensorsAllInUnitRangeOverALongRandomRun) {
  SpherusSimulator::Options options;
  options.objects = 30;
  SpherusSimulator simulator(options, std::make_unique<RandomController>(7));
  auto& spherus = simulator.spherus();
  ASSERT_EQ(spherus.sensors().size(), 35u);
  ASSERT_EQ(spherus.effectors().size(), 5u);
  bool touched = false;
  bool saw = false;
  for (int step = 0; step < 20000; ++step) {
    simulator.advanceTime();
    for (const real s : spherus.sensors()) ASSERT_TRUE(s >= 0 && s <= 1) << "step " << step;
    for (const real e : spherus.effectors()) ASSERT_TRUE(e >= 0 && e <= 1);
    for (int c = 0; c < 2; ++c) {
      for (int k = 0; k < 8; ++k) touched |= spherus.sensors()[c * 17 + k] > 0;
      for (int k = 8; k < 15; ++k) saw |= spherus.sensors()[c * 17 + k] > 0;
    }
  }
  EXPECT_TRUE(touched) << "the contact sensors fired at some point";
  EXPECT_TRUE(saw) << "the eyes saw something";
  for (const PhysicalObject& object : simulator.objects) {
    if (object.fixed) continue;
    EXPECT_TRUE(object.r.x > 0 && object.r.x < 10 && object.r.y > 0 && object.r.y < 10)
        << "nothing escapes the arena";
  }
}

TEST(Spherus, ForwardRocketsMoveItForwardAndOppositeRocketsTurnItInPlace) {
  HandDriven forward;
  const Vector2 start = forward.spherus().centre();
  forward.run(100, {1, 0, 1, 0, real(0.6)});
  // Both circles pushed with 1 N, mass 1 each: 1 m/s along +y. Effectors act from phase 7
  // on, i.e. on the next step: 99 of the 100 steps move, 0.99 m.
  EXPECT_NEAR(forward.spherus().centre().x, start.x, test::loose);
  EXPECT_NEAR(forward.spherus().centre().y, start.y + real(0.99), real(1e-3));
  EXPECT_NEAR(forward.spherus().sensors()[15], 1, real(1e-3)) << "left forward velocity";
  EXPECT_NEAR(forward.spherus().sensors()[16], 0, real(1e-3)) << "left backward velocity";

  HandDriven turn;
  turn.run(50, {1, 0, 0, 1, real(0.6)});
  EXPECT_NEAR(distance(turn.spherus().centre(), start), 0, real(1e-3)) << "turns in place";
  const Vector2 f = turn.spherus().forward();
  // Left circle (at -x) pushed along +y, right one along -y: a clockwise turn, so forward
  // swings from +y toward +x.
  EXPECT_GT(f.x, real(0.5));
}

TEST(Spherus, LinkEffectorChangesTheLinkLength) {
  HandDriven spherus;
  spherus.run(300, {0, 0, 0, 0, real(0.9)});
  EXPECT_NEAR(distance(spherus.spherus().leftCircle().r, spherus.spherus().rightCircle().r),
              real(0.9), real(1e-3));
  EXPECT_NEAR(spherus.spherus().sensors()[34], real(0.9), real(1e-3));
  spherus.run(300, {0, 0, 0, 0, real(0.2)});
  EXPECT_NEAR(distance(spherus.spherus().leftCircle().r, spherus.spherus().rightCircle().r),
              real(0.2), real(1e-3));
}

TEST(Spherus, ObjectStraightAheadLightsTheMiddlePixels) {
  HandDriven spherus;
  auto& target = spherus.simulator.registerObject(std::make_unique<Circle>(real(0.3), real(1)));
  target.r = spherus.spherus().centre() + Vector2{0, 3};
  spherus.run(1, {0, 0, 0, 0, real(0.6)});
  // From each circle (0.3 m left or right of the centre) the target is 3 m ahead: it spans
  // about 2 asin(0.3 / 3) = 11.5 degrees near the middle pixel (index 3, at 8 + 3 = 11).
  for (int c = 0; c < 2; ++c) {
    const auto s = spherus.spherus().sensors().subspan(c * 17 + 8, 7);
    EXPECT_GT(s[3], real(0.3)) << "circle " << c;
    EXPECT_EQ(s[0], 0);
    EXPECT_EQ(s[6], 0);
  }
}

TEST(Spherus, CircleBetweenTheBodyCirclesIsCarriedAlong) {
  HandDriven spherus;
  // The link open (0.9 m), a small circle just ahead of the link's middle; then the link closes
  // on it and Spherus drives forward: the circle stays between the body circles.
  auto& carried = spherus.simulator.registerObject(std::make_unique<Circle>(real(0.15), real(1)));
  spherus.run(200, {0, 0, 0, 0, real(0.9)});
  carried.r = spherus.spherus().centre() + Vector2{0, real(0.1)};
  spherus.run(100, {0, 0, 0, 0, real(0.5)});
  spherus.run(150, {1, 0, 1, 0, real(0.5)});
  const Vector2 offset = carried.r - spherus.spherus().centre();
  EXPECT_GT(spherus.spherus().centre().y, real(5.9)) << "Spherus travelled";
  EXPECT_LT(std::abs(offset.x), real(0.1));
  EXPECT_GT(offset.y, 0);
  EXPECT_LT(offset.y, real(0.45)) << "still held between the circles";
}

TEST(Spherus, DefaultPoseIsTheCentreFacingUp) {
  SpherusSimulator::Options options;
  SpherusSimulator simulator(options, nullptr);
  EXPECT_NEAR(simulator.spherus().centre().x, options.size / 2, test::tight);
  EXPECT_NEAR(simulator.spherus().centre().y, options.size / 2, test::tight);
  EXPECT_NEAR(simulator.spherus().forward().x, 0, test::tight);
  EXPECT_NEAR(simulator.spherus().forward().y, 1, test::tight);
}

TEST(Spherus, RandomPoseIsSeededSpreadAndClearOfEverything) {
  const SpherusParameters parameters;
  const real reach = parameters.maxLinkLength / 2 + parameters.radius;
  SpherusSimulator::Options options;  // 20 circles in a 10 m arena
  const int seeds = 200;
  std::array<int, 4> quadrants{};
  double sumX = 0;
  double sumY = 0;
  for (int seed = 1; seed <= seeds; ++seed) {
    options.poseSeed = static_cast<std::uint32_t>(seed);
    SpherusSimulator simulator(options, nullptr);
    const Spherus& agent = simulator.spherus();
    const Vector2 centre = agent.centre();
    ASSERT_GE(centre.x, 2 * reach);
    ASSERT_LE(centre.x, options.size - 2 * reach);
    ASSERT_GE(centre.y, 2 * reach);
    ASSERT_LE(centre.y, options.size - 2 * reach);
    ASSERT_EQ(simulator.obstacles().size(), std::size_t{20});
    for (const Circle* circle : simulator.obstacles())
      ASSERT_GE(distance(circle->r, centre), reach + 2 * options.objectRadius) << "seed " << seed;
    const Vector2 f = agent.forward();
    ++quadrants[(f.x >= 0 ? 0 : 1) + (f.y >= 0 ? 0 : 2)];
    sumX += centre.x;
    sumY += centre.y;

    // The same seed gives the same world.
    SpherusSimulator again(options, nullptr);
    ASSERT_EQ(again.spherus().centre().x, centre.x);
    ASSERT_EQ(again.spherus().centre().y, centre.y);
    ASSERT_EQ(again.spherus().forward().x, f.x);
    ASSERT_EQ(scenes::stateHash(again), scenes::stateHash(simulator));
  }
  // Headings uniform: about 50 a quadrant (standard deviation about 6).
  for (const int count : quadrants) EXPECT_GE(count, 25);
  // Centres uniform over [2 reach, size - 2 reach]: the mean within five standard errors.
  const double spread = (options.size - 4 * reach) / std::sqrt(12.0) / std::sqrt(seeds);
  EXPECT_NEAR(sumX / seeds, options.size / 2, 5 * spread);
  EXPECT_NEAR(sumY / seeds, options.size / 2, 5 * spread);
}

TEST(Spherus, RandomPoseNeedsRoom) {
  SpherusSimulator::Options options;
  options.objects = 0;
  options.size = 2;
  SpherusSimulator centred(options, nullptr);  // without a random pose it is still built
  options.poseSeed = 3;
  try {
    SpherusSimulator simulator(options, nullptr);
    ADD_FAILURE() << "a random pose in a 2 m arena";
  } catch (const InvalidArgument& error) {
    EXPECT_EQ(error.field(), "SpherusSimulator.size");
  }
}

TEST(Spherus, SameSeedSameTrajectory) {
  std::uint64_t hashes[2];
  for (std::uint64_t& hash : hashes) {
    SpherusSimulator::Options options;
    options.seed = 11;
    SpherusSimulator simulator(options, std::make_unique<RandomController>(11));
    for (int step = 0; step < 3000; ++step) simulator.advanceTime();
    hash = scenes::stateHash(simulator);
  }
  EXPECT_EQ(hashes[0], hashes[1]);
}

}  // namespace
}  // namespace thyrix
