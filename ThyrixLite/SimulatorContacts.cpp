/// @file SimulatorContacts.cpp
/// @brief Phases 2 and 3 of a step: broad and narrow phase, contact indexing (the shapes'
/// geometry is in SimulatorGeometry.cpp).
#include <ThyrixLite/NarrowPhase.h>
#include <ThyrixLite/Simulator.h>
#include <Tools/Inlining.h>
#include <Tools/ProcessorFeatures.h>

#include <algorithm>
#include <bit>
#include <cmath>
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

/// Whether shapes @p a and @p b of one body, whose shapes begin at @p first, may touch: only
/// a multi-body object's may, and only where its filter says (its neighbouring links never do).
bool ownShapesMayTouch(const MultiBodyObject* multi, std::uint32_t first, std::uint32_t a,
                       std::uint32_t b) {
  return multi != nullptr && multi->selfCollision().mayTouch(a - first, b - first);
}

}  // namespace

void Simulator::markNeverPaired(std::uint32_t body) {
  // Bit d - 1 of a grid shape's word: the grid shape d slots later is of the same body and
  // the pair is one detectContacts drops (ownShapesMayTouch), whatever the poses. A body's
  // shapes are consecutive, and so are their grid slots (borders have none).
  const BodyState& state = bodyStates_[body];
  if (state.shapeCount < 2) return;  // no pair of its own (its words, if any, stay 0)
  const std::uint32_t first = state.firstShape;
  const std::uint32_t end = first + state.shapeCount;
  neverPaired_.bits.resize(gridShapes_.size(), 0);
  const MultiBodyObject* const multi = multiBodies_[body];
  if (multi != nullptr && gridSlot_[first] != ~0u && gridSlot_[end - 1] != ~0u &&
      gridSlot_[end - 1] - gridSlot_[first] == end - 1 - first) {
    // Every shape in the grid, in slots as consecutive as the shapes: the filter's own words
    // (what ownShapesMayTouch reads for shapes up to 64 apart), one per shape.
    for (std::uint32_t a = first; a < end; ++a)
      neverPaired_.bits[gridSlot_[a]] = multi->selfCollision().apartAfter(a - first);
    return;
  }
  for (std::uint32_t a = first; a < end; ++a) {
    const std::uint32_t slot = gridSlot_[a];
    if (slot == ~0u) continue;
    std::uint64_t word = 0;
    for (std::uint32_t b = a + 1; b < end; ++b) {
      const std::uint32_t other = gridSlot_[b];
      if (other == ~0u) continue;
      if (other - slot > 64) break;
      if (!ownShapesMayTouch(multi, first, a, b)) word |= std::uint64_t{1} << (other - slot - 1);
    }
    neverPaired_.bits[slot] = word;
  }
}

void Simulator::updateNeverPaired() {
  // Registration only appends: the new objects' bits are added. A multi-body object's rules
  // may be set again (a new stamp): its bits are then marked again.
  NeverPaired& never = neverPaired_;
  for (std::size_t index = never.objects; index < bodyStates_.size(); ++index) {
    const auto body = static_cast<std::uint32_t>(index);
    if (multiBodies_[index] != nullptr)
      never.rules.emplace_back(body, multiBodies_[index]->selfCollision().stamp());
    markNeverPaired(body);
  }
  if (never.objects != bodyStates_.size() && !never.bits.empty())
    never.bits.resize(gridShapes_.size(), 0);  // the shapes added alone pair with any other
  never.objects = bodyStates_.size();
  for (auto& [body, stamp] : never.rules) {
    const std::uint64_t now = multiBodies_[body]->selfCollision().stamp();
    if (now == stamp) continue;
    stamp = now;
    markNeverPaired(body);
  }
}

