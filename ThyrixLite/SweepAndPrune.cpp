#include <ThyrixLite/SweepAndPrune.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace thyrix {

void SweepAndPrune::reserve(std::uint32_t count) { entries_.reserve(std::size_t{count} + 1); }

bool SweepAndPrune::findPairs(std::span<const BoundingBox> boxes, real testsPerBox,
                              std::vector<BoxPair>& pairs) {
  Extents extents;
  for (const BoundingBox& box : boxes) extents.add(box);
  return findPairs(boxes, extents, testsPerBox, pairs);
}

bool SweepAndPrune::findPairs(std::span<const BoundingBox> boxes, const Extents& extents,
                              real testsPerBox, std::vector<BoxPair>& pairs) {
  // How many boxes each box would be tested against along each axis, if the boxes were spread
  // evenly over the span they cover on it: their count times their mean extent over the span
  // (which includes the extents: boxes on top of each other give the count, not a division by
  // zero). Summed in index order, so that the choice depends on the boxes only.
  const real testsX = extents.sumX / (extents.highX - extents.lowX);
  const real testsY = extents.sumY / (extents.highY - extents.lowY);
  // Along x unless y looks better or x is NaN (an infinite extent, or a NaN box: then along y
  // when that is a number); a NaN estimate declines. (x when only y is NaN: `testsX <= testsY`
  // alone chose y then, and declined a row along x for one box NaN in y.)
  const int axis = testsX <= testsY || std::isnan(testsY) ? 0 : 1;
  if (!((axis == 0 ? testsX : testsY) <= testsPerBox)) return false;

  // The entries, in the last call's order when it held as many boxes along the same axis,
  // else in index order. No coordinate on this axis is NaN (its estimate would be NaN): the
  // sort's order is strict and total. A NaN on the other axis fails every comparison, so such
  // a box pairs with nothing, as with BoundingBox::overlaps().
  const auto count = static_cast<std::uint32_t>(boxes.size());
  const bool keepOrder = axis == axis_ && entries_.size() == std::size_t{count} + 1;
  if (!keepOrder) {
    entries_.resize(std::size_t{count} + 1);
    for (std::uint32_t i = 0; i < count; ++i) entries_[i].index = i;
  }
  axis_ = axis;
  if (axis == 0)
    load<0>(boxes);
  else
    load<1>(boxes);
  sort(count);
  // A sentinel after the last entry starts beyond every box (the coordinates on the axis are
  // finite, or the estimate would be NaN): the scan below needs no end test.
  constexpr real beyond = std::numeric_limits<real>::infinity();
  entries_[count] = {beyond, beyond, beyond, beyond, count};

  // Each box against the boxes after it that start before it ends on the axis; the first that
  // starts beyond ends the scan (all later ones start later still). The scan's condition is
  // one side of the overlap on the axis; the other side is tested, as are both on the other
  // axis, so the pairs are exactly those BoundingBox::overlaps() accepts. Past a few times the
  // expected number of tests (clusters far apart look evenly spread), the sweep gives up.
  const std::size_t start = pairs.size();
  const std::size_t n = count;
  const std::size_t maxTests = static_cast<std::size_t>(3 * testsPerBox * static_cast<real>(n));
  const bool done = neverPaired_.size() == n ? sweep<true>(n, maxTests, neverPaired_.data(), pairs)
                                             : sweep<false>(n, maxTests, nullptr, pairs);
  if (!done) pairs.resize(start);
  return done;
}

template <bool filtered>
bool SweepAndPrune::sweep(std::size_t n, std::size_t maxTests, const std::uint64_t* never,
                          std::vector<BoxPair>& pairs) const {
  std::size_t tests = 0;
  const Entry* const entries = entries_.data();
  for (std::size_t k = 0; k < n; ++k) {
    const Entry p = entries[k];
    std::size_t m = k + 1;
    for (; entries[m].lower <= p.upper; ++m) {
      const Entry& q = entries[m];
      const std::uint32_t low = std::min(p.index, q.index);
      const std::uint32_t high = std::max(p.index, q.index);
      // Marked pairs first: where the marks serve (a chain), most boxes in reach on the axis
      // are such pairs, overlapping or not. (high - low - 1 wraps to a large number for
      // equal indices, which never occur.)
      if constexpr (filtered)
        if (high - low - 1 < 64 && ((never[low] >> (high - low - 1)) & 1) != 0) continue;
      if (p.lower <= q.upper && p.crossLower <= q.crossUpper && q.crossLower <= p.crossUpper)
        pairs.push_back({low, high});
    }
    tests += m - k - 1;
    if (tests > maxTests) return false;
  }
  return true;
}

template <int axis>
void SweepAndPrune::load(std::span<const BoundingBox> boxes) {
  // One loop per axis: no choice of coordinates per box.
  Entry* const entries = entries_.data();
  for (std::size_t k = 0; k < boxes.size(); ++k) {
    const std::uint32_t index = entries[k].index;
    const BoundingBox& box = boxes[index];
    if constexpr (axis == 0)
      entries[k] = {box.lower.x, box.upper.x, box.lower.y, box.upper.y, index};
    else
      entries[k] = {box.lower.y, box.upper.y, box.lower.x, box.upper.x, index};
  }
}

void SweepAndPrune::sort(std::size_t n) {
  const auto before = [](const Entry& a, const Entry& b) {
    return a.lower < b.lower || (a.lower == b.lower && a.index < b.index);
  };
  // Insertion sort from the last order: a few moves when the boxes moved a little. Past a
  // budget of moves (the order changed a lot), a full sort finishes the job in n log n.
  Entry* const entries = entries_.data();
  std::size_t budget = 4 * n + 64;
  for (std::size_t k = 1; k < n; ++k) {
    if (!before(entries[k], entries[k - 1])) continue;
    const Entry e = entries[k];
    std::size_t m = k;
    for (; m > 0 && before(e, entries[m - 1]); --m) entries[m] = entries[m - 1];
    entries[m] = e;
    const std::size_t moved = k - m;
    if (moved > budget) {
      std::sort(entries, entries + n, before);
      return;
    }
    budget -= moved;
  }
}

}  // namespace thyrix
