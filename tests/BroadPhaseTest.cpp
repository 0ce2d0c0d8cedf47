// Broad phase: the grid must find exactly the pairs that an all-pairs check finds, each once
// with first < second, deterministically and without allocating once warmed up.

#include "support/AllocationCounter.h"
#include "support/BoxPairs.h"

#include <ThyrixLite/BroadPhase.h>
#include <Tools/MTRandom.h>
#include <Tools/MathTools.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <new>
#include <utility>
#include <vector>

namespace thyrix {
namespace {

using test::box;
using test::bruteForce;
using test::Pair;
using test::randomBoxes;
using test::shuffleBoxes;
using test::sortedPairs;

using test::vec;

/// Checks the broad phase against brute force: the same set, each pair once.
void expectSameAsBruteForce(const std::vector<BoundingBox>& boxes,
                            const std::vector<BoxPair>& pairs) {
  const std::vector<Pair> found = sortedPairs(pairs);
  EXPECT_EQ(std::adjacent_find(found.begin(), found.end()), found.end()) << "a pair repeats";
  EXPECT_EQ(found, bruteForce(boxes));
}

TEST(BroadPhase, EmptyAndSingleBoxGiveNoPairs) {
  BroadPhase broadPhase;
  std::vector<BoxPair> pairs{{0, 1}, {2, 3}};  // stale content must be replaced
  broadPhase.findPairs({}, pairs);
  EXPECT_TRUE(pairs.empty());

  pairs = {{0, 1}};
  const std::vector<BoundingBox> one{box(0, 0, 1, 1)};
  broadPhase.findPairs(one, pairs);
  EXPECT_TRUE(pairs.empty());
}

TEST(BroadPhase, TwoBoxes) {
  BroadPhase broadPhase;
  std::vector<BoxPair> pairs;
  const std::vector<BoundingBox> overlapping{box(0, 0, 2, 2), box(1, 1, 3, 3)};
  broadPhase.findPairs(overlapping, pairs);
  ASSERT_EQ(pairs.size(), 1u);
  EXPECT_EQ(pairs[0].first, 0u);
  EXPECT_EQ(pairs[0].second, 1u);

  const std::vector<BoundingBox> identical{box(-1, -1, 1, 1), box(-1, -1, 1, 1)};
  broadPhase.findPairs(identical, pairs);
  EXPECT_EQ(pairs.size(), 1u);

  const std::vector<BoundingBox> apart{box(0, 0, 1, 1), box(1.5, 0, 2.5, 1)};
  broadPhase.findPairs(apart, pairs);
  EXPECT_TRUE(pairs.empty());
}

TEST(BroadPhase, TouchingBoxesOverlap) {
  BroadPhase broadPhase;
  std::vector<BoxPair> pairs;
  // Sharing the edge x = 1; sharing only the corner (1, 1); 0.01 apart.
  const std::vector<BoundingBox> edge{box(0, 0, 1, 1), box(1, 0.5, 2, 1.5)};
  broadPhase.findPairs(edge, pairs);
  EXPECT_EQ(pairs.size(), 1u);
  const std::vector<BoundingBox> corner{box(0, 0, 1, 1), box(1, 1, 2, 2)};
  broadPhase.findPairs(corner, pairs);
  EXPECT_EQ(pairs.size(), 1u);
  const std::vector<BoundingBox> gap{box(0, 0, 1, 1), box(1.01, 0, 2, 1)};
  broadPhase.findPairs(gap, pairs);
  EXPECT_TRUE(pairs.empty());
}

TEST(BroadPhase, GridOfTouchingUnitBoxes) {
  // An n x n grid of unit boxes [i, i+1] x [j, j+1], from -3 so it spans negative and positive
  // cells: each box touches its 8 neighbours (edges and corners), which lie in other grid
  // cells (cell side 2 x mean size = 2). Pairs: n(n-1) along rows, as many along columns,
  // 2 (n-1)^2 diagonal; for n = 6: 30 + 30 + 50 = 110.
  const int n = 6;
  std::vector<BoundingBox> boxes;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) boxes.push_back(box(i - 3, j - 3, i - 2, j - 2));
  BroadPhase broadPhase;
  std::vector<BoxPair> pairs;
  broadPhase.findPairs(boxes, pairs);
  EXPECT_EQ(pairs.size(), 110u);
  expectSameAsBruteForce(boxes, pairs);
}

TEST(BroadPhase, AllBoxesOnTopOfEachOther) {
  // 40 identical boxes: all 40 * 39 / 2 = 780 pairs.
  const std::vector<BoundingBox> boxes(40, box(2, 3, 3, 4));
  BroadPhase broadPhase;
  std::vector<BoxPair> pairs;
  broadPhase.findPairs(boxes, pairs);
  EXPECT_EQ(pairs.size(), 780u);
  expectSameAsBruteForce(boxes, pairs);
}

TEST(BroadPhase, MatchesBruteForceOnRandomBoxes) {
  BroadPhase broadPhase;  // one instance over all cases, so stale buffers would show
  std::vector<BoxPair> pairs;
  std::size_t total = 0;
  for (const int count : {2, 3, 10, 100, 1000, 50, 2000}) {
    for (std::uint32_t seed = 1; seed <= 4; ++seed) {
      const int oversized = count >= 10 ? 1 + static_cast<int>(seed) : 0;
      // World sides giving sparse and crowded scenes.
      for (const double world : {5.0, 40.0}) {
        const std::vector<BoundingBox> boxes =
            randomBoxes(seed * 1000 + static_cast<std::uint32_t>(count), count, oversized,
                        world * std::sqrt(count / 100.0));
        broadPhase.findPairs(boxes, pairs);
        SCOPED_TRACE(::testing::Message()
                     << count << " boxes, seed " << seed << ", world " << world);
        expectSameAsBruteForce(boxes, pairs);
        total += pairs.size();
      }
    }
  }
  EXPECT_GT(total, 10000u);  // the scenes are crowded enough to test something
}

TEST(BroadPhase, OversizedBoxesAmongSmallOnes) {
  // Oversized boxes overlapping each other and the small ones: a few huge boxes among tiny ones.
  std::vector<BoundingBox> boxes = randomBoxes(99, 300, 0, 30);
  boxes.push_back(box(-100, -100, 100, 100));  // covers everything
  boxes.insert(boxes.begin(), box(10, -5, 12, 50));
  boxes.insert(boxes.begin() + 100, box(-5, 10, 50, 11));
  BroadPhase broadPhase;
  std::vector<BoxPair> pairs;
  broadPhase.findPairs(boxes, pairs);
  expectSameAsBruteForce(boxes, pairs);
  // The covering box (last) pairs with every other box.
  const auto last = static_cast<std::uint32_t>(boxes.size() - 1);
  EXPECT_EQ(
      std::count_if(pairs.begin(), pairs.end(), [&](const BoxPair& p) { return p.second == last; }),
      static_cast<std::ptrdiff_t>(last));
}

TEST(BroadPhase, NegativeAndLargeCoordinates) {
  BroadPhase broadPhase;
  std::vector<BoxPair> pairs;
  // Around the origin in negative coordinates, and far away: sizes in the tens so that float
  // keeps the boxes' shapes at 1e6 (float spacing there is 0.0625).
  const Vector2 origins[] = {vec(-60, -45), vec(-1e6, 2e6), vec(3e6, -4e6)};
  for (const Vector2 origin : origins) {
    const std::vector<BoundingBox> boxes = randomBoxes(7, 400, 3, 40, origin, 10);
    broadPhase.findPairs(boxes, pairs);
    SCOPED_TRACE(::testing::Message() << "origin " << origin.x << ", " << origin.y);
    expectSameAsBruteForce(boxes, pairs);
    EXPECT_GT(pairs.size(), 100u);
  }
  // Boxes straddling the axes: cells -1 and 0 on both sides.
  const std::vector<BoundingBox> straddling{box(-1, -1, -0.1, -0.1), box(-0.1, -0.1, 0.5, 0.5),
                                            box(0.5, -1, 1.2, -0.1), box(-1, 0.5, -0.1, 1.3)};
  broadPhase.findPairs(straddling, pairs);
  expectSameAsBruteForce(straddling, pairs);
  EXPECT_EQ(pairs.size(), 3u);  // box 1 touches each of the others at a corner
}

TEST(BroadPhase, OutputIsDeterministic) {
  const std::vector<BoundingBox> boxes = randomBoxes(4242, 800, 4, 25);
  const std::vector<BoundingBox> other = randomBoxes(17, 1500, 2, 60);
  auto equal = [](const std::vector<BoxPair>& x, const std::vector<BoxPair>& y) {
    return std::equal(x.begin(), x.end(), y.begin(), y.end(), [](BoxPair p, BoxPair q) {
      return p.first == q.first && p.second == q.second;
    });
  };
  BroadPhase broadPhase;
  std::vector<BoxPair> first;
  std::vector<BoxPair> second;
  broadPhase.findPairs(boxes, first);
  broadPhase.findPairs(boxes, second);
  ASSERT_FALSE(first.empty());
  EXPECT_TRUE(equal(first, second)) << "same instance, same input, different order";

  // A fresh instance, and one that saw other boxes first, give the same order too.
  BroadPhase fresh;
  fresh.findPairs(boxes, second);
  EXPECT_TRUE(equal(first, second));
  BroadPhase used;
  used.findPairs(other, second);
  used.findPairs(boxes, second);
  EXPECT_TRUE(equal(first, second));
}

bool samePairs(const std::vector<BoxPair>& x, const std::vector<BoxPair>& y) {
  return std::equal(x.begin(), x.end(), y.begin(), y.end(), [](BoxPair p, BoxPair q) {
    return p.first == q.first && p.second == q.second;
  });
}

TEST(BroadPhase, DenseAndHashedGridsGiveTheSameOrder) {
  // A pile-like crowded layout (dense grid) and scattered ones (either grid), with oversized
  // boxes: the hashed grid, forced, must give the very same sequence of pairs.
  BroadPhase dense;
  BroadPhase hashed;
  hashed.allowDenseGrid = false;
  std::vector<BoxPair> densePairs;
  std::vector<BoxPair> hashedPairs;
  for (const double world : {3.0, 10.0, 40.0}) {
    const std::vector<BoundingBox> boxes = randomBoxes(5, 1000, 3, world);
    dense.findPairs(boxes, densePairs);
    hashed.findPairs(boxes, hashedPairs);
    SCOPED_TRACE(::testing::Message() << "world " << world);
    expectSameAsBruteForce(boxes, densePairs);
    EXPECT_TRUE(samePairs(densePairs, hashedPairs));
  }
  // Unit boxes in a square: the dense grid for sure.
  std::vector<BoundingBox> square;
  for (int j = 0; j < 30; ++j)
    for (int i = 0; i < 30; ++i) square.push_back(box(i * 0.9, j * 0.9, i * 0.9 + 1, j * 0.9 + 1));
  dense.findPairs(square, densePairs);
  hashed.findPairs(square, hashedPairs);
  expectSameAsBruteForce(square, densePairs);
  EXPECT_TRUE(samePairs(densePairs, hashedPairs));
}

/// A chain of @p count capsule-like boxes of length 1 and half width @p width, joint to joint,
/// each turned from its parent by a random angle within @p bend (rad), from @p start.
std::vector<BoundingBox> chainBoxes(std::uint32_t seed, int count, double bend, double width,
                                    double startAngle, Vector2 start = {}) {
  MTRandom random(seed);
  std::vector<BoundingBox> boxes;
  double angle = startAngle;
  Vector2 joint = start;
  for (int i = 0; i < count; ++i) {
    angle += random.uniform(-bend, bend);
    const Vector2 tip = joint + vec(std::cos(angle), std::sin(angle));
    boxes.push_back({vec(std::min(joint.x, tip.x) - width, std::min(joint.y, tip.y) - width),
                     vec(std::max(joint.x, tip.x) + width, std::max(joint.y, tip.y) + width)});
    joint = tip;
  }
  return boxes;
}

TEST(BroadPhase, SweepMatchesBruteForceOnLinesOfBoxes) {
  // Lines of boxes (the sweep's case): straight along x, along y and diagonal, bent chains that
  // may fold onto themselves, rows of touching boxes, lines with stacked duplicates and with
  // an oversized box; the sweep and the grid must both give brute force's pairs.
  BroadPhase sweep;  // one instance over all cases, so stale orders would show
  BroadPhase grid;
  grid.allowSweep = false;
  std::vector<BoxPair> sweepPairs;
  std::vector<BoxPair> gridPairs;
  std::vector<std::vector<BoundingBox>> layouts;
  for (const double angle : {0.0, pi<double> / 2, pi<double> / 4, -2.0, pi<double>})
    layouts.push_back(chainBoxes(1, 500, 0.0, 0.125, angle, vec(-3, 7)));
  for (std::uint32_t seed = 1; seed <= 4; ++seed) {
    layouts.push_back(chainBoxes(seed, 1000, 0.3, 0.125, -pi<double> / 2));  // a hanging chain
    layouts.push_back(chainBoxes(seed, 300, 1.5, 0.2, seed));                // folds onto itself
  }
  std::vector<BoundingBox> row;  // touching end to end, then two rows on top of each other
  for (int i = 0; i < 200; ++i) row.push_back(box(i, 0, i + 1, 1));
  layouts.push_back(row);
  for (int i = 0; i < 200; ++i) row.push_back(box(i + 0.5, 1, i + 1.5, 2));
  layouts.push_back(row);
  std::vector<BoundingBox> stacked = chainBoxes(9, 400, 0.2, 0.1, 0.3);
  for (int i = 0; i < 400; i += 7) stacked[i + 1] = stacked[i];  // identical boxes
  stacked[123] = box(-10, -10, 500, 0);                          // oversized
  layouts.push_back(stacked);
  for (const std::vector<BoundingBox>& boxes : layouts) {
    SCOPED_TRACE(::testing::Message() << "layout " << (&boxes - layouts.data()));
    sweep.findPairs(boxes, sweepPairs);
    grid.findPairs(boxes, gridPairs);
    expectSameAsBruteForce(boxes, sweepPairs);
    expectSameAsBruteForce(boxes, gridPairs);
  }
}

TEST(BroadPhase, SweepFollowsMovingBoxes) {
  // A chain swinging and a line of boxes drifting past each other, step after step: the sweep
  // starts from its last order, which must never change the result.
  BroadPhase moving;
  std::vector<BoxPair> pairs;
  std::vector<BoxPair> freshPairs;
  MTRandom random(5);
  for (int step = 0; step < 60; ++step) {
    // The chain turns (large turns late: the order changes a lot, a full sort takes over).
    const double angle = -pi<double> / 2 + 0.05 * step * step * 0.1;
    std::vector<BoundingBox> boxes = chainBoxes(3, 600, 0.2, 0.125, angle);
    // Boxes of a second line slide along the chain.
    for (int i = 0; i < 100; ++i) {
      const double y = -5.0 * i - 0.3 * step;
      boxes.push_back(box(-0.5 + random.uniform(-0.1, 0.1), y, 0.5, y + 1));
    }
    moving.findPairs(boxes, pairs);
    SCOPED_TRACE(::testing::Message() << "step " << step);
    expectSameAsBruteForce(boxes, pairs);
    BroadPhase fresh;  // no last order: the same pairs in the same order
    fresh.findPairs(boxes, freshPairs);
    ASSERT_TRUE(samePairs(pairs, freshPairs));
  }
}

TEST(BroadPhase, SweepLeavesOutBoxesWithNaN) {
  // A NaN corner overlaps nothing, as in BoundingBox::overlaps() (every comparison is false):
  // the pairs are those of the same layout with the NaN boxes moved out of everyone's way.
  std::vector<BoundingBox> boxes = chainBoxes(2, 200, 0.1, 0.125, 0.2);
  const real nan = std::numeric_limits<real>::quiet_NaN();
  boxes[10].lower.x = nan;
  boxes[50].upper.x = nan;  // (x only: the estimate along y stays a number, the sweep runs)
  std::vector<BoundingBox> away = boxes;
  away[10] = box(1e6, 1e6, 1e6, 1e6);
  away[50] = box(-1e6, 1e6, -1e6, 1e6);
  BroadPhase broadPhase;
  std::vector<BoxPair> pairs;
  broadPhase.findPairs(boxes, pairs);
  EXPECT_EQ(sortedPairs(pairs), bruteForce(away));
  boxes[10] = boxes[11];  // finite again: found again, whatever the last call left out
  away[10] = boxes[11];
  broadPhase.findPairs(boxes, pairs);
  EXPECT_EQ(sortedPairs(pairs), bruteForce(away));
  // Infinite sides are numbers: a box across all x meets every box in its band of y.
  const real inf = std::numeric_limits<real>::infinity();
  boxes[100] = away[100] = {{-inf, boxes[100].lower.y}, {inf, boxes[100].upper.y}};
  broadPhase.findPairs(boxes, pairs);
  EXPECT_EQ(sortedPairs(pairs), bruteForce(away));
}

TEST(BroadPhase, SweepGivesUpOnCrowdsItCannotSee) {
  // Two dense clusters far apart look like a sparse line to the even-spread estimate; the
  // sweep then runs out of its budget and the grid must give the pairs.
  std::vector<BoundingBox> boxes;
  for (int c = 0; c < 2; ++c)
    for (int j = 0; j < 20; ++j)
      for (int i = 0; i < 20; ++i) {
        const double x = c * 1e5 + i * 0.5;
        boxes.push_back(box(x, j * 0.5, x + 1, j * 0.5 + 1));
      }
  BroadPhase broadPhase;
  std::vector<BoxPair> pairs;
  broadPhase.findPairs(boxes, pairs);
  expectSameAsBruteForce(boxes, pairs);
}

TEST(BroadPhase, FewBoxesRetestOnlyTheMovedOnes) {
  // Up to smallCount boxes, a call told which boxes moved must give what a full test gives.
  MTRandom random(3);
  std::vector<BoundingBox> boxes = randomBoxes(11, 40, 2, 6);
  std::vector<std::uint64_t> moved(1, 0);  // one bit per box
  BroadPhase incremental;
  BroadPhase full;
  std::vector<BoxPair> incrementalPairs;
  std::vector<BoxPair> fullPairs;
  incremental.findPairs(boxes, moved, incrementalPairs);  // nothing remembered yet: all tested
  full.findPairs(boxes, fullPairs);
  EXPECT_TRUE(samePairs(incrementalPairs, fullPairs));
  for (int step = 0; step < 200; ++step) {
    moved[0] = 0;
    const int moving = 1 + static_cast<int>(random.integer(4));
    for (int k = 0; k < moving; ++k) {
      const std::uint32_t i = random.integer(static_cast<std::uint32_t>(boxes.size()));
      const Vector2 shift = vec(random.uniform(-1, 1), random.uniform(-1, 1));
      boxes[i] = {boxes[i].lower + shift, boxes[i].upper + shift};
      moved[0] |= std::uint64_t{1} << i;
    }
    incremental.findPairs(boxes, moved, incrementalPairs);
    full.findPairs(boxes, fullPairs);
    SCOPED_TRACE(::testing::Message() << "step " << step);
    ASSERT_TRUE(samePairs(incrementalPairs, fullPairs));
    expectSameAsBruteForce(boxes, incrementalPairs);
  }
  // A different box count: the promise is not used (box 0 moved but is not flagged).
  boxes.pop_back();
  boxes[0] = {boxes[0].lower + vec(3, 3), boxes[0].upper + vec(3, 3)};
  moved[0] = 0;
  incremental.findPairs(boxes, moved, incrementalPairs);
  expectSameAsBruteForce(boxes, incrementalPairs);
}

TEST(BroadPhase, FewBoxesFollowOverlapsWithNaNInfinitiesAndSignedZeros) {
  // The few-box path tests several boxes at once (by coordinate): the pairs must be exactly
  // those BoundingBox::overlaps accepts, whatever the count (whole vectors or not) and the
  // values (a comparison with NaN is false; -0 equals +0; infinite corners).
  const real inf = std::numeric_limits<real>::infinity();
  const real nan = std::numeric_limits<real>::quiet_NaN();
  const real specials[] = {nan, inf, -inf, real(-0.0), real(0.0)};
  MTRandom random(17);
  for (const std::uint32_t count : {2u, 3u, 4u, 5u, 7u, 33u, 47u, BroadPhase::smallCount}) {
    std::vector<BoundingBox> boxes = randomBoxes(count, static_cast<int>(count), 0, 4);
    for (std::uint32_t i = 0; i < count; i += 3) {  // a special value in one corner coordinate
      real* corner[] = {&boxes[i].lower.x, &boxes[i].lower.y, &boxes[i].upper.x, &boxes[i].upper.y};
      *corner[random.integer(4)] = specials[random.integer(5)];
    }
    BroadPhase broadPhase;
    std::vector<BoxPair> pairs;
    broadPhase.findPairs(boxes, pairs);
    std::vector<Pair> expected;
    for (std::uint32_t i = 0; i < count; ++i)
      for (std::uint32_t j = i + 1; j < count; ++j)
        if (boxes[i].overlaps(boxes[j])) expected.emplace_back(i, j);
    SCOPED_TRACE(::testing::Message() << count << " boxes");
    EXPECT_EQ(sortedPairs(pairs), expected);
  }
}

TEST(BroadPhase, WarmedUpCallsReuseTheirBuffers) {
  const std::vector<BoundingBox> large = randomBoxes(31, 1200, 3, 35);
  // A prefix: no more boxes, cells or pairs than the large input.
  const std::vector<BoundingBox> small(large.begin(), large.begin() + 300);
  BroadPhase broadPhase;
  std::vector<BoxPair> pairs;
  long before = test::allocationCount();
  broadPhase.findPairs(large, pairs);  // warms up every buffer
  const long warmUp = test::allocationCount() - before;
  EXPECT_GT(warmUp, 0);  // the counter does see the broad phase's allocations
  const BoxPair* const data = pairs.data();

  before = test::allocationCount();
  broadPhase.findPairs(large, pairs);
  const long again = test::allocationCount() - before;
  EXPECT_EQ(again, 0);
  EXPECT_EQ(pairs.data(), data);
  expectSameAsBruteForce(large, pairs);

  before = test::allocationCount();
  broadPhase.findPairs(small, pairs);
  const long smaller = test::allocationCount() - before;
  EXPECT_EQ(smaller, 0);
  EXPECT_EQ(pairs.data(), data);
  expectSameAsBruteForce(small, pairs);  // nothing stale from the larger call

  before = test::allocationCount();
  broadPhase.findPairs(large, pairs);
  const long back = test::allocationCount() - before;
  EXPECT_EQ(back, 0);
  expectSameAsBruteForce(large, pairs);
}

TEST(BroadPhase, AlternatingSweepAndGridGiveWhatAFreshInstanceGives) {
  // How much work a call does depends on the last one (after the grid, the grid's extents are
  // gathered together with the sweep's estimate); the pairs and their order must not.
  const std::vector<BoundingBox> line = chainBoxes(3, 400, 0.1, 0.125, 0.3);
  const std::vector<BoundingBox> pile = randomBoxes(5, 600, 2, 20);
  BroadPhase used;
  std::vector<BoxPair> pairs;
  std::vector<BoxPair> expected;
  for (const auto* boxes : {&line, &pile, &pile, &line, &line, &pile}) {
    BroadPhase fresh;
    fresh.findPairs(*boxes, expected);
    used.findPairs(*boxes, pairs);
    EXPECT_TRUE(samePairs(pairs, expected));
    expectSameAsBruteForce(*boxes, pairs);
  }
}

TEST(BroadPhase, ExtentsGatheredByTheCallerGiveTheSamePairs) {
  // The simulator gathers the sweep's extents while it computes a chain's boxes and hands them
  // over: the pairs must be those the broad phase finds gathering them itself, whether the
  // sweep (a line of links) or the grid (a pile) takes the boxes.
  const std::vector<BoundingBox> line = chainBoxes(3, 400, 0.1, 0.125, 0.3);
  const std::vector<BoundingBox> pile = randomBoxes(5, 600, 2, 20);
  BroadPhase given;
  std::vector<BoxPair> pairs;
  std::vector<BoxPair> expected;
  for (const auto* boxes : {&line, &pile, &line}) {
    SweepAndPrune::Extents extents;
    for (const BoundingBox& box : *boxes) extents.add(box);
    BroadPhase fresh;
    fresh.findPairs(*boxes, expected);
    given.findPairs(*boxes, {}, pairs, &extents);
    EXPECT_TRUE(samePairs(pairs, expected));
    expectSameAsBruteForce(*boxes, pairs);
  }
}

}  // namespace
}  // namespace thyrix
