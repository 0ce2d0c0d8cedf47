#pragma once
// What the broad-phase tests share: the pairs as comparable values, and a shuffle of boxes.

#include <ThyrixLite/BoundingBox.h>
#include <ThyrixLite/BroadPhase.h>
#include <Tools/MTRandom.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

namespace thyrix::test {

/// A pair of box indices, first < second.
using Pair = std::pair<std::uint32_t, std::uint32_t>;

/// The broad phase's pairs, each checked to be first < second as documented, then sorted (the
/// order is each path's own; the set is what the tests compare).
inline std::vector<Pair> sortedPairs(const std::vector<BoxPair>& found) {
  std::vector<Pair> pairs;
  for (const BoxPair& p : found) {
    EXPECT_LT(p.first, p.second);
    pairs.emplace_back(p.first, p.second);
  }
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

/// Shuffles @p boxes with the random stream of @p seed (Fisher-Yates), so that the boxes of a
/// kind (larger, oversized) lie anywhere in the list, not only first.
inline void shuffleBoxes(std::vector<BoundingBox>& boxes, std::uint32_t seed) {
  MTRandom shuffle(seed);
  for (std::size_t i = boxes.size(); i > 1; --i)
    std::swap(boxes[i - 1], boxes[shuffle.integer(static_cast<std::uint32_t>(i))]);
}

}  // namespace thyrix::test
