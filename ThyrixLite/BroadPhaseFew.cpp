/// @file BroadPhaseFew.cpp
/// @brief BroadPhase's incremental paths: up to smallCount boxes, every pair as one bit mask per
/// box; above, when few boxes moved, the moved boxes against every box.
#include <ThyrixLite/BroadPhase.h>
#include <Tools/Inlining.h>
#include <Tools/Wide.h>

#include <algorithm>
#include <bit>
#include <type_traits>

namespace thyrix {
namespace {

static_assert(BroadPhase::smallCount <= 64, "few boxes keep their overlaps in 64-bit masks");

/// An unsigned integer of a real's size, to compare reals bit for bit.
using Bits = std::conditional_t<sizeof(real) == 8, std::uint64_t, std::uint32_t>;

/// Bits 0 to count - 1.
std::uint64_t lowBits(std::uint32_t count) {
  return count >= 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << count) - 1;
}

/// The moved boxes of at most 64 (one word of bits), in increasing index m, each with its row:
/// one word, at `rows + m` (the few-box path).
class FewMovedRows {
 public:
  /// Whether a row is one word (at most 64 boxes).
  static constexpr bool oneWord = true;
  FewMovedRows(std::uint64_t moved, std::uint64_t* rows) : bits_(moved), rows_(rows) {}
  /// The next moved box @p m and its row @p row; false when there is none.
  THYRIX_ALWAYS_INLINE bool next(std::uint32_t& m, std::uint64_t*& row) {
    if (bits_ == 0) return false;
    m = static_cast<std::uint32_t>(std::countr_zero(bits_));
    bits_ &= bits_ - 1;
    row = rows_ + m;
    return true;
  }

 private:
  std::uint64_t bits_;
  std::uint64_t* rows_;
};

/// The moved boxes of many (bit m % 64 of word m / 64), in increasing m, each with its row of
/// `words` words: the k-th moved box's (k from 0) at `rows + k * words`.
class ManyMovedRows {
 public:
  static constexpr bool oneWord = false;
  ManyMovedRows(const std::uint64_t* moved, std::size_t words, std::uint64_t* rows)
      : moved_(moved), words_(words), bits_(moved[0]), row_(rows) {}
  THYRIX_ALWAYS_INLINE bool next(std::uint32_t& m, std::uint64_t*& row) {
    while (bits_ == 0) {
      if (++word_ >= words_) return false;
      bits_ = moved_[word_];
    }
    m = static_cast<std::uint32_t>(64 * word_ + static_cast<std::size_t>(std::countr_zero(bits_)));
    bits_ &= bits_ - 1;
    row = row_;
    row_ += words_;
    return true;
  }

