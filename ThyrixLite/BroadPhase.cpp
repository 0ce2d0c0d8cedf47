/// @file BroadPhase.cpp
/// @brief BroadPhase above smallCount boxes: the sweep or the grid (dense or hashed).
#include <ThyrixLite/BroadPhase.h>
#include <Tools/Inlining.h>
#include <Tools/Wide.h>

#include <algorithm>
#include <bit>
#include <cstring>
#include <type_traits>

namespace thyrix {
namespace {

std::uint32_t hashCell(std::int64_t x, std::int64_t y, std::uint32_t mask) {
  const auto h = static_cast<std::uint64_t>(x) * 0x9E3779B97F4A7C15ull ^
                 static_cast<std::uint64_t>(y) * 0xC2B2AE3D27D4EB4Full;
  return static_cast<std::uint32_t>(h >> 32) & mask;
}

real extent(const BoundingBox& box) {
  return std::max(box.upper.x - box.lower.x, box.upper.y - box.lower.y);
}

constexpr std::uint32_t oversizedMark = ~0u;

/// Where a BoxPair's first index lies in the word its bytes make (the second in the other
/// half).
constexpr int firstShift = std::endian::native == std::endian::little ? 0 : 32;

/// The pair (@p first, @p second) as the word a BoxPair's bytes hold.
std::uint64_t pairWord(std::uint32_t first, std::uint32_t second) {
  return std::uint64_t{first} << firstShift | std::uint64_t{second} << (32 - firstShift);
}

/// Stores the pair @p word (see pairWord) at @p out, in one store.
void storePair(BoxPair* out, std::uint64_t word) {
  static_assert(sizeof(BoxPair) == sizeof(word) && std::is_trivially_copyable_v<BoxPair>);
  std::memcpy(out, &word, sizeof(word));
}

/// The pair stored at @p pair, as its word (see pairWord).
std::uint64_t loadPair(const BoxPair* pair) {
  std::uint64_t word;
  std::memcpy(&word, pair, sizeof(word));
  return word;
}

/// The dense grid is used while it has at most this many cells per box (plus a margin for
/// small counts); sparser layouts hash their cells instead.
constexpr std::int64_t denseCellsPerBox = 4;
constexpr std::int64_t denseCellsMargin = 64;

/// Hash buckets for @p count boxes: a power of two, at least twice the count.
std::uint32_t bucketCountFor(std::uint32_t count) {
  std::uint32_t buckets = 1;
  while (buckets < 2 * count) buckets <<= 1;
  return buckets;
}

/// Regular boxes have cell coordinates in [-cellLimit, cellLimit): their differences, and their
/// neighbours' coordinates, are then far from std::int64_t's limits. A box whose centre is
/// outside, NaN or infinite is oversized instead (2^62 cells of 1 mm span 4.6e12 km).
constexpr std::int64_t cellLimit = std::int64_t{1} << 62;

/// floor(@p q) as an integer, for q in the range of std::int64_t: the same value as
/// `static_cast<std::int64_t>(std::floor(q))`, without the library call std::floor is without
/// SSE4.1 (and the spills around it). The truncation of a real is a real, so comparing it
/// back is exact. For any other q (NaN, infinite, too large) the least or the greatest
/// std::int64_t, without undefined behaviour, so that one look at the least and greatest
/// cells tells whether every box is in range (cellLimit).
std::int64_t floorToInt(real q) {
  const std::int64_t t = simd::truncateToInt64(q);
  // (Unsigned: q just below the least std::int64_t gives the greatest, out of cellLimit.)
  return static_cast<std::int64_t>(static_cast<std::uint64_t>(t) -
                                   std::uint64_t{static_cast<real>(t) > q});
}

/// Whether @p q, a centre in cells, lies in the cells of regular boxes (see cellLimit).
bool inCellRange(Vector2 q) {
  constexpr auto bound = static_cast<real>(cellLimit);  // (exact: a power of two)
  return q.x >= -bound && q.x < bound && q.y >= -bound && q.y < bound;
}

/// Two reals as one value: a 2D vector's x and y.
using Pair = simd::Wide<real, 2>;
static_assert(std::is_standard_layout_v<BoundingBox> && sizeof(BoundingBox) == 4 * sizeof(real),
              "a box is read as its two corners, each its x and y");

/// The x and y of @p v as one value.
Pair load(const Vector2& v) { return Pair::load(&v.x); }

/// The centre of @p box in cells of side @p cellSize (x and y together: GCC made two of each
/// operation otherwise).
Vector2 centreInCells(const BoundingBox& box, real cellSize) {
  const Pair q =
      (load(box.lower) + load(box.upper)) * Pair::broadcast(real(0.5)) / Pair::broadcast(cellSize);
  return {q.at(0), q.at(1)};
}

/// Adds every box of @p boxes, in index order, to @p extents (the sweep's) and, with
/// @p forGrid, to the sum @p extentSum and the largest @p maxExtent of their extents (the
/// grid's, see extent()): a box's x and y together. The same operations as
/// SweepAndPrune::Extents::add and std::max: std::min(a, b) is `b < a ? b : a`, simd::min(b, a).
template <bool forGrid>
void gatherExtents(std::span<const BoundingBox> boxes, SweepAndPrune::Extents& extents,
                   real& extentSum, real& maxExtent) {
  Pair sums = simd::pair(extents.sumX, extents.sumY);
  Pair low = simd::pair(extents.lowX, extents.lowY);
  Pair high = simd::pair(extents.highX, extents.highY);
  real sum = extentSum;
  real most = maxExtent;
  for (const BoundingBox& box : boxes) {
    const Pair lower = load(box.lower);
    const Pair upper = load(box.upper);
    const Pair sides = upper - lower;
    sums = sums + sides;
    low = min(lower, low);
    high = max(upper, high);
    if constexpr (forGrid) {
      const real sideX = sides.at(0);
      const real sideY = sides.at(1);
      const real side = sideX < sideY ? sideY : sideX;
      sum += side;
      most = most < side ? side : most;
    }
  }
  extents.sumX = sums.at(0);
  extents.sumY = sums.at(1);
  extents.lowX = low.at(0);
  extents.lowY = low.at(1);
  extents.highX = high.at(0);
  extents.highY = high.at(1);
  extentSum = sum;
  maxExtent = most;
}

}  // namespace

void BroadPhase::findPairs(std::span<const BoundingBox> boxes, std::vector<BoxPair>& pairs) {
  findPairs(boxes, {}, pairs, nullptr);
}

void BroadPhase::findPairs(std::span<const BoundingBox> boxes, std::span<const std::uint64_t> moved,
                           std::vector<BoxPair>& pairs, const SweepAndPrune::Extents* extents) {
  pairs.clear();
  const auto count = static_cast<std::uint32_t>(boxes.size());
  // Few boxes: testing every pair is cheaper than building the grid (measured: a 22-body
  // arena spent a quarter of its step in the grid).
  if (count <= smallCount) {
    const bool remembered = !moved.empty() && rememberedCount_ == count && count > 0;
    findPairsAmongFew(boxes, remembered ? moved[0] : 0, remembered, pairs);
    return;
  }
  findPairsAboveFew(boxes, moved, pairs, extents);
}

void BroadPhase::findPairsAboveFew(std::span<const BoundingBox> boxes,
                                   std::span<const std::uint64_t> moved,
                                   std::vector<BoxPair>& pairs,
                                   const SweepAndPrune::Extents* extents) {
  const auto count = static_cast<std::uint32_t>(boxes.size());
  // Many boxes: when few changed since the last call, those against all (the pairs among the
  // others are the last call's). Which changed is judged by the corners, bit for bit (the
  // flagged boxes compared with the last call's): not by the flags, so that the path, and the
  // order of the pairs, depend on the boxes alone (a simulator without rest skipping flags
  // every box, and must find the same pairs in the same order).
  // (A span too short to flag every box is no promise: every pair is tested.)
  if (moved.size() >= (std::size_t{count} + 63) / 64 && rememberedCount_ == count) {
    const std::uint32_t changed = findChanged(boxes, moved);
    if (changed <= movedLimit(count)) {
      findPairsAmongMoved(boxes, pairs);
      keepPairs(pairs);
      return;
    }
  }
  findPairsAmongMany(boxes, extents, pairs);
  // (A sweep given never-paired bits leaves such pairs out: not every pair, none kept.)
  if (lastTookGrid_ || neverPairedCount_ != count) rememberAll(boxes, pairs);
}

void BroadPhase::findPairsAmongMany(std::span<const BoundingBox> boxes,
                                    const SweepAndPrune::Extents* gathered,
                                    std::vector<BoxPair>& pairs) {
  rememberedCount_ = 0;
  reserveFor(static_cast<std::uint32_t>(boxes.size()));
  // The sweep estimates its cost from the boxes' extents along each axis; the grid sizes its
  // cells by their larger sides. When the last call took the grid (a pile: the sweep
  // declines), one pass gathers both; else the grid's pass waits until the sweep declines.
  // Either way the same sums in the same order: only the work depends on the last call.
  SweepAndPrune::Extents extents;
  real extentSum = 0;
  real maxExtent = 0;
  const auto addGridExtent = [&extentSum, &maxExtent](const BoundingBox& box) {
    extentSum += extent(box);
    maxExtent = std::max(maxExtent, extent(box));
  };
  const bool gridExpected = lastTookGrid_ || !allowSweep;
  if (gridExpected)
    gatherExtents<true>(boxes, extents, extentSum, maxExtent);
  else if (gathered != nullptr)  // (the caller's: the same sums)
    extents = *gathered;
  else
    gatherExtents<false>(boxes, extents, extentSum, maxExtent);
  lastTookGrid_ = false;
  if (allowSweep && sweep_.findPairs(boxes, extents, sweepTestsPerBox, pairs)) return;
  if (!gridExpected)
    for (const BoundingBox& box : boxes) addGridExtent(box);
  lastTookGrid_ = true;
  findPairsInGrid(boxes, extentSum, maxExtent, pairs);
}

namespace {

/// BoundingBox::overlaps of one box against others, as 1 or 0 without a branch (whether
/// candidates of a grid overlap is random to the branch predictor): lower corners against
/// upper corners, x and y together (a comparison with NaN is false, as in C++).
class OverlapTest {
 public:
  explicit OverlapTest(const BoundingBox& box) : lower_(load(box.lower)), upper_(load(box.upper)) {}
  std::size_t operator()(const BoundingBox& o) const {
    const auto hit = lessOrEqual(lower_, load(o.upper)) & lessOrEqual(load(o.lower), upper_);
    // 1 for both lanes' bits (3), else 0: an add and a shift (not a compare and a widening).
    return (hit.bits() + 1) >> 2;
  }

