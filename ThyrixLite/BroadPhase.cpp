/// @file BroadPhase.cpp
/// @brief BroadPhase above smallCount boxes: the sweep or the grid (dense or hashed).
#include <ThyrixLite/BroadPhase.h>
#include <Tools/Inlining.h>
#include <Tools/ProcessorFeatures.h>

#include <algorithm>
#include <bit>
#include <cstring>
#include <type_traits>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif
#if defined(THYRIX_AVX_DISPATCH)
#include <immintrin.h>
#endif

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
#if defined(__SSE2__) && (defined(__x86_64__) || defined(_M_X64))
  // The instruction the cast compiles to, whose result out of range is defined: the least
  // std::int64_t (a pile pays nothing for the range test).
  std::int64_t t;
  if constexpr (std::is_same_v<real, double>)
    t = _mm_cvttsd_si64(_mm_set_sd(q));
  else  // (the cast is a no-op in float; Clang checks this branch in double builds too)
    t = _mm_cvttss_si64(_mm_set_ss(static_cast<float>(q)));
#else
  constexpr real bound = 0x1p63;  // (exact in float and double)
  if (!(q >= -bound && q < bound)) return INT64_MIN;
  const auto t = static_cast<std::int64_t>(q);
#endif
  // (Unsigned: q just below the least std::int64_t gives the greatest, out of cellLimit.)
  return static_cast<std::int64_t>(static_cast<std::uint64_t>(t) -
                                   std::uint64_t{static_cast<real>(t) > q});
}

/// Whether @p q, a centre in cells, lies in the cells of regular boxes (see cellLimit).
bool inCellRange(Vector2 q) {
  constexpr auto bound = static_cast<real>(cellLimit);  // (exact: a power of two)
  return q.x >= -bound && q.x < bound && q.y >= -bound && q.y < bound;
}

/// The centre of @p box in cells of side @p cellSize. (A template, as gatherExtents: a float
/// build never instantiates the double branch, whose conversions it warned about.)
template <class Real>
Vector2 centreInCells(const BoundingBox& box, Real cellSize) {
#if defined(__SSE2__)
  if constexpr (std::is_same_v<Real, double>) {
    // x and y in one register: one addition, multiplication and division for both (GCC made
    // two of each), the same operations on the same values.
    const auto* const corners = reinterpret_cast<const Real*>(&box);
    const __m128d q = _mm_div_pd(
        _mm_mul_pd(_mm_add_pd(_mm_loadu_pd(corners), _mm_loadu_pd(corners + 2)), _mm_set1_pd(0.5)),
        _mm_set1_pd(cellSize));
    // (The casts change nothing in double; clang checks this branch in a float build too.)
    return {static_cast<real>(_mm_cvtsd_f64(q)),
            static_cast<real>(_mm_cvtsd_f64(_mm_unpackhi_pd(q, q)))};
  }
#endif
  return (box.lower + box.upper) * real(0.5) / cellSize;
}

/// Adds every box of @p boxes, in index order, to @p extents (the sweep's) and, with
/// @p forGrid, to the sum @p extentSum and the largest @p maxExtent of their extents (the
/// grid's, see extent()). A template: a float build never instantiates the double branch.
template <class Real, bool forGrid>
void gatherExtents(std::span<const BoundingBox> boxes, SweepAndPrune::Extents& extents,
                   Real& extentSum, Real& maxExtent) {
#if defined(__SSE2__)
  if constexpr (std::is_same_v<Real, double>) {
    // A box's x and y in the two halves of a register (a pile's boxes in every step): the
    // same operations in the same order, so the same bits. std::min(a, b) is `b < a ? b : a`,
    // which is MINPD(b, a), and std::max(a, b) is `a < b ? b : a`, MAXPD(b, a); the extent,
    // std::max(x side, y side), is MAXSD(y side, x side).
    static_assert(std::is_standard_layout_v<BoundingBox> && sizeof(BoundingBox) == 4 * sizeof(real),
                  "a box is read as its four coordinates");
    __m128d sums = _mm_set_pd(extents.sumY, extents.sumX);
    __m128d low = _mm_set_pd(extents.lowY, extents.lowX);
    __m128d high = _mm_set_pd(extents.highY, extents.highX);
    __m128d sum = _mm_set_sd(extentSum);
    __m128d most = _mm_set_sd(maxExtent);
    for (const BoundingBox& box : boxes) {
      const auto* const corners = reinterpret_cast<const Real*>(&box);
      const __m128d lower = _mm_loadu_pd(corners);
      const __m128d upper = _mm_loadu_pd(corners + 2);
      const __m128d sides = _mm_sub_pd(upper, lower);
      sums = _mm_add_pd(sums, sides);
      low = _mm_min_pd(lower, low);
      high = _mm_max_pd(upper, high);
      if constexpr (forGrid) {
        const __m128d side = _mm_max_sd(_mm_unpackhi_pd(sides, sides), sides);
        sum = _mm_add_sd(sum, side);
        most = _mm_max_sd(side, most);
      }
    }
    // (The casts change nothing in double; clang checks this branch in a float build too.)
    extents.sumX = static_cast<real>(_mm_cvtsd_f64(sums));
    extents.sumY = static_cast<real>(_mm_cvtsd_f64(_mm_unpackhi_pd(sums, sums)));
    extents.lowX = static_cast<real>(_mm_cvtsd_f64(low));
    extents.lowY = static_cast<real>(_mm_cvtsd_f64(_mm_unpackhi_pd(low, low)));
    extents.highX = static_cast<real>(_mm_cvtsd_f64(high));
    extents.highY = static_cast<real>(_mm_cvtsd_f64(_mm_unpackhi_pd(high, high)));
    extentSum = _mm_cvtsd_f64(sum);
    maxExtent = _mm_cvtsd_f64(most);
    return;
  }
#endif
  for (const BoundingBox& box : boxes) {
    extents.add(box);
    if constexpr (forGrid) {
      extentSum += extent(box);
      maxExtent = std::max(maxExtent, extent(box));
    }
  }
}

