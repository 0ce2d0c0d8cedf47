/// @file SimulatorBorderReach.cpp
/// @brief Phase 2's borders: which grid shapes reach behind each border's line, kept as one bit
/// per shape and border and retested only for the shapes that moved (the contacts themselves
/// are made in SimulatorContacts.cpp).
#include <ThyrixLite/Simulator.h>
#include <Tools/Wide.h>

#include <algorithm>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <type_traits>

namespace thyrix {

namespace {

/// Bits 0 to count - 1 of word @p word of a bit set of @p count bits.
std::uint64_t wordMask(std::size_t word, std::size_t count) {
  const std::size_t rest = count - 64 * word;
  return rest >= 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << rest) - 1;
}

/// Up to this many unmoved borders have their reach updated together (the piles have 3).
constexpr std::size_t fusedBorders = 4;

/// Slots of BorderLines: a whole register of the widest kind a kernel runs (8 floats in AVX2).
constexpr std::size_t lineSlots = 8;

/// The lines of up to fusedBorders borders by coordinate, each through its point with its unit
/// normal; the slots past the last border repeat it (whole registers of borders).
struct BorderLines {
  real pointX[lineSlots];
  real pointY[lineSlots];
  real normalX[lineSlots];
  real normalY[lineSlots];
};

/// Sets the line of border @p k of @p lines, and of the slots after it, through @p point with
/// unit @p normal.
void setLine(BorderLines& lines, std::size_t k, Vector2 point, Vector2 normal) {
  for (std::size_t slot = k; slot < lineSlots; ++slot) {
    lines.pointX[slot] = point.x;
    lines.pointY[slot] = point.y;
    lines.normalX[slot] = normal.x;
    lines.normalY[slot] = normal.y;
  }
}

/// Sets in @p reach (one word per border of @p lines) the bits of @p retest whose boxes (from
/// @p boxes, the word's first) reach behind each border, that is, unless the box (margin
/// included) lies entirely on the border's free side. The borders go in the lanes of a
/// register (the last repeated to fill it), so each box is read once for all of them and its
/// bits set without a branch; a whole word of moved shapes (a crowd in motion) is tested
/// without the walk over its bits.
template <std::size_t Borders, class W = simd::Native<real>>
void reachWord(const BorderLines& lines, const BoundingBox* boxes, std::uint64_t retest,
               std::uint64_t* reach) {
  constexpr std::size_t lanes = W::lanes;
  constexpr std::size_t groups = (Borders + lanes - 1) / lanes;
  static_assert(groups * lanes <= lineSlots, "the lines fill whole registers");
  W pointX[groups], pointY[groups], normalX[groups], normalY[groups], absX[groups], absY[groups];
  for (std::size_t g = 0; g < groups; ++g) {
    pointX[g] = W::load(lines.pointX + g * lanes);
    pointY[g] = W::load(lines.pointY + g * lanes);
    normalX[g] = W::load(lines.normalX + g * lanes);
    normalY[g] = W::load(lines.normalY + g * lanes);
    absX[g] = abs(normalX[g]);
    absY[g] = abs(normalY[g]);
  }
  const W half = W::broadcast(real(0.5));
  const W zero = W::broadcast(real(0));
  using Bits = simd::Words<real, lanes>;
  Bits bits[groups];
  for (std::size_t g = 0; g < groups; ++g) bits[g] = Bits::broadcast(0);
  // Box j's bit @p bit set in the lanes of the borders it reaches behind.
  const auto test = [&](std::size_t j, Bits bit) {
    const BoundingBox& box = boxes[j];
    const W lowerX = W::broadcast(box.lower.x), lowerY = W::broadcast(box.lower.y);
    const W upperX = W::broadcast(box.upper.x), upperY = W::broadcast(box.upper.y);
    const W centreX = (lowerX + upperX) * half, centreY = (lowerY + upperY) * half;
    const W halfX = (upperX - lowerX) * half, halfY = (upperY - lowerY) * half;
    for (std::size_t g = 0; g < groups; ++g) {
      // dot(centre - point, normal) - extent <= 0, the extent along the normal.
      const W along = (centreX - pointX[g]) * normalX[g] + (centreY - pointY[g]) * normalY[g];
      const W extent = absX[g] * halfX + absY[g] * halfY;
      bits[g] = bits[g] | select(lessOrEqual(along - extent, zero), bit);
    }
  };
  if (retest == ~std::uint64_t{0}) {
    Bits bit = Bits::broadcast(1);
    for (std::size_t j = 0; j < 64; ++j) {
      test(j, bit);
      bit = bit + bit;
    }
  } else {
    for (std::uint64_t rest = retest; rest != 0; rest &= rest - 1)
      test(static_cast<std::size_t>(std::countr_zero(rest)), Bits::broadcast(rest & (~rest + 1)));
  }
  std::uint64_t found[groups * lanes];
  for (std::size_t g = 0; g < groups; ++g) bits[g].store(found + g * lanes);
  for (std::size_t k = 0; k < Borders; ++k) reach[k] |= found[k];
}

/// findBorderReachTogether()'s loop over the words of @p movedBits, for @p borders borders
/// (at most fusedBorders) of @p lines, in registers of @p W.
template <class W>
void reachTogether(const BorderLines& lines, std::size_t borders, const std::uint64_t* movedBits,
                   const BoundingBox* gridBoxes, std::uint64_t* borderReach, std::size_t words) {
  for (std::size_t w = 0; w < words; ++w) {
    const std::uint64_t retest = movedBits[w];
    if (retest == 0) continue;
    std::uint64_t reach[fusedBorders] = {};
    for (std::size_t k = 0; k < borders; ++k) reach[k] = borderReach[k * words + w] & ~retest;
    const BoundingBox* const boxes = gridBoxes + 64 * w;
    static_assert(fusedBorders == 4, "a case per border count");
    switch (borders) {
      case 1:
        reachWord<1, W>(lines, boxes, retest, reach);
        break;
      case 2:
        reachWord<2, W>(lines, boxes, retest, reach);
        break;
      case 3:
        reachWord<3, W>(lines, boxes, retest, reach);
        break;
      default:  // fusedBorders
        reachWord<4, W>(lines, boxes, retest, reach);
        break;
    }
    for (std::size_t k = 0; k < borders; ++k) borderReach[k * words + w] = reach[k];
  }
}

#if defined(THYRIX_SIMD_AVX2_DISPATCH)
/// reachTogether() in AVX2 registers: four borders (an arena's) in one.
THYRIX_SIMD_AVX2_KERNEL void reachTogetherAvx2(const BorderLines& lines, std::size_t borders,
                                               const std::uint64_t* movedBits,
                                               const BoundingBox* gridBoxes,
                                               std::uint64_t* borderReach, std::size_t words) {
  reachTogether<simd::Avx2<real>>(lines, borders, movedBits, gridBoxes, borderReach, words);
}
#endif

}  // namespace