 private:
  const std::uint64_t* moved_;
  std::size_t words_;
  std::uint64_t bits_;
  std::size_t word_ = 0;
  std::uint64_t* row_;
};

/// For each moved box m of @p rows (FewMovedRows or ManyMovedRows), bit j % 64 of word j / 64
/// of its row set when box j of @p count overlaps box m of @p boxes: the same four comparisons
/// as BoundingBox::overlaps (false with NaN), on the corners stored by coordinate, a register
/// of boxes at a time (the padding of @p soa, 7 past count, makes the last register whole; its
/// bits are garbage, masked by the caller). A word of 64 boxes at a time: one, for few boxes,
/// so that the compiler keeps no loop over words.
template <class W, class Rows>
void overlapRowsOf(const BoundingBox* boxes, Rows rows, const BoxColumns& soa,
                   std::uint32_t count) {
  std::uint32_t m = 0;
  std::uint64_t* row = nullptr;
  while (rows.next(m, row)) {
    const W boxLowerX = W::broadcast(boxes[m].lower.x);
    const W boxUpperX = W::broadcast(boxes[m].upper.x);
    const W boxLowerY = W::broadcast(boxes[m].lower.y);
    const W boxUpperY = W::broadcast(boxes[m].upper.y);
    for (std::uint32_t base = 0; Rows::oneWord || base < count; base += 64) {
      const std::uint32_t end = Rows::oneWord ? count : std::min(count - base, 64u);
      std::uint64_t word = 0;
      for (std::uint32_t j = 0; j < end; j += W::lanes) {
        const std::uint32_t at = base + j;
        // (lower <= upper written upper >= lower where the lower is loaded: the load is then
        // the comparison's operand.)
        const auto hit = lessOrEqual(boxLowerX, W::load(soa.upperX + at)) &
                         greaterOrEqual(boxUpperX, W::load(soa.lowerX + at)) &
                         lessOrEqual(boxLowerY, W::load(soa.upperY + at)) &
                         greaterOrEqual(boxUpperY, W::load(soa.lowerY + at));
        word |= std::uint64_t{hit.bits()} << j;
      }
      row[base / 64] = word;
      if constexpr (Rows::oneWord) break;
    }
  }
}

#if defined(THYRIX_SIMD_AVX2_DISPATCH)
/// overlapRowsOf() in AVX2 registers, twice SSE2's boxes per comparison.
template <class Rows>
THYRIX_SIMD_AVX2_KERNEL void overlapRowsAvx2(const BoundingBox* boxes, Rows rows,
                                             const BoxColumns& soa, std::uint32_t count) {
  overlapRowsOf<simd::Avx2<real>>(boxes, rows, soa, count);
}

/// overlapRowsOf() in AVX-512 registers, eight doubles per comparison (a crowd in motion
/// spends half its step here). A template on the real type: a float build never instantiates it.
template <class Real, class Rows>
THYRIX_SIMD_AVX512_KERNEL void overlapRowsAvx512(const BoundingBox* boxes, Rows rows,
                                                 const BoxColumns& soa, std::uint32_t count) {
  overlapRowsOf<simd::Wide<Real, 8>>(boxes, rows, soa, count);
}
#endif

/// overlapRowsOf() in the widest registers the processor has.
template <class Rows>
void overlapRows(const BoundingBox* boxes, Rows rows, const BoxColumns& soa, std::uint32_t count) {
#if defined(THYRIX_SIMD_AVX2_DISPATCH)
  if constexpr (sizeof(real) == 8)
    if (processorHasAvx512()) return overlapRowsAvx512<real>(boxes, rows, soa, count);
  if (processorHasAvx2()) return overlapRowsAvx2(boxes, rows, soa, count);
#endif
  overlapRowsOf<simd::Native<real>>(boxes, rows, soa, count);
}

/// Bits above @p i.
std::uint64_t above(std::uint32_t i) { return ~std::uint64_t{0} << i << 1; }

/// Stores the corners of @p box as box @p i of the columns @p soa.
THYRIX_ALWAYS_INLINE void storeCorners(const BoxColumns& soa, std::size_t i,
                                       const BoundingBox& box) {
  soa.lowerX[i] = box.lower.x;
  soa.upperX[i] = box.upper.x;
  soa.lowerY[i] = box.lower.y;
  soa.upperY[i] = box.upper.y;
}

}  // namespace

