// The world gravity field, Simulator::setGravity(): under F = m v a free body moves at the field's
// velocity; a body on a floor is held by its weight m |g|; the field gives the bits of the
// weight added by hand before each step (rigid bodies, custom objects, an articulated agent's
// links and base, an elastoid's bodies once each), with both contact solvers; a zero field
// changes nothing; bad input is refused.

#include "TestTolerances.h"
#include "support/SameAgentMotion.h"
#include "support/SolverCases.h"

#include <Scenes.h>
#include <ThyrixLite/Border.h>
#include <ThyrixLite/CappedRectangle.h>
#include <ThyrixLite/Circle.h>
#include <ThyrixLite/ComposedPhysicalObject.h>
#include <ThyrixLite/Elastoid.h>
#include <ThyrixLite/InvalidArgument.h>
#include <ThyrixLite/Simulator.h>
#include <ThyrixPro/ArticulatedAgentQuasistatic.h>
#include <ThyrixPro/ArticulatedLimb.h>
#include <ThyrixPro/ArticulatedLink.h>

#include <gtest/gtest.h>

#include <limits>
#include <memory>
#include <vector>

namespace thyrix {
namespace {

using test::bitsOf;
using test::loose;
using test::solverName;
using test::tight;

using Agent = ArticulatedAgentQuasistatic;

/// A circle that overrides a step hook, so the simulator weighs it through
/// PhysicalObject::applyWeight() rather than in the core shapes' pass.
class CustomCircle : public Circle {
 public:
  CustomCircle(real radius, real mass) : Circle(radius, mass) {}
  void control() override { ++controls; }
  int controls = 0;
};

/// A circle with its own phase-5 hook (that calls the default one) but the default
/// applyWeight(): the simulator weighs it once, by applyWeight(), before the hook.
class OwnHookCircle : public Circle {
 public:
  OwnHookCircle(real radius, real mass) : Circle(radius, mass) {}
  void computeDerivativesWithoutContacts() override {
    ++hooks;
    Circle::computeDerivativesWithoutContacts();
  }
  int hooks = 0;
};

/// A circle that overrides nothing: not a core shape by its type, so weighed by applyWeight().
class PlainSubclassCircle : public Circle {
 public:
  PlainSubclassCircle(real radius, real mass) : Circle(radius, mass) {}
};

/// A circle that floats: its applyWeight() adds nothing.
class Balloon : public Circle {
 public:
  Balloon(real radius, real mass) : Circle(radius, mass) {}
  void applyWeight(Vector2 /*gravity*/) override {}
};

/// Two bodies (a circle and a custom circle, mass 2 each) joined centre to centre by a link at
/// its rest length, so it pulls neither.
class Pair : public Elastoid {
 public:
  Pair() {
    left = &addBody(std::make_unique<Circle>(real(0.25), real(2)));
    right = &addBody(std::make_unique<CustomCircle>(real(0.25), real(2)));
    left->r = {1, 5};
    right->r = {3, 5};
    addLink(*left, {0, 0}, *right, {0, 0}, real(2), real(4));
  }
  Circle* left;
  CustomCircle* right;
};

class GravityTest : public ::testing::TestWithParam<ContactSolverKind> {};

// ---------------------------------------------------------------------------------------------
// Closed forms

TEST(Gravity, IsZeroByDefault) {
  const Simulator simulator;
  EXPECT_EQ(bitsOf(simulator.gravity().x), bitsOf(real(0)));
  EXPECT_EQ(bitsOf(simulator.gravity().y), bitsOf(real(0)));
}

TEST(Gravity, FreeBodiesMoveAtTheFieldsVelocityAndFixedOnesStay) {
  // F = m v: the weight m g moves a body of any mass at g, without turning it.
  const Vector2 g{real(0.3), real(-2.5)};
  const real dt = real(0.01);
  Simulator simulator(dt);
  simulator.setGravity(g);
  EXPECT_EQ(simulator.gravity(), g);
  auto& circle = simulator.registerObject(std::make_unique<Circle>(real(0.5), real(3)));
  auto& capsule =
      simulator.registerObject(std::make_unique<CappedRectangle>(real(1), real(0.25), real(0.7)));
  auto composed = std::make_unique<ComposedPhysicalObject>();
  composed->add(std::make_unique<Circle>(real(0.3), real(1)), {-1, 0});
  composed->add(std::make_unique<CappedRectangle>(real(0.4), real(0.1), real(5)), {1, 0}, 1);
  auto& body = simulator.registerObject(std::move(composed));
  auto& custom = simulator.registerObject(std::make_unique<CustomCircle>(real(0.5), real(4)));
  auto& fixed = simulator.registerObject(std::make_unique<Circle>(real(0.5), real(1)));
  circle.r = {0, 100};
  capsule.r = {10, 100};
  capsule.alpha = real(0.4);
  body.r = {20, 100};
  custom.r = {30, 100};
  fixed.r = {40, 100};
  fixed.fixed = true;
  PhysicalObject* movers[] = {&circle, &capsule, &body, &custom};
  std::vector<Vector2> starts;
  for (const PhysicalObject* mover : movers) starts.push_back(mover->r);

  const int steps = 50;
  for (int step = 0; step < steps; ++step) simulator.advanceTime();
  for (std::size_t k = 0; k < std::size(movers); ++k) {
    const PhysicalObject& mover = *movers[k];
    EXPECT_NEAR(mover.v.x, g.x, tight) << mover.typeName();
    EXPECT_NEAR(mover.v.y, g.y, tight) << mover.typeName();
    EXPECT_EQ(mover.omega, 0) << mover.typeName();
    EXPECT_NEAR(mover.r.x, starts[k].x + g.x * dt * steps, loose) << mover.typeName();
    EXPECT_NEAR(mover.r.y, starts[k].y + g.y * dt * steps, loose) << mover.typeName();
  }
  EXPECT_EQ(capsule.alpha, real(0.4));
  // A body only its weight pushes moves at g exactly (the shortcut writes the field).
  EXPECT_EQ(circle.v, g);
  EXPECT_EQ(fixed.v, Vector2{});
  EXPECT_EQ(fixed.r, (Vector2{40, 100}));
  EXPECT_EQ(custom.controls, steps);
}

TEST(Gravity, SubclassesAreWeighedOnceThroughApplyWeight) {
  // A subclass of Circle with its own hook, one with no override at all, and one whose
  // applyWeight() adds nothing: the first two fall at g (not 2 g: weighed once; mass 4, so
  // (m g) / m is g exactly), the balloon stays. Bodies registered after steps have run feel
  // the field from their first step.
  const Vector2 g{real(0.25), real(-1.5)};
  Simulator simulator(real(0.01));
  simulator.setGravity(g);
  auto& early = simulator.registerObject(std::make_unique<Circle>(real(0.5), real(3)));
  for (int step = 0; step < 5; ++step) simulator.advanceTime();
  auto& ownHook = simulator.registerObject(std::make_unique<OwnHookCircle>(real(0.5), real(4)));
  auto& plain = simulator.registerObject(std::make_unique<PlainSubclassCircle>(real(0.5), real(4)));
  auto& balloon = simulator.registerObject(std::make_unique<Balloon>(real(0.5), real(4)));
  auto& late = simulator.registerObject(std::make_unique<Circle>(real(0.5), real(3)));
  ownHook.r = {10, 0};
  plain.r = {20, 0};
  balloon.r = {30, 0};
  late.r = {40, 0};
  for (int step = 0; step < 10; ++step) simulator.advanceTime();
  EXPECT_EQ(ownHook.hooks, 10);
  EXPECT_EQ(ownHook.v, g);
  EXPECT_EQ(plain.v, g);
  EXPECT_EQ(balloon.v, Vector2{});
  EXPECT_EQ(balloon.r, (Vector2{30, 0}));
  EXPECT_EQ(late.v, g);
  EXPECT_EQ(early.v, g);
  for (const PhysicalObject* body :
       {static_cast<const PhysicalObject*>(&ownHook), static_cast<const PhysicalObject*>(&plain)}) {
    EXPECT_NEAR(body->r.y, g.y * real(0.1), loose);
    EXPECT_EQ(body->externalForce, Vector2{});
  }
  EXPECT_NEAR(late.r.x, 40 + g.x * real(0.1), loose);
}

TEST(Gravity, AddsToTheVelocityOfThePushedBody) {
  // v = F / m + g, the force reset after use as without a field.
  const Vector2 g{0, -1};
  Simulator simulator(real(0.01));
  simulator.setGravity(g);
  auto& circle = simulator.registerObject(std::make_unique<Circle>(real(0.5), real(2)));
  circle.externalForce = {3, 4};
  circle.externalTorque = 1;
  simulator.advanceTime();
  EXPECT_NEAR(circle.v.x, real(1.5), tight);
  EXPECT_NEAR(circle.v.y, real(1), tight);
  EXPECT_NEAR(circle.omega, 1 / circle.I, tight);
  EXPECT_EQ(circle.externalForce, Vector2{});
  EXPECT_EQ(circle.externalTorque, 0);
  simulator.advanceTime();
  EXPECT_EQ(circle.v, g);
  EXPECT_EQ(circle.omega, 0);
}

TEST_P(GravityTest, ABodyOnTheFloorIsHeldByItsWeight) {
  // The floor pushes back m |g| (here 2 x 3 = 6 N) and the circle stays where it rests.
  Simulator simulator(real(0.01));
  simulator.setContactSolver(GetParam());
  simulator.setGravity({0, -3});
  simulator.registerObject(std::make_unique<Border>(Vector2{0, 0}, Vector2{0, 1}));
  auto& circle = simulator.registerObject(std::make_unique<Circle>(real(0.5), real(2)));
  circle.r = {1, real(0.5)};
  for (int step = 0; step < 100; ++step) simulator.advanceTime();
  real force = 0;
  for (const GlobalContactInfo& contact : simulator.contacts) force += contact.force;
  EXPECT_NEAR(force, 6, loose);
  EXPECT_NEAR(circle.r.x, 1, tight);
  EXPECT_NEAR(circle.r.y, real(0.5), loose);
  EXPECT_NEAR(circle.v.y, 0, loose);
}

TEST(Gravity, AFreeArticulatedAgentFallsRigidlyAtTheFieldsVelocity) {
  // Each body weighed at its own centre of mass, m_b g: the translation at g with still joints
  // gives every body exactly its weight's velocity, so it solves (J^T D J) u = J^T F. Without
  // the base's weight (or with a link's missing) the agent would fold.
  const Vector2 g{real(-0.5), real(-2)};
  Simulator simulator(real(0.01));
  simulator.setGravity(g);
  ArticulatedLimb limb({real(0.5), 0});
  limb.addLink(-1, 1, real(0.1), real(0.5), real(0.3));
  limb.addLink(0, real(1.5), real(0.1), real(2), real(-0.4));
  limb.addLink(1, real(0.7), real(0.1), real(0.25), real(0.9));
  auto& agent = simulator.registerObject(std::make_unique<Agent>(
      std::vector<ArticulatedBasePart>{ArticulatedBasePart::circle(real(0.5), 3)},
      std::vector<ArticulatedLimb>{limb}));
  agent.setPose({2, 50}, real(0.2));
  for (int step = 0; step < 20; ++step) simulator.advanceTime();
  for (int b = Agent::base; b < agent.linkCount(); ++b) {
    EXPECT_NEAR(agent.bodyVelocity(b).x, g.x, loose) << b;
    EXPECT_NEAR(agent.bodyVelocity(b).y, g.y, loose) << b;
    EXPECT_NEAR(agent.bodyAngularVelocity(b), 0, loose) << b;
  }
  for (int i = 0; i < agent.linkCount(); ++i) EXPECT_NEAR(agent.jointRate(i), 0, loose) << i;
  EXPECT_NEAR(agent.r.x, 2 + g.x * real(0.2), loose);
  EXPECT_NEAR(agent.r.y, 50 + g.y * real(0.2), loose);
}

TEST(Gravity, AFixedBasesLinkHangsStraightDown) {
  // A fixed base and one free link, laid horizontally: the link's weight turns it about its
  // joint until its centre of mass is right under the joint; the base does not move.
  Simulator simulator(real(0.01));
  simulator.setGravity({0, -2});
  ArticulatedLimb limb({real(0.5), 0});
  limb.addLink(-1, 1, real(0.1), real(0.5), 0);
  auto& agent = simulator.registerObject(std::make_unique<Agent>(
      std::vector<ArticulatedBasePart>{ArticulatedBasePart::circle(real(0.5), 3)},
      std::vector<ArticulatedLimb>{limb}));
  agent.setPose({0, 10}, 0);
  agent.fixed = true;
  const Vector2 base = agent.centerOfMass(Agent::base);
  simulator.advanceTime();
  EXPECT_LT(agent.jointRate(0), 0) << "the link starts turning down";
  for (int step = 0; step < 2000; ++step) simulator.advanceTime();
  EXPECT_EQ(agent.centerOfMass(Agent::base), base);
  const Vector2 joint = agent.jointPosition(0);
  EXPECT_NEAR(agent.centerOfMass(0).x, joint.x, loose);
  EXPECT_NEAR(agent.centerOfMass(0).y, joint.y - real(0.5), loose);
  EXPECT_NEAR(agent.jointRate(0), 0, loose);
}

TEST(Gravity, AJointLimitHoldsTheLinksWeightsMoment) {
  // A fixed base and one horizontal link of mass m and length L whose joint may not turn
  // down (limits [0, 1]): the limit holds the moment of the link's weight about the joint,
  // m |g| L / 2 = 0.5 x 2 x 1.2 / 2 = 0.6 N m, and the link stays.
  Simulator simulator(real(0.01));
  simulator.setGravity({0, -2});
  ArticulatedLimb limb({real(0.5), 0});
  limb.addLink(-1, real(1.2), real(0.1), real(0.5), 0);
  limb.setLimits(0, 0, 1);
  auto& agent = simulator.registerObject(std::make_unique<Agent>(
      std::vector<ArticulatedBasePart>{ArticulatedBasePart::circle(real(0.5), 3)},
      std::vector<ArticulatedLimb>{limb}));
  agent.fixed = true;
  for (int step = 0; step < 50; ++step) simulator.advanceTime();
  EXPECT_NEAR(agent.limitTorque(0), real(0.6), loose);
  EXPECT_NEAR(agent.jointAngle(0), 0, real(1e-3));
  EXPECT_NEAR(agent.jointRate(0), 0, loose);
}

TEST(Gravity, AnElastoidsBodiesAreWeighedOnceEach) {
  // The elastoid (fixed, infinitely heavy) weighs nothing itself; its bodies, a core circle and
  // a custom one, fall together at g (their link stays at its rest length, 2 along x): counted
  // twice, they would fall at 2 g.
  const Vector2 g{0, -2};
  Simulator simulator(real(0.01));
  simulator.setGravity(g);
  auto& pair = simulator.registerObject(std::make_unique<Pair>());
  for (int step = 0; step < 10; ++step) simulator.advanceTime();
  EXPECT_EQ(pair.left->v, g);
  EXPECT_EQ(pair.right->v, g);
  EXPECT_EQ(pair.v, Vector2{});
  EXPECT_EQ(pair.externalForce, Vector2{});
  EXPECT_EQ(pair.left->r.x, 1);
  EXPECT_EQ(pair.right->r.x, 3);
  EXPECT_NEAR(pair.left->r.y, 5 + g.y * real(0.1), loose);
  EXPECT_EQ(pair.right->r.y, pair.left->r.y);
}

// ---------------------------------------------------------------------------------------------
// The same bits as the weight added by hand

/// A pile of circles (masses 1/2, 1, 2, 4), capsules and custom circles over a floor between
/// two walls: dividing by these masses is exact, so a core shape's `F / m + g` and
/// `(F + m g) / m` are both `F / m + g` rounded once, to the bit.
std::vector<PhysicalObject*> addWeighablePile(Simulator& simulator) {
  simulator.registerObject(std::make_unique<Border>(Vector2{0, 0}, Vector2{0, 1}));
  simulator.registerObject(std::make_unique<Border>(Vector2{0, 0}, Vector2{1, 0}));
  simulator.registerObject(std::make_unique<Border>(Vector2{6, 0}, Vector2{-1, 0}));
  const real masses[] = {real(0.5), 1, 2, 4};
  std::vector<PhysicalObject*> bodies;
  for (int i = 0; i < 36; ++i) {
    const real mass = masses[i % 4];
    PhysicalObject* body = nullptr;
    if (i % 5 == 3)
      body =
          &simulator.registerObject(std::make_unique<CappedRectangle>(real(0.3), real(0.2), mass));
    else if (i % 7 == 2)
      body = &simulator.registerObject(std::make_unique<CustomCircle>(real(0.35), mass));
    else
      body = &simulator.registerObject(std::make_unique<Circle>(real(0.4), mass));
    body->r = {
        real(0.6) + real(1.1) * static_cast<real>(i % 5) + real(0.05) * static_cast<real>(i % 3),
        real(0.5) + real(0.9) * static_cast<real>(i / 5)};
    body->alpha = real(0.3) * static_cast<real>(i);
    bodies.push_back(body);
  }
  return bodies;
}

TEST_P(GravityTest, APileInTheFieldHasTheBitsOfThePileWeighedByHand) {
  const Vector2 g{real(0.125), real(-1.7)};
  Simulator field(real(0.01));
  Simulator byHand(real(0.01));
  field.setContactSolver(GetParam());
  byHand.setContactSolver(GetParam());
  field.setGravity(g);
  // Gravity also orders Gauss-Seidel's sweeps by height, which the weights by hand do not.
  field.solverSettings().gaussSeidelHeightOrder = false;
  addWeighablePile(field);
  const std::vector<PhysicalObject*> bodies = addWeighablePile(byHand);
  std::size_t contacts = 0;
  for (int step = 0; step < 150; ++step) {
    for (PhysicalObject* body : bodies) body->externalForce += g * body->m;
    field.advanceTime();
    byHand.advanceTime();
    ASSERT_EQ(scenes::stateHash(field), scenes::stateHash(byHand)) << "step " << step;
    contacts += field.contacts.size();
  }
  ASSERT_EQ(field.contacts.size(), byHand.contacts.size());
  for (std::size_t k = 0; k < field.contacts.size(); ++k)
    EXPECT_EQ(bitsOf(field.contacts[k].force), bitsOf(byHand.contacts[k].force)) << k;
  EXPECT_GT(contacts, 1000u) << "the pile settles on its floor";
}

TEST_P(GravityTest, AnArticulatedAgentInTheFieldHasTheBitsOfItsLinksWeighedByHand) {
  // A free and a fixed agent (the fixed base weighs nothing), links of different masses or of
  // one mass (a uniform chain, weighed by one product), over a floor they fall onto: the
  // field's weights are applyLinkForceAtCenterOfMass(b, m_b g).
  for (const int variant : {0, 1, 2}) {
    const bool fixedBase = variant == 1;
    const bool uniform = variant == 2;
    const Vector2 g{real(0.3), real(-1.3)};
    Simulator worlds[2] = {Simulator(real(0.01)), Simulator(real(0.01))};
    Agent* agents[2] = {};
    for (int k = 0; k < 2; ++k) {
      worlds[k].setContactSolver(GetParam());
      worlds[k].registerObject(std::make_unique<Border>(Vector2{0, 0}, Vector2{0, 1}));
      ArticulatedLimb limb({real(0.4), 0});
      const real masses[] = {real(0.7), real(1.9), real(0.3), real(1.1), real(2.6)};
      for (int i = 0; i < 5; ++i)
        limb.addLink(i - 1, real(0.8), real(0.1), uniform ? real(0.7) : masses[i],
                     i == 0 ? real(-0.5) : real(0.3));
      agents[k] = &worlds[k].registerObject(std::make_unique<Agent>(
          std::vector<ArticulatedBasePart>{ArticulatedBasePart::circle(real(0.4), real(1.3))},
          std::vector<ArticulatedLimb>{limb}));
      agents[k]->setPose({3, fixedBase ? real(1) : real(2.5)}, real(0.1));
      agents[k]->fixed = fixedBase;
      agents[k]->setJointTorque(2, real(0.05));
    }
    worlds[0].setGravity(g);
    Agent& byHand = *agents[1];
    int touching = 0;
    for (int step = 0; step < 200; ++step) {
      if (!fixedBase)
        byHand.applyLinkForceAtCenterOfMass(Agent::base,
                                            byHand.articulatedBody().mass(Agent::base) * g);
      for (int i = 0; i < byHand.linkCount(); ++i)
        byHand.applyLinkForceAtCenterOfMass(i, byHand.articulatedBody().mass(i) * g);
      for (Simulator& world : worlds) world.advanceTime();
      touching += worlds[0].contacts.empty() ? 0 : 1;
    }
    EXPECT_GT(touching, 0) << "the agent reaches the floor (variant " << variant << ")";
    SCOPED_TRACE(::testing::Message() << "variant " << variant);
    test::expectSameAgentMotion(*agents[0], byHand);
  }
}

TEST_P(GravityTest, AZeroFieldChangesNoBit) {
  // Either sign of zero: the steps compute what they compute without a field.
  Simulator plain(real(0.01));
  Simulator zero(real(0.01));
  Simulator negativeZero(real(0.01));
  zero.setGravity({0, 0});
  negativeZero.setGravity({real(-0.0), real(-0.0)});
  EXPECT_EQ(bitsOf(negativeZero.gravity().x), bitsOf(real(0)));
  EXPECT_EQ(bitsOf(negativeZero.gravity().y), bitsOf(real(0)));
  std::vector<PhysicalObject*> bodies[3];
  Simulator* worlds[] = {&plain, &zero, &negativeZero};
  for (int k = 0; k < 3; ++k) {
    worlds[k]->setContactSolver(GetParam());
    bodies[k] = scenes::addMixedPile(*worlds[k], 30, 7);
  }
  for (int step = 0; step < 100; ++step) {
    for (int k = 0; k < 3; ++k) {
      // A force whose x is -0, so free bodies move at v.x = -0, which a field's + 0 would turn
      // into +0.
      for (PhysicalObject* body : bodies[k])
        body->externalForce = Vector2{real(-0.0), real(-0.8)} * body->m;
      worlds[k]->advanceTime();
    }
    ASSERT_EQ(scenes::stateHash(zero), scenes::stateHash(plain)) << step;
    ASSERT_EQ(scenes::stateHash(negativeZero), scenes::stateHash(plain)) << step;
  }
}

// ---------------------------------------------------------------------------------------------
// Bad input

TEST(Gravity, ANonFiniteFieldIsRefusedAndTheFieldKept) {
  constexpr real inf = std::numeric_limits<real>::infinity();
  constexpr real nan = std::numeric_limits<real>::quiet_NaN();
  Simulator simulator;
  const Vector2 g{real(0.5), -1};
  simulator.setGravity(g);
  for (const Vector2 bad : {Vector2{nan, -1}, Vector2{0, nan}, Vector2{inf, 0}, Vector2{0, -inf}}) {
    try {
      simulator.setGravity(bad);
      ADD_FAILURE() << "accepted (" << bad.x << ", " << bad.y << ")";
    } catch (const InvalidArgument& e) {
      EXPECT_EQ(e.field(), "Simulator.setGravity.gravity");
    }
    EXPECT_EQ(simulator.gravity(), g);
  }
}

INSTANTIATE_TEST_SUITE_P(Solvers, GravityTest,
                         ::testing::Values(ContactSolverKind::Baraff,
                                           ContactSolverKind::GaussSeidel),
                         solverName);

}  // namespace
}  // namespace thyrix