void Simulator::findBorderReach(std::size_t k, std::size_t words, bool borderMoved) {
  const std::uint32_t border = borderShapes_[k];
  BorderLines line;
  setLine(line, 0, geometry_[border].p0, geometry_[border].p1);
  const std::size_t count = gridShapes_.size();
  for (std::size_t w = 0; w < words; ++w) {
    const std::uint64_t retest = borderMoved ? wordMask(w, count) : gridMovedBits_[w];
    std::uint64_t& reach = borderReach_[k * words + w];
    reach &= ~retest;
    reachWord<1>(line, gridBoxes_.data() + 64 * w, retest, &reach);
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
  for (std::size_t k = 0; k < borders; ++k)
    if (shapeMoved_[borderShapes_[k]] != 0) return false;
  BorderLines lines;
  for (std::size_t k = 0; k < borders; ++k) {
    const std::uint32_t border = borderShapes_[k];
    setLine(lines, k, geometry_[border].p0, geometry_[border].p1);
  }
#if defined(THYRIX_SIMD_AVX2_DISPATCH)
  if (processorHasAvx2()) {
    reachTogetherAvx2(lines, borders, gridMovedBits_.data(), gridBoxes_.data(), borderReach_.data(),
                      words);
    return true;
  }
#endif
  reachTogether<simd::Native<real>>(lines, borders, gridMovedBits_.data(), gridBoxes_.data(),
                                    borderReach_.data(), words);
  return true;
}

}  // namespace thyrix