void BroadPhase::findPairsAmongFew(std::span<const BoundingBox> boxes, std::uint64_t moved,
                                   bool remembered, std::vector<BoxPair>& pairs) {
  const auto count = static_cast<std::uint32_t>(boxes.size());
  if (overlaps_.empty()) {  // the first call, even with no box (columns_ must not be null)
    overlaps_.resize(smallCount);
    movedRows_.resize(smallCount);
    // Padded to whole vectors of eight (the rows mask the padding out).
    columns_.resize(4 * (smallCount + 7));
  }
  // Not remembered: every box moved. (Bits from count on are no box: ignored.)
  const std::uint64_t inBoxes = lowBits(count);
  moved = remembered ? moved & inBoxes : inBoxes;
  // The corners by coordinate (unmoved boxes are as stored by the last call).
  const std::size_t stride = smallCount + 7;
  const BoxColumns soa{columns_.data(), columns_.data() + stride, columns_.data() + 2 * stride,
                       columns_.data() + 3 * stride};
  for (std::uint64_t bits = moved; bits != 0; bits &= bits - 1) {
    const auto m = static_cast<std::uint32_t>(std::countr_zero(bits));
    storeCorners(soa, m, boxes[m]);
  }
  // Only rows that had pairs, moved boxes, and boxes below a moved box that now meets them can
  // change; every other row stays empty.
  std::uint64_t visit = (remembered ? rowsWithPairs_ : 0) | moved;
  overlapRows(boxes.data(), FewMovedRows(moved, movedRows_.data()), soa, count);
  for (std::uint64_t bits = moved; bits != 0; bits &= bits - 1) {
    const auto m = static_cast<std::uint32_t>(std::countr_zero(bits));
    movedRows_[m] &= inBoxes & ~(std::uint64_t{1} << m);
    visit |= movedRows_[m] & ~above(m);
  }
  rowsWithPairs_ = 0;
  for (; visit != 0; visit &= visit - 1) {
    const auto i = static_cast<std::uint32_t>(std::countr_zero(visit));
    std::uint64_t row;
    if ((moved >> i) & 1) {
      row = movedRows_[i] & above(i);
    } else {
      // Unmoved against unmoved: as last time; against the moved boxes above: their rows say.
      row = overlaps_[i] & ~moved;
      for (std::uint64_t m = moved & above(i); m != 0; m &= m - 1) {
        const auto j = static_cast<std::uint32_t>(std::countr_zero(m));
        row |= ((movedRows_[j] >> i) & 1) << j;
      }
    }
    overlaps_[i] = row;
    rowsWithPairs_ |= std::uint64_t{row != 0} << i;
    for (; row != 0; row &= row - 1)
      pairs.push_back({i, static_cast<std::uint32_t>(std::countr_zero(row))});
  }
  rememberedCount_ = count;
}

void BroadPhase::keepPairs(const std::vector<BoxPair>& pairs) {
  // (Grown geometrically, as the caller's pairs: assign() would allocate the exact size each
  // time the pairs grow.)
  if (pairs.size() > keptPairs_.capacity())
    keptPairs_.reserve(std::max(pairs.size(), 2 * keptPairs_.capacity()));
  keptPairs_.assign(pairs.begin(), pairs.end());
}

BoxColumns BroadPhase::manyColumns(std::uint32_t count) {
  const std::size_t stride = std::size_t{count} + 7;  // (padding: whole vectors of eight)
  if (manyColumns_.size() < 4 * stride) manyColumns_.resize(4 * stride);
  real* const columns = manyColumns_.data();
  return {columns, columns + stride, columns + 2 * stride, columns + 3 * stride};
}

void BroadPhase::rememberAll(std::span<const BoundingBox> boxes,
                             const std::vector<BoxPair>& pairs) {
  const auto count = static_cast<std::uint32_t>(boxes.size());
  const BoxColumns soa = manyColumns(count);
  for (std::uint32_t i = 0; i < count; ++i) {
    storeCorners(soa, i, boxes[i]);
  }
  keepPairs(pairs);
  // Room for the rows of as many changed boxes as findPairsAmongMoved() takes.
  const std::size_t words = (std::size_t{count} + 63) / 64;
  if (manyRows_.size() < movedLimit(count) * words) manyRows_.resize(movedLimit(count) * words);
  rememberedCount_ = count;
}

