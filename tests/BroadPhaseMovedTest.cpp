// Broad phase, many boxes of which few changed: the changed boxes are tested against every box
// and the other pairs are the last call's. It must find every pair (those of a full call), in
// an order that depends on the boxes of this call and the earlier ones alone, never on which
// boxes the caller flagged.

#include "support/AllocationCounter.h"
#include "support/BoxPairs.h"

#include <ThyrixLite/BroadPhase.h>
#include <Tools/MTRandom.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace thyrix {
namespace {

using test::box;
using test::bruteForce;
using test::Pair;
using test::randomBoxes;
using test::sortedPairs;
using test::vec;

/// The pairs as values, in their order.
std::vector<Pair> inOrder(const std::vector<BoxPair>& pairs) {
  std::vector<Pair> values;
  for (const BoxPair& p : pairs) values.emplace_back(p.first, p.second);
  return values;
}

/// A flag for every box.
std::vector<std::uint64_t> allFlagged(std::size_t count) {
  std::vector<std::uint64_t> bits((count + 63) / 64, ~std::uint64_t{0});
  if (count % 64 != 0) bits.back() = (std::uint64_t{1} << (count % 64)) - 1;
  return bits;
}

void flag(std::vector<std::uint64_t>& bits, std::uint32_t i) {
  bits[i / 64] |= std::uint64_t{1} << (i % 64);
}

/// Moves @p moving random boxes of @p boxes by up to a box size, and returns their flags, with
/// @p extra unmoved boxes flagged too (a flag promises nothing but may be set in excess).
std::vector<std::uint64_t> moveSome(std::vector<BoundingBox>& boxes, MTRandom& random, int moving,
                                    int extra) {
  std::vector<std::uint64_t> bits((boxes.size() + 63) / 64, 0);
  const auto count = static_cast<std::uint32_t>(boxes.size());
  for (int k = 0; k < moving; ++k) {
    const std::uint32_t i = random.integer(count);
    const Vector2 shift = vec(random.uniform(-1.5, 1.5), random.uniform(-1.5, 1.5));
    boxes[i] = {boxes[i].lower + shift, boxes[i].upper + shift};
    flag(bits, i);
  }
  for (int k = 0; k < extra; ++k) flag(bits, random.integer(count));
  return bits;
}

TEST(BroadPhaseMoved, FewChangedBoxesAmongManyGiveEveryPair) {
  // Counts around the all-pairs limit and across words of 64 boxes; from one moved box to more
  // than the limit (then every pair is tested), flags in excess or not.
  for (const std::uint32_t count : {BroadPhase::smallCount + 1, 64u, 65u, 200u, 700u}) {
    SCOPED_TRACE(::testing::Message() << count << " boxes");
    std::vector<BoundingBox> boxes =
        randomBoxes(count, static_cast<int>(count), 2, std::sqrt(double(count)) * 2);
    MTRandom random(count);
    BroadPhase flagged;     // told which boxes moved (and some that did not)
    BroadPhase everything;  // told that every box moved, as a simulator without rest skipping
    std::vector<BoxPair> pairs;
    std::vector<BoxPair> everyPairs;
    // Both first see the same boxes: the order depends on the boxes of every call so far.
    flagged.findPairs(boxes, allFlagged(count), pairs);
    everything.findPairs(boxes, allFlagged(count), everyPairs);
    const int limit = static_cast<int>(BroadPhase::movedLimit(count));
    for (int step = 0; step < 120; ++step) {
      SCOPED_TRACE(::testing::Message() << "step " << step);
      const int moving =
          step % 10 == 9 ? limit + 3
                         : 1 + static_cast<int>(random.integer(static_cast<std::uint32_t>(limit)));
      const std::vector<std::uint64_t> moved = moveSome(boxes, random, moving, step % 3);
      flagged.findPairs(boxes, moved, pairs);
      everything.findPairs(boxes, allFlagged(count), everyPairs);
      const std::vector<Pair> found = sortedPairs(pairs);
      ASSERT_EQ(std::adjacent_find(found.begin(), found.end()), found.end()) << "a pair repeats";
      ASSERT_EQ(found, bruteForce(boxes));
      ASSERT_EQ(inOrder(pairs), inOrder(everyPairs));
    }
  }
}

/// The pairs of the changed boxes of @p changed, in the documented order: by changed box, then
/// by the other box's index, each pair once (a changed box below gave it already).
std::vector<Pair> changedPairs(const std::vector<BoundingBox>& boxes,
                               const std::vector<std::uint32_t>& changed) {
  std::vector<Pair> pairs;
  for (const std::uint32_t m : changed) {  // (increasing)
    for (std::uint32_t j = 0; j < boxes.size(); ++j) {
      const bool changedBelow =
          j < m && std::find(changed.begin(), changed.end(), j) != changed.end();
      if (j == m || changedBelow || !boxes[m].overlaps(boxes[j])) continue;
      pairs.emplace_back(std::min(m, j), std::max(m, j));
    }
  }
  return pairs;
}

TEST(BroadPhaseMoved, KeepsTheOrderOfThePairsOfUnchangedBoxes) {
  std::vector<BoundingBox> boxes = randomBoxes(7, 300, 0, 12);  // crowded: many neighbours
  BroadPhase broadPhase;
  std::vector<BoxPair> pairs;
  broadPhase.findPairs(boxes, allFlagged(boxes.size()), pairs);
  const std::vector<Pair> before = inOrder(pairs);
  // Boxes 10 and 130 moved onto boxes 200 and 20: their old pairs go, the rest keep their
  // order, and their new pairs come last, box 10's first, each by the other box's index.
  for (const auto& [moving, onto] : {std::pair{10u, 200u}, std::pair{130u, 20u}}) {
    const Vector2 shift = boxes[onto].lower - boxes[moving].lower + vec(0.05, 0.05);
    boxes[moving] = {boxes[moving].lower + shift, boxes[moving].upper + shift};
  }
  std::vector<std::uint64_t> moved((boxes.size() + 63) / 64, 0);
  flag(moved, 10);
  flag(moved, 130);
  broadPhase.findPairs(boxes, moved, pairs);
  std::vector<Pair> expected;
  for (const Pair& p : before)
    if (p.first != 10 && p.second != 10 && p.first != 130 && p.second != 130) expected.push_back(p);
  const std::vector<Pair> added = changedPairs(boxes, {10, 130});
  EXPECT_GT(added.size(), 6u);  // several neighbours each, below and above
  expected.insert(expected.end(), added.begin(), added.end());
  EXPECT_EQ(inOrder(pairs), expected);
  // Unchanged boxes, flagged or not: the same sequence again.
  const std::vector<Pair> again = inOrder(pairs);
  broadPhase.findPairs(boxes, allFlagged(boxes.size()), pairs);
  EXPECT_EQ(inOrder(pairs), again);
}

TEST(BroadPhaseMoved, ChangedBoxesWithNaNInfinitiesAndSignedZeros) {
  // Comparisons with NaN are false (BoundingBox::overlaps): a NaN box overlaps nothing; -0 and
  // +0 are equal as corners, but a corner changed from one to the other is a changed box.
  const real inf = std::numeric_limits<real>::infinity();
  const real nan = std::numeric_limits<real>::quiet_NaN();
  const real specials[] = {nan, inf, -inf, real(-0.0), real(0.0)};
  std::vector<BoundingBox> boxes = randomBoxes(9, 150, 1, 12);
  MTRandom random(23);
  BroadPhase broadPhase;
  std::vector<BoxPair> pairs;
  broadPhase.findPairs(boxes, allFlagged(boxes.size()), pairs);
  for (int step = 0; step < 60; ++step) {
    std::vector<std::uint64_t> moved((boxes.size() + 63) / 64, 0);
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t i = random.integer(static_cast<std::uint32_t>(boxes.size()));
      real* corner[] = {&boxes[i].lower.x, &boxes[i].lower.y, &boxes[i].upper.x, &boxes[i].upper.y};
      *corner[random.integer(4)] = specials[random.integer(5)];
      flag(moved, i);
    }
    broadPhase.findPairs(boxes, moved, pairs);
    std::vector<Pair> expected;
    for (std::uint32_t i = 0; i < boxes.size(); ++i)
      for (std::uint32_t j = i + 1; j < boxes.size(); ++j)
        if (boxes[i].overlaps(boxes[j])) expected.emplace_back(i, j);
    SCOPED_TRACE(::testing::Message() << "step " << step);
    ASSERT_EQ(sortedPairs(pairs), expected);
  }
}

