// A warmed-up simulator allocates nothing per step. This executable links
// support/AllocationCounter.cpp to count allocations; the count is read around the steps under test
// only.

#include "support/AllocationCounter.h"

#include <Scenes.h>
#include <ThyrixLite/Simulator.h>

#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <new>
#include <vector>

namespace thyrix {
namespace {

class AllocationTest : public ::testing::TestWithParam<ContactSolverKind> {};

TEST_P(AllocationTest, PileOf2000CirclesStepsWithoutAllocating) {
  Simulator simulator(real(1) / 60);
  simulator.setContactSolver(GetParam());
  const auto circles = scenes::addPile(simulator, 2000, 1);
  // Quasistatic weight m g with g = 1: the circles fall at 1 m/s; after 300 steps the pile has
  // formed. Frictionless, it keeps compacting slowly (more contacts each step), so the contact
  // buffers are reserved for the densest packing: 3 contacts per circle, plus the walls.
  simulator.reserveContacts(3 * 2000 + 200);
  for (int step = 0; step < 300; ++step) {
    scenes::push(circles, {0, -1});
    simulator.advanceTime();
  }
  // (Most of the pile's contacts touch: at rest the speculative margin is narrow.)
  ASSERT_GT(simulator.contacts.size(), 1200u) << "the pile should be in contact";
  const long before = test::allocationCount();
  for (int step = 0; step < 100; ++step) {
    scenes::push(circles, {0, -1});
    simulator.advanceTime();
  }
  EXPECT_EQ(test::allocationCount() - before, 0);
}

TEST_P(AllocationTest, GrowingPileWithoutReservedBuffersAllocatesOnlyToGrowThem) {
  // Without reserveContacts, the buffers grow with the contacts: geometrically, so a pile whose
  // contacts keep increasing step after step allocates a few times per buffer, not once a step
  // (as a buffer resized to each new largest island exactly would).
  Simulator simulator(real(1) / 60);
  simulator.setContactSolver(GetParam());
  const auto circles = scenes::addPile(simulator, 1000, 1);
  for (int step = 0; step < 100; ++step) {
    scenes::push(circles, {0, -1});
    simulator.advanceTime();
  }
  const long before = test::allocationCount();
  for (int step = 0; step < 400; ++step) {
    scenes::push(circles, {0, -1});
    simulator.advanceTime();
  }
  EXPECT_LT(test::allocationCount() - before, 100);
}

TEST(AllocationCounter, CountsAllocations) {
  const long before = test::allocationCount();
  std::vector<int> grown;
  grown.reserve(static_cast<std::size_t>(::testing::UnitTest::GetInstance()->random_seed()) + 10);
  EXPECT_EQ(test::allocationCount() - before, 1);
}

TEST(AllocationCounter, CountsOverAlignedAllocations) {
  // Over-aligned types (GaussSeidelSolver's rows are cache lines: alignas(64)) are allocated
  // through the aligned operator new, which must be counted too.
  struct alignas(64) Line {
    double words[8];
  };
  const long before = test::allocationCount();
  const long liveBefore = test::liveHeapBytes();
  {
    std::vector<Line> lines;
    lines.reserve(static_cast<std::size_t>(::testing::UnitTest::GetInstance()->random_seed()) + 10);
    EXPECT_EQ(test::allocationCount() - before, 1);
    EXPECT_GE(test::liveHeapBytes() - liveBefore, static_cast<long>(10 * sizeof(Line)));
    EXPECT_EQ(reinterpret_cast<std::uintptr_t>(lines.data()) % alignof(Line), 0u);
  }
  EXPECT_EQ(test::liveHeapBytes(), liveBefore);
}

INSTANTIATE_TEST_SUITE_P(BothSolvers, AllocationTest,
                         ::testing::Values(ContactSolverKind::Baraff,
                                           ContactSolverKind::GaussSeidel),
                         [](const auto& solver) {
                           return solver.param == ContactSolverKind::Baraff ? "Baraff"
                                                                            : "GaussSeidel";
                         });

}  // namespace
}  // namespace thyrix
