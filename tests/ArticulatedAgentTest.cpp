// Articulated agents (ThyrixPro/ArticulatedAgentQuasistatic) in a real Simulator, with both
// contact solvers: motion against the core algorithm solved directly (ArticulatedBody), joint
// limits, contacts with borders, fixed and free circles and the agent's own links, agreement
// between Baraff and Gauss-Seidel, implicit servos, determinism, validation and no allocation
// per step.
//
// This executable links support/AllocationCounter.cpp to count allocations during steps.

#include "TestTolerances.h"
#include "support/AllocationCounter.h"
#include "support/SameAgentMotion.h"
#include "support/SolverCases.h"

#include <Scenes.h>
#include <ThyrixLite/Border.h>
#include <ThyrixLite/Circle.h>
#include <ThyrixLite/ComposedPhysicalObject.h>
#include <ThyrixLite/GUI.h>
#include <ThyrixLite/InvalidArgument.h>
#include <ThyrixLite/SelfCollisionFilter.h>
#include <ThyrixLite/Simulator.h>
#include <ThyrixLite/SweepAndPrune.h>
#include <ThyrixPro/ArticulatedAgentQuasistatic.h>
#include <ThyrixPro/ArticulatedBody.h>
#include <ThyrixPro/ArticulatedLimb.h>
#include <Tools/MathTools.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <memory>
#include <new>
#include <string>
#include <utility>
#include <vector>

