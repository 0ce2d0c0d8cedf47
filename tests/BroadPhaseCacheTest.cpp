// Broad phase of a stepping caller (findPairs with moved bits): above smallCount the grid's
// pairs come from candidates kept between calls (fat boxes). Whatever the boxes do from call
// to call (drift, jump far, outrun the margin, stop, change count, turn NaN or infinite), each
// call must give exactly the overlapping pairs, sorted by first then second index, as a brute
// force over all pairs does; and it must allocate nothing once warmed up.

#include "support/AllocationCounter.h"
#include "support/BoxPairs.h"

#include <ThyrixLite/BroadPhase.h>
#include <Tools/MTRandom.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

namespace thyrix {
namespace {

using test::Pair;
using test::sortedPairs;

constexpr real nan = std::numeric_limits<real>::quiet_NaN();
constexpr real inf = std::numeric_limits<real>::infinity();

/// Every overlapping pair (i < j), in order by i then j, by testing all pairs.
std::vector<Pair> allPairs(const std::vector<BoundingBox>& boxes) {
  std::vector<Pair> pairs;
  for (std::uint32_t i = 0; i < boxes.size(); ++i)
    for (std::uint32_t j = i + 1; j < boxes.size(); ++j)
      if (boxes[i].overlaps(boxes[j])) pairs.emplace_back(i, j);
  return pairs;
}

std::vector<Pair> inOrder(const std::vector<BoxPair>& pairs) {
  std::vector<Pair> out;
  for (const BoxPair& p : pairs) out.emplace_back(p.first, p.second);
  return out;
}

/// A box of half side @p half around (@p x, @p y).
BoundingBox around(double x, double y, double half) {
  return {{real(x - half), real(y - half)}, {real(x + half), real(y + half)}};
}

/// @p count boxes of half side about 0.55 (a circle of radius 0.5 and its margin) on a
/// jittered lattice of pitch @p pitch: a pile (pitch about 1) or a scattered crowd.
std::vector<BoundingBox> latticeBoxes(std::uint32_t seed, int count, double pitch) {
  MTRandom random(seed);
  std::vector<BoundingBox> boxes;
  const int columns = static_cast<int>(std::sqrt(count)) + 1;
  for (int i = 0; i < count; ++i) {
    const double x = (i % columns) * pitch + random.uniform(-0.1, 0.1);
    const double y = (i / columns) * pitch + random.uniform(-0.1, 0.1);
    boxes.push_back(around(x, y, 0.55 + random.uniform(0, 0.02)));
  }
  return boxes;
}

/// Moves every box by up to @p step along each axis and grows or shrinks it a little; one box
/// in @p jumpOneIn (0: none) jumps up to 20 away instead.
void moveBoxes(std::vector<BoundingBox>& boxes, MTRandom& random, double step, int jumpOneIn) {
  for (BoundingBox& b : boxes) {
    const bool jump = jumpOneIn > 0 && random.integer(static_cast<std::uint32_t>(jumpOneIn)) == 0;
    const double reach = jump ? 20 : step;
    const Vector2 shift{real(random.uniform(-reach, reach)), real(random.uniform(-reach, reach))};
    const auto grow = real(random.uniform(-0.2, 0.2) * step);
    b = {b.lower + shift - Vector2{grow, grow}, b.upper + shift + Vector2{grow, grow}};
  }
}

/// A caller's moved bits for @p count boxes (every box moved: above smallCount they are not
/// read anyway).
std::vector<std::uint64_t> allMoved(std::size_t count) {
  return std::vector<std::uint64_t>((count + 63) / 64, ~std::uint64_t{0});
}

/// One stepping instance per grid (dense, hashed), each checked against the sorted brute
/// force at every call, plus one that may sweep (its order is the sweep's when it does).
class SteppingInstances {
 public:
  SteppingInstances() {
    dense_.allowSweep = false;
    hashed_.allowSweep = false;
    hashed_.allowDenseGrid = false;
  }

  void check(const std::vector<BoundingBox>& boxes) {
    const std::vector<std::uint64_t> moved = allMoved(boxes.size());
    const std::vector<Pair> expected = allPairs(boxes);
    dense_.findPairs(boxes, moved, pairs_);
    EXPECT_EQ(inOrder(pairs_), expected) << "dense grid";
    hashed_.findPairs(boxes, moved, pairs_);
    EXPECT_EQ(inOrder(pairs_), expected) << "hashed grid";
    maySweep_.findPairs(boxes, moved, pairs_);
    EXPECT_EQ(sortedPairs(pairs_), expected) << "sweep allowed";
    found_ += expected.size();
  }

