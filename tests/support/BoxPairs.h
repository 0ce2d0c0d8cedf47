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

/// A vector of reals from doubles.
constexpr Vector2 vec(double x, double y) { return {real(x), real(y)}; }

/// The box from (@p x0, @p y0) to (@p x1, @p y1).
inline BoundingBox box(double x0, double y0, double x1, double y1) {
  return {vec(x0, y0), vec(x1, y1)};
}

/// Every overlapping or touching pair, by checking all pairs (written independently of
/// BoundingBox::overlaps), sorted.
inline std::vector<Pair> bruteForce(const std::vector<BoundingBox>& boxes) {
  std::vector<Pair> pairs;
  for (std::uint32_t i = 0; i < boxes.size(); ++i) {
    for (std::uint32_t j = i + 1; j < boxes.size(); ++j) {
      const BoundingBox& a = boxes[i];
      const BoundingBox& b = boxes[j];
      const bool apartX = a.upper.x < b.lower.x || b.upper.x < a.lower.x;
      const bool apartY = a.upper.y < b.lower.y || b.upper.y < a.lower.y;
      if (!apartX && !apartY) pairs.emplace_back(i, j);
    }
  }
  return pairs;
}

/// Shuffles @p boxes with the random stream of @p seed (Fisher-Yates), so that the boxes of a
/// kind (larger, oversized) lie anywhere in the list, not only first.
inline void shuffleBoxes(std::vector<BoundingBox>& boxes, std::uint32_t seed) {
  MTRandom shuffle(seed);
  for (std::size_t i = boxes.size(); i > 1; --i)
    std::swap(boxes[i - 1], boxes[shuffle.integer(static_cast<std::uint32_t>(i))]);
}

/// @p count random boxes with lower corners in [0, world]^2: mostly small (0.1 to 2 per side,
/// some thin), one in 20 medium (2 to 8 per side: around the cell side, so on either side of the
/// oversized threshold) and @p oversized large ones (15 to 40 per side); all scaled by @p scale
/// and shifted by @p origin.
inline std::vector<BoundingBox> randomBoxes(std::uint32_t seed, int count, int oversized,
                                            double world, Vector2 origin = {}, double scale = 1) {
  MTRandom random(seed);
  std::vector<BoundingBox> boxes;
  for (int i = 0; i < count; ++i) {
    const bool big = i < oversized;
    const bool medium = !big && i % 20 == 19;
    const double w = big      ? random.uniform(15, 40)
                     : medium ? random.uniform(2, 8)
                              : random.uniform(0.1, 2);
    const double h = big      ? random.uniform(15, 40)
                     : medium ? random.uniform(2, 8)
                              : random.uniform(0.1, 2) * random.uniform();
    const double x = random.uniform(0, world);
    const double y = random.uniform(0, world);
    boxes.push_back(
        {origin + vec(x * scale, y * scale), origin + vec((x + w) * scale, (y + h) * scale)});
  }
  shuffleBoxes(boxes, seed + 1);  // the oversized boxes anywhere in the list
  return boxes;
}

}  // namespace thyrix::test
