/// @file SimulatorBorderReach.cpp
/// @brief Phase 2's borders: which grid shapes reach behind each border's line, kept as one bit
/// per shape and border and retested only for the shapes that moved (the contacts themselves
/// are made in SimulatorContacts.cpp).
#include <ThyrixLite/Simulator.h>
#include <Tools/ProcessorFeatures.h>

#include <bit>
#include <cstddef>
#include <cstdint>
#include <type_traits>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif
#if defined(THYRIX_AVX_DISPATCH)
#include <immintrin.h>
#endif

namespace thyrix {

namespace {

/// Bits 0 to count - 1 of word @p word of a bit set of @p count bits.
std::uint64_t wordMask(std::size_t word, std::size_t count) {
  const std::size_t rest = count - 64 * word;
  return rest >= 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << rest) - 1;
}

/// A border's line as its reach test reads it.
struct BorderLine {
  Vector2 point;
  Vector2 normal;
  Vector2 absNormal;  // |normal.x|, |normal.y|
};

static_assert(std::is_standard_layout_v<BorderLine> && sizeof(BorderLine) == 6 * sizeof(real),
              "a line is read as an array of six coordinates");

/// The line of a border through @p point with unit @p normal.
BorderLine borderLine(Vector2 point, Vector2 normal) {
  return {point, normal, {std::abs(normal.x), std::abs(normal.y)}};
}

/// Up to this many unmoved borders have their reach updated together (the piles have 3).
constexpr std::size_t fusedBorders = 4;

/// 1 when @p box (margin included) reaches behind @p line, that is, unless it lies entirely
/// on the free side; else 0.
std::uint64_t reachesBehind(const BorderLine& line, Vector2 centre, Vector2 half) {
  const real extent = line.absNormal.x * half.x + line.absNormal.y * half.y;
  return std::uint64_t{dot(centre - line.point, line.normal) - extent <= 0};
}

#if defined(__SSE2__)
/// reachesBehind for the 64 boxes from @p boxes, two at a time (one box per half of a
/// register: the same operations in the same order, so the same bits), ORed into @p reach.
/// (Double only: a float build keeps the plain loop.)
template <std::size_t Borders>
void reachFullWord(const BorderLine* lines, const BoundingBox* boxes, std::uint64_t* reach) {
  static_assert(std::is_standard_layout_v<BoundingBox> && sizeof(BoundingBox) == 4 * sizeof(real),
                "the boxes are read as arrays of four coordinates");
  const auto* const corners = reinterpret_cast<const double*>(boxes);  // lower x, y, upper x, y
  const __m128d half = _mm_set1_pd(0.5);
  const __m128d zero = _mm_setzero_pd();
  std::uint64_t bits[Borders] = {};
  for (std::size_t j = 0; j < 64; j += 2) {
    const double* const a = corners + 4 * j;
    const __m128d lowerA = _mm_loadu_pd(a);
    const __m128d upperA = _mm_loadu_pd(a + 2);
    const __m128d lowerB = _mm_loadu_pd(a + 4);
    const __m128d upperB = _mm_loadu_pd(a + 6);
    const __m128d lowerX = _mm_unpacklo_pd(lowerA, lowerB);
    const __m128d lowerY = _mm_unpackhi_pd(lowerA, lowerB);
    const __m128d upperX = _mm_unpacklo_pd(upperA, upperB);
    const __m128d upperY = _mm_unpackhi_pd(upperA, upperB);
    const __m128d centreX = _mm_mul_pd(_mm_add_pd(lowerX, upperX), half);
    const __m128d centreY = _mm_mul_pd(_mm_add_pd(lowerY, upperY), half);
    const __m128d halfX = _mm_mul_pd(_mm_sub_pd(upperX, lowerX), half);
    const __m128d halfY = _mm_mul_pd(_mm_sub_pd(upperY, lowerY), half);
    for (std::size_t k = 0; k < Borders; ++k) {
      const BorderLine& line = lines[k];
      const __m128d along = _mm_add_pd(
          _mm_mul_pd(_mm_sub_pd(centreX, _mm_set1_pd(line.point.x)), _mm_set1_pd(line.normal.x)),
          _mm_mul_pd(_mm_sub_pd(centreY, _mm_set1_pd(line.point.y)), _mm_set1_pd(line.normal.y)));
      const __m128d extent = _mm_add_pd(_mm_mul_pd(_mm_set1_pd(line.absNormal.x), halfX),
                                        _mm_mul_pd(_mm_set1_pd(line.absNormal.y), halfY));
      const auto hit = static_cast<std::uint64_t>(
          _mm_movemask_pd(_mm_cmple_pd(_mm_sub_pd(along, extent), zero)));
      bits[k] |= hit << j;
    }
  }
  for (std::size_t k = 0; k < Borders; ++k) reach[k] |= bits[k];
}

/// reachesBehind for the boxes of @p retest (from @p boxes), two borders at a time (one border
/// per half of a register: the same operations in the same order, so the same bits), each box
/// read once for all of them and its bit set without a branch, ORed into @p reach.
template <std::size_t Borders>
void reachMovedBoxes(const BorderLine* lines, const BoundingBox* boxes, std::uint64_t retest,
                     std::uint64_t* reach) {
  constexpr std::size_t pairs = (Borders + 1) / 2;
  // The lines by coordinate, borders 2p and 2p + 1 in pair p (an odd count: the last twice).
  __m128d pointX[pairs], pointY[pairs], normalX[pairs], normalY[pairs], absX[pairs], absY[pairs];
  __m128i bits[pairs];
  for (std::size_t p = 0; p < pairs; ++p) {
    // (point x, y, normal x, y, |normal| x, y)
    const auto* const a = reinterpret_cast<const double*>(lines + 2 * p);
    const auto* const b = reinterpret_cast<const double*>(lines + std::min(2 * p + 1, Borders - 1));
    const __m128d pointA = _mm_loadu_pd(a), pointB = _mm_loadu_pd(b);
    const __m128d normalA = _mm_loadu_pd(a + 2), normalB = _mm_loadu_pd(b + 2);
    const __m128d absA = _mm_loadu_pd(a + 4), absB = _mm_loadu_pd(b + 4);
    pointX[p] = _mm_unpacklo_pd(pointA, pointB);
    pointY[p] = _mm_unpackhi_pd(pointA, pointB);
    normalX[p] = _mm_unpacklo_pd(normalA, normalB);
    normalY[p] = _mm_unpackhi_pd(normalA, normalB);
    absX[p] = _mm_unpacklo_pd(absA, absB);
    absY[p] = _mm_unpackhi_pd(absA, absB);
    bits[p] = _mm_setzero_si128();
  }
  const auto* const corners = reinterpret_cast<const double*>(boxes);  // lower x, y, upper x, y
  const __m128d half = _mm_set1_pd(0.5);
  const __m128d zero = _mm_setzero_pd();
  for (std::uint64_t rest = retest; rest != 0; rest &= rest - 1) {
    const double* const box = corners + 4 * static_cast<std::size_t>(std::countr_zero(rest));
    const __m128d lower = _mm_loadu_pd(box);
    const __m128d upper = _mm_loadu_pd(box + 2);
    const __m128d centre = _mm_mul_pd(_mm_add_pd(lower, upper), half);
    const __m128d extents = _mm_mul_pd(_mm_sub_pd(upper, lower), half);
    const __m128d centreX = _mm_unpacklo_pd(centre, centre);
    const __m128d centreY = _mm_unpackhi_pd(centre, centre);
    const __m128d halfX = _mm_unpacklo_pd(extents, extents);
    const __m128d halfY = _mm_unpackhi_pd(extents, extents);
    const __m128i bit = _mm_set1_epi64x(static_cast<long long>(rest & (~rest + 1)));
    for (std::size_t p = 0; p < pairs; ++p) {
      const __m128d along = _mm_add_pd(_mm_mul_pd(_mm_sub_pd(centreX, pointX[p]), normalX[p]),
                                       _mm_mul_pd(_mm_sub_pd(centreY, pointY[p]), normalY[p]));
      const __m128d extent = _mm_add_pd(_mm_mul_pd(absX[p], halfX), _mm_mul_pd(absY[p], halfY));
      const __m128d hit = _mm_cmple_pd(_mm_sub_pd(along, extent), zero);
      bits[p] = _mm_or_si128(bits[p], _mm_and_si128(_mm_castpd_si128(hit), bit));
    }
  }
  std::uint64_t found[2 * pairs];
  for (std::size_t p = 0; p < pairs; ++p)
    _mm_storeu_si128(reinterpret_cast<__m128i*>(found + 2 * p), bits[p]);
  for (std::size_t k = 0; k < Borders; ++k) reach[k] |= found[k];
}
#endif

#if defined(THYRIX_AVX_DISPATCH)
/// findBorderReachTogether with AVX2: the borders (up to fusedBorders) in one register, one per
/// lane (the same operations in the same order as reachesBehind: the same bits), each moved box
/// read once for all of them and its bit set without a branch. @p lines: each border's point
/// and unit normal (x, y, x, y), fusedBorders of them (the last border repeated); @p reach:
/// @p words words a border.
template <class Real>
[[gnu::target("avx2")]] void reachTogetherAvx2(const Real* const* lines, std::size_t borders,
                                               const std::uint64_t* movedBits,
                                               const BoundingBox* boxes, std::uint64_t* reach,
                                               std::size_t words) {
  static_assert(fusedBorders == 4, "a border per lane");
  const auto lane = [lines](std::size_t i) __attribute__((target("avx2"))) {
    return _mm256_set_pd(lines[3][i], lines[2][i], lines[1][i], lines[0][i]);
  };
  const __m256d pointX = lane(0), pointY = lane(1), normalX = lane(2), normalY = lane(3);
  const __m256d noSign = _mm256_castsi256_pd(_mm256_set1_epi64x(0x7fffffffffffffff));
  const __m256d absX = _mm256_and_pd(normalX, noSign), absY = _mm256_and_pd(normalY, noSign);
  const __m256d half = _mm256_set1_pd(0.5);
  const __m256d zero = _mm256_setzero_pd();
  for (std::size_t w = 0; w < words; ++w) {
    const std::uint64_t retest = movedBits[w];
    if (retest == 0) continue;
    const auto* const corners = reinterpret_cast<const Real*>(boxes + 64 * w);
    __m256i bits = _mm256_setzero_si256();
    const auto test = [&](std::size_t j, __m256i bit) __attribute__((target("avx2"))) {
      const Real* const box = corners + 4 * j;  // lower x, y, upper x, y
      const __m256d lowerX = _mm256_broadcast_sd(box), lowerY = _mm256_broadcast_sd(box + 1);
      const __m256d upperX = _mm256_broadcast_sd(box + 2), upperY = _mm256_broadcast_sd(box + 3);
      const __m256d centreX = _mm256_mul_pd(_mm256_add_pd(lowerX, upperX), half);
      const __m256d centreY = _mm256_mul_pd(_mm256_add_pd(lowerY, upperY), half);
      const __m256d halfX = _mm256_mul_pd(_mm256_sub_pd(upperX, lowerX), half);
      const __m256d halfY = _mm256_mul_pd(_mm256_sub_pd(upperY, lowerY), half);
      const __m256d along = _mm256_add_pd(_mm256_mul_pd(_mm256_sub_pd(centreX, pointX), normalX),
                                          _mm256_mul_pd(_mm256_sub_pd(centreY, pointY), normalY));
      const __m256d extent = _mm256_add_pd(_mm256_mul_pd(absX, halfX), _mm256_mul_pd(absY, halfY));
      const __m256d hit = _mm256_cmp_pd(_mm256_sub_pd(along, extent), zero, _CMP_LE_OQ);
      bits = _mm256_or_si256(bits, _mm256_and_si256(_mm256_castpd_si256(hit), bit));
    };
    if (retest == ~std::uint64_t{0}) {  // a crowd in motion: every box, no walk over the bits
      __m256i bit = _mm256_set1_epi64x(1);
      for (std::size_t j = 0; j < 64; ++j) {
        test(j, bit);
        bit = _mm256_add_epi64(bit, bit);
      }
    } else {
      for (std::uint64_t rest = retest; rest != 0; rest &= rest - 1)
        test(static_cast<std::size_t>(std::countr_zero(rest)),
             _mm256_set1_epi64x(static_cast<long long>(rest & (~rest + 1))));
    }
    alignas(32) std::uint64_t found[fusedBorders];
    _mm256_store_si256(reinterpret_cast<__m256i*>(found), bits);
    for (std::size_t k = 0; k < borders; ++k) {
      std::uint64_t& word = reach[k * words + w];
      word = (word & ~retest) | found[k];
    }
  }
}
#endif

/// Sets in @p reach (one word per border of @p lines) the bits of @p retest whose boxes (from
/// @p boxes, the word's first) reach behind each border. A whole word of moved shapes (a crowd
/// in motion) is tested without the walk over its bits, in double two boxes at a time with SSE2
/// (reachFullWord); the moved boxes of a word, for several borders, two borders at a time with
/// SSE2 (reachMovedBoxes); otherwise plain loops.
template <std::size_t Borders>
void reachWord(const BorderLine* lines, const BoundingBox* boxes, std::uint64_t retest,
               std::uint64_t* reach) {
  const auto test = [&](std::size_t j, std::uint64_t bit) {
    const BoundingBox& box = boxes[j];
    const Vector2 centre = (box.lower + box.upper) * real(0.5);
    const Vector2 half = (box.upper - box.lower) * real(0.5);
    for (std::size_t k = 0; k < Borders; ++k)
      reach[k] |= bit & (std::uint64_t{0} - reachesBehind(lines[k], centre, half));
  };
  if (retest == ~std::uint64_t{0}) {
#if defined(__SSE2__)
    if constexpr (std::is_same_v<real, double>) {
      reachFullWord<Borders>(lines, boxes, reach);
      return;
    }
#endif
    for (std::size_t j = 0; j < 64; ++j) test(j, std::uint64_t{1} << j);
    return;
  }
#if defined(__SSE2__)
  if constexpr (std::is_same_v<real, double> && Borders > 1) {
    reachMovedBoxes<Borders>(lines, boxes, retest, reach);
    return;
  }
#endif
  for (std::uint64_t bits = retest; bits != 0; bits &= bits - 1)
    test(static_cast<std::size_t>(std::countr_zero(bits)), bits & (~bits + 1));
}

}  // namespace

