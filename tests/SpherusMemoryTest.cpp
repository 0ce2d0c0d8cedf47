// The memory of a Spherus world: its heap stays under 64 KiB, and its steps allocate nothing.
// This executable replaces the global operator new to count live bytes (a size header in front
// of each block) and allocations.

#include <Controller/RandomController.h>
#include <SpherusSimulator.h>

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <new>

namespace {
long liveBytes = 0;
long allocations = 0;
constexpr std::size_t header = alignof(std::max_align_t);
}  // namespace

void* operator new(std::size_t size) {
  auto* block = static_cast<unsigned char*>(std::malloc(size + header));
  if (block == nullptr) throw std::bad_alloc();
  *reinterpret_cast<std::size_t*>(block) = size;
  liveBytes += static_cast<long>(size);
  ++allocations;
  return block + header;
}
void operator delete(void* p) noexcept {
  if (p == nullptr) return;
  auto* block = static_cast<unsigned char*>(p) - header;
  liveBytes -= static_cast<long>(*reinterpret_cast<std::size_t*>(block));
  std::free(block);
}
void operator delete(void* p, std::size_t) noexcept { operator delete(p); }

namespace thyrix {
namespace {

TEST(SpherusWorld, TakesAtMost64KiBOfHeapAndStepsWithoutAllocating) {
  const long before = liveBytes;
  {
    SpherusSimulator::Options options;  // the default arena: 20 circles, 4 walls
    SpherusSimulator simulator(options, std::make_unique<RandomController>(1));
    // The first step sizes the eyes' buffers (they learn the world's size) and the controller's
    // (it learns the effector count); the world's contact buffers were reserved at construction.
    simulator.advanceTime();
    const long builtBytes = liveBytes - before;
    const long allocationsBefore = allocations;
    for (int step = 0; step < 20000; ++step) simulator.advanceTime();
    const long worldBytes = liveBytes - before;
    const long stepAllocations = allocations - allocationsBefore;
    EXPECT_EQ(stepAllocations, 0) << "no step after the first allocates";
    EXPECT_EQ(worldBytes, builtBytes);
    EXPECT_LE(worldBytes, 64 * 1024) << "heap of a Spherus world: " << worldBytes << " bytes";
    EXPECT_GT(worldBytes, 0);
    std::printf("heap of a Spherus world: %ld bytes\n", worldBytes);
  }
  EXPECT_EQ(liveBytes, before) << "destroying the world frees everything it allocated";
}

}  // namespace
}  // namespace thyrix
