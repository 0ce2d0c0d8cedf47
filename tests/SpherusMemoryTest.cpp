// The memory of a Spherus world: its heap stays under 64 KiB, and its steps allocate nothing.
// This executable links support/AllocationCounter.cpp, which counts live heap bytes and
// allocations.

#include "support/AllocationCounter.h"

#include <Agents/SpherusSimulator.h>
#include <Controller/RandomController.h>

#include <gtest/gtest.h>

#include <cstdio>

namespace thyrix {
namespace {

TEST(SpherusWorld, TakesAtMost64KiBOfHeapAndStepsWithoutAllocating) {
  const long before = test::liveHeapBytes();
  {
    SpherusSimulator::Options options;  // the default arena: 20 circles, 4 walls
    SpherusSimulator simulator(options, std::make_unique<RandomController>(1));
    // The first step sizes the eyes' buffers (they learn the world's size) and the controller's
    // (it learns the effector count); the world's contact buffers were reserved at construction.
    simulator.advanceTime();
    const long builtBytes = test::liveHeapBytes() - before;
    const long allocationsBefore = test::allocationCount();
    for (int step = 0; step < 20000; ++step) simulator.advanceTime();
    const long worldBytes = test::liveHeapBytes() - before;
    const long stepAllocations = test::allocationCount() - allocationsBefore;
    EXPECT_EQ(stepAllocations, 0) << "no step after the first allocates";
    EXPECT_EQ(worldBytes, builtBytes);
    EXPECT_LE(worldBytes, 64 * 1024) << "heap of a Spherus world: " << worldBytes << " bytes";
    EXPECT_GT(worldBytes, 0);
    std::printf("heap of a Spherus world: %ld bytes\n", worldBytes);
  }
  EXPECT_EQ(test::liveHeapBytes(), before) << "destroying the world frees everything it allocated";
}

}  // namespace
}  // namespace thyrix