void Simulator::findBorderReach(std::size_t k, std::size_t words, bool borderMoved) {
  const std::uint32_t border = borderShapes_[k];
  const BorderLine line = borderLine(geometry_[border].p0, geometry_[border].p1);
  const std::size_t count = gridShapes_.size();
  for (std::size_t w = 0; w < words; ++w) {
    const std::uint64_t retest = borderMoved ? wordMask(w, count) : gridMovedBits_[w];
    std::uint64_t& reach = borderReach_[k * words + w];
    reach &= ~retest;
    reachWord<1>(&line, gridBoxes_.data() + 64 * w, retest, &reach);
  }
}

bool Simulator::findBorderReachTogether(std::size_t words) {
  // The common case of a crowd, borders that stay: every border retests the moved shapes, so
  // each moved shape's box is read once for all of them (and the bits are set without a
  // branch). The same test as findBorderReach: the same bits. (A world of up to 64 shapes
  // too: tested together, the arena's four borders take half the instructions of four walks,
  // without more mispredicted branches as callgrind simulates them.)
  const std::size_t borders = borderShapes_.size();
  if (borders == 0) return true;  // nothing to reach
  if (borders > fusedBorders) return false;
#if defined(THYRIX_AVX_DISPATCH)
  if constexpr (std::is_same_v<real, double>) {
    if (processorHasAvx2()) {
      static_assert(std::is_standard_layout_v<ShapeGeometry> &&
                        offsetof(ShapeGeometry, p1) == 2 * sizeof(real),
                    "a border's point and normal are read as four coordinates");
      const std::uint32_t* const borderShapes = borderShapes_.data();
      const std::uint8_t* const shapeMoved = shapeMoved_.data();
      const ShapeGeometry* const geometry = geometry_.data();
      const real* lines[fusedBorders];
      for (std::size_t k = 0; k < borders; ++k) {
        const std::uint32_t border = borderShapes[k];
        if (shapeMoved[border] != 0) return false;
        lines[k] = reinterpret_cast<const real*>(geometry + border);
      }
      for (std::size_t k = borders; k < fusedBorders; ++k) lines[k] = lines[borders - 1];
      reachTogetherAvx2(lines, borders, gridMovedBits_.data(), gridBoxes_.data(),
                        borderReach_.data(), words);
      return true;
    }
  }
#endif
  for (std::size_t k = 0; k < borders; ++k)
    if (shapeMoved_[borderShapes_[k]] != 0) return false;
  BorderLine lines[fusedBorders];
  for (std::size_t k = 0; k < borders; ++k) {
    const std::uint32_t border = borderShapes_[k];
    lines[k] = borderLine(geometry_[border].p0, geometry_[border].p1);
  }
  for (std::size_t w = 0; w < words; ++w) {
    const std::uint64_t retest = gridMovedBits_[w];
    if (retest == 0) continue;
    std::uint64_t reach[fusedBorders] = {};
    for (std::size_t k = 0; k < borders; ++k) reach[k] = borderReach_[k * words + w] & ~retest;
    const BoundingBox* const boxes = gridBoxes_.data() + 64 * w;
    static_assert(fusedBorders == 4, "a case per border count");
    switch (borders) {
      case 1:
        reachWord<1>(lines, boxes, retest, reach);
        break;
      case 2:
        reachWord<2>(lines, boxes, retest, reach);
        break;
      case 3:
        reachWord<3>(lines, boxes, retest, reach);
        break;
      default:  // fusedBorders
        reachWord<4>(lines, boxes, retest, reach);
        break;
    }
    for (std::size_t k = 0; k < borders; ++k) borderReach_[k * words + w] = reach[k];
  }
  return true;
}

}  // namespace thyrix
