// Iunctus: its sensor and effector layout, the scripted grasp, reproducibility.

#include <Agents/IunctusSimulator.h>
#include <Controller/RandomController.h>
#include <Scenes.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

namespace thyrix {
namespace {

TEST(Iunctus, HasSevenEffectorsAndThirtySensorsAllInUnitRangeOverALongRandomRun) {
  IunctusSimulator::Options options;
  options.objects = 6;
  IunctusSimulator simulator(options, std::make_unique<RandomController>(7));
  auto& agent = simulator.iunctus();
  ASSERT_EQ(agent.sensors().size(), 30u);
  ASSERT_EQ(agent.effectors().size(), 7u);
  bool touched = false;
  for (int step = 0; step < 20000; ++step) {
    simulator.advanceTime();
    for (const real s : agent.sensors()) ASSERT_TRUE(s >= 0 && s <= 1) << "step " << step;
    for (const real e : agent.effectors()) ASSERT_TRUE(e >= 0 && e <= 1);
    for (int k = Iunctus::firstBaseTouch; k < Iunctus::heldSensor; ++k)
      touched |= agent.sensors()[static_cast<std::size_t>(k)] > 0;
  }
  EXPECT_TRUE(touched) << "the touch sensors fired at some point";
  for (const PhysicalObject& object : simulator.objects) {
    if (object.fixed) continue;
    EXPECT_TRUE(object.r.x > 0 && object.r.x < 8 && object.r.y > 0 && object.r.y < 8)
        << "nothing escapes the arena";
  }
}

TEST(Iunctus, JointSensorsFollowTheServoEffectors) {
  IunctusSimulator::Options options;
  options.objects = 0;
  IunctusSimulator simulator(options, nullptr);
  auto& agent = simulator.iunctus();
  for (int i = 0; i < 3; ++i)
    agent.effectors()[static_cast<std::size_t>(Iunctus::firstServo + i)] = real(0.3);
  for (int step = 0; step < 300; ++step) simulator.advanceTime();
  for (int i = 0; i < 3; ++i)
    EXPECT_NEAR(agent.sensors()[static_cast<std::size_t>(i)], real(0.3), real(0.01)) << i;
}

class Grasp : public ::testing::TestWithParam<ContactSolverKind> {};

TEST_P(Grasp, TheScriptedControllerGraspsTheObjectAndCarriesItASetDistance) {
  IunctusSimulator::Options options;
  IunctusSimulator simulator(options, nullptr);
  simulator.setContactSolver(GetParam());
  const real carry = 2;
  IunctusGrasper& grasper = simulator.useGrasper(carry);
  const Iunctus& agent = simulator.iunctus();
  const Circle& object = *simulator.objectsToCatch().front();
  bool wasHeld = false;
  real farthest = 0;  // from the base's centre, while carrying
  int step = 0;
  for (; step < 4000 && !grasper.done(); ++step) {
    simulator.advanceTime();
    if (grasper.phase() == IunctusGrasper::Phase::Carrying) {
      farthest = std::max(farthest, distance(object.r, agent.r));
      ASSERT_TRUE(agent.encloses(object.r)) << "step " << step;
      wasHeld |= agent.sensors()[Iunctus::heldSensor] == 1;
    }
  }
  ASSERT_TRUE(grasper.done()) << "phase " << static_cast<int>(grasper.phase());
  EXPECT_GT(step, 500) << "opening, approaching, closing and carrying take time";
  std::printf("grasped and carried in %d steps\n", step);
  EXPECT_GE(distance(object.r, grasper.carryStart()), carry);
  EXPECT_LT(farthest, real(0.8)) << "held close to the base throughout the carry";
  EXPECT_TRUE(wasHeld) << "the held sensor saw it";
  // Still held, standing.
  for (int k = 0; k < 200; ++k) simulator.advanceTime();
  EXPECT_TRUE(agent.encloses(object.r));
  EXPECT_EQ(agent.sensors()[Iunctus::heldSensor], 1);
}

INSTANTIATE_TEST_SUITE_P(Solvers, Grasp,
                         ::testing::Values(ContactSolverKind::Baraff,
                                           ContactSolverKind::GaussSeidel));

TEST(Iunctus, SameSeedSameTrajectory) {
  std::uint64_t hashes[2];
  for (std::uint64_t& hash : hashes) {
    IunctusSimulator::Options options;
    options.seed = 11;
    options.objects = 4;
    IunctusSimulator simulator(options, std::make_unique<RandomController>(11));
    for (int step = 0; step < 3000; ++step) simulator.advanceTime();
    hash = scenes::stateHash(simulator);
  }
  EXPECT_EQ(hashes[0], hashes[1]);
}

}  // namespace
}  // namespace thyrix
