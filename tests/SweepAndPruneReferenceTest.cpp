// SweepAndPrune against a plain reference: a fresh full sort of the boxes by (lower side,
// index) and a sweep over copies of them, as the sweep was first written. The sweep keeps its
// order between calls, sweeps before sorting when that order held, and reads the boxes in
// place; none of that may change its output: the same pairs in the same order, and the same
// answer (done or declined), call after call.

#include <ThyrixLite/SweepAndPrune.h>
#include <Tools/MTRandom.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

namespace thyrix {
namespace {

/// SweepAndPrune::findPairs() as first written: no state, every call sorts from scratch.
bool referencePairs(std::span<const BoundingBox> boxes, real testsPerBox,
                    std::span<const std::uint64_t> never, std::vector<BoxPair>& pairs) {
  SweepAndPrune::Extents extents;
  for (const BoundingBox& box : boxes) extents.add(box);
  const real testsX = extents.sumX / (extents.highX - extents.lowX);
  const real testsY = extents.sumY / (extents.highY - extents.lowY);
  const int axis = testsX <= testsY || std::isnan(testsY) ? 0 : 1;
  if (!((axis == 0 ? testsX : testsY) <= testsPerBox)) return false;
  struct Entry {
    real lower, upper, crossLower, crossUpper;
    std::uint32_t index;
  };
  std::vector<Entry> entries;
  for (std::uint32_t i = 0; i < boxes.size(); ++i) {
    const BoundingBox& b = boxes[i];
    if (axis == 0)
      entries.push_back({b.lower.x, b.upper.x, b.lower.y, b.upper.y, i});
    else
      entries.push_back({b.lower.y, b.upper.y, b.lower.x, b.upper.x, i});
  }
  std::sort(entries.begin(), entries.end(), [](const Entry& a, const Entry& b) {
    return a.lower < b.lower || (a.lower == b.lower && a.index < b.index);
  });
  const std::size_t n = entries.size();
  const bool filtered = never.size() == n;
  const auto maxTests = static_cast<std::size_t>(3 * testsPerBox * static_cast<real>(n));
  const std::size_t start = pairs.size();
  std::size_t tests = 0;
  for (std::size_t k = 0; k < n; ++k) {
    const Entry& p = entries[k];
    std::size_t m = k + 1;
    for (; m < n && entries[m].lower <= p.upper; ++m) {
      const Entry& q = entries[m];
      const std::uint32_t low = std::min(p.index, q.index);
      const std::uint32_t high = std::max(p.index, q.index);
      if (filtered && high - low <= 64 && ((never[low] >> (high - low - 1)) & 1) != 0) continue;
      if (p.lower <= q.upper && p.crossLower <= q.crossUpper && q.crossLower <= p.crossUpper)
        pairs.push_back({low, high});
    }
    tests += m - k - 1;
    if (tests > maxTests) {
      pairs.resize(start);
      return false;
    }
  }
  return true;
}

/// Compares one call of @p sweep with the reference on @p boxes (marks @p never).
void expectAsReference(SweepAndPrune& sweep, const std::vector<BoundingBox>& boxes,
                       const std::vector<std::uint64_t>& never, real testsPerBox = 4) {
  sweep.setNeverPaired(never);
  std::vector<BoxPair> found{{7, 8}};  // appended to, kept when declined
  std::vector<BoxPair> expected{{7, 8}};
  const bool done = sweep.findPairs(boxes, testsPerBox, found);
  const bool expectedDone = referencePairs(boxes, testsPerBox, never, expected);
  ASSERT_EQ(done, expectedDone);
  ASSERT_EQ(found.size(), expected.size());
  for (std::size_t k = 0; k < found.size(); ++k) {
    ASSERT_EQ(found[k].first, expected[k].first) << "pair " << k;
    ASSERT_EQ(found[k].second, expected[k].second) << "pair " << k;
  }
}

/// A chain of @p count boxes of about unit length from the origin at @p angle, bending by up to
/// @p bend a link; coordinates rounded to multiples of @p grain when not 0 (ties).
std::vector<BoundingBox> chain(MTRandom& random, int count, double angle, double bend, double width,
                               double grain) {
  std::vector<BoundingBox> boxes;
  double x = 0;
  double y = 0;
  const auto round = [grain](double v) { return grain == 0 ? v : grain * std::round(v / grain); };
  for (int k = 0; k < count; ++k) {
    angle += random.uniform(-bend, bend);
    const double tx = x + std::cos(angle);
    const double ty = y + std::sin(angle);
    boxes.push_back({{real(round(std::min(x, tx) - width)), real(round(std::min(y, ty) - width))},
                     {real(round(std::max(x, tx) + width)), real(round(std::max(y, ty) + width))}});
    x = tx;
    y = ty;
  }
  return boxes;
}

/// Neighbours marked (a chain's links), and now and then random farther marks.
std::vector<std::uint64_t> chainMarks(MTRandom& random, std::size_t count, bool farther) {
  std::vector<std::uint64_t> never(count, 0);
  for (std::size_t k = 0; k + 1 < count; ++k) {
    never[k] = 1;
    if (farther && random.uniform() < 0.3) never[k] |= std::uint64_t{1} << (1 + k % 5);
  }
  return never;
}

TEST(SweepAndPruneReference, MovingChainsGiveTheReferencePairsCallAfterCall) {
  // Chains swinging a little each call (their order mostly held, now and then a few boxes
  // trading places), with and without marks, sometimes on a grid of coordinates (ties).
  for (std::uint32_t seed = 1; seed <= 12; ++seed) {
    SCOPED_TRACE(::testing::Message() << "seed " << seed);
    MTRandom random(seed);
    const int count = seed % 3 == 0 ? 40 : 300;
    const double grain = seed % 4 == 0 ? 0.25 : 0;
    std::vector<BoundingBox> boxes =
        chain(random, count, random.uniform(-3.2, 3.2), seed % 2 == 0 ? 0.05 : 0.6, 0.15, grain);
    const std::vector<std::uint64_t> never = chainMarks(random, boxes.size(), seed % 5 == 0);
    const std::vector<std::uint64_t> none;
    SweepAndPrune sweep;
    for (int call = 0; call < 80; ++call) {
      SCOPED_TRACE(::testing::Message() << "call " << call);
      // Every box drifts; some calls shift a few boxes far enough to change the order.
      const double step = call % 7 == 3 ? 0.6 : 0.002;
      for (BoundingBox& b : boxes) {
        const double dx = random.uniform(-step, step);
        const double dy = random.uniform(-step, step);
        const Vector2 d{real(grain == 0 ? dx : grain * std::round(dx / grain)),
                        real(grain == 0 ? dy : grain * std::round(dy / grain))};
        if (random.uniform() < (call % 7 == 3 ? 0.05 : 1.0)) b = {b.lower + d, b.upper + d};
      }
      expectAsReference(sweep, boxes, call % 9 == 8 ? none : never);
    }
  }
}

TEST(SweepAndPruneReference, DeclinesAsTheReferenceFromAHeldOrder) {
  // A line whose order held, then clusters far apart the sweep gives up on: from the held
  // order (not yet sorted for the clusters) and again from theirs; a line again after.
  MTRandom random(17);
  SweepAndPrune sweep;
  const std::vector<std::uint64_t> none;
  std::vector<BoundingBox> line = chain(random, 400, 0.0, 0.1, 0.1, 0);
  expectAsReference(sweep, line, none);
  expectAsReference(sweep, line, none);  // the order held
  std::vector<BoundingBox> clusters(line.size());
  for (std::size_t k = 0; k < clusters.size(); ++k) {
    const double x = (k % 2 == 0 ? 0 : 1e5) + random.uniform(0, 10);
    const double y = random.uniform(0, 10);
    clusters[k] = {{real(x), real(y)}, {real(x + 1), real(y + 1)}};
  }
  expectAsReference(sweep, clusters, none);
  expectAsReference(sweep, clusters, none);
  // Clusters whose order is the line's: the held order is sorted, and still declined.
  std::vector<BoundingBox> sortedClusters = clusters;
  std::sort(sortedClusters.begin(), sortedClusters.end(),
            [](const BoundingBox& a, const BoundingBox& b) { return a.lower.x < b.lower.x; });
  expectAsReference(sweep, line, none);
  expectAsReference(sweep, sortedClusters, none);
  expectAsReference(sweep, sortedClusters, none);
  expectAsReference(sweep, line, none);
  // From a held order, boxes whose first 50 in that order overlap along x and all start after
  // the 350 others: in the held order each of the 50 scans about all boxes (past the budget
  // before the first box out of order is met), in the sorted order only the 50 scan each
  // other. Done, as the reference.
  std::vector<BoundingBox> row(400);
  for (std::size_t k = 0; k < row.size(); ++k)
    row[k] = {{real(2 * k), real(0)}, {real(2 * k + 1), real(1)}};
  expectAsReference(sweep, row, none);
  expectAsReference(sweep, row, none);  // the order held
  for (std::size_t k = 0; k < row.size(); ++k) {
    const real x = k < 50 ? real(1000 + 0.01 * static_cast<double>(k)) : real(k - 50);
    row[k] = {{x, real(0)}, {k < 50 ? real(1001.5) : x + real(0.5), real(1)}};
  }
  expectAsReference(sweep, row, none);
  // Budgets around the tests a line takes: done or declined exactly as the reference.
  for (const real budget : {real(0.5), real(0.9), real(1), real(1.2), real(2)}) {
    expectAsReference(sweep, line, none, budget);
    expectAsReference(sweep, line, none, budget);
  }
}

TEST(SweepAndPruneReference, NaNOnTheOtherAxisCountChangesAndTurnsFollowTheReference) {
  MTRandom random(23);
  SweepAndPrune sweep;
  const real nan = std::numeric_limits<real>::quiet_NaN();
  for (int call = 0; call < 40; ++call) {
    SCOPED_TRACE(::testing::Message() << "call " << call);
    const int count = call % 5 == 4 ? 120 : 150;  // another count now and then
    // Turning by a quarter every 10 calls: the axis changes.
    std::vector<BoundingBox> boxes = chain(random, count, (call / 10) * 1.5708, 0.2, 0.12, 0);
    const std::vector<std::uint64_t> never = chainMarks(random, boxes.size(), true);
    if (call % 3 == 0) {  // NaN across the axis: such a box pairs with nothing
      const bool alongX = (call / 10) % 2 == 0;
      BoundingBox& b = boxes[static_cast<std::size_t>(call) % boxes.size()];
      (alongX ? b.lower.y : b.upper.x) = nan;
    }
    expectAsReference(sweep, boxes, never);
    expectAsReference(sweep, boxes, never);
  }
  // Two boxes, one box, none.
  for (const std::size_t count : {std::size_t{2}, std::size_t{1}, std::size_t{0}}) {
    std::vector<BoundingBox> boxes = chain(random, 2, 0.3, 0, 0.2, 0);
    boxes.resize(count);
    expectAsReference(sweep, boxes, {});
    expectAsReference(sweep, boxes, std::vector<std::uint64_t>(count, 1));
  }
}

}  // namespace
}  // namespace thyrix
