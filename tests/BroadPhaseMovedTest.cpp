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

TEST(BroadPhaseMoved, KeepsTheOrderOfThePairsOfUnchangedBoxes) {
  std::vector<BoundingBox> boxes = randomBoxes(7, 300, 0, 30);
  BroadPhase broadPhase;
  std::vector<BoxPair> pairs;
  broadPhase.findPairs(boxes, allFlagged(boxes.size()), pairs);
  const std::vector<Pair> before = inOrder(pairs);
  // Box 10 is moved onto box 20: its old pairs go, the rest keep their order, and its new
  // pairs come last, by the other box's index.
  const Vector2 shift = boxes[20].lower - boxes[10].lower;
  boxes[10] = {boxes[10].lower + shift, boxes[10].upper + shift};
  std::vector<std::uint64_t> moved((boxes.size() + 63) / 64, 0);
  moved[0] = std::uint64_t{1} << 10;
  broadPhase.findPairs(boxes, moved, pairs);
  std::vector<Pair> expected;
  for (const Pair& p : before)
    if (p.first != 10 && p.second != 10) expected.push_back(p);
  for (const Pair& p : bruteForce(boxes))
    if (p.first == 10 || p.second == 10) expected.push_back(p);
  EXPECT_EQ(inOrder(pairs), expected);
  EXPECT_NE(std::find(expected.begin(), expected.end(), Pair{10, 20}), expected.end());
  // Unchanged boxes, flagged or not: the same sequence again.
  std::vector<Pair> again = inOrder(pairs);
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