TEST(BroadPhaseMoved, ASweepThatLeftOutPairsIsNotKept) {
  // A line of boxes takes the sweep, which leaves out the never-paired pairs it is given: the
  // next call cannot keep its pairs, and must give what a fresh broad phase gives.
  std::vector<BoundingBox> line;
  for (int i = 0; i < 200; ++i) line.push_back({vec(i, 0), vec(i + 1.5, 0.25)});
  std::vector<std::uint64_t> never(line.size(), 1);  // each box never pairs with the next
  BroadPhase used;
  used.setNeverPaired(never);
  std::vector<BoxPair> pairs;
  used.findPairs(line, allFlagged(line.size()), pairs);
  line[100] = {line[100].lower + vec(0, 0.1), line[100].upper + vec(0, 0.1)};
  std::vector<std::uint64_t> moved((line.size() + 63) / 64, 0);
  flag(moved, 100);
  used.findPairs(line, moved, pairs);
  BroadPhase fresh;
  fresh.setNeverPaired(never);
  std::vector<BoxPair> expected;
  fresh.findPairs(line, expected);
  EXPECT_EQ(inOrder(pairs), inOrder(expected));
  EXPECT_EQ(std::find(inOrder(pairs).begin(), inOrder(pairs).end(), Pair{100, 101}),
            inOrder(pairs).end());
}

