// Gauss-Seidel's warm start: each contact starts from the force it ended the last step with,
// found by its identity (shapes and feature) whatever its place in the new contact list.

#include "TestTolerances.h"

#include <ThyrixLite/Border.h>
#include <ThyrixLite/Circle.h>
#include <ThyrixLite/Simulator.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <memory>

namespace thyrix {
namespace {

constexpr int columnHeight = 10;
// A speed the solver is converged to (its tolerance is 1e-7 m/s in double, 1e-5 in float).
constexpr real tolerance = test::isFloat ? real(1e-4) : real(1e-5);

/// A column of unit disks on the floor, pushed down from the top by 1 N each step, solved by
/// Gauss-Seidel. Optionally a loose disk beside
/// the column, a speculative contact (no force) away from its third disk. Returns the top disk.
PhysicalObject& buildColumn(Simulator& simulator, bool warmStart, PhysicalObject** loose) {
  simulator.setContactSolver(ContactSolverKind::GaussSeidel);
  ContactSolverSettings& settings = simulator.solverSettings();
  settings.warmStart = warmStart;
  simulator.registerObject(std::make_unique<Border>(Vector2{0, 0}, Vector2{0, 1}));
  PhysicalObject* top = nullptr;
  for (int i = 0; i < columnHeight; ++i) {
    top = &simulator.registerObject(std::make_unique<Circle>(real(0.5), real(1)));
    top->r = {0, real(0.5) + static_cast<real>(i)};
  }
  if (loose != nullptr) {
    *loose = &simulator.registerObject(std::make_unique<Circle>(real(0.5), real(1)));
    (*loose)->r = {real(1.01), real(2.5)};
  }
  return *top;
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
  PhysicalObject& warmTop = buildColumn(warm, true, nullptr);
  Simulator cold;
  PhysicalObject& coldTop = buildColumn(cold, false, nullptr);
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
  PhysicalObject* loose = nullptr;
  PhysicalObject& top = buildColumn(simulator, true, &loose);
  pushedStep(simulator, top, 1000);
  ASSERT_EQ(simulator.contacts.size(), static_cast<std::size_t>(columnHeight + 1))
      << "the loose disk should have its speculative contact";
  // Its contact leaves the list: the contacts after it are no longer where they were.
  loose->r = {10, real(0.5)};
  pushedStep(simulator, top, 2);
  EXPECT_LT(largestSpeed(simulator), tolerance);
}

}  // namespace
}  // namespace thyrix