  std::size_t found() const { return found_; }

 private:
  BroadPhase dense_;
  BroadPhase hashed_;
  BroadPhase maySweep_;
  std::vector<BoxPair> pairs_;
  std::size_t found_ = 0;
};

TEST(BroadPhaseCache, DriftingAndJumpingBoxesGiveTheSortedPairs) {
  for (const double pitch : {1.0, 3.0}) {
    for (const int count : {60, 400}) {
      SCOPED_TRACE(::testing::Message() << count << " boxes, pitch " << pitch);
      SteppingInstances instances;
      MTRandom random(static_cast<std::uint32_t>(count) + 7);
      std::vector<BoundingBox> boxes = latticeBoxes(3, count, pitch);
      for (int step = 0; step < 150; ++step) {
        SCOPED_TRACE(::testing::Message() << "step " << step);
        // Mostly a drift well within the margin, now and then a box jumps far.
        moveBoxes(boxes, random, 0.01, step % 10 == 9 ? count : 0);
        if (step % 40 == 39) boxes.pop_back();  // the count changes
        if (step % 40 == 19) boxes.push_back(boxes[boxes.size() / 2]);
        instances.check(boxes);
      }
      EXPECT_GT(instances.found(), 100u);
    }
  }
}

TEST(BroadPhaseCache, BoxesOutrunningTheMarginThenAtRestAreFollowed) {
  // Boxes faster than the margin (no call reuses the fat boxes: the search goes without a
  // margin for a while), then still (the boxes themselves are reused), then drifting again.
  SteppingInstances instances;
  MTRandom random(11);
  std::vector<BoundingBox> boxes = latticeBoxes(5, 300, 1.0);
  for (int step = 0; step < 120; ++step) {
    SCOPED_TRACE(::testing::Message() << "step " << step);
    const double speed = step < 40 ? 0.8 : step < 80 ? 0 : 0.02;
    if (speed > 0) moveBoxes(boxes, random, speed, 0);
    instances.check(boxes);
  }
  EXPECT_GT(instances.found(), 1000u);
}

TEST(BroadPhaseCache, FastBoxesCrossingACrowdAtRestGiveTheSortedPairs) {
  // A crowd at rest and a few boxes crossing it a unit a call, each out of its fat box at every
  // call (tested against every box, up to fatStraysLimit of them; more: the grid again). Two
  // of them travel side by side, overlapping each other; one turns NaN for a while.
  for (const int fast : {1, 2, 8, 9}) {
    SCOPED_TRACE(::testing::Message() << fast << " fast boxes");
    SteppingInstances instances;
    const std::vector<BoundingBox> crowd = latticeBoxes(29, 400, 1.0);
    std::vector<BoundingBox> boxes = crowd;
    for (int step = 0; step < 40; ++step) {
      SCOPED_TRACE(::testing::Message() << "step " << step);
      for (int k = 0; k < fast; ++k) {
        const double x = -5 + step + (k == 1 ? 0.3 : 0);  // boxes 0 and 1 side by side
        const double y = 3 + (k == 1 ? 0 : 2.1 * k);
        boxes[static_cast<std::size_t>(37 * k + 5)] = around(x, y, 0.6);
      }
      if (fast == 2 && step >= 10 && step < 15) boxes[5] = {{nan, nan}, {nan, nan}};
      instances.check(boxes);
    }
    EXPECT_GT(instances.found(), 1000u);
  }
}

TEST(BroadPhaseCache, NaNAndInfiniteBoxesComeAndGo) {
  // A box with a NaN corner overlaps nothing, an infinite one everything it covers; either may
  // appear in a crowd and leave again.
  const std::vector<BoundingBox> bad = {
      {{nan, nan}, {nan, nan}}, {{0, nan}, {1, nan}},     {{-inf, -inf}, {inf, inf}},
      {{0, -inf}, {1, inf}},    {{inf, inf}, {inf, inf}},
  };
  SteppingInstances instances;
  MTRandom random(13);
  std::vector<BoundingBox> boxes = latticeBoxes(7, 200, 1.0);
  for (int step = 0; step < 100; ++step) {
    SCOPED_TRACE(::testing::Message() << "step " << step);
    moveBoxes(boxes, random, 0.01, 0);
    std::vector<BoundingBox> seen = boxes;
    if (step % 20 >= 5) {  // a bad box for 15 calls in every 20, at a place of its own
      const std::size_t k = static_cast<std::size_t>(step / 20) % bad.size();
      seen[(37 * k + 11) % seen.size()] = bad[k];
    }
    instances.check(seen);
  }
}

TEST(BroadPhaseCache, PlainCallsBetweenSteppingCallsKeepTheGridOrder) {
  // findPairs without moved bits gives the grid's own order, whatever the instance keeps.
  MTRandom random(17);
  std::vector<BoundingBox> boxes = latticeBoxes(9, 500, 1.0);
  BroadPhase used;
  std::vector<BoxPair> pairs;
  for (int step = 0; step < 20; ++step) {
    moveBoxes(boxes, random, 0.01, 0);
    used.findPairs(boxes, allMoved(boxes.size()), pairs);
    EXPECT_EQ(inOrder(pairs), allPairs(boxes));
    BroadPhase fresh;
    std::vector<BoxPair> expected;
    fresh.findPairs(boxes, expected);
    used.findPairs(boxes, pairs);
    EXPECT_EQ(inOrder(pairs), inOrder(expected));
  }
}

TEST(BroadPhaseCache, KeptCandidatesAfterTheSweepTookCallsAreCheckedAgain) {
  // A pile (the grid keeps its fat boxes), the same count in a row (the sweep takes the call,
  // the fat boxes stay), then the pile again: nudged, the kept candidates serve; squeezed to
  // half its pitch, most boxes have left their fat boxes and new pairs overlap (the
  // check after the sweep declined, not the one the grid's extents pass makes).
  const int count = 200;
  const std::vector<BoundingBox> pile = latticeBoxes(23, count, 1.0);
  std::vector<BoundingBox> row;
  for (int i = 0; i < count; ++i) row.push_back(around(i, 0, 0.55));
  const auto shifted = [&](double by, double scale) {
    std::vector<BoundingBox> boxes;
    for (const BoundingBox& b : pile) {
      const Vector2 centre = (b.lower + b.upper) * real(0.5);
      const Vector2 half = (b.upper - b.lower) * real(0.5);
      const Vector2 place = centre * real(scale) + Vector2{real(by), real(by)};
      boxes.push_back({place - half, place + half});
    }
    return boxes;
  };
  const std::vector<std::uint64_t> moved = allMoved(count);
  BroadPhase broadPhase;
  std::vector<BoxPair> pairs;
  // Every other call the row (the sweep's pairs in its own order, compared as a set).
  const std::vector<std::vector<BoundingBox>> piles = {pile, shifted(0.01, 1), shifted(0.02, 1),
                                                       shifted(0.02, 0.5), shifted(0.03, 0.5)};
  for (const std::vector<BoundingBox>& boxes : piles) {
    broadPhase.findPairs(boxes, moved, pairs);
    EXPECT_EQ(inOrder(pairs), allPairs(boxes));
    broadPhase.findPairs(row, moved, pairs);
    EXPECT_EQ(sortedPairs(pairs), allPairs(row));
  }
  EXPECT_GT(allPairs(piles[3]).size(), 2 * allPairs(pile).size());
}

TEST(BroadPhaseCache, SteppingAllocatesNothingOnceWarmedUp) {
  // Boxes circling about their places (radius 0.15, each at its own phase, period 40 calls):
  // the fat boxes are left and searched again every few calls, and every count repeats.
  const std::vector<BoundingBox> places = latticeBoxes(21, 1000, 1.0);
  std::vector<BoundingBox> boxes = places;
  const auto circle = [&](int step) {
    for (std::size_t i = 0; i < boxes.size(); ++i) {
      const double angle = 2 * 3.14159265358979 * (step / 40.0 + static_cast<double>(i) / 7.0);
      const Vector2 shift{real(0.15 * std::cos(angle)), real(0.15 * std::sin(angle))};
      boxes[i] = {places[i].lower + shift, places[i].upper + shift};
    }
  };
  const std::vector<std::uint64_t> moved = allMoved(boxes.size());
  BroadPhase broadPhase;
  std::vector<BoxPair> pairs;
  int step = 0;
  for (; step < 80; ++step) {  // warms up over two periods
    circle(step);
    broadPhase.findPairs(boxes, moved, pairs);
  }
  const long before = test::allocationCount();
  for (; step < 200; ++step) {
    circle(step);
    broadPhase.findPairs(boxes, moved, pairs);
  }
  EXPECT_EQ(test::allocationCount() - before, 0);
  EXPECT_EQ(inOrder(pairs), allPairs(boxes));
}

}  // namespace
}  // namespace thyrix
