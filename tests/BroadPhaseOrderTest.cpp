// Broad phase: the grid's output order, pair by pair, against a reference written from its
// documented rule (BroadPhase.h, BroadPhase.cpp). Detection appends contacts in this order, so
// a faster grid must keep it exactly, not only the set of pairs.

#include "support/BoxPairs.h"

#include <ThyrixLite/BroadPhase.h>
#include <Tools/MTRandom.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <tuple>
#include <utility>
#include <vector>

namespace thyrix {
namespace {

using test::Pair;
using test::shuffleBoxes;

real extentOf(const BoundingBox& b) {
  return std::max(b.upper.x - b.lower.x, b.upper.y - b.lower.y);
}

/// The grid's pairs in the grid's order: cells of side min(largest extent, twice the mean),
/// a box larger than a cell "oversized"; each regular box i in index order meets the boxes
/// of its own cell after it, then those of cells (x+1, y-1), (x+1, y), (x+1, y+1), (x, y+1),
/// each cell by index; then each oversized box meets every box (each pair once).
std::vector<Pair> referenceOrder(const std::vector<BoundingBox>& boxes) {
  const auto count = static_cast<std::uint32_t>(boxes.size());
  real sum = 0;
  real largest = 0;
  for (const BoundingBox& b : boxes) {
    sum += extentOf(b);
    largest = std::max(largest, extentOf(b));
  }
  const real cell = std::max(std::min(largest, 2 * (sum / static_cast<real>(count))), realEpsilon);
  std::vector<bool> oversized(count);
  std::vector<std::int64_t> x(count);
  std::vector<std::int64_t> y(count);
  for (std::uint32_t i = 0; i < count; ++i) {
    oversized[i] = extentOf(boxes[i]) > cell;
    const Vector2 q = (boxes[i].lower + boxes[i].upper) * real(0.5) / cell;
    x[i] = static_cast<std::int64_t>(std::floor(q.x));
    y[i] = static_cast<std::int64_t>(std::floor(q.y));
  }
  std::vector<Pair> pairs;
  for (std::uint32_t i = 0; i < count; ++i) {
    if (oversized[i]) continue;
    std::vector<std::tuple<int, std::uint32_t>> met;  // (neighbour cell in visiting order, j)
    for (std::uint32_t j = 0; j < count; ++j) {
      if (j == i || oversized[j] || !boxes[i].overlaps(boxes[j])) continue;
      const std::int64_t dx = x[j] - x[i];
      const std::int64_t dy = y[j] - y[i];
      int rank = -1;
      if (dx == 0 && dy == 0 && j > i) rank = 0;
      if (dx == 1 && dy >= -1 && dy <= 1) rank = 2 + static_cast<int>(dy);
      if (dx == 0 && dy == 1) rank = 4;
      if (rank >= 0) met.emplace_back(rank, j);
    }
    std::sort(met.begin(), met.end());
    for (const auto& [rank, j] : met) pairs.emplace_back(std::min(i, j), std::max(i, j));
  }
  for (std::uint32_t big = 0; big < count; ++big) {
    if (!oversized[big]) continue;
    for (std::uint32_t j = 0; j < count; ++j) {
      if (j == big || (oversized[j] && j < big)) continue;
      if (boxes[big].overlaps(boxes[j])) pairs.emplace_back(std::min(big, j), std::max(big, j));
    }
  }
  return pairs;
}

std::vector<Pair> asPairs(const std::vector<BoxPair>& pairs) {
  std::vector<Pair> out;
  for (const BoxPair& p : pairs) out.emplace_back(p.first, p.second);
  return out;
}

/// A pile of @p count equal circles' boxes (side 2 * @p half) on a jittered triangular lattice,
/// a few boxes @p grown larger (travelling faster): the layout of pile1000, where every box
/// fits a cell and the cell is the largest box.
std::vector<BoundingBox> pileBoxes(std::uint32_t seed, int count, int grown, double half) {
  MTRandom random(seed);
  std::vector<BoundingBox> boxes;
  const int columns = static_cast<int>(std::sqrt(count)) + 1;
  for (int i = 0; i < count; ++i) {
    const double cx = (i % columns) + 0.5 * ((i / columns) % 2) + random.uniform(-0.05, 0.05);
    const double cy = (i / columns) * 0.87 + random.uniform(-0.05, 0.05);
    const double h = half + (i < grown ? random.uniform(0, 0.3) : random.uniform(0, 0.01));
    boxes.push_back({{real(cx - h), real(cy - h)}, {real(cx + h), real(cy + h)}});
  }
  shuffleBoxes(boxes, seed + 7);  // the larger ones anywhere in the list
  return boxes;
}

/// Random boxes of mixed sizes: small, some around the cell side, @p oversized large ones.
std::vector<BoundingBox> mixedBoxes(std::uint32_t seed, int count, int oversized, double world) {
  MTRandom random(seed);
  std::vector<BoundingBox> boxes;
  for (int i = 0; i < count; ++i) {
    const double side = i < oversized  ? random.uniform(10, 30)
                        : i % 15 == 14 ? random.uniform(1.5, 5)
                                       : random.uniform(0.2, 1.5);
    const double x = random.uniform(-world, world);
    const double y = random.uniform(-world, world);
    boxes.push_back({{real(x), real(y)}, {real(x + side), real(y + side * random.uniform())}});
  }
  shuffleBoxes(boxes, seed + 3);
  return boxes;
}

TEST(BroadPhaseOrder, DenseAndHashedGridsFollowTheReferenceOrder) {
  // One instance per grid over every case (stale buffers would show), the pile moving from
  // call to call as a pile does: boxes change cells, counts change, some grow oversized.
  BroadPhase dense;
  dense.allowSweep = false;
  BroadPhase hashed;
  hashed.allowSweep = false;
  hashed.allowDenseGrid = false;
  std::vector<BoxPair> pairs;
  std::size_t total = 0;
  for (std::uint32_t seed = 1; seed <= 6; ++seed) {
    for (const int count : {60, 400, 1000, 999}) {
      for (const int grown : {0, 3}) {
        std::vector<std::vector<BoundingBox>> cases{pileBoxes(seed, count, grown, 0.5),
                                                    mixedBoxes(seed, count, grown, 12)};
        if (seed % 2 == 0) {  // a few boxes nudged, as between two steps
          std::vector<BoundingBox> nudged = cases[0];
          MTRandom random(seed * 31);
          for (int k = 0; k < 20; ++k) {
            BoundingBox& b = nudged[random.integer(static_cast<std::uint32_t>(count))];
            const Vector2 shift{real(random.uniform(-0.3, 0.3)), real(random.uniform(-0.3, 0.3))};
            b = {b.lower + shift, b.upper + shift};
          }
          cases.push_back(nudged);
        }
        for (const std::vector<BoundingBox>& boxes : cases) {
          SCOPED_TRACE(::testing::Message()
                       << count << " boxes, seed " << seed << ", grown " << grown);
          const std::vector<Pair> expected = referenceOrder(boxes);
          dense.findPairs(boxes, pairs);
          EXPECT_EQ(asPairs(pairs), expected) << "dense grid";
          hashed.findPairs(boxes, pairs);
          EXPECT_EQ(asPairs(pairs), expected) << "hashed grid";
          total += expected.size();
        }
      }
    }
  }
  EXPECT_GT(total, 50000u);  // crowded enough to test something
}

}  // namespace
}  // namespace thyrix