TEST(BroadPhaseMoved, ADifferentCountIsTestedWhole) {
  // The promise holds only for as many boxes as the last call's: a box that changed without a
  // flag is found anyway when the count changed.
  std::vector<BoundingBox> boxes = randomBoxes(13, 120, 0, 15);
  BroadPhase broadPhase;
  std::vector<BoxPair> pairs;
  broadPhase.findPairs(boxes, allFlagged(boxes.size()), pairs);
  boxes.pop_back();
  boxes[0] = boxes[1];  // moved, not flagged
  broadPhase.findPairs(boxes, std::vector<std::uint64_t>((boxes.size() + 63) / 64, 0), pairs);
  EXPECT_EQ(sortedPairs(pairs), bruteForce(boxes));
}

TEST(BroadPhaseMoved, FlagBitsPastTheCountAreIgnored) {
  // Garbage in the last word past the box count, and a word too many: the same pairs in the
  // same order as with clean flags, for few boxes and for many.
  for (const std::uint32_t count : {30u, 150u}) {
    SCOPED_TRACE(::testing::Message() << count << " boxes");
    std::vector<BoundingBox> boxes = randomBoxes(count, static_cast<int>(count), 0, 12);
    MTRandom random(count + 1);
    BroadPhase clean;
    BroadPhase dirty;
    std::vector<BoxPair> cleanPairs;
    std::vector<BoxPair> dirtyPairs;
    for (int step = 0; step < 30; ++step) {
      const std::vector<std::uint64_t> moved = moveSome(boxes, random, 1 + step % 4, 0);
      std::vector<std::uint64_t> garbage = moved;
      garbage.back() |= ~std::uint64_t{0} << (count % 64);
      garbage.push_back(~std::uint64_t{0});
      clean.findPairs(boxes, moved, cleanPairs);
      dirty.findPairs(boxes, garbage, dirtyPairs);
      ASSERT_EQ(sortedPairs(dirtyPairs), bruteForce(boxes)) << "step " << step;
      ASSERT_EQ(inOrder(dirtyPairs), inOrder(cleanPairs)) << "step " << step;
    }
  }
}

