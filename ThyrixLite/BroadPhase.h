#pragma once
/// @file BroadPhase.h
/// @brief Finds the pairs of overlapping bounding boxes in near-linear time.

#include <ThyrixLite/BoundingBox.h>
#include <ThyrixLite/SweepAndPrune.h>

#include <cstdint>
#include <span>
#include <vector>

namespace thyrix {

/// Pointers to the four corner coordinates of boxes stored by coordinate (structure of
/// arrays), for testing one box against many at once.
struct BoxColumns {
  real* lowerX;  ///< lower corner x of each box
  real* upperX;  ///< upper corner x of each box
  real* lowerY;  ///< lower corner y of each box
  real* upperY;  ///< upper corner y of each box
};

/// Finds every pair of overlapping boxes.
///
/// Up to smallCount boxes, every pair is tested, and the result is remembered as one bit mask
/// per box: a later call that is told which boxes moved tests only the pairs with a moved box.
/// Above, boxes strung out along a line (few boxes per length of the line along x or along y:
/// a chain, a row) are sorted and swept along that axis (SweepAndPrune); the others go into a
/// uniform grid rebuilt every call by counting sort; the cell side is as
/// small as the largest box allows (at most twice the mean), and a box larger than a cell is
/// "oversized" and tested against all boxes (few such boxes keep this linear). Every other box
/// lies in one cell (by its centre) and can only overlap boxes in the 3 x 3 neighbouring cells.
/// The grid is a dense array of cells when the boxes fill their bounding rectangle well (piles:
/// neighbouring cells are then contiguous in memory), else a hash table of cells (scattered
/// boxes). Both grids give the same pairs in the same order; the sweep gives them in its own.
/// A box whose centre is NaN, infinite, or more than 2^62 cells from the origin is oversized
/// too: any box is accepted, and one with a NaN corner overlaps nothing (BoundingBox::overlaps).
///
/// The output order depends only on the input, so runs are reproducible. Buffers are kept
/// between calls: once warmed up with as many boxes, finding pairs allocates nothing.
///
/// A caller that steps a world (findPairs() with moved bits) gets the grid's pairs from
/// candidates kept between calls (temporal coherence, a "Verlet list"): the grid is searched
/// for "fat" boxes, each box enlarged by fatMarginPerCell of a cell on every side, and the
/// overlapping pairs of fat boxes are kept, sorted by first then second index. While every
/// box lies within its fat box, each of its overlaps is such a pair: a call tests only these,
/// in their order. A few boxes out of their fat boxes (strays: one fast body crossing a crowd
/// at rest) are tested against every box instead, their pairs merged into the order; the grid
/// is searched again once more boxes than fatStraysLimit have left their fat boxes or the
/// count has changed. The output is therefore the grid's pairs sorted by first then second
/// index, whenever the candidates were found: it still depends only on the input.
class BroadPhase {
 public:
  /// Up to this many boxes, every pair is tested directly (and remembered, see above).
  static constexpr std::uint32_t smallCount = 48;

  /// Replaces @p pairs with every overlapping pair of @p boxes, ordered by first then second
  /// up to smallCount boxes.
  void findPairs(std::span<const BoundingBox> boxes, std::vector<BoxPair>& pairs);

  /// The same pairs as findPairs(boxes, pairs), for a caller that calls once a step with boxes
  /// that move a little. Up to smallCount boxes, in the same order and faster when few boxes
  /// moved: a box whose bit in @p moved is 0 (bit `i % 64` of word `i / 64` for box i) is
  /// promised to be the same as in the last call (same index, same corners), so its overlaps
  /// with other such boxes are not tested again (the promise is only used when the last call
  /// had as many boxes; otherwise every pair is tested). Above, the sweep's pairs in its order,
  /// or the grid's ordered by first then second index, from the kept candidates (see above).
  void findPairs(std::span<const BoundingBox> boxes, std::span<const std::uint64_t> moved,
                 std::vector<BoxPair>& pairs);

  /// Pairs the caller drops anyway, which the sweep then leaves out of its output
  /// (SweepAndPrune::setNeverPaired(), same bits, same conditions); the few-box test and the
  /// grid still report them.
  void setNeverPaired(std::span<const std::uint64_t> bits) { sweep_.setNeverPaired(bits); }

  /// With false the grid always hashes its cells (for tests comparing the two grids).
  bool allowDenseGrid = true;
  /// With false more than smallCount boxes always go into the grid (for tests and
  /// comparisons); with true a sweep is used when the boxes are strung out along an axis.
  bool allowSweep = true;

  /// The sweep is chosen when the boxes' mean extent along an axis, times their count, over the
  /// span they cover on it (the expected number of boxes each must be tested against)
  /// is at most this. A line of boxes end to end gives about 1, a filled square of n boxes
  /// about sqrt(n).
  static constexpr real sweepTestsPerBox = 4;

  /// The kept candidates' fat boxes are the boxes enlarged by this share of the grid's cell side
  /// on every side (measured on piles of circles, the cell a circle's box: 0.15 to 0.3 served
  /// equally; smaller margins are left sooner, larger ones give more candidates to test).
  static constexpr real fatMarginPerCell = real(0.25);
  /// Fat boxes that served only the call that found them (boxes moving farther than the
  /// margin in a step): the next this many searches use no margin.
  static constexpr std::uint32_t fatBackOff = 8;
  /// Up to this many boxes out of their fat boxes are tested against every box, each call,
  /// instead of searching the grid again (a search costs about as much as testing some tens of
  /// boxes against a thousand).
  static constexpr std::uint32_t fatStraysLimit = 8;

