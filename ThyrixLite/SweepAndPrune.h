#pragma once
/// @file SweepAndPrune.h
/// @brief Finds the pairs of overlapping bounding boxes by sorting them along one axis and
/// sweeping: fast for boxes strung out along a line (a chain, a row), which a grid serves badly.

#include <ThyrixLite/BoundingBox.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace thyrix {

/// Sort and sweep along one axis (Baraff 1992, "sort and sweep"). The boxes are sorted by their
/// lower side along the axis (ties by index), then each box is tested against the boxes that
/// follow it in that order until one starts beyond its upper side: only boxes whose intervals
/// on the axis overlap are ever tested, so the cost is linear in the boxes plus those interval
/// overlaps. That is small when the boxes are spread along the axis (a hanging chain along y,
/// a row along x), and quadratic when they are piled across it: findPairs() estimates which
/// axis serves, and declines piles (BroadPhase then uses its grid).
///
/// The order of the last call is the start of the next sort (insertion sort): boxes that moved
/// a little need only a few swaps. When the last call's order needed no change, the sweep
/// runs on it at once and checks each box against the next as it goes, and only sorts (and
/// sweeps again) when the order has changed: a chain whose boxes keep their order is read
/// once. The sorted order is a strict total order of the boxes, so the output depends only on
/// the input, never on the previous call. The sweep reads the boxes where they are (the order
/// is a list of their offsets): no copy of them is made.
///
/// A box with a NaN corner overlaps nothing (every comparison with it is false), as in
/// BoundingBox::overlaps(): the sweep runs along an axis without NaN, or declines. Buffers
/// are kept between calls.
class SweepAndPrune {
 public:
  /// Appends to @p pairs every pair of overlapping @p boxes, `first < second`, each once, in
  /// sweep order, and returns true; or returns false, with @p pairs as it was, when the boxes
  /// are not strung out along x or y. That is, when spread evenly over the span they cover,
  /// each box would overlap more than @p testsPerBox others on the axis (the count times the
  /// mean extent over the span), for both axes; or, since an even spread is only an estimate
  /// (clusters far apart look spread), when the sweep takes more than 3 times as many tests.
  /// The axis is the one with the lower estimate.
  bool findPairs(std::span<const BoundingBox> boxes, real testsPerBox, std::vector<BoxPair>& pairs);

  /// What findPairs() estimates its cost from: the boxes' summed extents along each axis and
  /// the span they cover, gathered in index order (the sums depend on the order).
  struct Extents {
    real sumX = 0;          ///< sum of the boxes' extents along x
    real sumY = 0;          ///< sum of the boxes' extents along y
    real lowX = realMax;    ///< least lower x
    real lowY = realMax;    ///< least lower y
    real highX = -realMax;  ///< greatest upper x
    real highY = -realMax;  ///< greatest upper y

    /// Adds @p box, the next one in index order.
    void add(const BoundingBox& box) {
      sumX += box.upper.x - box.lower.x;
      sumY += box.upper.y - box.lower.y;
      lowX = std::min(lowX, box.lower.x);
      lowY = std::min(lowY, box.lower.y);
      highX = std::max(highX, box.upper.x);
      highY = std::max(highY, box.upper.y);
    }
  };

  /// The same as findPairs(boxes, testsPerBox, pairs), with @p extents gathered by the caller
  /// over every box of @p boxes (in index order): one pass over the boxes less when the caller
  /// reads them anyway.
  bool findPairs(std::span<const BoundingBox> boxes, const Extents& extents, real testsPerBox,
                 std::vector<BoxPair>& pairs);

  /// Sizes the buffers for @p count boxes, so that calls with no more boxes do not allocate.
  void reserve(std::uint32_t count);

  /// Pairs the caller would drop anyway (shapes of one body that never touch, e.g. a chain's
  /// neighbouring links): bit `d - 1` of `bits[i]` set when boxes i and i + d (d = 1 to 64)
  /// are not to be reported. findPairs() then leaves them out of its output, which is
  /// otherwise the same, in the same order; its choice of axis and its giving up count them
  /// as before. Used by the calls with as many boxes as @p bits has words (else ignored);
  /// the words must stay valid until set again. Empty by default: nothing is left out.
  void setNeverPaired(std::span<const std::uint64_t> bits) { neverPaired_ = bits; }

 private:
  /// How a sweep ended.
  enum class Outcome {
    done,      // every pair found
    gaveUp,    // past its budget of tests
    unsorted,  // the order was not the sorted one (found as the sweep goes)
  };
  /// Puts order_ in sweep order along @p axis (0 x, 1 y): by lower side, then by index.
  /// Returns whether any box moved in the order.
  template <int axis>
  bool sort(std::span<const BoundingBox> boxes);
  /// The sweep along @p axis over the boxes in order_ (findPairs()), leaving out the pairs
  /// @p never marks (when @p filtered); gives up past @p maxTests tests. Each box is also
  /// compared with the next in order_: unsorted when that is out of order (the pairs
  /// appended so far are then the caller's to drop).
  template <int axis, bool filtered>
  Outcome sweep(std::span<const BoundingBox> boxes, std::size_t maxTests,
                const std::uint64_t* never, std::vector<BoxPair>& pairs) const;
  /// Sorts if needed and sweeps along @p axis (findPairs()): true when done.
  template <int axis>
  bool sortAndSweep(std::span<const BoundingBox> boxes, std::size_t maxTests,
                    std::vector<BoxPair>& pairs);

  /// The boxes in sweep order (the last call's, until sorted), as their offsets in bytes
  /// in the array (index * sizeof(BoundingBox), which compare as the indices do).
  std::vector<std::size_t> order_;
  int axis_ = -1;  // the last call's axis (0 x, 1 y), -1 before the first call
  // Whether the last call found its order sorted: this call then sweeps before sorting.
  bool orderHeld_ = false;
  std::span<const std::uint64_t> neverPaired_;  // see setNeverPaired()
};

}  // namespace thyrix
