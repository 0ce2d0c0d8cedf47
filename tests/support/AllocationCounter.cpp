// The replaced global operator new and delete of test programs that count allocations, the
// over-aligned ones included. Each block carries its size in a header, so live bytes can be
// counted without the sized delete.

#include "AllocationCounter.h"

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <cstdlib>
#include <new>

namespace {
std::atomic<long> allocations{0};
std::atomic<long> bytes{0};
constexpr std::size_t header = alignof(std::max_align_t);
}  // namespace

void* operator new(std::size_t size) {
  auto* block = static_cast<unsigned char*>(std::malloc(size + header));
  if (block == nullptr) throw std::bad_alloc();
  *reinterpret_cast<std::size_t*>(block) = size;
  allocations.fetch_add(1, std::memory_order_relaxed);
  bytes.fetch_add(static_cast<long>(size), std::memory_order_relaxed);
  return block + header;
}

void operator delete(void* p) noexcept {
  if (p == nullptr) return;
  auto* block = static_cast<unsigned char*>(p) - header;
  bytes.fetch_sub(static_cast<long>(*reinterpret_cast<std::size_t*>(block)),
                  std::memory_order_relaxed);
  std::free(block);
}

void operator delete(void* p, std::size_t) noexcept { operator delete(p); }

// Over-aligned types (alignas beyond the default new alignment) come through these: the header
// takes a whole alignment, so that the block after it keeps the alignment asked for.
void* operator new(std::size_t size, std::align_val_t alignment) {
  const std::size_t align = std::max(static_cast<std::size_t>(alignment), header);
#ifdef _MSC_VER
  auto* block = static_cast<unsigned char*>(_aligned_malloc(size + align, align));
#else
  // aligned_alloc wants a size that is a multiple of the alignment.
  auto* block = static_cast<unsigned char*>(
      std::aligned_alloc(align, (size + 2 * align - 1) / align * align));
#endif
  if (block == nullptr) throw std::bad_alloc();
  *reinterpret_cast<std::size_t*>(block) = size;
  allocations.fetch_add(1, std::memory_order_relaxed);
  bytes.fetch_add(static_cast<long>(size), std::memory_order_relaxed);
  return block + align;
}

void operator delete(void* p, std::align_val_t alignment) noexcept {
  if (p == nullptr) return;
  const std::size_t align = std::max(static_cast<std::size_t>(alignment), header);
  auto* block = static_cast<unsigned char*>(p) - align;
  bytes.fetch_sub(static_cast<long>(*reinterpret_cast<std::size_t*>(block)),
                  std::memory_order_relaxed);
#ifdef _MSC_VER
  _aligned_free(block);
#else
  std::free(block);
#endif
}

void operator delete(void* p, std::size_t, std::align_val_t alignment) noexcept {
  operator delete(p, alignment);
}

namespace thyrix::test {
long allocationCount() { return allocations.load(std::memory_order_relaxed); }
long liveHeapBytes() { return bytes.load(std::memory_order_relaxed); }
}  // namespace thyrix::test