#if defined(THYRIX_AVX_DISPATCH)
/// gatherExtents() in VEX form, chosen at run time: the same operations, so the same bits,
/// without SSE2's register copies (3 of the sweep's 12 instructions a box).
template <class Real, bool forGrid>
[[gnu::target("avx")]] void gatherExtentsAvx(std::span<const BoundingBox> boxes,
                                             SweepAndPrune::Extents& extents, Real& extentSum,
                                             Real& maxExtent) {
  gatherExtents<Real, forGrid>(boxes, extents, extentSum, maxExtent);
}
#endif

/// gatherExtents(), in its AVX copy where the processor has it.
template <class Real, bool forGrid>
void gatherExtentsFast(std::span<const BoundingBox> boxes, SweepAndPrune::Extents& extents,
                       Real& extentSum, Real& maxExtent) {
#if defined(THYRIX_AVX_DISPATCH)
  if (processorHasAvx()) {
    gatherExtentsAvx<Real, forGrid>(boxes, extents, extentSum, maxExtent);
    return;
  }
#endif
  gatherExtents<Real, forGrid>(boxes, extents, extentSum, maxExtent);
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
    gatherExtentsFast<real, true>(boxes, extents, extentSum, maxExtent);
  else if (gathered != nullptr)  // (the caller's: the same sums)
    extents = *gathered;
  else
    gatherExtentsFast<real, false>(boxes, extents, extentSum, maxExtent);
  lastTookGrid_ = false;
  if (allowSweep && sweep_.findPairs(boxes, extents, sweepTestsPerBox, pairs)) return;
  if (!gridExpected)
    for (const BoundingBox& box : boxes) addGridExtent(box);
  lastTookGrid_ = true;
  findPairsInGrid(boxes, extentSum, maxExtent, pairs);
}

namespace {

/// BoundingBox::overlaps of one box against others, as 1 or 0 without a branch (whether
/// candidates of a grid overlap is random to the branch predictor).
template <class Real>
class OverlapTest {
 public:
  explicit OverlapTest(const BoundingBox& box) : box_(box) {}
  std::size_t operator()(const BoundingBox& o) const {
    return static_cast<std::size_t>((box_.lower.x <= o.upper.x) & (o.lower.x <= box_.upper.x) &
                                    (box_.lower.y <= o.upper.y) & (o.lower.y <= box_.upper.y));
  }

 private:
  BoundingBox box_;
};

#if defined(__SSE2__)
// The same comparisons two or four at a time: lower corners against upper corners (a
// comparison with NaN is false, as in C++). A box is its corners' coordinates in a row.
template <>
class OverlapTest<double> {
 public:
  explicit OverlapTest(const BoundingBox& box)
      : lower_(_mm_loadu_pd(row(box))), upper_(_mm_loadu_pd(row(box) + 2)) {}
  std::size_t operator()(const BoundingBox& o) const {
    const __m128d hit = _mm_and_pd(_mm_cmple_pd(lower_, _mm_loadu_pd(row(o) + 2)),
                                   _mm_cmple_pd(_mm_loadu_pd(row(o)), upper_));
    // 1 for both lanes' bits (3), else 0: an add and a shift (not a compare and a widening).
    return (static_cast<std::uint32_t>(_mm_movemask_pd(hit)) + 1) >> 2;
  }

