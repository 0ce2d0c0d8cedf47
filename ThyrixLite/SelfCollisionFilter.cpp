#include <ThyrixLite/SelfCollisionFilter.h>

#include <algorithm>
#include <atomic>

namespace thyrix {

void SelfCollisionFilter::assign(std::span<const std::uint32_t> partOf,
                                 std::span<const std::pair<std::uint32_t, std::uint32_t>> apart) {
  partOf_.assign(partOf.begin(), partOf.end());
  std::uint32_t parts = 0;
  for (const std::uint32_t part : partOf_) parts = std::max(parts, part + 1);
  for (const auto& [a, b] : apart) parts = std::max({parts, a + 1, b + 1});
  // Each pair listed under both of its parts (counting sort), so that a lookup reads one list.
  apartStart_.assign(parts + 1, 0);
  for (const auto& [a, b] : apart) {
    ++apartStart_[a + 1];
    ++apartStart_[b + 1];
  }
  for (std::uint32_t p = 0; p < parts; ++p) apartStart_[p + 1] += apartStart_[p];
  apart_.resize(apartStart_[parts]);
  std::vector<std::uint32_t> fill(apartStart_.begin(), apartStart_.end() - 1);
  for (const auto& [a, b] : apart) {
    apart_[fill[a]++] = b;
    apart_[fill[b]++] = a;
  }
  const std::size_t count = partOf_.size();
  apartNear_.assign(count, 0);
  for (std::size_t k = 0; k < count; ++k)
    for (std::size_t d = 1; d <= nearRange && k + d < count; ++d)
      if (!listedPartsMayTouch(partOf_[k], partOf_[k + d]))
        apartNear_[k] |= std::uint64_t{1} << (d - 1);
  // One counter for every filter of the program (simulators may run in several threads).
  static std::atomic<std::uint64_t> lastStamp{0};
  stamp_ = lastStamp.fetch_add(1, std::memory_order_relaxed) + 1;
}

}  // namespace thyrix
