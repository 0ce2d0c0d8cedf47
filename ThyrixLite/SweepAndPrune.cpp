#include <ThyrixLite/SweepAndPrune.h>
#include <Tools/Inlining.h>

#include <algorithm>
#include <cmath>
#include <type_traits>

namespace thyrix {
namespace {

/// @p point's coordinate along @p axis (0 x, 1 y).
template <int axis>
real along(const Vector2& point) {
  if constexpr (axis == 0)
    return point.x;
  else
    return point.y;
}
/// A box's lower and upper sides along @p axis.
template <int axis>
real lowerOf(const BoundingBox& box) {
  return along<axis>(box.lower);
}
template <int axis>
real upperOf(const BoundingBox& box) {
  return along<axis>(box.upper);
}

/// The box at byte offset @p offset from @p base (the order holds offsets: reading a box then
/// takes no multiplication).
inline const BoundingBox& boxAt(const BoundingBox* base, std::size_t offset) {
  return *reinterpret_cast<const BoundingBox*>(reinterpret_cast<const char*>(base) + offset);
}

constexpr std::size_t stride = sizeof(BoundingBox);  // from one box's offset to the next's

/// Whether the pair of boxes at offsets @p i and @p j is marked in @p never (see
/// setNeverPaired()).
inline bool marked(const std::uint64_t* never, std::size_t i, std::size_t j) {
  const std::size_t low = std::min(i, j) / stride;
  const std::size_t gap = std::max(i, j) / stride - low;  // (never 0: the boxes differ)
  return gap <= 64 && ((never[low] >> (gap - 1)) & 1) != 0;
}

}  // namespace

void SweepAndPrune::reserve(std::uint32_t count) { order_.reserve(count); }

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

  // The order of the last call when it held as many boxes along the same axis, else the
  // index order. No coordinate on this axis is NaN or infinite (its estimate would be NaN):
  // the sort's order is strict and total. A NaN on the other axis fails every comparison, so
  // such a box pairs with nothing, as with BoundingBox::overlaps().
  if (axis != axis_ || order_.size() != boxes.size()) {
    order_.resize(boxes.size());
    for (std::size_t i = 0; i < boxes.size(); ++i) order_[i] = i * stride;
    orderHeld_ = false;
  }
  axis_ = axis;
  // Past a few times the expected number of tests (clusters far apart look evenly spread),
  // the sweep gives up.
  const std::size_t maxTests =
      static_cast<std::size_t>(3 * testsPerBox * static_cast<real>(boxes.size()));
  return axis == 0 ? sortAndSweep<0>(boxes, maxTests, pairs)
                   : sortAndSweep<1>(boxes, maxTests, pairs);
}

template <int axis>
bool SweepAndPrune::sortAndSweep(std::span<const BoundingBox> boxes, std::size_t maxTests,
                                 std::vector<BoxPair>& pairs) {
  const std::size_t start = pairs.size();
  const bool filtered = neverPaired_.size() == boxes.size();
  const auto sweepOnce = [&] {
    return filtered ? sweep<axis, true>(boxes, maxTests, neverPaired_.data(), pairs)
                    : sweep<axis, false>(boxes, maxTests, nullptr, pairs);
  };
  // Sorted first, unless the last call found its order unchanged: then the sweep checks the
  // order as it goes. Either way the sweep that counts runs over the sorted order.
  const bool sortedFirst = !orderHeld_;
  if (sortedFirst) orderHeld_ = !sort<axis>(boxes);
  Outcome outcome = sweepOnce();
  // Out of order, or out of tests on an order not known to be sorted: sorted, then swept
  // again if the order changed (else the tests were the sorted order's, and so is the outcome).
  if (outcome != Outcome::done && !sortedFirst) {
    orderHeld_ = !sort<axis>(boxes);
    if (!orderHeld_) {
      pairs.resize(start);
      outcome = sweepOnce();
    }
  }
  if (outcome == Outcome::done) return true;
  pairs.resize(start);
  return false;
}

namespace {

/// The scan of the box at offset @p i (findPairs()): the boxes from @p at on in the order, up
/// to @p end, while they start before box i ends on @p axis, each tested unless marked in
/// @p never (when @p filtered); their pairs appended to @p pairs. Returns the number of boxes
/// scanned (the tests). Out of line: the sweep's loop keeps its registers for a chain's
/// links, which need no call.
template <int axis, bool filtered>
THYRIX_NO_INLINE std::size_t scan(const BoundingBox* base, std::size_t i, const std::size_t* at,
                                  const std::size_t* end, const std::uint64_t* never,
                                  std::vector<BoxPair>& pairs) {
  const BoundingBox& p = boxAt(base, i);
  const real upper = upperOf<axis>(p);
  const std::size_t* const from = at;
  for (; at != end && lowerOf<axis>(boxAt(base, *at)) <= upper; ++at) {
    const std::size_t j = *at;
    // Marked pairs first: where the marks serve (a chain), most boxes in reach on the axis
    // are such pairs, overlapping or not.
    if constexpr (filtered)
      if (marked(never, i, j)) continue;
    const BoundingBox& q = boxAt(base, j);
    if (lowerOf<axis>(p) <= upperOf<axis>(q) && lowerOf<1 - axis>(p) <= upperOf<1 - axis>(q) &&
        lowerOf<1 - axis>(q) <= upperOf<1 - axis>(p))
      pairs.push_back({static_cast<std::uint32_t>(std::min(i, j) / stride),
                       static_cast<std::uint32_t>(std::max(i, j) / stride)});
  }
  return static_cast<std::size_t>(at - from);
}

}  // namespace

