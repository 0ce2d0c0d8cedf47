// The islands Baraff hands to Gauss-Seidel for their size are counted
// (StepStatistics::baraffOversizedIslands), and the limit (baraffMaxIslandContacts) says which.

#include <ThyrixLite/Border.h>
#include <ThyrixLite/Circle.h>
#include <ThyrixLite/Simulator.h>
#include <gtest/gtest.h>
#include "TestTolerances.h"

#include <limits>
#include <memory>
#include <vector>

namespace thyrix {
namespace {

/// A column of @p count unit disks on a floor, the top one pressed down: one island of
/// @p count contacts that all need a force.
struct Column {
  Column(int count, ContactSolverKind solver) {
    simulator.setContactSolver(solver);
    simulator.registerObject(std::make_unique<Border>(Vector2{0, 0}, Vector2{0, 1}));
    for (int i = 0; i < count; ++i) {
      auto& disk = simulator.registerObject(std::make_unique<Circle>(real(0.5), real(1)));
      disk.r = {0, real(0.5) + static_cast<real>(i)};
      disks.push_back(&disk);
    }
  }
  void step() {
    disks.back()->externalForce = {0, -1};
    simulator.advanceTime();
  }
  Simulator simulator;
  std::vector<Circle*> disks;
};

TEST(BaraffIslandLimitTest, AnIslandAboveTheLimitIsCountedAndSolvedByGaussSeidel) {
  Column column(40, ContactSolverKind::Baraff);
  ASSERT_EQ(column.simulator.solverSettings().baraffMaxIslandContacts, 32) << "the default";
  column.step();
  const StepStatistics& statistics = column.simulator.statistics();
  ASSERT_EQ(statistics.contacts, 40u);
  EXPECT_EQ(statistics.solvedIslands, 1u);
  EXPECT_EQ(statistics.baraffOversizedIslands, 1u);
  EXPECT_EQ(statistics.baraffPivots, 0u) << "Baraff never saw it";
  EXPECT_GT(statistics.gaussSeidelSweeps, 0u);
  EXPECT_EQ(statistics.baraffFallbacks, 0u) << "not a failure of Baraff's";
}

TEST(BaraffIslandLimitTest, RaisedLimitSolvesTheSameIslandExactly) {
  for (const int limit : {40, std::numeric_limits<int>::max()}) {
    Column column(40, ContactSolverKind::Baraff);
    column.simulator.solverSettings().baraffMaxIslandContacts = limit;
    column.step();
    const StepStatistics& statistics = column.simulator.statistics();
    ASSERT_EQ(statistics.contacts, 40u);
    EXPECT_EQ(statistics.baraffOversizedIslands, 0u) << "limit " << limit;
    EXPECT_GT(statistics.baraffPivots, 0u);
    EXPECT_EQ(statistics.gaussSeidelSweeps, 0u);
    // Exact: the push goes down the column unchanged, 1 N through every contact.
    for (const GlobalContactInfo& c : column.simulator.contacts)
      EXPECT_NEAR(c.force, 1, test::loose);
  }
}

TEST(BaraffIslandLimitTest, IslandsWithinTheLimitAndGaussSeidelChosenCountNothing) {
  Column small(32, ContactSolverKind::Baraff);
  small.step();
  EXPECT_EQ(small.simulator.statistics().baraffOversizedIslands, 0u);
  EXPECT_GT(small.simulator.statistics().baraffPivots, 0u);

  Column chosen(40, ContactSolverKind::GaussSeidel);
  chosen.step();
  EXPECT_EQ(chosen.simulator.statistics().baraffOversizedIslands, 0u);
  EXPECT_GT(chosen.simulator.statistics().gaussSeidelSweeps, 0u);
}

TEST(BaraffIslandLimitTest, TheCountIsPerStep) {
  Column column(40, ContactSolverKind::Baraff);
  column.step();
  ASSERT_EQ(column.simulator.statistics().baraffOversizedIslands, 1u);
  column.simulator.solverSettings().baraffMaxIslandContacts = 64;
  column.step();
  EXPECT_EQ(column.simulator.statistics().baraffOversizedIslands, 0u);
}

}  // namespace
}  // namespace thyrix
