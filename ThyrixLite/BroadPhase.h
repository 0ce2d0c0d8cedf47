#pragma once
/// @file BroadPhase.h
/// @brief Finds the pairs of overlapping bounding boxes in near-linear time.

#include <ThyrixLite/BoundingBox.h>
#include <ThyrixLite/SweepAndPrune.h>
#include <Tools/Inlining.h>

#include <algorithm>
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
/// Above smallCount boxes too, a call told which boxes moved, when few of them changed, tests
/// only those against every box and keeps the other pairs of the last call (findPairs()).
///
/// The output order depends only on the boxes of this call and of the earlier ones, and on
/// which of these calls passed flags (not on the flags themselves), so runs are reproducible.
/// Buffers are kept between calls: once warmed up with as many boxes, finding pairs allocates
/// nothing.
class BroadPhase {
 public:
  /// Up to this many boxes, every pair is tested directly (and remembered, see above).
  static constexpr std::uint32_t smallCount = 48;

  /// Replaces @p pairs with every overlapping pair of @p boxes, ordered by first then second
  /// up to smallCount boxes.
  void findPairs(std::span<const BoundingBox> boxes, std::vector<BoxPair>& pairs);

  /// The same pairs as findPairs(boxes, pairs) (but for never-paired pairs, which only the
  /// sweep leaves out), faster when few boxes moved: a box whose bit in @p moved is 0 (bit
  /// `i % 64` of word `i / 64` for box i; @p moved has a word for every 64 boxes, or fewer for
  /// no promise at all; the bits from the box count on are ignored) is promised to be the same
  /// as in the last call (same index, same corners), so its overlaps with other such boxes
  /// are not tested again. The promise is used when the last call, with flags or without, had
  /// as many boxes, and:
  /// - up to smallCount boxes: the pairs then come in the same order as findPairs(boxes, pairs);
  /// - above, when the last call's pairs were complete (not a sweep that left out never-paired
  ///   pairs) and at most movedLimit(count) of the flagged boxes differ from the last call's,
  ///   bit for bit. Each such box is then tested against every box, and the pairs come in
  ///   another order than a full call's: the last call's pairs of two unchanged boxes in their
  ///   order, then the changed boxes' pairs, by changed box, then by the other box's index. A
  ///   box flagged but unchanged is as if not flagged: when every call passes flags, the order
  ///   depends on the boxes of this call and of the earlier ones, not on which were flagged (a
  ///   simulator without rest skipping flags every box, and finds the same pairs in the same
  ///   order). A call without flags is a full call, and starts the order afresh. A world where
  ///   few bodies move keeps its pairs in the same order from step to step.
  ///
  /// Otherwise every pair is tested.
  /// With @p extents not null, the boxes' SweepAndPrune::Extents, gathered by the caller
  /// over every box in index order (as it computed them): one pass over the boxes less.
  void findPairs(std::span<const BoundingBox> boxes, std::span<const std::uint64_t> moved,
                 std::vector<BoxPair>& pairs, const SweepAndPrune::Extents* extents = nullptr);

  /// Makes room for @p count pairs in what findPairs() keeps between calls, so that calls with
  /// no more pairs than that allocate nothing (else it grows geometrically, as the pairs do).
  void reservePairs(std::size_t count) { keptPairs_.reserve(count); }

  /// Pairs the caller drops anyway, which the sweep then leaves out of its output
  /// (SweepAndPrune::setNeverPaired(), same bits, same conditions); the few-box test, the grid
  /// and the test of changed boxes still report them.
  void setNeverPaired(std::span<const std::uint64_t> bits) {
    sweep_.setNeverPaired(bits);
    neverPairedCount_ = bits.size();
  }

  /// Above smallCount boxes, the most changed boxes for which findPairs() tests the changed
  /// boxes against every box instead of sweeping or gridding them all. A changed box costs
  /// about count / 4 vector comparisons (AVX), a full call some 100 to 200 instructions per box:
  /// up to a quarter of the boxes, at most 64 (measured: the arena of 160 balls, 100000 steps,
  /// 9% fewer instructions than with at most a sixteenth, no fewer with half).
  static constexpr std::uint32_t movedLimit(std::uint32_t count) {
    return std::min(64u, count / 4);
  }

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

