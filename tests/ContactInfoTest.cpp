// ContactInfo as the original users' guide describes it: the point p relative to the object's
// reference point, the normal n, the sign sigma of the force's direction and the type; and an
// articulated agent's joint at its limit listed as a torque contact of its link.

#include <ThyrixLite/Border.h>
#include <ThyrixLite/CappedRectangle.h>
#include <ThyrixLite/Circle.h>
#include <ThyrixLite/ComposedPhysicalObject.h>
#include <ThyrixLite/ContactInfo.h>
#include <ThyrixLite/InvalidArgument.h>
#include <ThyrixLite/Simulator.h>
#include <ThyrixPro/ArticulatedAgentQuasistatic.h>
#include <ThyrixPro/ArticulatedLimb.h>
#include <ThyrixPro/LinkContactInfo.h>
#include <gtest/gtest.h>
#include "TestTolerances.h"
#include "support/SolverCases.h"

#include <cmath>
#include <memory>
#include <span>
#include <vector>

namespace thyrix {
namespace {

using test::loose;
using test::tight;

void expectNear(Vector2 actual, Vector2 expected, real tolerance) {
  EXPECT_NEAR(actual.x, expected.x, tolerance);
  EXPECT_NEAR(actual.y, expected.y, tolerance);
}

class ContactInfoTest : public ::testing::TestWithParam<ContactSolverKind> {};

TEST_P(ContactInfoTest, CircleOnABorderSeesItsPointAtMinusRadiusAlongTheNormal) {
  Simulator simulator;
  simulator.setContactSolver(GetParam());
  auto& floor = simulator.registerObject(std::make_unique<Border>(Vector2{0, 0}, Vector2{0, 1}));
  const real radius = real(0.5);
  auto& disk = simulator.registerObject(std::make_unique<Circle>(radius, real(1)));
  disk.r = {real(2), radius};  // touching the floor
  const real push = 3;
  disk.externalForce = {0, -push};
  simulator.advanceTime();

  ASSERT_EQ(disk.contacts().size(), 1u);
  const ContactInfo& c = disk.contacts()[0];
  EXPECT_EQ(c.type, ContactType::Force);
  EXPECT_EQ(c.other, &floor);
  // The force on the disk is sigma * force * n, straight up, and balances the push.
  expectNear(c.sigma * c.n, {0, 1}, tight);
  expectNear(c.normal, c.sigma * c.n, 0);
  EXPECT_NEAR(c.force, push, loose);
  // p is relative to the disk's centre: -R times the direction of the force on it.
  expectNear(c.p, -radius * c.normal, tight);
  expectNear(c.point, Vector2{2, 0}, tight);
  // The floor sees the same contact with the same n, from the other side.
  ASSERT_EQ(floor.contacts().size(), 1u);
  const ContactInfo& f = floor.contacts()[0];
  expectNear(f.n, c.n, 0);
  EXPECT_EQ(f.sigma, -c.sigma);
  expectNear(f.p, f.point - floor.r, 0);
}

TEST_P(ContactInfoTest, TwoCirclesSeeOneNormalWithOppositeSigns) {
  Simulator simulator;
  simulator.setContactSolver(GetParam());
  auto& a = simulator.registerObject(std::make_unique<Circle>(real(0.5), real(1)));
  auto& b = simulator.registerObject(std::make_unique<Circle>(real(0.25), real(1)));
  // Touching along the direction (0.6, 0.8).
  const Vector2 direction{real(0.6), real(0.8)};
  a.r = {1, 1};
  b.r = a.r + real(0.75) * direction;
  a.externalForce = direction;  // A pushed into B
  simulator.advanceTime();

  ASSERT_EQ(a.contacts().size(), 1u);
  ASSERT_EQ(b.contacts().size(), 1u);
  const ContactInfo& ca = a.contacts()[0];
  const ContactInfo& cb = b.contacts()[0];
  // One n for the contact; each body pushed away from the other.
  expectNear(ca.n, cb.n, 0);
  EXPECT_EQ(ca.sigma, -cb.sigma);
  expectNear(ca.sigma * ca.n, -direction, tight);
  expectNear(cb.sigma * cb.n, direction, tight);
  // The point on the surfaces, relative to each centre.
  expectNear(ca.p, real(0.5) * direction, tight);
  expectNear(cb.p, -real(0.25) * direction, tight);
  // Both move together at the total force over the total mass: the force is half the push.
  EXPECT_NEAR(ca.force, real(0.5), loose);
  EXPECT_EQ(ca.force, cb.force);
}

TEST_P(ContactInfoTest, PartOfAComposedBodyIsSeenRelativeToTheBodysReferencePoint) {
  Simulator simulator;
  simulator.setContactSolver(GetParam());
  simulator.registerObject(std::make_unique<Border>(Vector2{0, 0}, Vector2{0, 1}));
  auto composed = std::make_unique<ComposedPhysicalObject>();
  composed->add(std::make_unique<Circle>(real(0.5), real(1)), {-1, 0});
  composed->add(std::make_unique<Circle>(real(0.5), real(1)), {1, 0});
  auto& body = simulator.registerObject(std::move(composed));
  body.r = {3, 1};
  body.alpha = real(-0.5235987755982988);  // -30 degrees: the part at (-1, 0) is highest
  // The lower part touches the floor below its centre, at (cos, sin)(-30 deg) from r. The
  // contacts are detected before the body moves in the step.
  const Vector2 detectedAt = body.r;
  const Vector2 lowCentre = body.r + Vector2{std::cos(body.alpha), std::sin(body.alpha)};
  body.externalForce = {0, -1};
  simulator.advanceTime();

  ASSERT_EQ(body.contacts().size(), 1u);
  const ContactInfo& c = body.contacts()[0];
  expectNear(c.point, {lowCentre.x, 0}, tight);
  expectNear(c.p, c.point - detectedAt, 0);
  expectNear(c.p, Vector2{lowCentre.x - detectedAt.x, -detectedAt.y}, tight);
}

// ---------------------------------------------------------------------------------------------
// Joint limits as torque contacts

/// A circle base (radius 0.5, mass 2) with a chain of three links (length 1, radius 0.1, mass
/// 0.5) along +x, the middle joint limited to [-0.4, 0.6].
std::unique_ptr<ArticulatedAgentQuasistatic> makeLimitedArm() {
  ArticulatedLimb limb = ArticulatedLimb::chain({real(0.5), 0}, 3, 1, real(0.1), real(0.5));
  limb.setLimits(1, real(-0.4), real(0.6));
  return std::make_unique<ArticulatedAgentQuasistatic>(
      std::vector<ArticulatedBasePart>{ArticulatedBasePart::circle(real(0.5), 2)},
      std::vector<ArticulatedLimb>{limb});
}

/// The torque contacts of @p list.
std::vector<LinkContactInfo> torqueContacts(std::span<const LinkContactInfo> list) {
  std::vector<LinkContactInfo> torques;
  for (const LinkContactInfo& c : list)
    if (c.type == ContactType::Torque) torques.push_back(c);
  return torques;
}

TEST_P(ContactInfoTest, LimbPushedAgainstItsJointLimitShowsATorqueContact) {
  Simulator simulator;
  simulator.setContactSolver(GetParam());
  auto& agent = simulator.registerObject(makeLimitedArm());
  const real tau = real(0.8);
  for (const real applied : {-tau, tau}) {  // into the lower limit, then into the upper
    agent.setJointTorque(1, applied);
    for (int step = 0; step < 400; ++step) simulator.advanceTime();
    ASSERT_NEAR(agent.jointRate(1), 0, loose) << "at rest on the limit";

    const std::vector<LinkContactInfo> link = torqueContacts(agent.linkContacts(1));
    ASSERT_EQ(link.size(), 1u);
    const LinkContactInfo& c = link[0];
    EXPECT_EQ(c.body, 1);
    EXPECT_EQ(c.index, ContactInfo::noIndex);
    EXPECT_EQ(c.other, &agent);
    EXPECT_EQ(c.primitive, &agent.linkShape(1));
    EXPECT_EQ(c.otherPrimitive, &agent.linkShape(0));
    // At rest with nothing else on the joint, the limit's torque cancels the applied one.
    EXPECT_NEAR(c.sigma * c.force, -applied, loose);
    EXPECT_EQ(c.sigma, applied < 0 ? 1 : -1) << "the lower limit turns the link forward";
    EXPECT_EQ(c.sigma * c.force, agent.limitTorque(1));
    // At the joint, relative to the link's centre of mass half way along it (length 1).
    const real angle = agent.bodyAngle(1);
    expectNear(c.point, agent.jointPosition(1), 0);
    expectNear(c.p, real(-0.5) * Vector2{std::cos(angle), std::sin(angle)}, loose);
    EXPECT_NEAR(c.depth, 0, loose) << "on the limit";
    expectNear(c.n, {0, 0}, 0);

    // The parent feels the opposite torque; the last link none.
    const std::vector<LinkContactInfo> parent = torqueContacts(agent.linkContacts(0));
    ASSERT_EQ(parent.size(), 1u);
    EXPECT_EQ(parent[0].body, 0);
    EXPECT_EQ(parent[0].sigma, -c.sigma);
    EXPECT_EQ(parent[0].force, c.force);
    EXPECT_EQ(parent[0].otherPrimitive, &agent.linkShape(1));
    expectNear(parent[0].p, agent.jointPosition(1) - agent.centerOfMass(0), 0);
    EXPECT_TRUE(torqueContacts(agent.linkContacts(2)).empty());
    EXPECT_TRUE(torqueContacts(agent.linkContacts(ArticulatedAgentBase::base)).empty());
  }

  // Released from the limit: no torque contact.
  agent.setJointTorque(1, -tau);
  simulator.advanceTime();
  EXPECT_EQ(agent.limitTorque(1), 0);
  EXPECT_TRUE(torqueContacts(agent.linkContacts(1)).empty());
}

TEST_P(ContactInfoTest, LinkContactsListTheForceContactsOfTheirBody) {
  Simulator simulator;
  simulator.setContactSolver(GetParam());
  // A floor under the arm's capsules (radius 0.1), which the base (radius 0.5) overlaps.
  simulator.registerObject(std::make_unique<Border>(Vector2{0, real(0.4)}, Vector2{0, 1}));
  auto& agent = simulator.registerObject(makeLimitedArm());
  agent.setPose({0, real(0.5)}, 0);
  agent.fixed = false;
  agent.externalForce = {0, -1};
  for (int b = 0; b < agent.linkCount(); ++b)
    agent.applyLinkForce(b, {0, -1}, agent.centerOfMass(b));
  simulator.advanceTime();

  std::size_t listed = 0;
  for (int b = ArticulatedAgentBase::base; b < agent.linkCount(); ++b) {
    for (const LinkContactInfo& c : agent.linkContacts(b)) {
      if (c.type != ContactType::Force) continue;
      ++listed;
      EXPECT_EQ(c.body, b);
      EXPECT_EQ(ArticulatedAgentBase::bodyOf(*c.primitive), b);
      expectNear(c.p, c.point - agent.centerOfMass(b), 0);
      expectNear(c.normal, c.sigma * c.n, 0);
    }
  }
  EXPECT_EQ(listed, agent.contacts().size()) << "each contact in its body's list, once";
  EXPECT_GE(listed, 4u) << "the base and the three links on the floor";
  EXPECT_THROW(static_cast<void>(agent.linkContacts(agent.linkCount())), InvalidArgument);
}

INSTANTIATE_TEST_SUITE_P(BothSolvers, ContactInfoTest,
                         ::testing::Values(ContactSolverKind::Baraff,
                                           ContactSolverKind::GaussSeidel),
                         test::solverName);

}  // namespace
}  // namespace thyrix
