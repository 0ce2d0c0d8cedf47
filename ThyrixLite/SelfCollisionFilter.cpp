#include <ThyrixLite/SelfCollisionFilter.h>

#include <algorithm>

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
  // The near bits of primitive k: the primitives up to nearRange after it in its own part and
  // in the parts listed apart from its part (what listedPartsMayTouch() refuses), found in
  // the primitives grouped by part (counting sort, in order within a part) rather than by
  // asking for each of the nearRange pairs.
  const auto count = static_cast<std::uint32_t>(partOf_.size());
  std::vector<std::uint32_t> partStart(parts + 1, 0);
  for (const std::uint32_t part : partOf_) ++partStart[part + 1];
  for (std::uint32_t p = 0; p < parts; ++p) partStart[p + 1] += partStart[p];
  std::vector<std::uint32_t> byPart(count);
  fill.assign(partStart.begin(), partStart.end() - 1);
  for (std::uint32_t k = 0; k < count; ++k) byPart[fill[partOf_[k]]++] = k;
  apartNear_.assign(count, 0);
  for (std::uint32_t k = 0; k < count; ++k) {
    std::uint64_t word = 0;
    const auto mark = [&](std::uint32_t part) {
      const std::uint32_t* const begin = byPart.data() + partStart[part];
      const std::uint32_t* const end = byPart.data() + partStart[part + 1];
      for (const std::uint32_t* q = std::upper_bound(begin, end, k);
           q != end && *q - k <= nearRange; ++q)
        word |= std::uint64_t{1} << (*q - k - 1);
    };
    const std::uint32_t own = partOf_[k];
    mark(own);
    for (std::uint32_t j = apartStart_[own]; j < apartStart_[own + 1]; ++j) mark(apart_[j]);
    apartNear_[k] = word;
  }
  ++stamp_;
}

SelfCollisionFilter& SelfCollisionFilter::operator=(const SelfCollisionFilter& other) {
  // Past both stamps: this filter's stamp grows at every change, whichever rules it takes.
  // Copied first, then swapped in: a copy that fails leaves this filter as it was.
  SelfCollisionFilter copy(other);
  partOf_.swap(copy.partOf_);
  apartNear_.swap(copy.apartNear_);
  apartStart_.swap(copy.apartStart_);
  apart_.swap(copy.apart_);
  stamp_ = std::max(stamp_, other.stamp_) + 1;
  return *this;
}

}  // namespace thyrix