 private:
  Pair lower_;
  Pair upper_;
};

/// What the dense grid's candidate loop reads (BroadPhase's buffers, through plain pointers).
struct DenseCells {
  const BoundingBox* boxes;
  const std::uint32_t* cellOfBox;  // each box's cell, or oversizedMark
  const std::uint32_t* slotOfBox;  // each regular box's position in sorted
  const std::uint32_t* start;      // cell c's boxes are sorted[start[c]] to sorted[start[c + 1]]
  const std::uint32_t* sorted;     // the regular boxes by cell, by index within each
  std::uint32_t count;             // boxes
  std::uint32_t stride;            // cells per column
};

/// The dense grid's candidate pairs, each written at the end of @p candidates (sized ahead for
/// every candidate of the box at hand, grown when needed) and kept when OverlapTest says the
/// boxes overlap; @return the number kept. Each pair comes as (other, box): the caller puts every
/// pair in order. The visiting order: for each box by index, its own cell (higher indices:
/// those after the box itself, as a cell lists its boxes by index), then the cells (x+1, y-1),
/// (x+1, y), (x+1, y+1), then (x, y+1), each by increasing index.
/// Whether a candidate overlaps is random to the branch predictor: the pair is kept (the end
/// advanced) without a branch.
std::size_t findDenseCandidates(const DenseCells& grid, std::vector<BoxPair>& candidates) {
  std::size_t n = 0;
  BoxPair* out = candidates.data();
  std::size_t capacity = candidates.size();
  // Everything in locals: the stores of pairs might change what a reference shows (GCC
  // reloaded it at every candidate).
  const BoundingBox* const boxes = grid.boxes;
  const std::uint32_t* const cellOfBox = grid.cellOfBox;
  const std::uint32_t* const slotOfBox = grid.slotOfBox;
  const std::uint32_t* const start = grid.start;
  const std::uint32_t* const sorted = grid.sorted;
  const std::uint32_t boxCount = grid.count;
  const std::uint32_t stride = grid.stride;
  for (std::uint32_t i = 0; i < boxCount; ++i) {
    const std::uint32_t own = cellOfBox[i];
    if (own == oversizedMark) continue;
    const std::uint32_t ownBegin = slotOfBox[i] + 1;
    const std::uint32_t aboveBegin = start[own + 1];
    const std::uint32_t aboveEnd = start[own + 2];
    const std::uint32_t nextBegin = start[own + stride - 1];
    const std::uint32_t nextEnd = start[own + stride + 2];
    const std::size_t count = (aboveEnd - ownBegin) + (nextEnd - nextBegin);
    if (n + count > capacity) {  // rare: the buffer doubles
      candidates.resize(std::max(2 * capacity, n + count));
      out = candidates.data();
      capacity = candidates.size();
    }
    const OverlapTest overlaps(boxes[i]);
    // (j, i): the box's half of the word is made once, and each candidate's is its index.
    const std::uint64_t boxHalf = pairWord(0, i);
    // The three ranges of the sorted boxes, each loop written out: a loop over the ranges
    // kept them on the stack.
#define THYRIX_TEST_RANGE(begin, end)               \
  for (std::uint32_t k = (begin); k < (end); ++k) { \
    const std::uint32_t j = sorted[k];              \
    storePair(out + n, boxHalf | pairWord(j, 0));   \
    n += overlaps(boxes[j]);                        \
  }
    THYRIX_TEST_RANGE(ownBegin, aboveBegin)
    THYRIX_TEST_RANGE(nextBegin, nextEnd)
    THYRIX_TEST_RANGE(aboveBegin, aboveEnd)
#undef THYRIX_TEST_RANGE
  }
  return n;
}

}  // namespace

void BroadPhase::reserveFor(std::uint32_t count) {
  // Sized for the box count, not for this call's layout: a layout that spreads later needs no
  // more than the dense grid's limit or the hash table's buckets.
  if (count <= reservedCount_) return;
  const auto cells = static_cast<std::size_t>(denseCellsPerBox * count + denseCellsMargin);
  cellStart_.reserve(std::max<std::size_t>(cells, bucketCountFor(count)) + 2);
  cellCursor_.reserve(cellStart_.capacity());
  for (auto* buffer : {&cellOfBox_, &sortedBoxes_, &slotOfBox_, &oversized_})
    buffer->reserve(count);
  candidates_.reserve(2 * std::size_t{count} + 64);
  cellX_.reserve(count);
  cellY_.reserve(count);
  sweep_.reserve(count);
  reservedCount_ = count;
}

void BroadPhase::findPairsInGrid(std::span<const BoundingBox> boxes, real extentSum, real maxExtent,
                                 std::vector<BoxPair>& pairs) {
  const auto count = static_cast<std::uint32_t>(boxes.size());
  // Cells as small as the largest box allows (about one box per cell for similar sizes), but
  // no larger than twice the mean: rare big boxes are handled as oversized instead.
  const real meanExtent = extentSum / static_cast<real>(count);
  const real cellSize = std::max(std::min(maxExtent, 2 * meanExtent), realEpsilon);

  // Cell coordinates of the regular boxes, and the rectangle of cells they span.
  cellOfBox_.resize(count);
  cellX_.resize(count);
  cellY_.resize(count);
  oversized_.clear();
  std::int64_t lowX = INT64_MAX;
  std::int64_t lowY = INT64_MAX;
  std::int64_t highX = INT64_MIN;
  std::int64_t highY = INT64_MIN;
  // Through local pointers, the coordinates kept in registers (GCC reloaded the buffers'
  // pointers and the stored coordinates at every box).
  std::uint32_t* const cellOfBox = cellOfBox_.data();
  std::int64_t* const cellX = cellX_.data();
  std::int64_t* const cellY = cellY_.data();
  // With checkRange, a box whose centre is out of the cells' range (or NaN) is oversized.
  const auto assignCells = [&](auto mayBeOversized, auto checkRange) {
    const auto setOversized = [&](std::uint32_t i) {
      cellOfBox[i] = oversizedMark;
      oversized_.push_back(i);
    };
    for (std::uint32_t i = 0; i < count; ++i) {
      const BoundingBox& box = boxes[i];
      if (decltype(mayBeOversized)::value && extent(box) > cellSize) {
        setOversized(i);
        continue;
      }
      const Vector2 q = centreInCells(box, cellSize);
      if (decltype(checkRange)::value && !inCellRange(q)) {
        setOversized(i);
        continue;
      }
      const std::int64_t x = floorToInt(q.x);
      const std::int64_t y = floorToInt(q.y);
      cellX[i] = x;
      cellY[i] = y;
      cellOfBox[i] = 0;
      lowX = std::min(lowX, x);
      lowY = std::min(lowY, y);
      highX = std::max(highX, x);
      highY = std::max(highY, y);
    }
  };
  // No box is larger than a cell when the largest is not (a pile: the cell is the largest
  // box), and the loop then leaves the test out. (maxExtent is not NaN, and a NaN extent is
  // never larger.)
  if (maxExtent > cellSize)
    assignCells(std::true_type{}, std::false_type{});
  else
    assignCells(std::false_type{}, std::false_type{});
  // A centre out of range (NaN or infinite coordinates, or far away) gave a cell out of
  // cellLimit (see floorToInt): once per call, not per box. Then every box again, those out of
  // range oversized (tested against all boxes by BoundingBox::overlaps: NaN overlaps nothing).
  if (lowX < -cellLimit || highX >= cellLimit || lowY < -cellLimit || highY >= cellLimit) {
    oversized_.clear();
    lowX = lowY = INT64_MAX;
    highX = highY = INT64_MIN;
    assignCells(std::true_type{}, std::true_type{});
  }

  // One cell of padding on every side, so that the neighbours of every cell exist.
  const bool anyRegular = lowX <= highX;
  const auto limit = denseCellsPerBox * count + denseCellsMargin;
  const bool dense = anyRegular && allowDenseGrid && highX - lowX < limit && highY - lowY < limit &&
                     (highX - lowX + 3) * (highY - lowY + 3) <= limit;
  if (dense)
    findPairsInDenseGrid(boxes, lowX - 1, lowY - 1, highX - lowX + 3, highY - lowY + 3, pairs);
  else
    findPairsInHashedGrid(boxes, pairs);

  // Oversized boxes against everything (each pair once).
  for (const std::uint32_t big : oversized_) {
    for (std::uint32_t j = 0; j < count; ++j) {
      if (j == big || (cellOfBox_[j] == oversizedMark && j < big)) continue;
      if (boxes[big].overlaps(boxes[j])) pairs.push_back({std::min(big, j), std::max(big, j)});
    }
  }
}

void BroadPhase::sortByCell(std::uint32_t count, std::uint32_t cellCount) {
  // Counting sort in index order, so each cell lists its boxes by increasing index.
  cellStart_.assign(cellCount + 1, 0);
  for (std::uint32_t i = 0; i < count; ++i)
    if (cellOfBox_[i] != oversizedMark) ++cellStart_[cellOfBox_[i] + 1];
  for (std::uint32_t c = 0; c < cellCount; ++c) cellStart_[c + 1] += cellStart_[c];
  cellCursor_.assign(cellStart_.begin(), cellStart_.end() - 1);
  sortedBoxes_.resize(cellStart_[cellCount]);
  for (std::uint32_t i = 0; i < count; ++i)
    if (cellOfBox_[i] != oversizedMark) sortedBoxes_[cellCursor_[cellOfBox_[i]]++] = i;
}

void BroadPhase::findPairsInDenseGrid(std::span<const BoundingBox> boxes, std::int64_t lowX,
                                      std::int64_t lowY, std::int64_t columns, std::int64_t rows,
                                      std::vector<BoxPair>& pairs) {
  // Cells column by column: cell (x, y) is number (x - lowX) * rows + (y - lowY), so the three
  // cells of the next column around a box's row are consecutive, and so are its own cell and
  // the one above.
  const auto count = static_cast<std::uint32_t>(boxes.size());
  const auto cellCount = static_cast<std::uint32_t>(columns * rows);
  const auto stride = static_cast<std::uint32_t>(rows);
  // Counting sort in index order (each cell lists its boxes by increasing index), counted as
  // the cells are numbered. Counts are kept one entry late, so that the fill's cursors are
  // cellStart_ itself: cell c's cursor is entry c + 1, which ends as its end, the start of c + 1
  // (no copy of the starts for cursors, no second pass to count).
  cellStart_.assign(std::size_t{cellCount} + 2, 0);
  std::uint32_t* const cellOfBox = cellOfBox_.data();
  std::uint32_t* const cells = cellStart_.data();
  for (std::uint32_t i = 0; i < count; ++i) {
    if (cellOfBox[i] == oversizedMark) continue;
    const auto cell = static_cast<std::uint32_t>((cellX_[i] - lowX) * rows + (cellY_[i] - lowY));
    cellOfBox[i] = cell;
    ++cells[cell + 2];
  }
  for (std::uint32_t c = 0; c < cellCount; ++c) cells[c + 2] += cells[c + 1];
  sortedBoxes_.resize(cells[cellCount + 1]);
  slotOfBox_.resize(count);
  for (std::uint32_t i = 0; i < count; ++i) {
    if (cellOfBox[i] == oversizedMark) continue;
    const std::uint32_t slot = cells[cellOfBox[i] + 1]++;
    sortedBoxes_[slot] = i;
    slotOfBox_[i] = slot;
  }

  // The same visiting order as the hashed grid (findDenseCandidates()). The candidates go to
  // candidates_, which only grows (the caller's cleared output would be zero-filled when
  // sized ahead, every call); the pairs kept are then copied to the output.
  if (candidates_.size() < 2 * std::size_t{count} + 64)
    candidates_.resize(2 * std::size_t{count} + 64);
  const DenseCells grid{
      boxes.data(), cellOfBox, slotOfBox_.data(), cellStart_.data(), sortedBoxes_.data(),
      count,        stride};
  const std::size_t n = findDenseCandidates(grid, candidates_);
  BoxPair* const out = candidates_.data();
  // Each pair (lower index first) by a conditional move between its word and the word turned
  // by half (its halves swapped): which side of i j is on is random to the predictor (GCC
  // made std::min/max a branch). Only the pairs kept (a pile keeps one candidate in five).
  for (std::size_t k = 0; k < n; ++k) {
    const std::uint64_t word = loadPair(out + k);
    const auto first = static_cast<std::uint32_t>(word >> firstShift);
    const auto second = static_cast<std::uint32_t>(word >> (32 - firstShift));
    storePair(out + k, second < first ? std::rotr(word, 32) : word);
  }
  // (Grown geometrically, as the zero-filled output was: a count of pairs that creeps up must
  // not reallocate the output at every new largest count.)
  if (pairs.size() + n > pairs.capacity())
    pairs.reserve(std::max({pairs.size() + n, 2 * pairs.capacity(), 2 * std::size_t{count} + 64}));
  pairs.insert(pairs.end(), out, out + n);
}

void BroadPhase::findPairsInHashedGrid(std::span<const BoundingBox> boxes,
                                       std::vector<BoxPair>& pairs) {
  const auto count = static_cast<std::uint32_t>(boxes.size());
  const std::uint32_t bucketCount = bucketCountFor(count);
  const std::uint32_t mask = bucketCount - 1;
  for (std::uint32_t i = 0; i < count; ++i)
    if (cellOfBox_[i] != oversizedMark) cellOfBox_[i] = hashCell(cellX_[i], cellY_[i], mask);
  sortByCell(count, bucketCount);

  // Regular pairs. A box can only overlap boxes whose centres lie in the 3 x 3 cells around
  // its own; visiting its own cell (higher indices only) and the four "forward" cells (all
  // boxes) meets every such pair exactly once. A bucket may hold other cells' boxes (hash
  // collisions): the cell coordinates are compared, so nothing is paired twice.
  constexpr std::int64_t forward[4][2] = {{1, -1}, {1, 0}, {1, 1}, {0, 1}};
  for (std::uint32_t i = 0; i < count; ++i) {
    if (cellOfBox_[i] == oversizedMark) continue;
    const std::int64_t x = cellX_[i];
    const std::int64_t y = cellY_[i];
    const std::uint32_t own = cellOfBox_[i];
    for (std::uint32_t k = cellStart_[own]; k < cellStart_[own + 1]; ++k) {
      const std::uint32_t j = sortedBoxes_[k];
      if (j > i && cellX_[j] == x && cellY_[j] == y && boxes[i].overlaps(boxes[j]))
        pairs.push_back({i, j});
    }
    for (const auto& [dx, dy] : forward) {
      const std::uint32_t bucket = hashCell(x + dx, y + dy, mask);
      for (std::uint32_t k = cellStart_[bucket]; k < cellStart_[bucket + 1]; ++k) {
        const std::uint32_t j = sortedBoxes_[k];
        if (cellX_[j] == x + dx && cellY_[j] == y + dy && boxes[i].overlaps(boxes[j]))
          pairs.push_back({std::min(i, j), std::max(i, j)});
      }
    }
  }
}

}  // namespace thyrix