 private:
  void findPairsAmongFew(std::span<const BoundingBox> boxes, std::uint64_t moved, bool remembered,
                         std::vector<BoxPair>& pairs);
  /// The grid's pairs; @p extentSum and @p maxExtent are the sum and the largest of the
  /// boxes' extents (the larger side of each), summed in index order.
  /// More than smallCount boxes: the sweep or the grid. (Not inlined into findPairs, whose
  /// few-box calls then keep a light frame.)
#if defined(__GNUC__)
  [[gnu::noinline]]
#endif
  void
  findPairsAmongMany(std::span<const BoundingBox> boxes, bool keep, std::vector<BoxPair>& pairs);
  /// Searches the grid for the fat boxes of @p boxes (see fatMarginPerCell), whose extents'
  /// sum and largest are @p extentSum and @p maxExtent, into fatBoxes_ and fatPairs_.
  void findFatPairs(std::span<const BoundingBox> boxes, real extentSum, real maxExtent);
  /// Puts fatPairs_ (of @p count boxes) in order by first index, then by second.
  void sortFatPairs(std::uint32_t count);
  /// Writes to the front of candidates_, in their order, the pairs of fatPairs_ whose
  /// @p boxes overlap, and returns their number; with @p withStrays, without those of the
  /// boxes marked in strayMarks_.
  template <bool withStrays>
  std::size_t keepOverlappingFatPairs(std::span<const BoundingBox> boxes);
  /// Lists in strays_ the boxes of @p boxes out of their fat boxes; false (the list cut
  /// short) when there are more than fatStraysLimit.
  bool findStrays(std::span<const BoundingBox> boxes);
  /// The kept candidates' overlapping pairs without the strays', merged in order with the
  /// strays' pairs found by testing them against every box, appended to @p pairs.
  void filterWithStrays(std::span<const BoundingBox> boxes, std::vector<BoxPair>& pairs);
  void findPairsInGrid(std::span<const BoundingBox> boxes, real extentSum, real maxExtent,
                       std::vector<BoxPair>& pairs);
  void findPairsInDenseGrid(std::span<const BoundingBox> boxes, std::int64_t lowX,
                            std::int64_t lowY, std::int64_t columns, std::int64_t rows,
                            std::vector<BoxPair>& pairs);
  void findPairsInHashedGrid(std::span<const BoundingBox> boxes, std::vector<BoxPair>& pairs);
  /// Groups the regular boxes by cellOfBox_ (cells 0 to cellCount - 1) into sortedBoxes_,
  /// with cellStart_ marking each cell's range (the hashed grid; the dense grid sorts its own).
  void sortByCell(std::uint32_t count, std::uint32_t cellCount);
  void reserveFor(std::uint32_t count);

  // Few boxes: the corners by coordinate, smallCount + 3 of each (padding for whole vectors)
  // in columns_: lower x, upper x, lower y, upper y.
  std::vector<real> columns_;
  // Few boxes: bit j of overlaps_[i] is set when boxes i < j overlap (last call's result);
  // bit i of rowsWithPairs_ when overlaps_[i] is not zero.
  std::vector<std::uint64_t> overlaps_;
  std::vector<std::uint64_t> movedRows_;  // a moved box's overlaps with every other box
  std::uint64_t rowsWithPairs_ = 0;
  std::uint32_t rememberedCount_ = 0;  // boxes of the call overlaps_ describes (0: none)

  // Grid.
  std::uint32_t reservedCount_ = 0;          // box count the grid buffers are sized for
  std::vector<std::uint32_t> cellOfBox_;     // cell (dense) or bucket (hashed) of each box
  std::vector<std::int64_t> cellX_, cellY_;  // integer cell coordinates of each regular box
  // Counting-sort offsets: one per bucket + 1 (hashed grid); one per cell + 2 in the dense
  // grid, which counts one entry late so that the fill's cursors are the offsets themselves.
  std::vector<std::uint32_t> cellStart_;
  std::vector<std::uint32_t> cellCursor_;   // fill position of each bucket during the sort
  std::vector<std::uint32_t> sortedBoxes_;  // regular boxes grouped by cell, by index within
  std::vector<std::uint32_t> oversized_;    // boxes larger than a cell
  std::vector<std::uint32_t> slotOfBox_;    // position of each box in sortedBoxes_ (dense)
  std::vector<BoxPair> candidates_;         // the dense grid's candidate pairs (only grows)

  // Kept candidates (findPairs() with moved bits, in the grid).
  std::vector<BoundingBox> fatBoxes_;     // the boxes enlarged by fatMargin_ when searched
  std::vector<BoxPair> fatPairs_;         // the overlapping pairs of fatBoxes_, in order
  std::uint32_t fatCount_ = 0;            // boxes of fatBoxes_ (0: nothing kept)
  std::uint32_t fatCalls_ = 0;            // calls served since the search
  std::uint32_t fatPlainSearches_ = 0;    // searches left without a margin (fatBackOff)
  real fatMargin_ = 0;                    // the margin of fatBoxes_
  std::vector<std::uint32_t> strays_;     // boxes out of their fat boxes, by index
  std::vector<std::uint8_t> strayMarks_;  // 1 for a stray, else 0 (one per box)
  std::vector<BoxPair> strayPairs_;       // the strays' overlapping pairs

  SweepAndPrune sweep_;        // boxes along a line
  bool lastTookGrid_ = false;  // the last call of more than smallCount boxes used the grid
};

}  // namespace thyrix
