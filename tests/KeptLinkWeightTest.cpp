// The weight of equal links, kept as one wrench: ArticulatedBody::solve() with one wrench for
// every link gives the bits of solve() with those wrenches in an array, and an articulated
// agent whose links weigh alike, weighed by the field with forces of its own added before,
// after or without the weight, or with the field turned off, gives the bits of the same agent
// weighed by hand.

#include "TestTolerances.h"
#include "support/SameAgentMotion.h"
#include "support/SolverCases.h"

#include <ThyrixLite/Border.h>
#include <ThyrixLite/InvalidArgument.h>
#include <ThyrixLite/Simulator.h>
#include <ThyrixPro/ArticulatedAgentQuasistatic.h>
#include <ThyrixPro/ArticulatedBody.h>
#include <ThyrixPro/ArticulatedLimb.h>
#include <ThyrixPro/ArticulatedLink.h>

#include <gtest/gtest.h>

#include <memory>
#include <vector>

namespace thyrix {
namespace {

using test::bitsOf;

/// Whether @p a and @p b hold the same bits.
void expectSameBits(const ArticulatedBody::Output& a, const ArticulatedBody::Output& b) {
  ASSERT_EQ(a.velocities.size(), b.velocities.size());
  for (std::size_t k = 0; k < a.velocities.size(); ++k) {
    EXPECT_EQ(bitsOf(a.velocities[k].x), bitsOf(b.velocities[k].x)) << k;
    EXPECT_EQ(bitsOf(a.velocities[k].y), bitsOf(b.velocities[k].y)) << k;
    EXPECT_EQ(bitsOf(a.velocities[k].z), bitsOf(b.velocities[k].z)) << k;
  }
  ASSERT_EQ(a.jointRates.size(), b.jointRates.size());
  for (std::size_t i = 0; i < a.jointRates.size(); ++i)
    EXPECT_EQ(bitsOf(a.jointRates[i]), bitsOf(b.jointRates[i])) << i;
}

/// A body of 12 links of mass 0.7 at various angles: a plain chain (each link on the previous
/// one's tip), or a tree (some links on the base or on an earlier link).
ArticulatedBody makeBody(bool tree) {
  std::vector<ArticulatedLink> links;
  for (int i = 0; i < 12; ++i) {
    ArticulatedLink link;
    link.parent = tree && i % 4 == 3 ? (i / 2) - 2 : i - 1;
    link.length = real(0.5) + real(0.05) * real(i % 3);
    const real parentLength = i == 0 ? real(0) : links.back().length;
    link.jointPosition =
        link.parent == i - 1 && i > 0 ? Vector2{parentLength, 0} : Vector2{real(0.2), real(-0.1)};
    link.centerOfMass = {link.length / 2, real(0.02) * real(i % 2)};
    link.mass = real(0.7);
    link.inertia = real(0.03) + real(0.01) * real(i % 5);
    links.push_back(link);
  }
  ArticulatedBody body(real(1.3), real(0.4), links);
  std::vector<real> q;
  for (int i = 0; i < 12; ++i) q.push_back(real(0.3) * real(i % 7) - real(0.8));
  body.setBasePose({real(0.5), real(1)}, real(0.2));
  body.setJointAngles(q);
  return body;
}

TEST(KeptLinkWeight, SolveWithOneLinkWrenchHasTheBitsOfTheArray) {
  // A weight-like wrench (its torque a zero) and a general one; with and without torques; a
  // free and a fixed base; undamped and damped joints; a chain (which has a loop of its own)
  // and a tree. A respond() afterwards reuses the inertias both computed.
  const Vector3 baseWrench{real(0.1), real(-0.3), real(0.2)};
  for (const Vector3& linkWrench :
       {Vector3{real(0), real(0.21), real(-6.86)}, Vector3{real(-0.4), real(1.5), real(0.25)}})
    for (const bool tree : {false, true})
      for (const bool fixedBase : {false, true})
        for (const bool damped : {false, true})
          for (const bool withTorques : {false, true}) {
            SCOPED_TRACE(::testing::Message()
                         << "tree " << tree << " fixed " << fixedBase << " damped " << damped
                         << " torques " << withTorques << " wrench " << linkWrench.x);
            ArticulatedBody one = makeBody(tree);
            ArticulatedBody array = makeBody(tree);
            for (ArticulatedBody* body : {&one, &array}) {
              body->setBaseFixed(fixedBase);
              if (damped) body->setJointDamping(5, real(0.3));
            }
            std::vector<real> torques;
            if (withTorques)
              for (int i = 0; i < one.linkCount(); ++i) torques.push_back(real(0.01) * real(i));
            std::vector<Vector3> wrenches(static_cast<std::size_t>(one.linkCount()) + 1,
                                          linkWrench);
            wrenches[0] = baseWrench;
            ArticulatedBody::Output a = one.makeOutput();
            ArticulatedBody::Output b = array.makeOutput();
            one.solve(torques, baseWrench, linkWrench, a);
            array.solve(torques, wrenches, b);
            expectSameBits(a, b);
            const auto force = ArticulatedBody::TestForce::atPoint(3, {real(0.4), real(0.2)},
                                                                   {real(0.6), real(0.8)});
            one.respond(force, a);
            array.respond(force, b);
            expectSameBits(a, b);
          }
}

TEST(KeptLinkWeight, SolveWithOneLinkWrenchChecksTheTorques) {
  ArticulatedBody body = makeBody(false);
  ArticulatedBody::Output out = body.makeOutput();
  const std::vector<real> tooFew(3, real(0));
  EXPECT_THROW(body.solve(tooFew, Vector3{}, Vector3{}, out), InvalidArgument);
}

using Agent = ArticulatedAgentQuasistatic;

/// An agent that adds a force to link 2 in its own phase-5 hook, after the simulator weighed it
/// (and, with `early`, to link 4 in control(), before the next step's weighing).
class Pushing : public Agent {
 public:
  using Agent::Agent;
  void computeDerivativesWithoutContacts() override {
    if (late) applyLinkForce(2, {real(0.2), real(0.1)}, linkTip(2));
    Agent::computeDerivativesWithoutContacts();
  }
  void control() override {
    if (early) applyLinkForceAtCenterOfMass(4, {real(-0.1), real(0.3)});
  }
  bool late = false;
  bool early = false;
};

class KeptLinkWeightAgent : public ::testing::TestWithParam<ContactSolverKind> {};

TEST_P(KeptLinkWeightAgent, HasTheBitsOfTheWeightsAddedByHand) {
  // Two uniform chains over a floor: one in the field, one weighed by hand before each step
  // (the field's weights are applyLinkForceAtCenterOfMass(b, m_b g), added before the hook's
  // own force and after control()'s). The phases change every 40 steps: no force of its own,
  // a force in the hook, a force in control(), both; then the field off (and the weights by
  // hand stop).
  const Vector2 g{real(0.3), real(-1.3)};
  Simulator worlds[2] = {Simulator(real(0.01)), Simulator(real(0.01))};
  Pushing* agents[2] = {};
  for (int k = 0; k < 2; ++k) {
    worlds[k].setContactSolver(GetParam());
    worlds[k].registerObject(std::make_unique<Border>(Vector2{0, 0}, Vector2{0, 1}));
    ArticulatedLimb limb({real(0.4), 0});
    for (int i = 0; i < 6; ++i)
      limb.addLink(i - 1, real(0.8), real(0.1), real(0.7), i == 0 ? real(-0.5) : real(0.3));
    agents[k] = &worlds[k].registerObject(std::make_unique<Pushing>(
        std::vector<ArticulatedBasePart>{ArticulatedBasePart::circle(real(0.4), real(1.3))},
        std::vector<ArticulatedLimb>{limb}));
    agents[k]->setPose({3, real(2.5)}, real(0.1));
  }
  worlds[0].setGravity(g);
  Pushing& byHand = *agents[1];
  bool weighed = true;
  for (int step = 0; step < 200; ++step) {
    const int phase = step / 40;
    for (Pushing* agent : agents) {
      agent->late = phase == 1 || phase == 3;
      agent->early = phase == 2 || phase == 3;
    }
    if (phase == 4 && weighed) {
      worlds[0].setGravity({0, 0});
      weighed = false;
    }
    if (weighed) {
      byHand.applyLinkForceAtCenterOfMass(Agent::base,
                                          byHand.articulatedBody().mass(Agent::base) * g);
      for (int i = 0; i < byHand.linkCount(); ++i)
        byHand.applyLinkForceAtCenterOfMass(i, byHand.articulatedBody().mass(i) * g);
    }
    for (Simulator& world : worlds) world.advanceTime();
  }
  test::expectSameAgentMotion(*agents[0], byHand);
}

TEST(KeptLinkWeight, WeighedTwiceInAStepIsWeighedTwice) {
  // applyWeight() is public: called again by hand in a step, the second weight is added to the
  // first, as for an agent weighed by hand twice.
  const Vector2 g{real(0.1), real(-2)};
  Simulator worlds[2] = {Simulator(real(0.01)), Simulator(real(0.01))};
  Agent* agents[2] = {};
  for (int k = 0; k < 2; ++k) {
    ArticulatedLimb limb({real(0.4), 0});
    for (int i = 0; i < 4; ++i) limb.addLink(i - 1, real(0.8), real(0.1), real(0.5), real(0.2));
    agents[k] = &worlds[k].registerObject(std::make_unique<Agent>(
        std::vector<ArticulatedBasePart>{ArticulatedBasePart::circle(real(0.4), real(1.3))},
        std::vector<ArticulatedLimb>{limb}));
    agents[k]->fixed = true;
  }
  worlds[0].setGravity(g);
  for (int step = 0; step < 20; ++step) {
    agents[0]->applyWeight(g);  // the field adds the second
    for (int twice = 0; twice < 2; ++twice)
      for (int i = 0; i < agents[1]->linkCount(); ++i)
        agents[1]->applyLinkForceAtCenterOfMass(i, agents[1]->articulatedBody().mass(i) * g);
    for (Simulator& world : worlds) world.advanceTime();
  }
  test::expectSameAgentMotion(*agents[0], *agents[1]);
}

INSTANTIATE_TEST_SUITE_P(Solvers, KeptLinkWeightAgent,
                         ::testing::Values(ContactSolverKind::Baraff,
                                           ContactSolverKind::GaussSeidel),
                         test::solverName);

}  // namespace
}  // namespace thyrix