void Simulator::detectContacts() {
  // Appending to contacts of another detection: this list is no basis for the next reuse.
  const bool fromEmpty = contacts.empty();
  const auto start = static_cast<std::uint32_t>(contacts.size());
  updateGeometry();
  // Reuse needs the last detection's complete list (eraseContacts kept it aside).
  // (Only pairs of unmoved shapes are reused: none when every shape moved.)
  const bool reuse = restSkipping && previousValid_ && fromEmpty;
  previousIndexed_ = false;  // indexed at most once a detection, for the shapes of now
  previousCursor_ = 0;
  previousCount_ = previousContacts_.size();
  reusedBegin_ = 0;  // no run of reused contacts yet
  reusedEnd_ = 0;
  if (pairChains_.size() != shapes_.size()) {  // new shapes: no pair in either list yet
    pairChains_.resize(shapes_.size());
    previousChains_.resize(shapes_.size());
  }
  nextListStamp();
  if (countedObjects_.size() < objects.size() + 1) fitCountedObjects();
  contactsSolved_ = false;  // these contacts, until the solver gives them forces
  statistics_.reusedContacts = 0;
  // (Without new objects or objects with rules, there is nothing to look at.)
  if (neverPaired_.objects != bodyStates_.size() || !neverPaired_.rules.empty())
    updateNeverPaired();
  broadPhase_.setNeverPaired(neverPaired_.bits);
  broadPhase_.findPairs(gridBoxes_, gridMovedBits_, pairs_,
                        gridExtentsCount_ == gridShapes_.size() ? &gridExtents_ : nullptr);
  // The pairs of two circles in reach (most of a crowd's) are batched: their square roots and
  // divisions, in a short loop of their own, overlap from pair to pair (measured: one pair
  // at a time, each waited for the last). A batch is emptied before any other pair adds
  // contacts, so the order is the pairs'.
  CirclePair batch[circleBatch];
  std::size_t batched = 0;
  // (An empty batch is no call: most pairs of a small world at rest find it empty.)
  const auto flush = [&] {
    if (batched == 0) return;
    addCirclePairs(std::span<const CirclePair>(batch, batched));
    batched = 0;
  };
  for (const BoxPair& pair : pairs_) {
    const std::uint32_t a = gridShapes_[pair.first];
    const std::uint32_t b = gridShapes_[pair.second];
    // Pairs within one body are settled here, without a call: a chain's neighbouring links
    // overlap in every step and never touch (the sweep leaves such pairs out already, the
    // few-box test and the grid do not).
    const Shape& sa = shapes_[a];
    const Shape& sb = shapes_[b];
    if (sa.body == sb.body) {
      // Tested whether or not the shapes moved (so is a border's: whether it collides is its
      // object's call).
      if (ownShapesMayTouch(multiBodies_[sa.body], bodyStates_[sa.body].firstShape, a, b)) {
        flush();
        addContacts(a, b);
      }
      continue;
    }
    if (reuse && (shapeMoved_[a] | shapeMoved_[b]) == 0) {
      flush();
      // (Of two bodies: reusePair's shape A is the one addContacts would take first.)
      const bool swap = sb.type < sa.type;
      reusePair(swap ? b : a, swap ? a : b);
    } else if (sa.type == ShapeType::Circle && sb.type == ShapeType::Circle) {
      // Kept (the count advanced) without a branch: which candidates are in reach is random to
      // the predictor.
      batched += std::size_t{circlesInReach(a, b, batch[batched])};
      if (batched == circleBatch) flush();
    } else {
      flush();
      addContacts(a, b);
    }
  }
  flush();
  findBorderContacts(reuse);
  flushReused();
  if (contacts.size() > unchainedContacts) chainFirstPairs(start);
  contactsComplete_ = fromEmpty;
  previousValid_ = false;  // used: the next detection compares against this one
  statistics_.contacts = contacts.size();
  for (const std::uint32_t index : customObjects_) objects[index].updateSensors(*this);
}