 private:
  void findPairsAmongFew(std::span<const BoundingBox> boxes, std::uint64_t moved, bool remembered,
                         std::vector<BoxPair>& pairs);
  /// findPairs() for more than smallCount boxes: those that changed, or all. (Out of line:
  /// findPairs()'s few-box calls then keep a light frame.)
#if defined(__GNUC__)
  THYRIX_NO_INLINE
#endif
  void findPairsAboveFew(std::span<const BoundingBox> boxes, std::span<const std::uint64_t> moved,
                         std::vector<BoxPair>& pairs, const SweepAndPrune::Extents* extents);
  /// More than smallCount boxes, as many as the last call's, which remembered them: marks in
  /// changed_ the boxes flagged in @p moved whose corners differ, bit for bit, from the last
  /// call's; @return their count (once it exceeds movedLimit(), some more at most: the words
  /// after are not looked at).
  std::uint32_t findChanged(std::span<const BoundingBox> boxes,
                            std::span<const std::uint64_t> moved);
  /// More than smallCount boxes, the boxes of changed_ (at most movedLimit) changed, the last
  /// call's pairs remembered: the pairs kept among the others, then the changed boxes'.
  void findPairsAmongMoved(std::span<const BoundingBox> boxes, std::vector<BoxPair>& pairs);
  /// Remembers @p pairs, every pair of @p boxes (more than smallCount), and the boxes' corners
  /// by coordinate, for the next call's findPairsAmongMoved().
  void rememberAll(std::span<const BoundingBox> boxes, const std::vector<BoxPair>& pairs);
  /// Copies @p pairs to keptPairs_.
  void keepPairs(const std::vector<BoxPair>& pairs);
  /// Where the corners of @p count boxes (more than smallCount) are kept by coordinate: in
  /// manyColumns_, sized for them (not filled).
  BoxColumns manyColumns(std::uint32_t count);
  /// More than smallCount boxes: the sweep or the grid.
  void findPairsAmongMany(std::span<const BoundingBox> boxes, const SweepAndPrune::Extents* extents,
                          std::vector<BoxPair>& pairs);
  /// The grid's pairs; @p extentSum and @p maxExtent are the sum and the largest of the
  /// boxes' extents (the larger side of each), summed in index order.
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

  // Few boxes: the corners by coordinate, smallCount + 7 of each (padding for whole vectors)
  // in columns_: lower x, upper x, lower y, upper y.
  std::vector<real> columns_;
  // Few boxes: bit j of overlaps_[i] is set when boxes i < j overlap (last call's result);
  // bit i of rowsWithPairs_ when overlaps_[i] is not zero.
  std::vector<std::uint64_t> overlaps_;
  std::vector<std::uint64_t> movedRows_;  // a moved box's overlaps with every other box
  std::uint64_t rowsWithPairs_ = 0;
  // Boxes of the last call, if it remembered them (0: none): up to smallCount, in overlaps_;
  // above, in keptPairs_ and manyColumns_.
  std::uint32_t rememberedCount_ = 0;

  // Many boxes, few moved: the last call's pairs, the corners by coordinate (count + 7 of each:
  // padding for whole vectors), the moved boxes' rows (words of 64 boxes each).
  std::vector<BoxPair> keptPairs_;
  std::vector<real> manyColumns_;
  std::vector<std::uint64_t> manyRows_;
  std::vector<std::uint64_t> changed_;  // findChanged(): a bit per box
  std::size_t neverPairedCount_ = 0;    // setNeverPaired()'s bits: the sweep's filter if = count

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

  SweepAndPrune sweep_;        // boxes along a line
  bool lastTookGrid_ = false;  // the last call of more than smallCount boxes used the grid
};

}  // namespace thyrix