std::uint32_t BroadPhase::findChanged(std::span<const BoundingBox> boxes,
                                      std::span<const std::uint64_t> moved) {
  const auto count = static_cast<std::uint32_t>(boxes.size());
  const std::size_t words = (std::size_t{count} + 63) / 64;
  changed_.assign(words, 0);
  const BoxColumns soa = manyColumns(count);
  const auto difference = [](real a, real b) {
    return std::bit_cast<Bits>(a) ^ std::bit_cast<Bits>(b);
  };
  const std::uint32_t limit = movedLimit(count);
  std::uint32_t changedCount = 0;
  for (std::size_t w = 0; w < words; ++w) {
    std::uint64_t changed = 0;
    // (Bits from count on, in the last word, are no box: ignored.)
    const std::uint64_t flagged =
        w + 1 < words ? moved[w] : moved[w] & lowBits(count - static_cast<std::uint32_t>(64 * w));
    for (std::uint64_t bits = flagged; bits != 0; bits &= bits - 1) {
      const int bit = std::countr_zero(bits);
      const std::size_t m = 64 * w + static_cast<std::size_t>(bit);
      const BoundingBox& box = boxes[m];
      const bool different =
          (difference(box.lower.x, soa.lowerX[m]) | difference(box.upper.x, soa.upperX[m]) |
           difference(box.lower.y, soa.lowerY[m]) | difference(box.upper.y, soa.upperY[m])) != 0;
      changed |= std::uint64_t{different} << bit;
    }
    changed_[w] = changed;
    changedCount += static_cast<std::uint32_t>(std::popcount(changed));
    if (changedCount > limit) break;  // too many: every pair will be tested (a pile)
  }
  return changedCount;
}

void BroadPhase::findPairsAmongMoved(std::span<const BoundingBox> boxes,
                                     std::vector<BoxPair>& pairs) {
  const auto count = static_cast<std::uint32_t>(boxes.size());
  const std::size_t words = (std::size_t{count} + 63) / 64;
  const std::uint64_t* const movedBits = changed_.data();
  // The changed boxes' corners by coordinate (the others' are as the last call left them).
  const BoxColumns soa = manyColumns(count);
  for (std::size_t w = 0; w < words; ++w) {
    for (std::uint64_t bits = movedBits[w]; bits != 0; bits &= bits - 1) {
      const std::size_t m = 64 * w + static_cast<std::size_t>(std::countr_zero(bits));
      storeCorners(soa, m, boxes[m]);
    }
  }
  // The pairs of two unchanged boxes are the last call's, in its order.
  const auto isMoved = [movedBits](std::uint32_t i) { return (movedBits[i / 64] >> (i % 64)) & 1; };
  for (const BoxPair& pair : keptPairs_)
    if ((isMoved(pair.first) | isMoved(pair.second)) == 0) pairs.push_back(pair);
  // Then each changed box against every box: its row, less itself, the padding, and the changed
  // boxes below it (whose rows gave those pairs).
  overlapRows(boxes.data(), ManyMovedRows(movedBits, words, manyRows_.data()), soa, count);
  const std::uint64_t* row = manyRows_.data();
  for (std::size_t w = 0; w < words; ++w) {
    for (std::uint64_t bits = movedBits[w]; bits != 0; bits &= bits - 1, row += words) {
      const auto bit = static_cast<std::uint32_t>(std::countr_zero(bits));
      const auto m = static_cast<std::uint32_t>(64 * w + bit);
      for (std::size_t v = 0; v <= w; ++v) {  // boxes up to m: pairs (j, m)
        std::uint64_t hits = row[v] & ~movedBits[v];
        if (v == w) hits &= ~above(bit);  // (up to m itself, removed as a changed box)
        for (; hits != 0; hits &= hits - 1)
          pairs.push_back({static_cast<std::uint32_t>(64 * v + std::countr_zero(hits)), m});
      }
      for (std::size_t v = w; v < words; ++v) {  // boxes above m: pairs (m, j)
        std::uint64_t hits = row[v] & lowBits(count - static_cast<std::uint32_t>(64 * v));
        if (v == w) hits &= above(bit);
        for (; hits != 0; hits &= hits - 1)
          pairs.push_back({m, static_cast<std::uint32_t>(64 * v + std::countr_zero(hits))});
      }
    }
  }
}

}  // namespace thyrix