// Out of line, as its scans: each loop gets the registers to itself (inlined, the sweep kept
// the marks' address and a box index on the stack).
template <int axis, bool filtered>
THYRIX_NO_INLINE SweepAndPrune::Outcome SweepAndPrune::sweep(std::span<const BoundingBox> boxes,
                                                             std::size_t maxTests,
                                                             const std::uint64_t* never,
                                                             std::vector<BoxPair>& pairs) const {
  const std::size_t* const order = order_.data();
  const std::size_t* const end = order + order_.size();
  const BoundingBox* const base = boxes.data();
  if (order_.size() < 2) return Outcome::done;
  // Each box against the boxes after it that start before it ends on the axis; the first that
  // starts beyond ends the scan (all later ones start later still). The scan's condition is
  // one side of the overlap on the axis; the other side is tested, as are both on the other
  // axis, so the pairs are exactly those BoundingBox::overlaps() accepts.
  std::size_t tests = 0;
  // Box at[-1] against the boxes from at on; false to stop, with `outcome` set. With notLast
  // true, at is not the last place (the loop's; the last pair is taken after it): at[1] is.
  Outcome outcome = Outcome::done;
  const auto visit = [&](const std::size_t* at, auto notLast) {
    const std::size_t i = at[-1];
    const std::size_t next = *at;
    const real lower = lowerOf<axis>(boxAt(base, i));
    const real upper = upperOf<axis>(boxAt(base, i));
    const real nextLower = lowerOf<axis>(boxAt(base, next));
    // In order: the next box starts later, or as early with a higher index.
    if (!(lower < nextLower)) [[unlikely]]
      if (nextLower < lower || next < i) {
        outcome = Outcome::unsorted;
        return false;
      }
    if (!(nextLower <= upper)) return true;
    // A chain's link: the next box in the order, and no other, in reach, and the two
    // neighbours in the chain, marked. Else the scan. (A test that cannot make the tests
    // run away: they are compared with the budget after the scans and at the end.)
    if constexpr (filtered && decltype(notLast)::value) {
      // (Neighbours: next - i is stride or its negative, as an unsigned number.)
      const std::size_t step = next - i;
      const bool neighbours = step == stride || step == 0 - stride;
      if (neighbours && (never[std::min(i, next) / stride] & 1) != 0 &&
          !(lowerOf<axis>(boxAt(base, at[1])) <= upper)) {
        ++tests;
        return true;
      }
    }
    tests += scan<axis, filtered>(base, i, at, end, never, pairs);
    if (tests <= maxTests) return true;
    outcome = Outcome::gaveUp;
    return false;
  };
  for (const std::size_t* at = order + 1; at < end - 1; ++at)
    if (!visit(at, std::true_type{})) return outcome;
  if (!visit(end - 1, std::false_type{})) return outcome;
  return tests <= maxTests ? Outcome::done : Outcome::gaveUp;
}

template <int axis>
bool SweepAndPrune::sort(std::span<const BoundingBox> boxes) {
  const BoundingBox* const base = boxes.data();
  const auto before = [base](std::size_t a, std::size_t b) {
    const real lowerA = lowerOf<axis>(boxAt(base, a));
    const real lowerB = lowerOf<axis>(boxAt(base, b));
    return lowerA < lowerB || (lowerA == lowerB && a < b);
  };
  // Insertion sort from the last order: a few moves when the boxes moved a little. Past a
  // budget of moves (the order changed a lot), a full sort finishes the job in n log n.
  std::size_t* const order = order_.data();
  const std::size_t n = order_.size();
  std::size_t budget = 4 * n + 64;
  bool moved = false;
  for (std::size_t k = 1; k < n; ++k) {
    const std::size_t e = order[k];
    if (!before(e, order[k - 1])) continue;
    moved = true;
    std::size_t m = k;
    for (; m > 0 && before(e, order[m - 1]); --m) order[m] = order[m - 1];
    order[m] = e;
    const std::size_t shifted = k - m;
    if (shifted > budget) {
      std::sort(order, order + n, before);
      return true;
    }
    budget -= shifted;
  }
  return moved;
}

}  // namespace thyrix
