// Broad phase with boxes that are NaN, infinite or far beyond any scene: they must be handled
// without undefined behaviour (no float-to-integer conversion out of range, no overflow of
// cell arithmetic, no sort by a comparison that is not a strict weak order), and every path
// (few boxes, sweep, dense and hashed grids) must find exactly the pairs that
// BoundingBox::overlaps accepts: a box with a NaN corner overlaps nothing, an infinite box
// overlaps whatever it covers. Run under the sanitizers (THYRIX_SANITIZE) in CI.

#include "support/BoxPairs.h"

#include <ThyrixLite/Border.h>
#include <ThyrixLite/BroadPhase.h>
#include <ThyrixLite/Circle.h>
#include <ThyrixLite/Simulator.h>
#include <ThyrixLite/SweepAndPrune.h>
#include <Tools/MTRandom.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <span>
#include <type_traits>
#include <utility>
#include <vector>

namespace thyrix {
namespace {

using test::Pair;
using test::sortedPairs;

constexpr real nan = std::numeric_limits<real>::quiet_NaN();
constexpr real inf = std::numeric_limits<real>::infinity();

/// Every overlapping pair (i < j) by testing all pairs: the independent reference.
std::vector<Pair> allPairs(const std::vector<BoundingBox>& boxes) {
  std::vector<Pair> pairs;
  for (std::uint32_t i = 0; i < boxes.size(); ++i)
    for (std::uint32_t j = i + 1; j < boxes.size(); ++j)
      if (boxes[i].overlaps(boxes[j])) pairs.emplace_back(i, j);
  return pairs;
}

/// @p count unit boxes laid out as a pile (filled square: dense grid), scattered over a wide
/// square (hashed grid) or in a row (sweep), by @p layout 0, 1, 2.
std::vector<BoundingBox> layoutBoxes(int layout, int count, std::uint32_t seed) {
  MTRandom random(seed);
  std::vector<BoundingBox> boxes;
  const int columns = static_cast<int>(std::sqrt(count)) + 1;
  for (int i = 0; i < count; ++i) {
    double x = 0;
    double y = 0;
    if (layout == 0) {
      x = (i % columns) * 0.9 + random.uniform(-0.05, 0.05);
      y = (i / columns) * 0.9 + random.uniform(-0.05, 0.05);
    } else if (layout == 1) {
      x = random.uniform(-30 * columns, 30 * columns);
      y = random.uniform(-30 * columns, 30 * columns);
    } else {
      x = i * 0.9 + random.uniform(-0.05, 0.05);
      y = random.uniform(-0.05, 0.05);
    }
    const double h = 0.5 + random.uniform(0, 0.02);
    boxes.push_back({{real(x - h), real(y - h)}, {real(x + h), real(y + h)}});
  }
  return boxes;
}

/// The boxes no scene should make, but a simulation that blew up can.
std::vector<BoundingBox> badBoxes() {
  // Far: the centre over a cell (about 1) is beyond std::int64_t (1e300, or 1e38 in float).
  const auto far = static_cast<real>(std::is_same_v<real, double> ? 1e300 : 1e38);
  const real top = std::numeric_limits<real>::max();
  return {
      {{nan, nan}, {nan, nan}},    // NaN: overlaps nothing
      {{0, nan}, {1, nan}},        // NaN in y only
      {{far, far}, {far, far}},    // a point far away
      {{-far, 0}, {-far, 1}},      // far away on the other side
      {{-inf, -inf}, {inf, inf}},  // infinite: overlaps every box but the NaN ones
      {{0, -inf}, {1, inf}},       // an infinite strip
      {{inf, inf}, {inf, inf}},    // at infinity
      {{top, top}, {top, top}},    // finite, but lower + upper overflows
      {{-top, 2}, {top, 3}},       // finite, but its side overflows
      {{far, 0}, {2, 1}},          // inverted (lower x > upper x), its centre far
  };
}

/// The boxes of @p layout with the bad boxes put at indices spread over the list.
std::vector<BoundingBox> withBadBoxes(std::vector<BoundingBox> boxes, std::uint32_t seed) {
  MTRandom random(seed);
  for (const BoundingBox& bad : badBoxes())
    boxes[random.integer(static_cast<std::uint32_t>(boxes.size()))] = bad;
  return boxes;
}

TEST(BroadPhaseNonFinite, EveryPathFindsThePairsOfTheAllPairsReference) {
  std::size_t total = 0;
  for (const bool sweep : {true, false}) {
    for (const bool denseGrid : {true, false}) {
      // One instance over every case, as a simulator keeps it (stale buffers would show).
      BroadPhase broadPhase;
      broadPhase.allowSweep = sweep;
      broadPhase.allowDenseGrid = denseGrid;
      std::vector<BoxPair> pairs;
      for (const int count : {static_cast<int>(BroadPhase::smallCount), 49, 200, 1000}) {
        for (int layout = 0; layout < 3; ++layout) {
          for (std::uint32_t seed = 1; seed <= 3; ++seed) {
            SCOPED_TRACE(::testing::Message()
                         << count << " boxes, layout " << layout << ", seed " << seed << ", sweep "
                         << sweep << ", dense " << denseGrid);
            // Only one bad box, then all of them.
            for (const bool allBad : {false, true}) {
              std::vector<BoundingBox> boxes = layoutBoxes(layout, count, seed);
              if (allBad) {
                boxes = withBadBoxes(boxes, seed);
              } else {
                const std::vector<BoundingBox> bad = badBoxes();
                boxes[seed * 7 % boxes.size()] = bad[seed % bad.size()];
              }
              const std::vector<Pair> expected = allPairs(boxes);
              broadPhase.findPairs(boxes, pairs);
              EXPECT_EQ(sortedPairs(pairs), expected);
              total += expected.size();
            }
          }
        }
      }
    }
  }
  EXPECT_GT(total, 10000u);
}

TEST(BroadPhaseNonFinite, ABoxThatTurnsNaNOrFarAndBackIsFollowed) {
  // The same world from call to call, one box taken away and brought back, as a simulator
  // does when a body blows up and is reset: the few-box memory and the grids must follow.
  for (const int count : {30, 300}) {
    BroadPhase broadPhase;
    std::vector<BoxPair> pairs;
    const std::vector<BoundingBox> start = layoutBoxes(0, count, 5);
    std::vector<BoundingBox> boxes = start;
    const std::vector<std::uint64_t> moved((count + 63) / 64, ~std::uint64_t{0});
    const std::uint64_t only = std::uint64_t{1} << 7;  // box 7 alone moved
    for (const BoundingBox& bad : badBoxes()) {
      for (const BoundingBox& box : {bad, start[7]}) {
        boxes[7] = box;
        if (count <= static_cast<int>(BroadPhase::smallCount))
          broadPhase.findPairs(boxes, std::span<const std::uint64_t>(&only, 1), pairs);
        else
          broadPhase.findPairs(boxes, moved, pairs);
        EXPECT_EQ(sortedPairs(pairs), allPairs(boxes)) << count << " boxes";
      }
    }
  }
}

TEST(BroadPhaseNonFinite, TheSweepTakesTheAxisWithoutNaN) {
  // A row along x with one box NaN in y (its y estimate NaN): the sweep runs along x, as
  // documented, and the NaN box pairs with nothing (the comparisons across fail).
  for (const int nanAxis : {0, 1}) {
    std::vector<BoundingBox> boxes = layoutBoxes(2, 200, 4);
    if (nanAxis == 1)  // the row along y instead, NaN in x
      for (BoundingBox& box : boxes) box = {{box.lower.y, box.lower.x}, {box.upper.y, box.upper.x}};
    BoundingBox& odd = boxes[57];
    (nanAxis == 0 ? odd.lower.y : odd.lower.x) = nan;
    SweepAndPrune sweep;
    std::vector<BoxPair> pairs;
    EXPECT_TRUE(sweep.findPairs(boxes, BroadPhase::sweepTestsPerBox, pairs)) << nanAxis;
    EXPECT_EQ(sortedPairs(pairs), allPairs(boxes)) << nanAxis;
  }
}

/// A pile of @p count circles on a floor, in @p simulator; returns them.
std::vector<Circle*> pileOfCircles(Simulator& simulator, int count) {
  simulator.registerObject(std::make_unique<Border>(Vector2{0, 0}, Vector2{0, 1}));
  std::vector<Circle*> circles;
  MTRandom random(11);
  for (int i = 0; i < count; ++i) {
    auto& circle = simulator.registerObject(std::make_unique<Circle>(real(0.3), real(1)));
    circle.r = {real(0.65) * static_cast<real>(i % 14),
                real(0.4) + real(0.65) * static_cast<real>(i / 14) +
                    static_cast<real>(random.uniform(0, 0.05))};
    circles.push_back(&circle);
  }
  return circles;
}

/// Steps @p simulator @p steps times, pushing every circle down.
void stepPushingDown(Simulator& simulator, const std::vector<Circle*>& circles, int steps) {
  for (int step = 0; step < steps; ++step) {
    for (Circle* circle : circles) circle->externalForce += Vector2{0, -2};
    simulator.advanceTime();
  }
}

// The documented behaviour: a circle whose centre the user sets to NaN, infinite or
// astronomically far gets no contact (its box overlaps no other box: NaN overlaps nothing, and
// nothing is near it; it is not behind the floor, which would push it back). The others go
// on as a pile, with finite positions and their contacts, and nothing is undefined behaviour
// (this test runs under the sanitizers).
TEST(BroadPhaseNonFinite, ACircleSetToNaNOrFarAwayInACrowdGetsNoContacts) {
  const auto far = static_cast<real>(std::is_same_v<real, double> ? 1e300 : 1e38);
  const Vector2 places[] = {{nan, nan}, {2, nan},   {far, far}, {3, far},
                            {-far, 2},  {inf, inf}, {inf, 3},   {-inf, 3}};
  for (const Vector2 place : places) {
    SCOPED_TRACE(::testing::Message() << "set to (" << place.x << ", " << place.y << ")");
    Simulator simulator;
    simulator.checkInputs = false;  // the NaN must reach the broad phase (Debug refuses it)
    const std::vector<Circle*> circles = pileOfCircles(simulator, 200);
    stepPushingDown(simulator, circles, 20);
    Circle& lost = *circles[95];  // inside the pile
    lost.r = place;
    stepPushingDown(simulator, circles, 20);
    std::size_t contacts = 0;
    for (const GlobalContactInfo& contact : simulator.contacts) {
      EXPECT_NE(contact.objectA, &lost);
      EXPECT_NE(contact.objectB, &lost);
      ++contacts;
    }
    EXPECT_TRUE(lost.contacts().empty());
    EXPECT_GT(contacts, 200u) << "the others still touch";
    for (const Circle* circle : circles) {
      if (circle != &lost) {
        EXPECT_TRUE(std::isfinite(circle->r.x) && std::isfinite(circle->r.y));
      }
    }
  }
}

}  // namespace
}  // namespace thyrix