namespace thyrix {
namespace {

using test::bitsOf;
using test::isFloat;
using test::loose;
using test::solverName;
using test::tight;

using Agent = ArticulatedAgentQuasistatic;

constexpr real kNaN = std::numeric_limits<real>::quiet_NaN();

/// A circle base (radius 0.5, mass 2) with one chain of @p links links (length 1, radius 0.1,
/// mass 0.5) attached at its right edge, pointing along +x.
std::unique_ptr<Agent> makeArm(int links, real angle = 0) {
  return std::make_unique<Agent>(
      std::vector<ArticulatedBasePart>{ArticulatedBasePart::circle(real(0.5), 2)},
      std::vector<ArticulatedLimb>{
          ArticulatedLimb::chain({real(0.5), 0}, links, 1, real(0.1), real(0.5), angle)});
}

/// Two identical worlds, each with a five-link arm posed alike: a force given to each through
/// a different call must leave the two bit for bit alike.
struct TwinArms {
  explicit TwinArms(ContactSolverKind solver) {
    for (int k = 0; k < 2; ++k) {
      worlds[k].setContactSolver(solver);
      agents[k] = &worlds[k].registerObject(makeArm(links, real(0.3)));
      agents[k]->setPose({1, 2}, real(0.2));
    }
  }
  void advanceTime() {
    for (Simulator& world : worlds) world.advanceTime();
  }
  /// Expects every body's pose and velocities to have the same bits in both worlds.
  void expectSameMotion() const { test::expectSameAgentMotion(*agents[0], *agents[1]); }
  static constexpr int links = 5;
  Simulator worlds[2] = {Simulator(real(0.01)), Simulator(real(0.01))};
  Agent* agents[2] = {};
};

/// A fresh ArticulatedBody with the agent's description and state, built here, so the agent's
/// motion is compared with the core algorithm solved directly.
ArticulatedBody coreOf(const Agent& agent) {
  const ArticulatedBody& a = agent.articulatedBody();
  std::vector<ArticulatedLink> links(a.links().begin(), a.links().end());
  ArticulatedBody body(a.mass(ArticulatedBody::base), a.inertia(ArticulatedBody::base), links);
  body.setBasePose(agent.r, agent.alpha);
  body.setJointAngles(agent.jointAngles());
  return body;
}

/// The largest |a - b| over the base's velocity and every joint rate and body velocity.
real velocityDifference(const Agent& a, const Agent& b) {
  real d = std::abs(a.bodyAngularVelocity(-1) - b.bodyAngularVelocity(-1));
  for (int body = -1; body < a.linkCount(); ++body) {
    d = std::max(d, (a.bodyVelocity(body) - b.bodyVelocity(body)).length());
    d = std::max(d, std::abs(a.bodyAngularVelocity(body) - b.bodyAngularVelocity(body)));
  }
  for (int i = 0; i < a.linkCount(); ++i)
    d = std::max(d, std::abs(a.jointRate(i) - b.jointRate(i)));
  return d;
}

/// Gauss-Seidel converged far below the tolerances of the comparisons.
void tightenGaussSeidel(Simulator& simulator) {
  simulator.solverSettings().gaussSeidelTolerance = isFloat ? real(1e-7) : real(1e-13);
  simulator.solverSettings().gaussSeidelMaxIterations = 100000;
}

/// How many of the agent's contacts touch another of its own bodies.
int selfContacts(const Agent& agent) {
  int count = 0;
  for (std::size_t k = 0; k < agent.contacts().size(); ++k)
    count += agent.linkContact(k).other == &agent ? 1 : 0;
  return count;
}

class ArticulatedAgentTest : public ::testing::TestWithParam<ContactSolverKind> {};

// ---------------------------------------------------------------------------------------------
// Free motion

TEST_P(ArticulatedAgentTest, NoTorqueAndNoForceGiveNoMotion) {
  Simulator simulator(real(0.01));
  simulator.setContactSolver(GetParam());
  scenes::addWalls(simulator, 20, 20);
  auto& agent = simulator.registerObject(makeArm(5, real(0.3)));
  agent.setPose({6, 7}, real(0.4));
  for (int i = 0; i < 5; ++i) agent.setJointAngle(i, real(0.2) * real(i));
  const std::vector<real> q(agent.jointAngles().begin(), agent.jointAngles().end());
  for (int step = 0; step < 100; ++step) simulator.advanceTime();
  EXPECT_EQ(agent.r, (Vector2{6, 7}));
  EXPECT_EQ(agent.alpha, real(0.4));
  for (int i = 0; i < 5; ++i) {
    EXPECT_EQ(agent.jointAngle(i), q[i]);
    EXPECT_EQ(agent.jointRate(i), 0);
  }
  EXPECT_EQ(agent.v, Vector2{});
  EXPECT_EQ(agent.omega, 0);
}

TEST_P(ArticulatedAgentTest, AForceAtTheCentreOfMassGivesTheBitsOfTheSameForceAtThatPoint) {
  // Forces of every sign (signed zeros too: the torque is a zero whose sign depends on them)
  // on every body, base included, by the two calls, in two identical worlds.
  const Vector2 forces[] = {{real(0.3), real(-0.8)}, {real(-0.5), real(0.2)}, {0, real(-1)},
                            {real(-0.0), real(0.4)}, {real(0.7), real(-0.0)}, {real(-0.2), 0}};
  TwinArms twins(GetParam());
  Agent* const* agents = twins.agents;
  for (Agent* agent : twins.agents) agent->setJointTorque(2, real(0.1));
  const real start = agents[1]->jointAngle(1);
  for (int step = 0; step < 20; ++step) {
    for (int b = Agent::base; b < TwinArms::links; ++b) {
      const Vector2 force = forces[static_cast<std::size_t>(b + step + 1) % std::size(forces)];
      agents[0]->applyLinkForce(b, force, agents[0]->centerOfMass(b));
      agents[1]->applyLinkForceAtCenterOfMass(b, force);
    }
    twins.advanceTime();
  }
  twins.expectSameMotion();                    // centres of mass included
  EXPECT_NE(agents[1]->jointAngle(1), start);  // the forces moved it
}

TEST_P(ArticulatedAgentTest, AForceAtEveryLinksCentreOfMassGivesTheBitsOfTheForceOnEachLink) {
  const Vector2 forces[] = {{real(0.3), real(-0.8)},
                            {real(-0.5), real(0.2)},
                            {0, real(-1)},
                            {real(-0.0), real(0.4)},
                            {real(0.7), real(-0.0)}};
  TwinArms twins(GetParam());
  Agent* const* agents = twins.agents;
  for (int step = 0; step < 20; ++step) {
    const Vector2 force = forces[static_cast<std::size_t>(step) % std::size(forces)];
    for (int i = 0; i < TwinArms::links; ++i)
      agents[0]->applyLinkForce(i, force, agents[0]->centerOfMass(i));
    agents[1]->applyForceAtEveryLinkCenterOfMass(force);
    twins.advanceTime();
  }
  twins.expectSameMotion();
  EXPECT_NE(agents[1]->bodyAngularVelocity(2), 0);  // the forces moved it
}

TEST_P(ArticulatedAgentTest, TorqueTurnsAJointAtTheRateTheCorePredicts) {
  Simulator simulator(real(0.01));
  simulator.setContactSolver(GetParam());
  auto& agent = simulator.registerObject(makeArm(4, real(0.5)));
  agent.setPose({1, 2}, real(-0.3));
  agent.setJointTorque(1, real(0.7));
  agent.setJointTorque(3, real(-0.2));
  agent.externalForce = {real(0.3), real(-0.1)};
  agent.applyLinkForce(2, {0, real(0.4)}, agent.linkTip(2));
  for (int step = 0; step < 3; ++step) {
    ArticulatedBody core = coreOf(agent);
    std::vector<real> torques{0, real(0.7), 0, real(-0.2)};
    std::vector<Vector3> wrenches(5);
    if (step == 0) {
      // The accumulators act in the first step only.
      wrenches[0] = {0, real(0.3), real(-0.1)};
      wrenches[3] = {cross(agent.linkTip(2) - agent.centerOfMass(2), Vector2{0, real(0.4)}), 0,
                     real(0.4)};
    }
    ArticulatedBody::Output expected = core.makeOutput();
    core.solve(torques, wrenches, expected);
    const std::vector<real> q(agent.jointAngles().begin(), agent.jointAngles().end());
    simulator.advanceTime();
    for (int i = 0; i < 4; ++i) {
      EXPECT_NEAR(agent.jointRate(i), expected.jointRate(i), tight) << "step " << step;
      EXPECT_NEAR(agent.jointAngle(i), q[i] + expected.jointRate(i) * real(0.01), tight);
    }
    EXPECT_NEAR(agent.v.x, expected.linearVelocity(-1).x, tight);
    EXPECT_NEAR(agent.v.y, expected.linearVelocity(-1).y, tight);
    EXPECT_NEAR(agent.omega, expected.angularVelocity(-1), tight);
    // The shapes follow the kinematics: link 1's capsule runs from its joint to its tip.
    const CappedRectangle& shape = agent.linkShape(1);
    EXPECT_NEAR((shape.endPoint(0) - agent.jointPosition(1)).length(), 0, tight);
    EXPECT_NEAR((shape.endPoint(1) - agent.linkTip(1)).length(), 0, tight);
  }
  EXPECT_NE(agent.jointRate(1), 0);
}

TEST_P(ArticulatedAgentTest, FixedBaseStaysAndItsJointsMove) {
  Simulator simulator(real(0.01));
  simulator.setContactSolver(GetParam());
  auto& agent = simulator.registerObject(makeArm(3));
  agent.fixed = true;
  agent.setJointTorque(0, 1);
  agent.externalForce = {5, 5};
  for (int step = 0; step < 20; ++step) simulator.advanceTime();
  EXPECT_EQ(agent.r, agent.centreOfMassOffset());
  EXPECT_EQ(agent.alpha, 0);
  EXPECT_GT(agent.jointAngle(0), real(0.01));
}

// ---------------------------------------------------------------------------------------------
// Joint limits

TEST_P(ArticulatedAgentTest, JointDrivenIntoItsLimitStopsThereAndReleasedMovesFreely) {
  Simulator simulator(real(0.01));
  simulator.setContactSolver(GetParam());
  ArticulatedLimb limb = ArticulatedLimb::chain({real(0.5), 0}, 3, 1, real(0.1), real(0.5));
  limb.setLimits(1, real(-0.4), real(0.6));
  auto& agent = simulator.registerObject(std::make_unique<Agent>(
      std::vector<ArticulatedBasePart>{ArticulatedBasePart::circle(real(0.5), 2)},
      std::vector<ArticulatedLimb>{limb}));
  const real tau = real(0.8);
  agent.setJointTorque(1, -tau);
  const real tolerance = isFloat ? real(1e-5) : real(1e-9);
  bool reached = false;
  for (int step = 0; step < 400; ++step) {
    simulator.advanceTime();
    EXPECT_GE(agent.jointAngle(1), real(-0.4) - tolerance) << "step " << step;
    EXPECT_GE(agent.limitTorque(1), 0) << "step " << step;
    reached = reached || agent.limitTorque(1) > 0;
  }
  ASSERT_TRUE(reached);
  // At rest on the limit, nothing else acting on the joint: the limit torque balances the
  // applied one exactly, and nothing moves.
  EXPECT_NEAR(agent.jointAngle(1), real(-0.4), tolerance);
  EXPECT_NEAR(agent.limitTorque(1), tau, loose);
  EXPECT_NEAR(agent.jointRate(1), 0, loose);
  EXPECT_NEAR(agent.v.length(), 0, loose);

  // Reversed, the torque takes it away from the limit at the free rate of the core algorithm.
  agent.setJointTorque(1, tau);
  ArticulatedBody core = coreOf(agent);
  ArticulatedBody::Output expected = core.makeOutput();
  const std::vector<real> torques{0, tau, 0};
  core.solve(torques, {}, expected);
  simulator.advanceTime();
  EXPECT_EQ(agent.limitTorque(1), 0);
  EXPECT_NEAR(agent.jointRate(1), expected.jointRate(1), tight);
  EXPECT_GT(agent.jointRate(1), 0);
  for (int step = 0; step < 50; ++step) simulator.advanceTime();
  EXPECT_GT(agent.jointAngle(1), real(-0.3));

  // The upper limit, from the other side: its torque is negative.
  for (int step = 0; step < 400; ++step) {
    simulator.advanceTime();
    EXPECT_LE(agent.jointAngle(1), real(0.6) + tolerance);
    EXPECT_LE(agent.limitTorque(1), 0);
  }
  EXPECT_NEAR(agent.jointAngle(1), real(0.6), tolerance);
  EXPECT_NEAR(agent.limitTorque(1), -tau, loose);
}

TEST_P(ArticulatedAgentTest, JointStartedBeyondItsLimitReturnsWithinOneStep) {
  Simulator simulator(real(0.01));
  simulator.setContactSolver(GetParam());
  ArticulatedLimb limb = ArticulatedLimb::chain({real(0.5), 0}, 2, 1, real(0.1), real(0.5));
  limb.setLimits(0, real(-0.5), real(0.5));
  auto& agent = simulator.registerObject(std::make_unique<Agent>(
      std::vector<ArticulatedBasePart>{ArticulatedBasePart::circle(real(0.5), 2)},
      std::vector<ArticulatedLimb>{limb}));
  agent.setJointAngle(0, real(0.7));
  simulator.advanceTime();
  EXPECT_NEAR(agent.jointAngle(0), real(0.5), isFloat ? real(1e-5) : real(1e-9));
  EXPECT_LT(agent.limitTorque(0), 0);
}

// ---------------------------------------------------------------------------------------------
// Contacts

/// An arm over a floor (a Border at y = 0), its base 2.2 above it, its chain turned down (its
/// tip 0.5 above the floor) and driven further down by its joint torques while the whole agent
/// is pushed down too.
Agent& addArmOnFloor(Simulator& simulator) {
  simulator.registerObject(std::make_unique<Border>(Vector2{0, 0}, Vector2{0, 1}));
  auto& agent = simulator.registerObject(makeArm(3, real(-0.6)));
  agent.setPose({0, real(2.2)}, 0);
  for (int i = 0; i < 3; ++i) agent.setJointTorque(i, real(-0.5));
  return agent;
}

TEST_P(ArticulatedAgentTest, LinkPushedAgainstABorderDoesNotPenetrate) {
  Simulator simulator(real(0.01));
  simulator.setContactSolver(GetParam());
  Agent& agent = addArmOnFloor(simulator);
  int linkContacts = 0;
  for (int step = 0; step < 400; ++step) {
    agent.externalForce = {0, -1};
    simulator.advanceTime();
    EXPECT_LT(scenes::largestOverlap(simulator), real(0.01)) << "step " << step;
    for (std::size_t k = 0; k < agent.contacts().size(); ++k) {
      const LinkContactInfo c = agent.linkContact(k);
      if (c.body >= 0 && c.force > 0) ++linkContacts;
      EXPECT_GE(c.force, 0);
    }
    // No part of any link below the floor by more than the overlap allowed.
    for (int i = 0; i < agent.linkCount(); ++i) {
      const real lowest =
          std::min(agent.linkShape(i).endPoint(0).y, agent.linkShape(i).endPoint(1).y);
      EXPECT_GT(lowest - real(0.1), real(-0.01)) << "link " << i << " step " << step;
    }
  }
  EXPECT_GT(linkContacts, 0) << "the links should have touched the floor";
}

TEST_P(ArticulatedAgentTest, LinkPressedOnABorderBalancesItsJointTorque) {
  // A fixed base, one link turned down onto the floor by the torque tau = -0.5 at its joint. At
  // rest the floor's vertical forces f_k at the points p_k balance the torque about the joint:
  // sum_k f_k (p_k.x - joint.x) = -tau, and the link does not sink into the floor.
  Simulator simulator(real(0.01));
  simulator.setContactSolver(GetParam());
  tightenGaussSeidel(simulator);
  simulator.registerObject(std::make_unique<Border>(Vector2{0, 0}, Vector2{0, 1}));
  auto& agent = simulator.registerObject(makeArm(1, real(-0.6)));
  agent.setPose({0, real(0.9)}, 0);  // the link reaches the floor at about -0.93 rad
  agent.fixed = true;
  const real tau = real(-0.5);
  agent.setJointTorque(0, tau);
  // Touch sensors on the link work as on any capsule: 2 per side, 1 per end cap.
  agent.linkShape(0).setTactileSensors(2, 1, 1);
  for (int step = 0; step < 300; ++step) {
    simulator.advanceTime();
    EXPECT_LT(scenes::largestOverlap(simulator), real(0.01)) << "step " << step;
  }
  ASSERT_GT(agent.contacts().size(), 0u);
  EXPECT_NEAR(agent.jointRate(0), 0, loose);
  real moment = 0;
  for (std::size_t k = 0; k < agent.contacts().size(); ++k) {
    const LinkContactInfo c = agent.linkContact(k);
    EXPECT_EQ(c.body, 0);
    EXPECT_NEAR(c.normal.y, 1, tight);
    moment += c.force * (c.point.x - agent.jointPosition(0).x);
  }
  EXPECT_NEAR(moment, -tau, 100 * loose);
  EXPECT_NEAR(agent.contactForceOn(0), -tau / (agent.linkTip(0).x - agent.jointPosition(0).x),
              real(0.05));
  EXPECT_EQ(agent.contactForceOn(-1), 0);
  const auto touch = agent.linkShape(0).tactileActivations();
  EXPECT_GT(*std::max_element(touch.begin(), touch.end()), 0);
}

TEST_P(ArticulatedAgentTest, LinkPushedAgainstAFixedCircleDoesNotPenetrate) {
  Simulator simulator(real(0.01));
  simulator.setContactSolver(GetParam());
  auto& agent = simulator.registerObject(makeArm(3));
  auto& post = simulator.registerObject(std::make_unique<Circle>(real(0.3), 1));
  post.fixed = true;
  post.r = {2, real(-0.8)};  // below link 1, which turns down onto it
  agent.setJointTorque(0, real(-0.6));
  agent.setJointTorque(1, real(-0.3));
  int touching = 0;
  for (int step = 0; step < 400; ++step) {
    simulator.advanceTime();
    EXPECT_LT(scenes::largestOverlap(simulator), real(0.01)) << "step " << step;
    touching += agent.contactForceOn(0) + agent.contactForceOn(1) > 0 ? 1 : 0;
  }
  EXPECT_GT(touching, 100);
  EXPECT_EQ(post.r, (Vector2{2, real(-0.8)}));
}

/// Two identical simulators run the same steps with Baraff; then the second switches to a
/// tightly converged Gauss-Seidel for one step: both solve the same LCP from the same state.
template <class Build, class Drive, class Check>
void expectSolversAgree(Build build, Drive drive, int warmUp, real tolerance, Check check) {
  Simulator baraff(real(0.01));
  Simulator gaussSeidel(real(0.01));
  Agent& a = build(baraff);
  Agent& b = build(gaussSeidel);
  for (int step = 0; step < warmUp; ++step) {
    drive(a);
    drive(b);
    baraff.advanceTime();
    gaussSeidel.advanceTime();
  }
  ASSERT_EQ(scenes::stateHash(baraff), scenes::stateHash(gaussSeidel));
  gaussSeidel.setContactSolver(ContactSolverKind::GaussSeidel);
  tightenGaussSeidel(gaussSeidel);
  drive(a);
  drive(b);
  baraff.advanceTime();
  gaussSeidel.advanceTime();
  ASSERT_GT(baraff.statistics().solvedIslands, 0u) << "the step should need contact forces";
  check(a);
  check(b);
  EXPECT_EQ(baraff.statistics().baraffFallbacks, 0u);
  EXPECT_LE(velocityDifference(a, b), tolerance);
  for (std::size_t k = 0; k < baraff.contacts.size(); ++k)
    EXPECT_NEAR(baraff.contacts[k].force, gaussSeidel.contacts[k].force, 10 * tolerance)
        << "contact " << k;
  for (std::size_t o = 0; o < baraff.objects.size(); ++o) {
    EXPECT_NEAR(baraff.objects[o].v.x, gaussSeidel.objects[o].v.x, tolerance) << "object " << o;
    EXPECT_NEAR(baraff.objects[o].v.y, gaussSeidel.objects[o].v.y, tolerance) << "object " << o;
    EXPECT_NEAR(baraff.objects[o].omega, gaussSeidel.objects[o].omega, tolerance);
  }
}

TEST(ArticulatedAgentSolvers, ContactForcesAgreeBetweenBaraffAndGaussSeidel) {
  // The agent pushed down and left, its chain curled down by its torques: after the warm-up
  // the base presses on a fixed circle, the last link on the floor, and the last joint rests
  // on its lower limit: contacts on the base and a link, and a joint-limit row, in one LCP.
  const auto build = [](Simulator& simulator) -> Agent& {
    simulator.registerObject(std::make_unique<Border>(Vector2{0, 0}, Vector2{0, 1}));
    ArticulatedLimb limb =
        ArticulatedLimb::chain({real(0.5), 0}, 3, 1, real(0.1), real(0.5), real(-0.6));
    limb.setLimits(2, real(-0.3), real(0.3));
    auto& agent = simulator.registerObject(std::make_unique<Agent>(
        std::vector<ArticulatedBasePart>{ArticulatedBasePart::circle(real(0.5), 2)},
        std::vector<ArticulatedLimb>{limb}));
    agent.setPose({0, real(2.2)}, 0);
    auto& post = simulator.registerObject(std::make_unique<Circle>(real(0.4), 1));
    post.fixed = true;
    post.r = {real(-1.25), 1};
    for (int i = 0; i < 3; ++i) agent.setJointTorque(i, real(-0.5));
    return agent;
  };
  const auto drive = [](Agent& agent) { agent.externalForce = {real(-1), real(-1)}; };
  const auto check = [](const Agent& agent) {
    EXPECT_GT(agent.contactForceOn(-1), real(0.1)) << "the base on the fixed circle";
    EXPECT_GT(agent.contactForceOn(2), real(0.1)) << "the last link on the floor";
    EXPECT_GT(agent.limitTorque(2), real(0.1)) << "the last joint on its lower limit";
  };
  expectSolversAgree(build, drive, 300, isFloat ? real(1e-3) : real(1e-8), check);
}

TEST(ArticulatedAgentSolvers, AgentPushesAFreeCircleInOneIsland) {
  // A rigid body and a multi-body object in one island: the agent, pushed along +x, pushes a
  // free circle in front of its chain's tip. Nothing else acts, so the quasistatic momentum
  // sum_b m_b v_b (centres of mass) equals the total external force: the contact and joint
  // forces are internal.
  const auto build = [](Simulator& simulator) -> Agent& {
    auto& agent = simulator.registerObject(makeArm(2));
    // Servos hold the arm straight (free joints would let it buckle and slip off the ball).
    agent.setServoTarget(0, 0, 20);
    agent.setServoTarget(1, 0, 20);
    auto& ball = simulator.registerObject(std::make_unique<Circle>(real(0.4), real(1.5)));
    // On the arm's axis (off it, frictionless, the ball would slide over the arm), 0.02 away.
    ball.r = {real(2.5) + real(0.1) + real(0.4) + real(0.02), 0};
    return agent;
  };
  const auto drive = [](Agent& agent) { agent.externalForce = {2, 0}; };
  const auto check = [](const Agent& agent) {
    EXPECT_GT(agent.contactForceOn(1), real(0.1)) << "the arm's tip pushes the ball";
  };
  expectSolversAgree(build, drive, 50, isFloat ? real(1e-3) : real(1e-8), check);

  for (const ContactSolverKind kind : {ContactSolverKind::Baraff, ContactSolverKind::GaussSeidel}) {
    Simulator simulator(real(0.01));
    simulator.setContactSolver(kind);
    tightenGaussSeidel(simulator);
    Agent& agent = build(simulator);
    const PhysicalObject& ball = simulator.objects[1];
    for (int step = 0; step < 100; ++step) {
      drive(agent);
      simulator.advanceTime();
      EXPECT_LT(scenes::largestOverlap(simulator), real(0.01));
    }
    EXPECT_GT(ball.v.x, real(0.1)) << "the ball is pushed";
    EXPECT_GT(ball.r.x, real(3.1));
    const ArticulatedBody& body = agent.articulatedBody();
    Vector2 momentum = ball.v * ball.m;
    for (int b = -1; b < agent.linkCount(); ++b) momentum += agent.bodyVelocity(b) * body.mass(b);
    EXPECT_NEAR(momentum.x, 2, 100 * loose);
    EXPECT_NEAR(momentum.y, 0, 100 * loose);
  }
}

/// Expects none of @p agent's self-contacts at @p step between a link and its parent: they
/// overlap at their joint and must be left untouched.
void expectNoContactBetweenNeighbours(const Agent& agent, int step) {
  for (std::size_t k = 0; k < agent.contacts().size(); ++k) {
    const LinkContactInfo c = agent.linkContact(k);
    if (c.other != &agent) continue;
    const int other = Agent::bodyOf(*c.otherPrimitive);
    EXPECT_NE(agent.parent(c.body), other) << "step " << step;
    EXPECT_NE(agent.parent(other), c.body) << "step " << step;
  }
}

TEST_P(ArticulatedAgentTest, FoldedChainTouchesItselfWithoutInterpenetrating) {
  // A chain of 5 links curled by its joint torques: links that are not neighbours meet (and
  // the last ones reach the base). Self-contacts must appear and hold.
  Simulator simulator(real(0.01));
  simulator.setContactSolver(GetParam());
  auto& agent = simulator.registerObject(std::make_unique<Agent>(
      std::vector<ArticulatedBasePart>{ArticulatedBasePart::circle(real(0.5), 2)},
      std::vector<ArticulatedLimb>{
          ArticulatedLimb::chain({real(0.5), 0}, 5, real(0.8), real(0.15), real(0.5))}));
  for (int i = 1; i < 5; ++i) agent.setJointTorque(i, real(0.3));
  int self = 0;
  for (int step = 0; step < 600; ++step) {
    simulator.advanceTime();
    self += selfContacts(agent);
    EXPECT_LT(scenes::largestOverlap(simulator), real(0.02)) << "step " << step;
    expectNoContactBetweenNeighbours(agent, step);
  }
  EXPECT_GT(self, 0) << "the folded chain should touch itself";
  // Frictionless, the curled chain may keep sliding along itself, but slowly: the contacts,
  // not the links passing through each other, stop the curl.
  for (int i = 0; i < 5; ++i) EXPECT_LT(std::abs(agent.jointRate(i)), real(0.2)) << "joint " << i;
}

/// An agent whose self-collision rules can be set again after registration: every part apart
/// from every other, or the usual rules (a link apart from its parent only).
class RuledAgent : public Agent {
 public:
  using Agent::Agent;
  void setRules(bool allApart) {
    std::vector<std::uint32_t> parts(basePartCount(), 0);
    std::vector<std::pair<std::uint32_t, std::uint32_t>> apart;
    for (int i = 0; i < linkCount(); ++i) {
      const auto part = static_cast<std::uint32_t>(i + 1);
      parts.push_back(part);
      if (allApart)
        for (std::uint32_t other = 0; other < part; ++other) apart.emplace_back(part, other);
      else
        apart.emplace_back(part, static_cast<std::uint32_t>(parent(i) + 1));
    }
    selfCollision_.assign(parts, apart);
  }
  void setFilter(const SelfCollisionFilter& filter) { selfCollision_ = filter; }
};

/// The folded chain of FoldedChainTouchesItselfWithoutInterpenetrating with 60 fixed circles
/// in a row far away: more shapes than the broad phase tests pair by pair, strung along x, so
/// the sweep finds the pairs and leaves out those of shapes that never touch.
RuledAgent& addFoldedChainAmongCircles(Simulator& simulator) {
  for (int k = 0; k < 60; ++k) {
    auto& circle = simulator.registerObject(std::make_unique<Circle>(real(0.3), 1));
    circle.r = {real(k), -40};
    circle.fixed = true;
  }
  auto& agent = simulator.registerObject(std::make_unique<RuledAgent>(
      std::vector<ArticulatedBasePart>{ArticulatedBasePart::circle(real(0.5), 2)},
      std::vector<ArticulatedLimb>{
          ArticulatedLimb::chain({real(0.5), 0}, 5, real(0.8), real(0.15), real(0.5))}));
  for (int i = 1; i < 5; ++i) agent.setJointTorque(i, real(0.3));
  return agent;
}

/// The self-contacts of @p agent summed over @p steps steps of @p simulator.
int selfContactsOver(Simulator& simulator, const Agent& agent, int steps) {
  int self = 0;
  for (int step = 0; step < steps; ++step) {
    simulator.advanceTime();
    self += selfContacts(agent);
  }
  return self;
}

TEST_P(ArticulatedAgentTest, FoldedChainAmongManyShapesTouchesItselfAsTheRulesSay) {
  // The folded chain among many shapes (the sweep's path). Rules set again after
  // registration are followed: no self-contact while every part is apart from every other,
  // then contacts once the usual rules are back.
  Simulator simulator(real(0.01));
  simulator.setContactSolver(GetParam());
  RuledAgent& agent = addFoldedChainAmongCircles(simulator);
  agent.setRules(true);
  EXPECT_EQ(selfContactsOver(simulator, agent, 300), 0) << "every part is apart from every other";
  agent.setRules(false);
  int self = 0;
  for (int step = 0; step < 300; ++step) {
    simulator.advanceTime();
    self += selfContacts(agent);
    // (Links that passed through each other while apart may still overlap: not checked.)
    expectNoContactBetweenNeighbours(agent, step);
  }
  EXPECT_GT(self, 0) << "the folded chain should touch itself under the usual rules";
}

TEST(ArticulatedAgentRules, ComposedBodiesInARowTouchTheirNeighboursNotThemselves) {
  // Rigid bodies of two overlapping circles each, 60 in a row along x, each overlapping the
  // next: the sweep finds the pairs, leaving out each body's own pair (its shapes never
  // touch); the pairs of neighbours remain.
  Simulator simulator(real(0.01));
  std::vector<ComposedPhysicalObject*> bodies;
  for (int k = 0; k < 60; ++k) {
    auto body = std::make_unique<ComposedPhysicalObject>();
    body->add(std::make_unique<Circle>(real(0.32), 1), {real(-0.2), 0});
    body->add(std::make_unique<Circle>(real(0.32), 1), {real(0.2), 0});
    body->r = {real(k), 0};
    bodies.push_back(&simulator.registerObject(std::move(body)));
  }
  simulator.advanceTime();
  for (std::size_t k = 0; k < bodies.size(); ++k) {
    int withNext = 0;
    for (const ContactInfo& c : bodies[k]->contacts()) {
      EXPECT_NE(c.other, bodies[k]) << "body " << k;
      if (k + 1 < bodies.size() && c.other == bodies[k + 1]) ++withNext;
    }
    if (k + 1 < bodies.size()) {
      EXPECT_GT(withNext, 0) << "body " << k;
    }
  }
}

TEST(ArticulatedAgentRules, AFiltersStampFollowsItsOwnChangesOnly) {
  // docs/Design.md: no global mutable state. A filter's stamp counts its own changes, whatever
  // other filters do (an agent built here sets its own), and grows at every change, copies
  // assigned included, so that a simulator that kept it sees every change.
  const auto arm = makeArm(3);  // its filter's rules, assigned before this filter's
  const std::vector<std::uint32_t> parts = {0, 1, 2};
  const std::vector<std::pair<std::uint32_t, std::uint32_t>> apart = {{0, 1}};
  SelfCollisionFilter filter;
  EXPECT_EQ(filter.stamp(), 0u);
  filter.assign(parts, apart);
  EXPECT_EQ(filter.stamp(), 1u) << "another filter's rules moved this filter's stamp";
  SelfCollisionFilter other;
  other.assign(parts, {});
  other.assign(parts, {});
  other.assign(parts, {});
  const SelfCollisionFilter copy(other);
  EXPECT_EQ(copy.stamp(), other.stamp());
  const std::uint64_t before = filter.stamp();
  filter = other;
  EXPECT_GT(filter.stamp(), before);
  EXPECT_TRUE(filter.mayTouch(0, 1)) << "the rules assigned";
  other = copy;  // the same rules: still a change of this filter
  EXPECT_GT(other.stamp(), copy.stamp());
}

TEST_P(ArticulatedAgentTest, RulesAssignedBackFromACopyAreFollowed) {
  // The folded chain among many shapes (the sweep's path): every part apart, then the usual
  // rules back as a copy of the filter kept from before (an assignment, not assign()).
  Simulator simulator(real(0.01));
  simulator.setContactSolver(GetParam());
  RuledAgent& agent = addFoldedChainAmongCircles(simulator);
  const SelfCollisionFilter usual = agent.selfCollision();
  agent.setRules(true);
  EXPECT_EQ(selfContactsOver(simulator, agent, 300), 0) << "every part is apart from every other";
  agent.setFilter(usual);
  EXPECT_GT(selfContactsOver(simulator, agent, 300), 0)
      << "the folded chain should touch itself under the usual rules";
}

TEST(ArticulatedAgentRules, NearPairsOfAFilterAnswerAsTheirPartsLists) {
  // Random rules (parts of several primitives in any order, pairs repeated or of one part):
  // the near pairs, answered from the precomputed words, as the parts' lists say.
  std::uint64_t seed = 777;
  const auto next = [&seed](std::uint32_t range) {
    seed = seed * 6364136223846793005ull + 1442695040888963407ull;
    return static_cast<std::uint32_t>((seed >> 33) % range);
  };
  for (int trial = 0; trial < 4; ++trial) {
    std::vector<std::uint32_t> partOf(200);
    for (std::uint32_t& part : partOf) part = next(trial < 2 ? 30 : 200);
    std::vector<std::pair<std::uint32_t, std::uint32_t>> apart;
    for (int k = 0; k < 80; ++k) apart.emplace_back(next(30), next(30));
    apart.emplace_back(3, 3);
    apart.emplace_back(4, 5);
    apart.emplace_back(5, 4);
    SelfCollisionFilter filter;
    filter.assign(partOf, apart);
    for (std::size_t k = 0; k < partOf.size(); ++k)
      for (std::size_t d = 1; d <= 64 && k + d < partOf.size(); ++d)
        ASSERT_EQ(filter.mayTouch(k, k + d), filter.partsMayTouch(partOf[k], partOf[k + d]))
            << "trial " << trial << ": " << k << " and " << k + d;
  }
}

TEST(ArticulatedAgentRules, SweepLeavesOutExactlyThePairsMarkedNeverPaired) {
  // Random boxes along x: the sweep with some pairs marked gives the pairs of the sweep
  // without marks, in the same order, less the marked ones.
  std::uint64_t seed = 12345;
  const auto next = [&seed] {
    seed = seed * 6364136223846793005ull + 1442695040888963407ull;
    return static_cast<real>(seed >> 40) / static_cast<real>(1 << 24);
  };
  std::vector<BoundingBox> boxes;
  for (int k = 0; k < 300; ++k) {
    const Vector2 centre{real(k) * real(0.5) + next(), next()};
    const Vector2 half{real(0.2) + next() / 2, real(0.2) + next() / 2};
    boxes.push_back({centre - half, centre + half});
  }
  std::vector<std::uint64_t> never(boxes.size());
  for (std::uint64_t& word : never)
    word = static_cast<std::uint64_t>(next() * real(1 << 20)) * 0x9E3779B97F4A7C15ull;
  SweepAndPrune plain;
  SweepAndPrune filtered;
  filtered.setNeverPaired(never);
  std::vector<BoxPair> all;
  std::vector<BoxPair> kept;
  for (int call = 0; call < 2; ++call) {  // the second from the last order
    all.clear();
    kept.clear();
    ASSERT_TRUE(plain.findPairs(boxes, 4, all));
    ASSERT_TRUE(filtered.findPairs(boxes, 4, kept));
    std::vector<BoxPair> expected;
    std::size_t marked = 0;
    for (const BoxPair& pair : all) {
      const std::uint32_t gap = pair.second - pair.first;
      if (gap <= 64 && ((never[pair.first] >> (gap - 1)) & 1) != 0) {
        ++marked;
        continue;
      }
      expected.push_back(pair);
    }
    EXPECT_GT(marked, 0u);
    ASSERT_EQ(kept.size(), expected.size());
    for (std::size_t k = 0; k < kept.size(); ++k) {
      EXPECT_EQ(kept[k].first, expected[k].first);
      EXPECT_EQ(kept[k].second, expected[k].second);
    }
    for (BoundingBox& box : boxes) box = {box.lower + Vector2{0, real(0.01)}, box.upper};
  }
  // Marks for another count of boxes are not used.
  filtered.setNeverPaired(std::span<const std::uint64_t>(never).first(10));
  all.clear();
  kept.clear();
  ASSERT_TRUE(plain.findPairs(boxes, 4, all));
  ASSERT_TRUE(filtered.findPairs(boxes, 4, kept));
  EXPECT_EQ(kept.size(), all.size());
}

TEST(ArticulatedAgentSolvers, SelfContactForcesAgreeBetweenBaraffAndGaussSeidel) {
  // The curled chain of the test above, once its links press on each other (both sides of
  // each self-contact are the same object's: the LCP row reads J_A + J_B).
  const auto build = [](Simulator& simulator) -> Agent& {
    auto& agent = simulator.registerObject(std::make_unique<Agent>(
        std::vector<ArticulatedBasePart>{ArticulatedBasePart::circle(real(0.5), 2)},
        std::vector<ArticulatedLimb>{
            ArticulatedLimb::chain({real(0.5), 0}, 5, real(0.8), real(0.15), real(0.5))}));
    for (int i = 1; i < 5; ++i) agent.setJointTorque(i, real(0.3));
    return agent;
  };
  const auto check = [](const Agent& agent) {
    EXPECT_GT(selfContacts(agent), 0);
    EXPECT_GT(agent.contactForceOn(4), real(0.1)) << "the last link presses on the chain";
  };
  expectSolversAgree(
      build, [](Agent&) {}, 590, isFloat ? real(1e-3) : real(1e-8), check);
}

// ---------------------------------------------------------------------------------------------
// Servos

TEST_P(ArticulatedAgentTest, StiffServoConvergesWithoutOscillation) {
  // One link on a fixed base: effective inertia d = I + m l^2 about the joint; the implicit
  // servo shrinks the error by d / (d + k dt) per step, here 1 / 1001.
  Simulator simulator(real(0.01));
  simulator.setContactSolver(GetParam());
  auto& agent = simulator.registerObject(makeArm(1));
  agent.fixed = true;
  const ArticulatedLink& link = agent.articulatedBody().link(0);
  const real d = link.inertia + link.mass * link.centerOfMass.lengthSquared();
  const real k = 1000 * d / simulator.timestep();
  agent.setServoTarget(0, real(0.8), k);
  real error = real(0.8);
  for (int step = 0; step < 4; ++step) {
    simulator.advanceTime();
    const real next = real(0.8) - agent.jointAngle(0);
    EXPECT_GE(next, 0) << "overshoot at step " << step;
    EXPECT_NEAR(next, error / 1001, tight);
    error = next;
  }

  // Huge gains on a floating chain, with the servos holding against torques: converges to the
  // targets, nothing blows up.
  Simulator chain(real(0.01));
  chain.setContactSolver(GetParam());
  auto& arm = chain.registerObject(makeArm(6));
  for (int i = 0; i < 6; ++i) {
    arm.setServoTarget(i, real(0.25) * std::cos(real(i)), real(1e9));
    arm.setJointTorque(i, real(0.5));
  }
  real largest = std::numeric_limits<real>::max();
  for (int step = 0; step < 10; ++step) {
    chain.advanceTime();
    real now = 0;
    for (int i = 0; i < 6; ++i)
      now = std::max(now, std::abs(arm.jointAngle(i) - real(0.25) * std::cos(real(i))));
    EXPECT_LE(now, std::max(largest, real(isFloat ? 1e-5 : 1e-9))) << "step " << step;
    largest = now;
  }
  // The residual error is the torque over the gain: 0.5 / 1e9.
  EXPECT_LT(largest, isFloat ? real(1e-4) : real(1e-8));
  for (int i = 0; i < 6; ++i) EXPECT_NEAR(arm.servoTorque(i), real(-0.5), real(1e-3));
  arm.clearServo(2);
  EXPECT_FALSE(arm.hasServo(2));
  // A cleared servo leaves its joint free from the next step: no damping, no servo torque; the
  // others keep theirs. Clearing them all frees every joint.
  chain.advanceTime();
  EXPECT_EQ(arm.articulatedBody().jointDamping(2), 0);
  EXPECT_EQ(arm.servoTorque(2), 0);
  EXPECT_EQ(arm.articulatedBody().jointDamping(3), real(1e9) * chain.timestep());
  EXPECT_NE(arm.servoTorque(3), 0);
  for (int i = 0; i < 6; ++i) arm.clearServo(i);
  chain.advanceTime();
  for (int i = 0; i < 6; ++i) {
    EXPECT_EQ(arm.articulatedBody().jointDamping(i), 0);
    EXPECT_EQ(arm.servoTorque(i), 0);
  }
}

// ---------------------------------------------------------------------------------------------
// Determinism and allocation

/// A busy scene: an arm with limits and servos on a floor, pushing free circles.
Agent& addBusyScene(Simulator& simulator) {
  scenes::addWalls(simulator, 12, 8);
  ArticulatedLimb legs({real(0.4), 0});
  const int thigh = legs.addLink(-1, real(0.9), real(0.12), real(0.4), real(-0.8));
  legs.addLink(thigh, real(0.8), real(0.1), real(0.3), real(-0.5));
  legs.addLink(thigh, real(0.6), real(0.1), real(0.3), real(0.6));  // a fork at the thigh's tip
  legs.setLimits(1, real(-1.2), real(0.2));
  ArticulatedLimb arm = ArticulatedLimb::chain({real(-0.5), real(0.2)}, 4, real(0.7), real(0.1),
                                               real(0.3), real(2.5));
  auto& agent = simulator.registerObject(std::make_unique<Agent>(
      std::vector<ArticulatedBasePart>{
          ArticulatedBasePart::capsule(real(0.5), real(0.3), 2),
          ArticulatedBasePart::circle(real(0.35), 1, {real(-0.5), real(0.2)})},
      std::vector<ArticulatedLimb>{legs, arm}));
  agent.setPose({4, real(2.2)}, real(0.1));
  // The arm swings slowly toward the body; its elbow is held stiff at its angle.
  agent.setServoTarget(3, real(0.5), 2);
  agent.setServoTarget(4, 0, real(1e6));
  for (int i = 0; i < 6; ++i) {
    auto& ball = simulator.registerObject(std::make_unique<Circle>(real(0.3), 1));
    ball.r = {real(5.5) + real(0.7) * real(i), real(1) + real(0.3) * real(i % 2)};
  }
  return agent;
}

void driveBusy(Agent& agent, int step) {
  agent.externalForce = {real(1.5), real(-2)};
  agent.setJointTorque(0, real(0.6) * std::sin(real(0.05) * real(step)));
  agent.setJointTorque(1, real(-0.4));
  agent.applyLinkForce(6, {0, real(-0.3)}, agent.linkTip(6));
}

std::uint64_t agentHash(const Simulator& simulator, const Agent& agent) {
  std::uint64_t hash = scenes::stateHash(simulator);
  for (int i = 0; i < agent.linkCount(); ++i) {
    const real values[] = {agent.jointAngle(i), agent.jointRate(i)};
    for (const real value : values) {
      unsigned char bytes[sizeof(real)];
      std::memcpy(bytes, &value, sizeof(real));
      for (const unsigned char byte : bytes) hash = (hash ^ byte) * 1099511628211ull;
    }
  }
  return hash;
}

TEST_P(ArticulatedAgentTest, SameSceneGivesBitIdenticalRuns) {
  std::uint64_t hashes[2];
  for (std::uint64_t& hash : hashes) {
    Simulator simulator(real(0.01));
    simulator.setContactSolver(GetParam());
    Agent& agent = addBusyScene(simulator);
    int limited = 0;
    for (int step = 0; step < 300; ++step) {
      driveBusy(agent, step);
      simulator.advanceTime();
      // The limited knee stays within its limits among the contacts (to the overlap allowed).
      EXPECT_GE(agent.jointAngle(1), real(-1.2) - real(1e-3));
      EXPECT_LE(agent.jointAngle(1), real(0.2) + real(1e-3));
      limited += agent.limitTorque(1) != 0 ? 1 : 0;
    }
    EXPECT_GT(limited, 0);
    EXPECT_GT(simulator.contacts.size(), 0u);
    hash = agentHash(simulator, agent);
  }
  EXPECT_EQ(hashes[0], hashes[1]);
}

/// A scene that comes to rest with every kind of constraint active: the agent, pushed right and
/// down, squeezes a free ball against the right wall, its base on the floor, its chain curled
/// down onto the floor, its middle joint on its upper limit and its last joint on a servo.
Agent& addSteadyScene(Simulator& simulator) {
  scenes::addWalls(simulator, 12, 8);
  ArticulatedLimb tail =
      ArticulatedLimb::chain({real(-0.5), 0}, 3, real(0.8), real(0.1), real(0.4), pi<real>);
  tail.setLimits(1, real(-0.3), real(0.3));
  auto& agent = simulator.registerObject(std::make_unique<Agent>(
      std::vector<ArticulatedBasePart>{ArticulatedBasePart::circle(real(0.5), 2)},
      std::vector<ArticulatedLimb>{tail}));
  agent.setPose({9, real(0.52)}, 0);
  agent.setJointTorque(0, real(0.3));
  agent.setJointTorque(1, real(0.5));
  agent.setServoTarget(2, real(0.2), 100);
  auto& ball = simulator.registerObject(std::make_unique<Circle>(real(0.5), 1));
  ball.r = {real(11.45), real(0.52)};
  return agent;
}

TEST_P(ArticulatedAgentTest, StepsAllocateNothingAfterWarmUp) {
  // The buffers (the agent's and the simulator's) grow only when a step needs more than any
  // earlier one; once the scene has settled, the steps allocate nothing.
  Simulator simulator(real(0.01));
  simulator.setContactSolver(GetParam());
  Agent& agent = addSteadyScene(simulator);
  // The broad phase's candidate pairs vary as the chain settles (they are not contacts): room
  // for them up front, as for any scene (Simulator::reserveContacts()).
  simulator.reserveContacts(64);
  const auto drive = [&agent] { agent.externalForce = {1, -1}; };
  for (int step = 0; step < 400; ++step) {
    drive();
    simulator.advanceTime();
  }
  ASSERT_GT(agent.contactForceOn(-1), real(0.1)) << "the base presses on the ball and floor";
  ASSERT_GT(agent.contactForceOn(1) + agent.contactForceOn(2), 0) << "the chain on the floor";
  ASSERT_LT(agent.limitTorque(1), 0) << "the middle joint on its upper limit";
  const long before = test::allocationCount();
  for (int step = 0; step < 100; ++step) {
    drive();
    simulator.advanceTime();
  }
  EXPECT_EQ(test::allocationCount() - before, 0);
}

INSTANTIATE_TEST_SUITE_P(BothSolvers, ArticulatedAgentTest,
                         ::testing::Values(ContactSolverKind::Baraff,
                                           ContactSolverKind::GaussSeidel),
                         solverName);

// ---------------------------------------------------------------------------------------------
// Self-collision rules, drawing, validation

TEST(ArticulatedAgentRules, NeighboursNeverCollideOthersDo) {
  // Base; limb A: 0 -> 1, with 2 and 3 both on 1's tip (a fork); limb B: 4 on the base elsewhere.
  ArticulatedLimb a({real(0.5), 0});
  a.addLink(-1, 1, real(0.1), 1);
  a.addLink(0, 1, real(0.1), 1);
  a.addLink(1, 1, real(0.1), 1);
  a.addLink(1, 1, real(0.1), 1);
  ArticulatedLimb b({real(-0.5), 0});
  b.addLink(-1, 1, real(0.1), 1);
  Agent agent({ArticulatedBasePart::circle(real(0.5), 1),
               ArticulatedBasePart::circle(real(0.2), 1, {0, 1})},
              {a, b});
  const auto collide = [&](int x, int y) {
    const Primitive& px = x < 0 ? agent.basePart(static_cast<std::size_t>(-1 - x))
                                : static_cast<const Primitive&>(agent.linkShape(x));
    const Primitive& py = y < 0 ? agent.basePart(static_cast<std::size_t>(-1 - y))
                                : static_cast<const Primitive&>(agent.linkShape(y));
    EXPECT_EQ(agent.selfCollides(px, py), agent.selfCollides(py, px));
    return agent.selfCollides(px, py);
  };
  // Indices here: -1 and -2 are the two base parts; 0..4 the links.
  EXPECT_FALSE(collide(-1, -2));  // one rigid base
  EXPECT_FALSE(collide(-1, 0));   // the base and a link on it
  EXPECT_FALSE(collide(-2, 4));
  EXPECT_FALSE(collide(0, 1));  // parent and child
  EXPECT_FALSE(collide(2, 1));
  EXPECT_FALSE(collide(2, 3));  // the fork: siblings on one joint point
  EXPECT_TRUE(collide(0, 2));   // grandparent and grandchild
  EXPECT_TRUE(collide(-1, 1));  // a link not on the base
  EXPECT_TRUE(collide(0, 4));   // siblings on the base at different points
  EXPECT_TRUE(collide(3, 4));
  EXPECT_EQ(Agent::bodyOf(agent.linkShape(3)), 3);
  EXPECT_EQ(Agent::bodyOf(agent.basePart(1)), -1);
  // The words of pairs that never touch say what mayTouch() says, pair by pair.
  const SelfCollisionFilter& filter = agent.selfCollision();
  const std::size_t count = agent.primitives().size();
  for (std::size_t k = 0; k < count; ++k)
    for (std::size_t d = 1; d <= 64; ++d) {
      const bool apart = ((filter.apartAfter(k) >> (d - 1)) & 1) != 0;
      EXPECT_EQ(apart, k + d < count && !filter.mayTouch(k, k + d)) << k << " " << d;
    }
  EXPECT_EQ(SelfCollisionFilter().apartAfter(3), 0u);
}

TEST(ArticulatedAgentRules, LinkCapsulesLieHalfWayAlongTheirLinksBitForBit) {
  // Each capsule's centre is the link frame's point (half length, 0), placed from the
  // kinematics' centres of mass when every link's is there (the usual capsule link), else
  // computed: the same bits either way, also with one link's centre of mass elsewhere.
  for (const bool offCentre : {false, true}) {
    ArticulatedLimb limb({real(0.5), 0});
    for (int i = 0; i < 4; ++i) {
      ArticulatedLink link = ArticulatedLink::capsule(i - 1, i == 0 ? Vector2{} : Vector2{1, 0},
                                                      real(0.5), real(0.1), real(0.5));
      if (offCentre && i == 2) link.centerOfMass = {real(0.3), real(0.05)};
      limb.addLink(link, real(0.1), real(0.3) * real(i + 1));
    }
    Simulator simulator(real(0.01));
    auto& agent = simulator.registerObject(std::make_unique<Agent>(
        std::vector<ArticulatedBasePart>{ArticulatedBasePart::circle(real(0.5), 2)},
        std::vector<ArticulatedLimb>{limb}));
    agent.setPose({real(0.7), real(-0.2)}, real(0.9));
    agent.setJointTorque(1, real(0.5));
    for (int step = 0; step < 5; ++step) simulator.advanceTime();
    for (int i = 0; i < agent.linkCount(); ++i) {
      const Vector2 centre = agent.articulatedBody().toWorld(i, {real(0.5), 0});
      EXPECT_EQ(bitsOf(agent.linkShape(i).r.x), bitsOf(centre.x)) << offCentre << " link " << i;
      EXPECT_EQ(bitsOf(agent.linkShape(i).r.y), bitsOf(centre.y)) << offCentre << " link " << i;
    }
  }
}

TEST(ArticulatedAgentRules, LinkCapsulesCarryTheDirectionOfTheirAngle) {
  // The agent places each link's capsule with the kinematics' (cos, sin) of its angle, which
  // the simulator reuses for the capsule's end points (Primitive::direction()): it must be
  // exactly what cos and sin of the angle give, and follow an angle set by hand.
  Simulator simulator(real(0.01));
  Agent& agent = simulator.registerObject(makeArm(3, real(0.4)));
  agent.setJointTorque(1, real(0.5));
  for (int step = 0; step < 5; ++step) simulator.advanceTime();
  for (int i = 0; i < agent.linkCount(); ++i) {
    CappedRectangle& shape = agent.linkShape(i);
    ASSERT_NE(shape.alpha, 0);
    const Vector2 direction = shape.direction();
    EXPECT_EQ(direction.x, std::cos(shape.alpha));
    EXPECT_EQ(direction.y, std::sin(shape.alpha));
  }
  CappedRectangle& shape = agent.linkShape(2);
  shape.alpha = real(2.5);
  EXPECT_EQ(shape.direction().x, std::cos(real(2.5)));
  EXPECT_EQ(shape.direction().y, std::sin(real(2.5)));
}

TEST(ArticulatedAgentRules, DrawsPartsLinksAndJoints) {
  struct Counter : GUI {
    int circles = 0, capsules = 0;
    void drawCircle(Vector2, real, real, Color, Color) override { ++circles; }
    void drawCapsule(Vector2, Vector2, real, Color, Color) override { ++capsules; }
    void drawLine(Vector2, Vector2, Color, real) override {}
    void drawPolygon(std::span<const Vector2>, Color, Color) override {}
    void drawText(Vector2, std::string_view, Color) override {}
    void drawBorder(Vector2, Vector2, Color) override {}
  } gui;
  auto agent = makeArm(4);
  agent->draw(gui);
  EXPECT_EQ(gui.circles, 1 + 4);  // the base, then one circle per joint
  EXPECT_EQ(gui.capsules, 4);
}

TEST(ArticulatedAgentRules, CentreOfMassAndPoseOfAComposedBase) {
  // Two parts of masses 1 and 3 at x = 0 and x = 2: the centre of mass is at x = 1.5, and
  // the agent's r is there until it is moved.
  Agent agent({ArticulatedBasePart::circle(real(0.5), 1, {0, 0}),
               ArticulatedBasePart::capsule(real(0.4), real(0.2), 3, {2, 0}, real(0.5))},
              {ArticulatedLimb::chain({2, real(0.3)}, 2, 1, real(0.1), 1)});
  EXPECT_EQ(agent.centreOfMassOffset(), (Vector2{real(1.5), 0}));
  EXPECT_EQ(agent.r, (Vector2{real(1.5), 0}));
  EXPECT_NEAR(agent.m, 4, tight);
  agent.setPose({10, 10}, pi<real> / 2);
  // The capsule part's centre is 0.5 right of the centre of mass in the description: now 0.5 up.
  EXPECT_NEAR(agent.basePart(1).r.x, 10, tight);
  EXPECT_NEAR(agent.basePart(1).r.y, real(10.5), tight);
  EXPECT_NEAR(agent.basePart(1).alpha, real(0.5) + pi<real> / 2, tight);
  // The limb's attachment (2, 0.3) is (0.5, 0.3) from the centre of mass: turned, (-0.3, 0.5).
  EXPECT_NEAR(agent.jointPosition(0).x, real(9.7), tight);
  EXPECT_NEAR(agent.jointPosition(0).y, real(10.5), tight);
  EXPECT_NEAR(agent.linkTip(1).y, real(12.5), tight);
}

template <class Action>
std::string thrownField(Action&& action) {
  try {
    action();
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find(e.field()), std::string::npos) << e.what();
    return e.field();
  } catch (...) {
    return "<other exception>";
  }
  return "<no exception>";
}

TEST(ArticulatedAgentRules, LoopsZeroLengthLinksAndBadInputAreRefusedNamingTheField) {
  ArticulatedLimb limb({real(0.5), 0});
  limb.addLink(-1, 1, real(0.1), 1);
  // A loop can only be described by a parent that is not an earlier link.
  EXPECT_EQ(thrownField([&] { limb.addLink(1, 1, real(0.1), 1); }), "ArticulatedLink.parent");
  EXPECT_EQ(thrownField([&] { limb.addLink(5, 1, real(0.1), 1); }), "ArticulatedLink.parent");
  EXPECT_EQ(thrownField([&] { limb.addLink(-2, 1, real(0.1), 1); }), "ArticulatedLink.parent");
  ArticulatedLink self;
  self.parent = 1;  // the link being added, index 1, on itself
  EXPECT_EQ(thrownField([&] { limb.addLink(self, real(0.1)); }), "ArticulatedLink.parent");
  EXPECT_EQ(thrownField([&] { limb.addLink(0, 0, real(0.1), 1); }), "ArticulatedLink.length");
  ArticulatedLink flat;
  flat.parent = 0;
  flat.length = 0;
  EXPECT_EQ(thrownField([&] { limb.addLink(flat, real(0.1)); }), "ArticulatedLink.length");
  EXPECT_EQ(thrownField([&] { limb.addLink(0, 1, 0, 1); }), "ArticulatedLink.radius");
  EXPECT_EQ(thrownField([&] { limb.addLink(0, 1, real(0.1), 1, kNaN); }), "ArticulatedLimb.angle");
  EXPECT_EQ(thrownField([&] { limb.setLimits(0, 1, -1); }), "ArticulatedLink.qMax");
  EXPECT_EQ(thrownField([&] { limb.setLimits(3, -1, 1); }), "ArticulatedLimb.link");
  EXPECT_EQ(limb.linkCount(), 1) << "a refused link leaves the limb unchanged";
  EXPECT_EQ(thrownField([] { (void)ArticulatedLimb::chain({}, 0, 1, 1, 1); }),
            "ArticulatedLimb.count");
  EXPECT_EQ(thrownField([] { (void)ArticulatedLimb::chain({}, 3, 0, 1, 1); }),
            "ArticulatedLink.length");

  EXPECT_EQ(thrownField([&] { Agent agent({}, {limb}); }), "ArticulatedAgentBase.baseParts");
  EXPECT_EQ(thrownField([&] { Agent agent({ArticulatedBasePart::circle(-1, 1)}, {limb}); }),
            "ArticulatedBasePart.radius");
  EXPECT_EQ(
      thrownField([&] { Agent agent({ArticulatedBasePart::capsule(0, real(0.1), 1)}, {limb}); }),
      "ArticulatedBasePart.halfLength");

  Simulator simulator;
  auto& agent = simulator.registerObject(makeArm(2));
  EXPECT_EQ(thrownField([&] { agent.setJointTorque(2, 1); }), "ArticulatedAgentBase.joint");
  EXPECT_EQ(thrownField([&] { agent.setJointTorque(0, kNaN); }),
            "ArticulatedAgentBase.jointTorque");
  EXPECT_EQ(thrownField([&] { agent.setServoTarget(0, 1, 0); }), "ArticulatedAgentBase.servoGain");
  EXPECT_EQ(thrownField([&] { agent.setServoTarget(-1, 1, 1); }), "ArticulatedAgentBase.joint");
  EXPECT_EQ(thrownField([&] { agent.applyLinkForce(2, {1, 0}, {}); }), "ArticulatedAgentBase.body");
  EXPECT_EQ(thrownField([&] {
              agent.applyLinkForceAtCenterOfMass(-2, {1, 0});
            }),
            "ArticulatedAgentBase.body");
  EXPECT_EQ(thrownField([&] {
              agent.applyLinkForceAtCenterOfMass(0, {kNaN, 0});
            }),
            "ArticulatedAgentBase.force");
  EXPECT_EQ(thrownField([&] {
              agent.applyForceAtEveryLinkCenterOfMass({0, kNaN});
            }),
            "ArticulatedAgentBase.force");
  EXPECT_EQ(thrownField([&] { agent.setPose({kNaN, 0}, 0); }), "ArticulatedAgentBase.position");
  // The getters check their index as the setters do (two joints: 0 and 1; bodies -1 to 1).
  for (const int i : {-1, 2, 99}) {
    SCOPED_TRACE(i);
    EXPECT_EQ(thrownField([&] { (void)agent.jointAngle(i); }), "ArticulatedAgentBase.joint");
    EXPECT_EQ(thrownField([&] { (void)agent.jointRate(i); }), "ArticulatedAgentBase.joint");
    EXPECT_EQ(thrownField([&] { (void)agent.jointPosition(i); }), "ArticulatedAgentBase.joint");
    EXPECT_EQ(thrownField([&] { (void)agent.linkTip(i); }), "ArticulatedAgentBase.joint");
    EXPECT_EQ(thrownField([&] { (void)agent.linkShape(i); }), "ArticulatedAgentBase.joint");
    EXPECT_EQ(thrownField([&] { (void)agent.jointTorque(i); }), "ArticulatedAgentBase.joint");
    EXPECT_EQ(thrownField([&] { (void)agent.hasServo(i); }), "ArticulatedAgentBase.joint");
    EXPECT_EQ(thrownField([&] { (void)agent.servoTarget(i); }), "ArticulatedAgentBase.joint");
    EXPECT_EQ(thrownField([&] { (void)agent.servoGain(i); }), "ArticulatedAgentBase.joint");
    EXPECT_EQ(thrownField([&] { (void)agent.servoTorque(i); }), "ArticulatedAgentBase.joint");
    EXPECT_EQ(thrownField([&] { (void)agent.limitTorque(i); }), "ArticulatedAgentBase.joint");
  }
  for (const int b : {-2, 2, 99}) {
    SCOPED_TRACE(b);
    EXPECT_EQ(thrownField([&] { (void)agent.centerOfMass(b); }), "ArticulatedAgentBase.body");
    EXPECT_EQ(thrownField([&] { (void)agent.bodyAngle(b); }), "ArticulatedAgentBase.body");
    EXPECT_EQ(thrownField([&] { (void)agent.bodyVelocity(b); }), "ArticulatedAgentBase.body");
    EXPECT_EQ(thrownField([&] { (void)agent.bodyAngularVelocity(b); }),
              "ArticulatedAgentBase.body");
    EXPECT_EQ(thrownField([&] { (void)agent.pointVelocity(b, {}); }), "ArticulatedAgentBase.body");
    EXPECT_EQ(thrownField([&] { (void)agent.contactForceOn(b); }), "ArticulatedAgentBase.body");
  }
  EXPECT_EQ(thrownField([&] { (void)agent.linkContact(agent.contacts().size()); }),
            "ArticulatedAgentBase.linkContact.k");
  EXPECT_EQ(thrownField([&] { (void)agent.jointAngle(1); }), "<no exception>");
  EXPECT_EQ(thrownField([&] { (void)agent.centerOfMass(-1); }), "<no exception>");

  // A non-finite pose is refused at registration, and the world is unchanged.
  auto bad = makeArm(2);
  bad->r = {std::numeric_limits<real>::infinity(), 0};
  EXPECT_EQ(thrownField([&] { simulator.registerObject(std::move(bad)); }),
            "ArticulatedAgentQuasistatic.r");
  EXPECT_EQ(simulator.objects.size(), 1u);
  auto margin = makeArm(1);
  margin->limitMargin = -1;
  EXPECT_EQ(thrownField([&] { simulator.registerObject(std::move(margin)); }),
            "ArticulatedAgentQuasistatic.limitMargin");
}

}  // namespace
}  // namespace thyrix
