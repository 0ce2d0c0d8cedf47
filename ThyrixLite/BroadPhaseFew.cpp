/// @file BroadPhaseFew.cpp
/// @brief BroadPhase up to smallCount boxes: every pair, as one bit mask per box.
#include <ThyrixLite/BroadPhase.h>
#include <Tools/ProcessorFeatures.h>

#include <bit>
#include <type_traits>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif
#if defined(THYRIX_AVX_DISPATCH)
#include <immintrin.h>
#endif

namespace thyrix {
namespace {

static_assert(BroadPhase::smallCount <= 64, "few boxes keep their overlaps in 64-bit masks");

/// Bits 0 to count - 1.
std::uint64_t lowBits(std::uint32_t count) {
  return count >= 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << count) - 1;
}

#if defined(__SSE2__)

/// The SSE2 instructions of one precision: two doubles or four floats to a register.
template <class Real>
struct Sse;
template <>
struct Sse<double> {
  using Vector = __m128d;
  static constexpr std::uint32_t lanes = 2;
  static Vector broadcast(double x) { return _mm_set1_pd(x); }
  static Vector load(const double* p) { return _mm_loadu_pd(p); }
  static Vector lessOrEqual(Vector a, Vector b) { return _mm_cmple_pd(a, b); }
  static Vector both(Vector a, Vector b) { return _mm_and_pd(a, b); }
  static int signs(Vector a) { return _mm_movemask_pd(a); }
};
template <>
struct Sse<float> {
  using Vector = __m128;
  static constexpr std::uint32_t lanes = 4;
  static Vector broadcast(float x) { return _mm_set1_ps(x); }
  static Vector load(const float* p) { return _mm_loadu_ps(p); }
  static Vector lessOrEqual(Vector a, Vector b) { return _mm_cmple_ps(a, b); }
  static Vector both(Vector a, Vector b) { return _mm_and_ps(a, b); }
  static int signs(Vector a) { return _mm_movemask_ps(a); }
};

// For each box m of @p moved: bit j of @p rows[m] set when box j of @p count (in @p soa)
// overlaps box m of @p boxes, a register of boxes per instruction (a comparison with NaN is
// false, as in C++). Bits from count on are garbage (padding): the caller masks them.
void overlapRowsSse(const BoundingBox* boxes, std::uint64_t moved, const BoxColumns& soa,
                    std::uint32_t count, std::uint64_t* rows) {
  using S = Sse<real>;
  for (; moved != 0; moved &= moved - 1) {
    const auto m = static_cast<std::uint32_t>(std::countr_zero(moved));
    const auto boxLowerX = S::broadcast(boxes[m].lower.x);
    const auto boxUpperX = S::broadcast(boxes[m].upper.x);
    const auto boxLowerY = S::broadcast(boxes[m].lower.y);
    const auto boxUpperY = S::broadcast(boxes[m].upper.y);
    std::uint64_t row = 0;
    for (std::uint32_t j = 0; j < count; j += S::lanes) {
      auto hit = S::lessOrEqual(boxLowerX, S::load(soa.upperX + j));
      hit = S::both(hit, S::lessOrEqual(S::load(soa.lowerX + j), boxUpperX));
      hit = S::both(hit, S::lessOrEqual(boxLowerY, S::load(soa.upperY + j)));
      hit = S::both(hit, S::lessOrEqual(S::load(soa.lowerY + j), boxUpperY));
      row |= static_cast<std::uint64_t>(S::signs(hit)) << j;
    }
    rows[m] = row;
  }
}
#endif

#if defined(THYRIX_AVX_DISPATCH)
// overlapRowsSse in double with AVX, four boxes per instruction, and with AVX-512, eight, their
// four comparisons chained in a mask register. Comparisons only, ordered (false with NaN, as
// in C++; a <= b written b >= a where b is loaded, so that the load is the comparison's
// operand): the same bits. (Templates: a float build never instantiates them.)
template <class Real>
[[gnu::target("avx")]] void overlapRowsAvx(const BoundingBox* boxes, std::uint64_t moved,
                                           const Real* lowerX, const Real* upperX,
                                           const Real* lowerY, const Real* upperY,
                                           std::uint32_t count, std::uint64_t* rows) {
  for (; moved != 0; moved &= moved - 1) {
    const auto m = static_cast<std::uint32_t>(std::countr_zero(moved));
    const __m256d boxLowerX = _mm256_set1_pd(Real{boxes[m].lower.x});
    const __m256d boxUpperX = _mm256_set1_pd(Real{boxes[m].upper.x});
    const __m256d boxLowerY = _mm256_set1_pd(Real{boxes[m].lower.y});
    const __m256d boxUpperY = _mm256_set1_pd(Real{boxes[m].upper.y});
    std::uint64_t row = 0;
    for (std::size_t j = 0; j < count; j += 4) {
      __m256d hit = _mm256_cmp_pd(boxLowerX, _mm256_loadu_pd(upperX + j), _CMP_LE_OQ);
      hit = _mm256_and_pd(hit, _mm256_cmp_pd(boxUpperX, _mm256_loadu_pd(lowerX + j), _CMP_GE_OQ));
      hit = _mm256_and_pd(hit, _mm256_cmp_pd(boxLowerY, _mm256_loadu_pd(upperY + j), _CMP_LE_OQ));
      hit = _mm256_and_pd(hit, _mm256_cmp_pd(boxUpperY, _mm256_loadu_pd(lowerY + j), _CMP_GE_OQ));
      row |= static_cast<std::uint64_t>(_mm256_movemask_pd(hit)) << j;
    }
    rows[m] = row;
  }
}

template <class Real>
[[gnu::target("avx512f")]] void overlapRowsAvx512(const BoundingBox* boxes, std::uint64_t moved,
                                                  const Real* lowerX, const Real* upperX,
                                                  const Real* lowerY, const Real* upperY,
                                                  std::uint32_t count, std::uint64_t* rows) {
  for (; moved != 0; moved &= moved - 1) {
    const auto m = static_cast<std::uint32_t>(std::countr_zero(moved));
    const __m512d boxLowerX = _mm512_set1_pd(Real{boxes[m].lower.x});
    const __m512d boxUpperX = _mm512_set1_pd(Real{boxes[m].upper.x});
    const __m512d boxLowerY = _mm512_set1_pd(Real{boxes[m].lower.y});
    const __m512d boxUpperY = _mm512_set1_pd(Real{boxes[m].upper.y});
    std::uint64_t row = 0;
    for (std::size_t j = 0; j < count; j += 8) {
      __mmask8 hit = _mm512_cmp_pd_mask(boxLowerX, _mm512_loadu_pd(upperX + j), _CMP_LE_OQ);
      hit = _mm512_mask_cmp_pd_mask(hit, boxUpperX, _mm512_loadu_pd(lowerX + j), _CMP_GE_OQ);
      hit = _mm512_mask_cmp_pd_mask(hit, boxLowerY, _mm512_loadu_pd(upperY + j), _CMP_LE_OQ);
      hit = _mm512_mask_cmp_pd_mask(hit, boxUpperY, _mm512_loadu_pd(lowerY + j), _CMP_GE_OQ);
      row |= static_cast<std::uint64_t>(hit) << j;
    }
    rows[m] = row;
  }
}
#endif

/// For each box m of @p moved, bit j of @p rows[m] set when box j (of @p count, in @p soa)
/// overlaps box m of @p boxes: the same four comparisons as BoundingBox::overlaps, on the
/// corners stored by coordinate, several boxes at a time where the processor allows (the
/// padding of @p soa makes the last vector whole; its bits are garbage, masked by the caller).
/// All moved boxes in one call: one dispatch, and the vector code's entry and exit, a step.
void overlapRows(const BoundingBox* boxes, std::uint64_t moved, const BoxColumns& soa,
                 std::uint32_t count, std::uint64_t* rows) {
#if defined(THYRIX_AVX_DISPATCH)
  if constexpr (std::is_same_v<real, double>) {
    if (processorHasAvx512())
      return overlapRowsAvx512(boxes, moved, soa.lowerX, soa.upperX, soa.lowerY, soa.upperY, count,
                               rows);
    if (processorHasAvx())
      return overlapRowsAvx(boxes, moved, soa.lowerX, soa.upperX, soa.lowerY, soa.upperY, count,
                            rows);
  }
#endif
#if defined(__SSE2__)
  overlapRowsSse(boxes, moved, soa, count, rows);
#else
  for (; moved != 0; moved &= moved - 1) {
    const auto m = static_cast<std::uint32_t>(std::countr_zero(moved));
    const BoundingBox& box = boxes[m];
    std::uint64_t row = 0;
    for (std::uint32_t j = 0; j < count; ++j) {
      const bool hit = (box.lower.x <= soa.upperX[j]) & (soa.lowerX[j] <= box.upper.x) &
                       (box.lower.y <= soa.upperY[j]) & (soa.lowerY[j] <= box.upper.y);
      row |= std::uint64_t{hit} << j;
    }
    rows[m] = row;
  }
#endif
}

/// Bits above @p i.
std::uint64_t above(std::uint32_t i) { return ~std::uint64_t{0} << i << 1; }

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
  if (!remembered) moved = count == 0 ? 0 : ~std::uint64_t{0} >> (64 - count);
  // The corners by coordinate (unmoved boxes are as stored by the last call).
  const std::size_t stride = smallCount + 7;
  const BoxColumns soa{columns_.data(), columns_.data() + stride, columns_.data() + 2 * stride,
                       columns_.data() + 3 * stride};
  for (std::uint64_t bits = moved; bits != 0; bits &= bits - 1) {
    const auto m = static_cast<std::uint32_t>(std::countr_zero(bits));
    soa.lowerX[m] = boxes[m].lower.x;
    soa.upperX[m] = boxes[m].upper.x;
    soa.lowerY[m] = boxes[m].lower.y;
    soa.upperY[m] = boxes[m].upper.y;
  }
  // Only rows that had pairs, moved boxes, and boxes below a moved box that now meets them can
  // change; every other row stays empty.
  std::uint64_t visit = (remembered ? rowsWithPairs_ : 0) | moved;
  overlapRows(boxes.data(), moved, soa, count, movedRows_.data());
  const std::uint64_t inBoxes = lowBits(count);
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

}  // namespace thyrix