 private:
  static const double* row(const BoundingBox& box) { return reinterpret_cast<const double*>(&box); }
  __m128d lower_;
  __m128d upper_;
};

template <>
class OverlapTest<float> {
 public:
  explicit OverlapTest(const BoundingBox& box)
      : box_(_mm_loadu_ps(reinterpret_cast<const float*>(&box))) {}
  std::size_t operator()(const BoundingBox& o) const {
    const __m128 other = _mm_loadu_ps(reinterpret_cast<const float*>(&o));
    // (box lower x, y, other lower x, y) <= (other upper x, y, box upper x, y)
    const __m128 hit = _mm_cmple_ps(_mm_movelh_ps(box_, other), _mm_movehl_ps(box_, other));
    return (static_cast<std::uint32_t>(_mm_movemask_ps(hit)) + 1) >> 4;  // 1 for 15, else 0
  }

 private:
  __m128 box_;
};
#endif

#if defined(THYRIX_AVX_DISPATCH)
/// OverlapTest<double> for the AVX copy of the dense grid's loop: the four comparisons in one
/// register, the other box's corners (lower x, lower y, -upper x, -upper y) against this box's
/// (upper x, upper y, -lower x, -lower y): -upper <= -lower is lower <= upper (a negation is
/// exact, and a NaN stays NaN, which compares false). Only double is instantiated.
template <class Real>
class OverlapTestAvx {
 public:
  [[gnu::target("avx")]] explicit OverlapTestAvx(const BoundingBox& box)
      : signs_(_mm256_setr_pd(0.0, 0.0, -0.0, -0.0)),
        reference_(_mm256_xor_pd(_mm256_permute2f128_pd(load(box), load(box), 0x01), signs_)) {}
  [[gnu::target("avx")]] std::size_t operator()(const BoundingBox& o) const {
    const __m256d hit = _mm256_cmp_pd(_mm256_xor_pd(load(o), signs_), reference_, _CMP_LE_OS);
    return (static_cast<std::uint32_t>(_mm256_movemask_pd(hit)) + 1) >> 4;  // 1 for 15, else 0
  }

 private:
  static_assert(std::is_same_v<Real, double> && sizeof(BoundingBox) == 4 * sizeof(Real),
                "a box is read as its four coordinates in one register");
  [[gnu::target("avx")]] static __m256d load(const BoundingBox& box) {
    return _mm256_loadu_pd(reinterpret_cast<const Real*>(&box));
  }
  __m256d signs_;
  __m256d reference_;
};
#endif

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
/// every candidate of the box at hand, grown when needed) and kept when @p Test says the boxes
/// overlap; @return the number kept. Each pair comes as (other, box): the caller puts every
/// pair in order. The visiting order: for each box by index, its own cell (higher indices:
/// those after the box itself, as a cell lists its boxes by index), then the cells (x+1, y-1),
/// (x+1, y), (x+1, y+1), then (x, y+1), each by increasing index.
/// Whether a candidate overlaps is random to the branch predictor: the pair is kept (the end
/// advanced) without a branch.
template <class Test>
THYRIX_ALWAYS_INLINE std::size_t findDenseCandidates(const DenseCells& grid,
                                                     std::vector<BoxPair>& candidates) {
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
    const Test overlaps(boxes[i]);
    // (j, i): the box's half of the word is made once, and each candidate's is its index.
    const std::uint64_t boxHalf = pairWord(0, i);
    // The three ranges of the sorted boxes, each loop written out: a loop over the ranges
    // kept them on the stack, and a lambda, compiled for the default target, called the AVX
    // test instead of inlining it.
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

#if defined(THYRIX_AVX_DISPATCH)
/// findDenseCandidates compiled for AVX: the overlap test in one register (OverlapTestAvx),
/// and none of SSE2's register copies (18 instructions a candidate in SSE2, 14 here). The
/// same comparisons: the same pairs.
template <class Real>
[[gnu::target("avx")]] std::size_t findDenseCandidatesAvx(const DenseCells& grid,
                                                          std::vector<BoxPair>& candidates) {
  return findDenseCandidates<OverlapTestAvx<Real>>(grid, candidates);
}
#endif

/// findDenseCandidates, in AVX where the processor has it (double only). A template on the
/// real type, so that a float build never instantiates the AVX copy.
template <class Real>
std::size_t findDenseCandidatesOf(const DenseCells& grid, std::vector<BoxPair>& candidates) {
#if defined(THYRIX_AVX_DISPATCH)
  if constexpr (std::is_same_v<Real, double>)
    if (processorHasAvx()) return findDenseCandidatesAvx<Real>(grid, candidates);
#endif
  return findDenseCandidates<OverlapTest<Real>>(grid, candidates);
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
      const Vector2 q = centreInCells<real>(box, cellSize);
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
  const std::size_t n = findDenseCandidatesOf<real>(grid, candidates_);
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
