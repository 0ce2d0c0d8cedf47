// Gauss-Seidel's warm start: each contact starts from the force it ended the last step with,
// found by its identity (shapes and feature) whatever its place in the new contact list.

#include "TestTolerances.h"

#include <ThyrixLite/Border.h>
#include <ThyrixLite/Circle.h>
#include <ThyrixLite/Simulator.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <vector>

namespace thyrix {
namespace {

constexpr int columnHeight = 10;
// A speed the solver is converged to (its tolerance is 1e-7 m/s in double, 1e-5 in float).
constexpr real tolerance = test::isFloat ? real(1e-4) : real(1e-5);

/// A column of unit disks on the floor, solved by Gauss-Seidel, and optionally a loose disk
/// beside it: a speculative contact (no force) with the column's third disk.
struct Column {
  PhysicalObject* top = nullptr;
  PhysicalObject* loose = nullptr;
};

Column buildColumn(Simulator& simulator, bool warmStart, bool withLooseDisk) {
  simulator.setContactSolver(ContactSolverKind::GaussSeidel);
  simulator.solverSettings().warmStart = warmStart;
  simulator.registerObject(std::make_unique<Border>(Vector2{0, 0}, Vector2{0, 1}));
  Column column;
  for (int i = 0; i < columnHeight; ++i) {
    column.top = &simulator.registerObject(std::make_unique<Circle>(real(0.5), real(1)));
    column.top->r = {0, real(0.5) + static_cast<real>(i)};
  }
  if (withLooseDisk) {
    column.loose = &simulator.registerObject(std::make_unique<Circle>(real(0.5), real(1)));
    column.loose->r = {real(1.01), real(2.5)};
  }
  return column;
}

/// A contact's identity, as the warm start matches it.
struct Identity {
  std::uint32_t shapeA;
  std::uint32_t shapeB;
  std::uint32_t feature;
  bool operator==(const Identity&) const = default;
};

std::vector<Identity> identities(const Simulator& simulator) {
  std::vector<Identity> result;
  for (const GlobalContactInfo& c : simulator.contacts)
    result.push_back({c.shapeA, c.shapeB, c.feature});
  return result;
}

/// Steps @p simulator with the top disk pushed down, with at most @p sweeps sweeps.
void pushedStep(Simulator& simulator, PhysicalObject& top, int sweeps) {
  simulator.solverSettings().gaussSeidelMaxIterations = sweeps;
  top.externalForce = {0, -1};
  simulator.advanceTime();
}

/// The largest speed of a disk: zero when every contact carries the push.
real largestSpeed(const Simulator& simulator) {
  real largest = 0;
  for (const PhysicalObject& object : simulator.objects)
    largest = std::max(largest, object.v.length());
  return largest;
}

// A column converged in one step needs only two sweeps in the next, from its forces; from zero
// forces two sweeps leave the top disks moving.
TEST(WarmStart, TheLastStepsForcesSolveASteadyColumnInTwoSweeps) {
  Simulator warm;
  PhysicalObject& warmTop = *buildColumn(warm, true, false).top;
  Simulator cold;
  PhysicalObject& coldTop = *buildColumn(cold, false, false).top;
  pushedStep(warm, warmTop, 1000);
  pushedStep(cold, coldTop, 1000);
  EXPECT_LT(largestSpeed(warm), tolerance);
  EXPECT_LT(largestSpeed(cold), tolerance);

  pushedStep(warm, warmTop, 2);
  pushedStep(cold, coldTop, 2);
  EXPECT_LT(largestSpeed(warm), tolerance);
  EXPECT_GT(largestSpeed(cold), real(0.1));
  for (const GlobalContactInfo& contact : warm.contacts)  // each carries the push
    EXPECT_NEAR(contact.force, 1, 10 * tolerance);
}

TEST(WarmStart, ContactsOutOfLastStepsOrderAreFoundToo) {
  Simulator simulator;
  const Column column = buildColumn(simulator, true, true);
  pushedStep(simulator, *column.top, 1000);
  ASSERT_EQ(simulator.contacts.size(), static_cast<std::size_t>(columnHeight + 1))
      << "the loose disk should have its speculative contact";
  const std::vector<Identity> before = identities(simulator);
  // Its contact leaves the list: the contacts after it are no longer where they were.
  column.loose->r = {10, 5};
  pushedStep(simulator, *column.top, 2);
  const std::vector<Identity> after = identities(simulator);
  ASSERT_EQ(after.size(), before.size() - 1);
  ASSERT_FALSE(std::equal(after.begin(), after.end(), before.begin()))
      << "a contact before the end should have left, moving the ones after it";
  EXPECT_LT(largestSpeed(simulator), tolerance);
}

}  // namespace
}  // namespace thyrix
