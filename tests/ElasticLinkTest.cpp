// Elastic links and elastoids: relaxation at the rate F = m v predicts, pass-through.

#include "TestTolerances.h"

#include <ThyrixLite/Circle.h>
#include <ThyrixLite/Elastoid.h>
#include <ThyrixLite/InvalidArgument.h>
#include <ThyrixLite/Simulator.h>

#include <gtest/gtest.h>

#include <cmath>

namespace thyrix {
namespace {

using test::loose;
using test::tight;

/// Two circles joined centre to centre by a link, an elastoid.
class Pair : public Elastoid {
 public:
  Pair(real restLength, real stiffness) {
    left = &addBody(std::make_unique<Circle>(real(0.25), real(2)));
    right = &addBody(std::make_unique<Circle>(real(0.25), real(2)));
    right->r = {2, 0};
    link = &addLink(*left, {0, 0}, *right, {0, 0}, restLength, stiffness);
  }
  Circle* left;
  Circle* right;
  ElasticLink* link;
};

TEST(ElasticLink, StretchedLinkPullsAtTheRateFEqualsMvPredicts) {
  Simulator simulator(real(0.01));
  auto& pair = simulator.registerObject(std::make_unique<Pair>(real(1), real(4)));
  EXPECT_EQ(simulator.objects.size(), 3u) << "the elastoid brings its two bodies";
  simulator.advanceTime();
  // Stretch 1, k 4, w = 1/2 + 1/2: implicit force 4 / (1 + 0.01 * 4) on each circle of mass 2.
  const real force = 4 / (1 + real(0.01) * 4);
  EXPECT_NEAR(pair.link->tension(), force, tight);
  EXPECT_NEAR(pair.left->v.x, force / 2, tight);
  EXPECT_NEAR(pair.right->v.x, -force / 2, tight);
  // After the step the stretch shrank by exactly the factor 1 / (1 + dt k w).
  EXPECT_NEAR(pair.link->length() - 1, 1 / (1 + real(0.01) * 4), tight);
}

TEST(ElasticLink, RelaxesExponentiallyToRestLengthEvenWhenVeryStiff) {
  Simulator simulator(real(0.01));
  auto& pair = simulator.registerObject(std::make_unique<Pair>(real(0.5), real(1e6)));
  real previous = pair.link->length() - real(0.5);
  for (int step = 0; step < 20; ++step) {
    simulator.advanceTime();
    const real stretch = pair.link->length() - real(0.5);
    EXPECT_GE(stretch, -tight) << "never overshoots";
    EXPECT_LE(stretch, previous + tight);
    previous = stretch;
  }
  EXPECT_NEAR(pair.link->length(), real(0.5), loose);
}

TEST(ElasticLink, CommandedRestLengthChangesTheLength) {
  Simulator simulator(real(0.01));
  auto& pair = simulator.registerObject(std::make_unique<Pair>(real(2), real(50)));
  pair.link->setRestLength(real(1.2));
  for (int step = 0; step < 300; ++step) simulator.advanceTime();
  EXPECT_NEAR(pair.link->length(), real(1.2), loose);
}

TEST(ElasticLink, OtherBodiesPassThroughTheLinkAndTheBodiesThroughEachOther) {
  Simulator simulator(real(0.01));
  auto& pair = simulator.registerObject(std::make_unique<Pair>(real(2), real(5)));
  auto& crossing = simulator.registerObject(std::make_unique<Circle>(real(0.1), real(1)));
  crossing.r = {1, 1};
  for (int step = 0; step < 200; ++step) {
    crossing.externalForce = {0, -1};  // falls across the link between the circles
    simulator.advanceTime();
  }
  EXPECT_LT(crossing.r.y, real(-0.5)) << "passed through the link";
  // With rest length 0 the two circles of one elastoid overlap without a contact.
  pair.link->setRestLength(0);
  for (int step = 0; step < 300; ++step) simulator.advanceTime();
  EXPECT_LT(distance(pair.left->r, pair.right->r), real(0.1));
  for (const GlobalContactInfo& c : simulator.contacts)
    EXPECT_FALSE((c.objectA == pair.left && c.objectB == pair.right) ||
                 (c.objectA == pair.right && c.objectB == pair.left));
}

TEST(ElasticLink, BadArgumentsAreRefused) {
  Circle a(1, 1);
  Circle b(1, 1);
  const auto expectField = [](auto&& call, const char* field) {
    try {
      call();
      ADD_FAILURE() << "no exception for " << field;
    } catch (const InvalidArgument& error) {
      EXPECT_EQ(error.field(), field);
    }
  };
  expectField([&] { ElasticLink(a, {}, b, {}, -1, 1); }, "ElasticLink.restLength");
  expectField([&] { ElasticLink(a, {}, b, {}, 1, 0); }, "ElasticLink.stiffness");
  expectField([&] { ElasticLink(a, {real(NAN), 0}, b, {}, 1, 1); }, "ElasticLink.anchorA");
  expectField([&] { ElasticLink(a, {}, a, {}, 1, 1); }, "ElasticLink.b");
  ElasticLink link(a, {}, b, {}, 1, 1);
  expectField([&] { link.setRestLength(real(NAN)); }, "ElasticLink.restLength");
  EXPECT_EQ(link.restLength(), 1);
}

TEST(Elastoid, RefusedRegistrationRegistersNoneOfItsBodies) {
  Simulator simulator;
  auto pair = std::make_unique<Pair>(real(1), real(1));
  pair->right->r = {real(NAN), 0};
  try {
    simulator.registerObject(std::move(pair));
    ADD_FAILURE() << "a body with a NaN position was registered";
  } catch (const InvalidArgument& error) {
    EXPECT_EQ(error.field(), "Circle.r");
  }
  EXPECT_EQ(simulator.objects.size(), 0u);
  simulator.advanceTime();
}

}  // namespace
}  // namespace thyrix