namespace {

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
/// (reachFullWord); otherwise a plain loop over its 64 boxes.
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

void Simulator::findBorderContacts(bool reuse) {
  // Borders skip the broad phase: each meets every grid shape whose box reaches behind its
  // line. Which shapes do is kept as one bit per grid shape and border, retested only for
  // moved shapes; then the pairs are visited border by border, shape by shape.
  const std::size_t count = gridShapes_.size();
  const std::size_t words = (count + 63) / 64;
  const bool remembered = restSkipping && reachShapes_ == count;
  reachShapes_ = count;
  borderReach_.resize(borderShapes_.size() * words);
  if (!(remembered && findBorderReachTogether(words))) {
    for (std::size_t k = 0; k < borderShapes_.size(); ++k)
      findBorderReach(k, words, !remembered || shapeMoved_[borderShapes_[k]] != 0);
  }
  // (The words one after another, border by border. A word with no shape in reach, most of a
  // small world's, is passed over before anything is set up for its pairs.)
  const std::uint64_t* reach = borderReach_.data();
  for (const std::uint32_t border : borderShapes_) {
    for (std::size_t first = 0; first < count; first += 64, ++reach)
      if (*reach != 0) addBorderPairs(border, first, *reach, reuse && remembered);
  }
}

// Out of line: findBorderContacts' loop then keeps few values across its calls.
THYRIX_NO_INLINE void Simulator::addBorderPairs(std::uint32_t border, std::size_t first,
                                                std::uint64_t bits, bool reuse) {
  // A pair keeps its contacts if neither the border nor the shape moved.
  const bool reuseBorder = reuse && shapeMoved_[border] == 0;
  const std::uint32_t borderBody = shapes_[border].body;
  for (; bits != 0; bits &= bits - 1) {
    const std::uint32_t shape =
        gridShapes_[first + static_cast<std::size_t>(std::countr_zero(bits))];
    // (The border is shape A: a half-plane comes first. A pair within one body is always
    // tested: whether it collides is its object's call.)
    if (reuseBorder && shapeMoved_[shape] == 0 && shapes_[shape].body != borderBody)
      reusePair(border, shape);
    else
      addContacts(border, shape);
  }
}

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

// Inline: before each batch of contacts appended.
inline Simulator::ContactPair* Simulator::notesFor(std::size_t count) {
  if (count > contactPairs_.size())  // rare: the buffer doubles
    contactPairs_.resize(std::max({count, 2 * contactPairs_.size(), std::size_t{64}}));
  return contactPairs_.data();
}

// Inline: the first contact of every pair appended from position unchainedContacts on is
// chained. (A short list, a small world's, is searched by a scan instead (findPreviousPair);
// its first pairs are chained if it grows longer, at the end of the detection:
// chainFirstPairs().)
inline void Simulator::chainPair(ContactPair* notes, std::uint32_t position, std::uint32_t shapeA) {
  // Without a branch (whether a circle's pair is its first as shape A is random; GCC made
  // the selects a branch): a mask of ones when the chain goes on. A shape's first pair writes
  // its own link (noPair, all ones, as it is).
  PairChain& chain = pairChains_[shapeA];
  const std::uint32_t on = 0u - std::uint32_t{chain.stamp == listStamp_};
  notes[(chain.last & on) | (position & ~on)].nextOfA = position | ~on;
  chain.first = (chain.first & on) | (position & ~on);
  chain.last = position;
  chain.pairsAndRun = (chain.pairsAndRun & on) + 1;
  chain.stamp = listStamp_;
}

// Inline: every contact appended is noted (SimulatorPreviousContacts.cpp reads the notes).
inline void Simulator::noteContactPair(ContactPair* notes, std::uint32_t position,
                                       std::uint32_t shapeA, std::uint32_t shapeB, bool first) {
  // A detection visits each pair once and appends its points one after another: the first
  // point's pair is chained to shape A's last one, or begins its chain.
  notes[position] = {pairKey(shapeA, shapeB), noPair};
  if (first && position >= unchainedContacts) chainPair(notes, position, shapeA);
}

// Inline: every contact appended is counted.
inline void Simulator::countContact(std::uint32_t bodyA, std::uint32_t bodyB) {
  // Each body listed at its first contact without a branch (which contact is a body's first is
  // random to the predictor): written in the next place, which is kept if it was.
  std::uint32_t* const count = objectContactCursor_.data();
  std::uint32_t* const counted = countedObjects_.data();
  counted[countedCount_] = bodyA;
  countedCount_ += std::size_t{count[bodyA]++ == 0};
  counted[countedCount_] = bodyB;
  countedCount_ += std::size_t{count[bodyB]++ == 0};
}

void Simulator::chainFirstPairs(std::uint32_t start) {
  // The pairs chainPair() left out (positions start to unchainedContacts - 1), put at the
  // heads of their chains last first: the chains are then as if each pair had been chained
  // in order.
  ContactPair* const notes = contactPairs_.data();
  const auto end = static_cast<std::uint32_t>(std::min(contacts.size(), unchainedContacts));
  for (std::uint32_t position = end; position-- > start;) {
    if (position > start && notes[position - 1].key == notes[position].key)
      continue;  // not its pair's first contact
    PairChain& chain = pairChains_[notes[position].key >> 32];
    if (chain.stamp == listStamp_) {
      notes[position].nextOfA = chain.first;
      chain.first = position;
      ++chain.pairsAndRun;
    } else {
      chain = {position, position, 1, listStamp_};  // (its link is noPair, as noted)
    }
  }
}

// Out of line: objects registered since (rare); its callers then save no registers for it.
THYRIX_NO_INLINE void Simulator::fitCountedObjects() { countedObjects_.resize(objects.size() + 1); }

void Simulator::resetCounts() {
  for (std::size_t k = 0; k < countedCount_; ++k) objectContactCursor_[countedObjects_[k]] = 0;
  countedCount_ = 0;
  if (countedObjects_.size() < objects.size() + 1) fitCountedObjects();
}

// Inline: the detection loop and the borders' loop call it for every pair at rest.
inline void Simulator::reusePair(std::uint32_t shapeA, std::uint32_t shapeB) {
  // Neither shape moved and its filters did not change: the contacts are last detection's.
  // Pairs at rest come in the last step's order, so their contacts follow one another there:
  // they are appended as a run, when another contact is to follow them (flushReused()).
  const PreviousRange range = previousContactsOf(shapeA, shapeB);
  if (range.begin == range.end) return;  // in reach, not touching
  if (range.begin != reusedEnd_) {
    flushReused();
    reusedBegin_ = range.begin;
  }
  reusedEnd_ = range.end;
}

// Inline: before every other batch of contacts appended (most find no run).
inline void Simulator::flushReused() {
  if (reusedBegin_ != reusedEnd_) appendReused();
}

void Simulator::appendReused() {
  // The run's contacts as they were but for the force (the solver's output, not detection's),
  // counted and noted as if appended one by one.
  const std::uint32_t begin = reusedBegin_;
  const std::uint32_t count = reusedEnd_ - begin;
  reusedBegin_ = reusedEnd_;
  std::vector<GlobalContactInfo>& items = contacts.items_;
  const auto position = static_cast<std::uint32_t>(items.size());
  ContactPair* const notes = notesFor(std::size_t{position} + count);
  const GlobalContactInfo* const from = previousContacts_.data() + begin;
  items.insert(items.end(), from, from + count);
  GlobalContactInfo* const to = items.data() + position;
  const ContactPair* const pairs = previousPairs_.data() + begin;
  for (std::uint32_t i = 0; i < count; ++i) {
    to[i].force = 0;
    countContact(to[i].bodyA, to[i].bodyB);
    const std::uint64_t key = pairs[i].key;
    notes[position + i] = {key, noPair};
    // (The run holds whole pairs: its first contact begins one.)
    if (position + i >= unchainedContacts && (i == 0 || key != pairs[i - 1].key))
      chainPair(notes, position + i, static_cast<std::uint32_t>(key >> 32));
  }
  statistics_.reusedContacts += count;
}

// Inline: appendContacts and the circle batches store every contact through it.
inline void Simulator::appendContact(std::uint32_t shapeA, std::uint32_t shapeB,
                                     const ManifoldPoint& p, Vector2 normal) {
  const Shape& a = shapes_[shapeA];
  const Shape& b = shapes_[shapeB];
  contacts.items_.push_back({a.object, b.object, a.primitive, b.primitive, a.body, b.body, shapeA,
                             shapeB, p.feature, 0, p.point, normal, p.depth});
  countContact(a.body, b.body);
}

// Inline: the narrow phase calls it for every pair in reach.
inline void Simulator::appendContacts(std::uint32_t shapeA, std::uint32_t shapeB,
                                      const Manifold& manifold) {
  flushReused();  // (the reused contacts before it come first)
  const auto position = static_cast<std::uint32_t>(contacts.items_.size());
  const auto count = static_cast<std::uint32_t>(manifold.count);
  ContactPair* const notes = notesFor(std::size_t{position} + count);
  for (std::uint32_t i = 0; i < count; ++i) {
    appendContact(shapeA, shapeB, manifold.points[i], manifold.normal);
    noteContactPair(notes, position + i, shapeA, shapeB, i == 0);
  }
}

// Inline: the detection loop calls it for every pair of two circles.
inline bool Simulator::circlesInReach(std::uint32_t shapeA, std::uint32_t shapeB,
                                      CirclePair& pair) const {
  const Shape& a = shapes_[shapeA];
  const Shape& b = shapes_[shapeB];
  if (!a.movable && !b.movable) return false;
  if (a.group != 0 && a.group == b.group) return false;
  const ShapeGeometry& ga = geometry_[shapeA];
  const ShapeGeometry& gb = geometry_[shapeB];
  const real margin = std::min(ga.margin, gb.margin) + ga.travel + gb.travel;
  // Some candidate pairs of a crowd are out of reach: a conservative test on squared
  // distances (no square root, no call) drops them; the rest get the exact test.
  const Vector2 d = gb.p0 - ga.p0;
  // (The pair is written whether or not it is kept, so that the caller need not branch.)
  const real reach = (ga.radius + gb.radius + margin) * (1 + 64 * realEpsilon);
  pair = {ga.p0.x, ga.p0.y, gb.p0.x, gb.p0.y, ga.radius, gb.radius, margin, shapeA, shapeB};
  return !(d.lengthSquared() > reach * reach);
}

void Simulator::addCirclePairs(std::span<const CirclePair> pairs) {
  // collideCircles' one point, stored without a Manifold in between (zeroed, then read back
  // in a loop over its points).
  flushReused();  // (the reused contacts before them come first)
  auto position = static_cast<std::uint32_t>(contacts.items_.size());
  ContactPair* const notes = notesFor(position + pairs.size());
  const auto add = [&](auto longList) {
    for (const CirclePair& pair : pairs) {
      Vector2 normal;
      ManifoldPoint p;
      if (!narrow_phase::circlesPoint({pair.centreAx, pair.centreAy}, pair.radiusA,
                                      {pair.centreBx, pair.centreBy}, pair.radiusB, pair.margin,
                                      normal, p))
        continue;
      appendContact(pair.shapeA, pair.shapeB, p, normal);
      notes[position] = {pairKey(pair.shapeA, pair.shapeB), noPair};
      if (longList || position >= unchainedContacts) chainPair(notes, position, pair.shapeA);
      ++position;
    }
  };
  // (A crowd's batches begin past the unchained contacts: they chain every pair untested.)
  if (position >= unchainedContacts)
    add(std::true_type{});
  else
    add(std::false_type{});
}

void Simulator::addContacts(std::uint32_t shapeA, std::uint32_t shapeB) {
  if (shapes_[shapeB].type < shapes_[shapeA].type) std::swap(shapeA, shapeB);
  const Shape& a = shapes_[shapeA];
  const Shape& b = shapes_[shapeB];
  if (!a.movable && !b.movable) return;
  if (a.group != 0 && a.group == b.group) return;
  if (a.body == b.body &&
      !ownShapesMayTouch(multiBodies_[a.body], bodyStates_[a.body].firstShape, shapeA, shapeB))
    return;
  const ShapeGeometry& ga = geometry_[shapeA];
  const ShapeGeometry& gb = geometry_[shapeB];
  const real margin =
      (a.type == ShapeType::HalfPlane ? gb.margin : std::min(ga.margin, gb.margin)) + ga.travel +
      gb.travel;
  const auto append = [&](const Manifold& manifold) { appendContacts(shapeA, shapeB, manifold); };
  switch (a.type) {
    case ShapeType::HalfPlane:
      append(b.type == ShapeType::Circle
                 ? collideHalfPlaneCircle(ga.p0, ga.p1, gb.p0, gb.radius, margin)
                 : collideHalfPlaneCapsule(ga.p0, ga.p1, gb.p0, gb.p1, gb.radius, margin));
      break;
    case ShapeType::Circle:
      if (b.type == ShapeType::Circle) {
        CirclePair pair;
        if (circlesInReach(shapeA, shapeB, pair)) addCirclePairs({&pair, 1});
      } else {
        append(collideCircleCapsule(ga.p0, ga.radius, gb.p0, gb.p1, gb.radius, margin));
      }
      break;
    case ShapeType::Capsule:
      append(collideCapsules(ga.p0, ga.p1, ga.radius, gb.p0, gb.p1, gb.radius, margin));
      break;
  }
}

void Simulator::indexContacts() {
  // Counting sort by object into one array; each object's `contacts` is its slice of it. Only
  // the objects with contacts are visited (listed in order of their first contact), so a
  // world of many objects with few contacts pays for its contacts, not for its size. The
  // counts are detection's (countContact()), unless this list was indexed already.
  clearContactLists();
  if (!countsComplete_) {
    resetCounts();
    for (const GlobalContactInfo& c : contacts.items_) countContact(c.bodyA, c.bodyB);
  }
  countsComplete_ = false;  // the counts become cursors (clearContactLists() zeroes them)
  objectContacts_.resize(2 * contacts.size());
  const std::span<const std::uint32_t> counted(countedObjects_.data(), countedCount_);
  // Each listed object's slice is known from the counts: it is given now, before it is filled.
  std::uint32_t offset = 0;
  for (const std::uint32_t i : counted) {
    const std::uint32_t n = objectContactCursor_[i];
    objectContactCursor_[i] = offset;
    objects[i].contacts = std::span(objectContacts_).subspan(offset, n);
    offset += n;
  }
  // The contacts' forces: 0 from detection until the solve gives them (advanceTime() in a
  // world of core shapes indexes after it).
  for (std::uint32_t k = 0; k < contacts.size(); ++k) {
    const GlobalContactInfo& c = contacts.items_[k];
    objectContacts_[objectContactCursor_[c.bodyA]++] =
        ContactInfo{k, c.objectB, c.primitiveA, c.primitiveB, c.point, -c.normal, c.depth, c.force};
    objectContacts_[objectContactCursor_[c.bodyB]++] =
        ContactInfo{k, c.objectA, c.primitiveB, c.primitiveA, c.point, c.normal, c.depth, c.force};
  }
  // (Each cursor ends at its slice's end: clearContactLists() zeroes it with the list.)
  // The counted objects are the listed ones now (and none is counted).
  std::swap(listedObjects_, countedObjects_);
  listedCount_ = countedCount_;
  countedCount_ = 0;
  if (countedObjects_.size() < objects.size() + 1) fitCountedObjects();
}

void Simulator::clearContactLists() {
  // (Also the cursors indexContacts() left: each object's count starts from 0 again.)
  for (std::size_t k = 0; k < listedCount_; ++k) {
    const std::uint32_t i = listedObjects_[k];
    objects[i].contacts = {};
    objectContactCursor_[i] = 0;
  }
  listedCount_ = 0;
}

}  // namespace thyrix