TEST(BroadPhaseMoved, PairsAreKeptOnlyFromACompleteCall) {
  // A pile remembered from the grid, then a line that the sweep takes with never-paired bits
  // (leaving those pairs out): a call with nothing moved must not bring back the pile's pairs,
  // nor make up the left-out ones.
  std::vector<BoundingBox> pile;
  std::vector<BoundingBox> line;
  for (int i = 0; i < 100; ++i) {
    pile.push_back(box(i % 10, i / 10, i % 10 + 1.2, i / 10 + 1.2));
    line.push_back(box(i, 0, i + 1.5, 0.25));
  }
  const std::vector<std::uint64_t> never(100, 1);  // each box never pairs with the next
  BroadPhase broadPhase;
  broadPhase.setNeverPaired(never);
  std::vector<BoxPair> pairs;
  broadPhase.findPairs(pile, allFlagged(100), pairs);
  EXPECT_EQ(sortedPairs(pairs), bruteForce(pile));
  broadPhase.findPairs(line, allFlagged(100), pairs);
  const std::vector<Pair> swept = inOrder(pairs);
  EXPECT_EQ(swept.size(), 0u);  // (a box meets only its neighbours: all left out)
  broadPhase.findPairs(line, std::vector<std::uint64_t>(2, 0), pairs);
  EXPECT_EQ(inOrder(pairs), swept);
}

TEST(BroadPhaseMoved, AHistoryOfCountsPathsAndCallsGivesEveryPair) {
  // Counts crossing the all-pairs limit back and forth, a line that the sweep takes (without
  // never-paired bits: its pairs are kept), boxes around the origin (the columns' padding is
  // zero there), and calls without flags in between: every call finds every pair, and a
  // broad phase told that every box moved gives the same sequence as one told which did.
  std::vector<std::vector<BoundingBox>> layouts = {randomBoxes(41, 60, 0, 10, vec(-5, -5)),
                                                   randomBoxes(43, 40, 0, 8, vec(-4, -4)),
                                                   randomBoxes(47, 120, 1, 14, vec(-7, -7))};
  std::vector<BoundingBox> line;
  for (int i = 0; i < 90; ++i) line.push_back(box(i - 45, -0.1, i - 43.5, 0.15));
  layouts.push_back(line);
  MTRandom random(53);
  BroadPhase flagged;
  BroadPhase everything;
  std::vector<BoxPair> pairs;
  std::vector<BoxPair> everyPairs;
  for (int round = 0; round < 12; ++round) {
    std::vector<BoundingBox>& boxes = layouts[round % layouts.size()];
    SCOPED_TRACE(::testing::Message() << "round " << round << ", " << boxes.size() << " boxes");
    for (int step = 0; step < 15; ++step) {
      if (step == 7) {  // a call without flags: a full call for both
        flagged.findPairs(boxes, pairs);
        everything.findPairs(boxes, everyPairs);
      } else {
        // (The first call of a round flags everything: the count changed since the last.)
        const std::vector<std::uint64_t> moved =
            step == 0 ? allFlagged(boxes.size()) : moveSome(boxes, random, 1 + step % 5, 1);
        flagged.findPairs(boxes, moved, pairs);
        everything.findPairs(boxes, allFlagged(boxes.size()), everyPairs);
      }
      ASSERT_EQ(sortedPairs(pairs), bruteForce(boxes)) << "step " << step;
      ASSERT_EQ(inOrder(pairs), inOrder(everyPairs)) << "step " << step;
    }
  }
}

TEST(BroadPhaseMoved, WarmedUpCallsAllocateNothing) {
  std::vector<BoundingBox> boxes = randomBoxes(17, 500, 0, 40);
  MTRandom random(29);
  BroadPhase broadPhase;
  std::vector<BoxPair> pairs;
  pairs.reserve(4000);
  broadPhase.reservePairs(4000);
  broadPhase.findPairs(boxes, allFlagged(boxes.size()), pairs);
  std::vector<std::vector<std::uint64_t>> moves;
  std::vector<std::vector<BoundingBox>> layouts;
  for (int step = 0; step < 50; ++step) {  // prepared ahead: the test's own vectors allocate
    moves.push_back(moveSome(boxes, random, 1 + step % 8, 1));
    layouts.push_back(boxes);
  }
  broadPhase.findPairs(layouts[0], moves[0], pairs);  // the first moved call sizes its rows
  const long before = test::allocationCount();
  for (std::size_t step = 1; step < layouts.size(); ++step)
    broadPhase.findPairs(layouts[step], moves[step], pairs);
  EXPECT_EQ(test::allocationCount() - before, 0);
  EXPECT_EQ(sortedPairs(pairs), bruteForce(layouts.back()));
}

}  // namespace
}  // namespace thyrix
