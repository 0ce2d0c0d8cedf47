/// @file SimulatorGeometry.cpp
/// @brief Phase 2 of a step, first part: the shapes' geometry and grid boxes (what moved).
#include <ThyrixLite/Border.h>
#include <ThyrixLite/Simulator.h>
#include <Tools/Inlining.h>
#include <Tools/ProcessorFeatures.h>
#include <Tools/Wide.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <type_traits>

namespace thyrix {

namespace {

/// Bitwise equality: a pose is unchanged only if its bits are (so -0 differs from +0, and a
/// NaN equals itself), which is what makes reusing results exact.
std::uint64_t bitsOf(real a) {
  using Bits = std::conditional_t<sizeof(real) == 8, std::uint64_t, std::uint32_t>;
  return std::bit_cast<Bits>(a);
}
bool sameBits(real a, real b) { return bitsOf(a) == bitsOf(b); }
bool sameBits(Vector2 a, Vector2 b) { return sameBits(a.x, b.x) && sameBits(a.y, b.y); }

/// Sets bits @p begin to @p end - 1 of the bit set @p words (bit `i % 64` of word `i / 64`).
void setBits(std::uint64_t* words, std::uint32_t begin, std::uint32_t end) {
  for (std::uint32_t w = begin / 64; w <= (end - 1) / 64; ++w) {
    const std::uint32_t from = std::max(begin, 64 * w) - 64 * w;   // in this word
    const std::uint32_t to = std::min(end, 64 * w + 64) - 64 * w;  // (1 to 64)
    words[w] |= (~std::uint64_t{0} >> (64 - (to - from))) << from;
  }
}

/// Two reals as one value: a 2D vector's x and y, each step of the geometry for both at once
/// (a crowd's circles and a chain's capsules at every step).
using Pair = simd::Wide<real, 2>;
static_assert(std::is_standard_layout_v<Vector2> && sizeof(Vector2) == 2 * sizeof(real),
              "a Vector2 is read as its two coordinates");
Pair load(const Vector2& v) { return Pair::load(&v.x); }
void store(Vector2& v, Pair pair) { pair.store(&v.x); }

/// Widens the box (@p boxMin, @p boxMax) to take in the box from @p least - @p radius to
/// @p most + @p radius, coordinate by coordinate (a body's box is this union of its shapes'
/// boxes, in shape order): std::min(a, b) is `b < a ? b : a`, simd::min(b, a).
void includeWidened(Vector2& boxMin, Vector2& boxMax, Pair least, Pair most, real radius) {
  const Pair round = Pair::broadcast(radius);
  store(boxMin, min(least - round, load(boxMin)));
  store(boxMax, max(most + round, load(boxMax)));
}

/// Widens the box (@p boxMin, @p boxMax) by the box of the capsule of ends @p p0 and @p p1 and
/// radius @p radius, as capsuleGeometry does it.
inline void includeCapsuleBox(const Vector2& p0, const Vector2& p1, real radius, Vector2& boxMin,
                              Vector2& boxMax) {
  const Pair end0 = load(p0);
  const Pair end1 = load(p1);
  includeWidened(boxMin, boxMax, min(end1, end0), max(end1, end0), radius);
}

/// Adds @p box to @p extents, the next grid box in slot order, as BroadPhase gathers them
/// (Extents::add): the same operations in the same order, so the same sums. Each pair of
/// fields is read and written at once (a chain's links add theirs one after the other).
inline void addExtents(const BoundingBox& box, SweepAndPrune::Extents& extents) {
  using Extents = SweepAndPrune::Extents;
  static_assert(std::is_standard_layout_v<Extents> &&
                    offsetof(Extents, sumY) == offsetof(Extents, sumX) + sizeof(real) &&
                    offsetof(Extents, lowY) == offsetof(Extents, lowX) + sizeof(real) &&
                    offsetof(Extents, highY) == offsetof(Extents, highX) + sizeof(real),
                "the extents are read as pairs (x, y)");
  const Pair lower = load(box.lower);
  const Pair upper = load(box.upper);
  (Pair::load(&extents.sumX) + (upper - lower)).store(&extents.sumX);
  min(lower, Pair::load(&extents.lowX)).store(&extents.lowX);
  max(upper, Pair::load(&extents.highX)).store(&extents.highX);
}

/// A capsule's geometry from its centre @p r and half axis @p axis, exactly as
/// Simulator::updateShape computes it: its ends @p p0 and @p p1 and its @p travel (from the
/// ends' last values when @p known), its grid box @p gridBox (widened by @p radius, @p margin
/// and the travel), and its box widened by the radius taken into the body box (@p boxMin,
/// @p boxMax).
inline void capsuleGeometry(Vector2 r, Vector2 axis, Vector2& p0, Vector2& p1, real radius,
                            real margin, real& travel, real travelFactor, bool known,
                            BoundingBox& gridBox, Vector2& boxMin, Vector2& boxMax) {
  const Pair centre = load(r);
  const Pair half = load(axis);
  const Pair last0 = load(p0);
  const Pair last1 = load(p1);
  const Pair end0 = centre - half;
  const Pair end1 = centre + half;
  store(p0, end0);
  store(p1, end1);
  const Pair least = min(end1, end0);
  const Pair most = max(end1, end0);
  includeWidened(boxMin, boxMax, least, most, radius);
  real moved = 0;
  if (known) {
    const Pair d0 = abs(end0 - last0);
    const Pair d1 = abs(end1 - last1);
    const Pair sums = simd::lows(d0, d1) + simd::highs(d0, d1);  // |d.x| + |d.y| of each end
    moved = std::min(travelFactor * std::max(sums.at(0), sums.at(1)), radius);
  }
  travel = moved;
  const Pair reach = Pair::broadcast(radius + margin + moved);
  store(gridBox.lower, least - reach);
  store(gridBox.upper, most + reach);
}

/// A circle's geometry at centre @p r, exactly as Simulator::updateCircle computes it: its
/// axis @p p0, @p p1 (the centre twice), its travel from the centre's last value (@p p0) when
/// @p known, returned, its grid box @p gridBox (widened by @p radius, @p margin and the travel),
/// and its box taken into the body box (@p boxMin, @p boxMax).
inline real circleGeometry(Vector2 r, Vector2& p0, Vector2& p1, real radius, real margin,
                           real travelFactor, bool known, BoundingBox& gridBox, Vector2& boxMin,
                           Vector2& boxMax) {
  const Pair centre = load(r);
  const Pair last = load(p0);
  store(p0, centre);
  store(p1, centre);
  includeWidened(boxMin, boxMax, centre, centre, radius);
  real travel = 0;
  if (known) {
    const Pair d = abs(centre - last);
    travel = std::min(travelFactor * (d.at(0) + d.at(1)), radius);
  }
  const Pair reach = Pair::broadcast(radius + margin + travel);
  store(gridBox.lower, centre - reach);
  store(gridBox.upper, centre + reach);
  return travel;
}

/// A word of 8 bytes, byte @p i @p value, the others 0 (by bytes: the same in either byte order).
constexpr std::uint64_t byteWord(std::size_t i, unsigned char value) {
  std::array<unsigned char, 8> bytes{};
  bytes[i] = value;
  return std::bit_cast<std::uint64_t>(bytes);
}

// A body's bytes from its `fixed` on (Simulator::filterBytes), compared with its
// BodyState::filterKey at every step: 0 `fixed`, 1 sensing_, 2 rigid_, 3 padding, 4 to 7
// collisionGroup. The key has sensing_ false (a body with sensors differs, and is noted in the
// rare branch), and in the byte of rigid_, which the body's bytes drop with the padding, 1 if
// the body travels, that is, does not rest cheaply (it then always differs).
constexpr std::uint64_t groupBytes =
    byteWord(4, 0xff) | byteWord(5, 0xff) | byteWord(6, 0xff) | byteWord(7, 0xff);
constexpr std::uint64_t filterMask = byteWord(0, 0xff) | groupBytes;  // fixed, collisionGroup
constexpr std::uint64_t comparedMask = filterMask | byteWord(1, 0xff);
constexpr std::size_t travellingByte = 2;
constexpr std::uint64_t travellingBit = byteWord(travellingByte, 1);
// In the padding's byte of the key, 1 for a body that is never at rest (BodyState::alwaysAwake):
// the body's bytes there are masked off, so it always differs.
constexpr std::uint64_t alwaysAwakeBit = byteWord(3, 1);

/// The BodyState::filterKey of a body of filters @p fixed and @p group.
std::uint64_t filterKeyOf(std::uint32_t fixed, std::uint32_t group, bool travelling) {
  std::array<unsigned char, 8> bytes{};
  bytes[0] = static_cast<unsigned char>(fixed);
  bytes[travellingByte] = travelling ? 1 : 0;
  static_assert(sizeof group == 4, "the group is bytes 4 to 7");
  std::memcpy(bytes.data() + 4, &group, sizeof group);
  return std::bit_cast<std::uint64_t>(bytes);
}

/// Notes in @p key (a BodyState::filterKey) whether its body travels: one byte stored.
void setTravelling(std::uint64_t& key, bool travelling) {
  reinterpret_cast<unsigned char*>(&key)[travellingByte] = travelling ? 1 : 0;
}

}  // namespace

inline std::uint64_t Simulator::filterBytes(const PhysicalObject& object) {
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Winvalid-offsetof"
  constexpr std::size_t fixed = offsetof(PhysicalObject, fixed);
  static_assert(offsetof(PhysicalObject, sensing_) == fixed + 1 &&
                    offsetof(PhysicalObject, rigid_) == fixed + 2 &&
                    offsetof(PhysicalObject, collisionGroup) == fixed + 4 && sizeof(bool) == 1 &&
                    sizeof(object.collisionGroup) == 4,
                "a body's filters and flags are read as one word");
#pragma GCC diagnostic pop
  std::uint64_t bytes = 0;
  std::memcpy(&bytes, reinterpret_cast<const unsigned char*>(&object) + fixed, sizeof bytes);
  return bytes;
}

// Its two adjacent flags read as one 16-bit word: a test and a branch less for each of a
// chain's links (offsetof: conditionally supported on a class with virtual functions, as in
// Primitive.h).
inline bool Simulator::sensingOrRigid(const PhysicalObject& object) {
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Winvalid-offsetof"
  constexpr std::size_t sensing = offsetof(PhysicalObject, sensing_);
  static_assert(offsetof(PhysicalObject, rigid_) == sensing + 1 && sizeof(bool) == 1,
                "sensing_ and rigid_ are read as one word");
#pragma GCC diagnostic pop
  std::uint16_t flags = 0;
  std::memcpy(&flags, reinterpret_cast<const unsigned char*>(&object) + sensing, sizeof flags);
  return flags != 0;
}

// Inline: called from updateGeometry, the only caller, for the unmoved shapes of a composed
// body some of whose shapes moved (their geometry is as updateShape left it).
inline void Simulator::addCachedBox(std::uint32_t s, Vector2& boxMin, Vector2& boxMax) const {
  if (shapes_[s].type == ShapeType::HalfPlane) return;  // unbounded: no box
  addGeometryBox(geometry_[s], boxMin, boxMax);
}

inline void Simulator::addGeometryBox(const ShapeGeometry& g, Vector2& boxMin, Vector2& boxMax) {
  // A circle's axis is its centre twice (see updateShape): the capsule's box is its box.
  includeCapsuleBox(g.p0, g.p1, g.radius, boxMin, boxMax);
}

// THYRIX_ALWAYS_INLINE below where GCC kept a call (measured), THYRIX_NO_INLINE on a loop.

// Recomputes capsule @p s's geometry and grid box, and widens the body box (@p boxMin,
// @p boxMax) by its box (the one computation of a capsule, for standalone capsules and the
// parts of composed bodies alike).
THYRIX_ALWAYS_INLINE void Simulator::updateCapsule(std::uint32_t s, Primitive& primitive,
                                                   ShapePose& pose, ShapeGeometry& g,
                                                   bool poseKnown, const GridTargets& grid,
                                                   Vector2& boxMin, Vector2& boxMax) {
  const Vector2 r = primitive.r;
  const real alpha = primitive.alpha;
  // The half axis turns with the angle only: a capsule that slides keeps it. Kept in a
  // register: read back from the pose, it waited for its own store.
  Vector2 axis = pose.axis;
  if (!poseKnown || !sameBits(alpha, pose.alpha)) {
    // direction() is cached by the primitive, or set by an owner that placed it with the
    // (cos, sin) it already had (articulated links): no sine or cosine here then.
    axis = primitive.direction() * pose.halfLength;
    pose.axis = axis;
  }
  placeCapsule(s, r, alpha, axis, pose, g, poseKnown, grid, boxMin, boxMax);
}

THYRIX_ALWAYS_INLINE void Simulator::placeCapsule(std::uint32_t s, Vector2 r, real alpha,
                                                  Vector2 axis, ShapePose& pose, ShapeGeometry& g,
                                                  bool poseKnown, const GridTargets& grid,
                                                  Vector2& boxMin, Vector2& boxMax) {
  const std::uint32_t slot = grid.slots[s];
  grid.movedBits[slot / 64] |= std::uint64_t{1} << (slot % 64);
  placeLinkCapsule(r, alpha, axis, pose, g, poseKnown, grid.travelFactor, grid.boxes[slot], boxMin,
                   boxMax);
}

THYRIX_ALWAYS_INLINE void Simulator::placeLinkCapsule(Vector2 r, real alpha, Vector2 axis,
                                                      ShapePose& pose, ShapeGeometry& g,
                                                      bool poseKnown, real travelFactor,
                                                      BoundingBox& gridBox, Vector2& boxMin,
                                                      Vector2& boxMax) {
  pose.r = r;
  pose.alpha = alpha;
  capsuleGeometry(r, axis, g.p0, g.p1, g.radius, g.margin, g.travel, travelFactor, poseKnown,
                  gridBox, boxMin, boxMax);
}

// A circle: its geometry does not depend on its angle. Its axis is its centre twice, so that
// addCachedBox reads its box as a capsule's (min and max of equal values, which are that
// value, as are the capsule formulas with both ends at the centre). The travel is returned
// as computed (the caller that needs it would otherwise read it back from memory).
THYRIX_ALWAYS_INLINE real Simulator::updateCircle(std::uint32_t s, Vector2 r, bool poseKnown,
                                                  Vector2& boxMin, Vector2& boxMax) {
  ShapeGeometry& g = geometry_[s];
  const std::uint32_t slot = gridSlot_[s];
  gridMovedBits_[slot / 64] |= std::uint64_t{1} << (slot % 64);
  // How far the shape went in the last step, a bound on how far it goes in this one if it
  // keeps its speed: |dx| + |dy| (no square root; at most 1.42 times the distance), capped
  // at the radius (a shape moved by hand did not travel). Its grid box is its own box (not
  // the body's), widened by its speculative margin and travel.
  const real travel = circleGeometry(r, g.p0, g.p1, g.radius, g.margin, geometryTravel_, poseKnown,
                                     gridBoxes_[slot], boxMin, boxMax);
  g.travel = travel;
  return travel;
}

// Recomputes shape @p s's geometry and grid box, and widens the body box (@p boxMin,
// @p boxMax) by its box without margin; a half-plane is unbounded: no box, not in the grid.
// Radius and margin are not recomputed: they are in geometry_ since registration (the margin
// since the last change of the fraction), and the half length is in shapePoses_.
// With @p standalone (the shape is its body) a circle's pose is not noted: only a composed
// body's shapes (compared one by one) and capsules (their axis) read it.
THYRIX_ALWAYS_INLINE void Simulator::updateShape(std::uint32_t s, bool poseKnown, bool standalone,
                                                 Vector2& boxMin, Vector2& boxMax) {
  Primitive& primitive = *shapes_[s].primitive;
  ShapePose& pose = shapePoses_[s];
  ShapeGeometry& g = geometry_[s];
  const Vector2 r = primitive.r;
  const real alpha = primitive.alpha;
  switch (shapes_[s].type) {
    case ShapeType::HalfPlane:
      g.p0 = r;
      g.p1 = static_cast<const Border&>(primitive).normal();
      pose.r = r;
      pose.alpha = alpha;
      return;
    case ShapeType::Capsule:
      updateCapsule(s, primitive, pose, g, poseKnown, gridTargets(), boxMin, boxMax);
      return;
    case ShapeType::Circle:
      break;
  }
  if (!standalone) {
    pose.r = r;
    pose.alpha = alpha;
  }
  updateCircle(s, r, poseKnown, boxMin, boxMax);
}

// Inline (forced: GCC kept a call, which cost a pile of moving bodies 1% more instructions):
// called from updateGeometry, the only caller, for the bodies that changed or that have
// several shapes.
THYRIX_ALWAYS_INLINE void Simulator::updateBody(std::uint32_t index, bool changed,
                                                bool newFilters) {
  BodyState& state = bodyStates_[index];
  PhysicalObject& body = *state.object;
  std::uint8_t* const shapeMoved = shapeMoved_.data();
  const bool known = state.fixed != BodyState::unknown;
  if (changed) {
    // The filters copied to the shapes depend on `fixed` and `collisionGroup` only (and on
    // multiBodies_, set at registration): a body that only moved leaves them as they are.
    state.r = body.r;
    state.alpha = body.alpha;
    if (newFilters) {
      state.fixed = body.fixed ? 1 : 0;
      state.group = body.collisionGroup;
      state.movable = movable(index);
      for (std::uint32_t s = state.firstShape; s < state.firstShape + state.shapeCount; ++s) {
        shapes_[s].group = state.group;  // next to the shapes for the narrow phase
        shapes_[s].movable = state.movable;
      }
      // (Whether it travels as the key says, or before its first detection as registered.)
      const bool travelling = state.filterKey == ~std::uint64_t{0}
                                  ? !state.restsCheaply
                                  : (state.filterKey & travellingBit) != 0;
      state.filterKey = filterKeyOf(state.fixed, state.group, travelling) |
                        (state.alwaysAwake ? alwaysAwakeBit : 0);
    }
  }
  if (state.standalone) {  // a primitive of its own: its pose is the body's (common case)
    const std::uint32_t s = state.firstShape;
    auto& primitive = static_cast<Primitive&>(body);  // the body is its one primitive
    if (primitive.sensing_) sensingPrimitives_.push_back(&primitive);
    // A shape that travelled in the last step has a wider margin, narrowed when it stops.
    if (!changed && geometry_[s].travel == 0) return;
    shapeMoved[s] = 1;
    // The body box is the union of its shapes' boxes, taken in shape order (so NaNs and
    // signed zeros come out as they always did), starting from the empty box. (Declared here:
    // GCC stored it on the stack before the branches, for every body.)
    Vector2 boxMin{realMax, realMax};
    Vector2 boxMax{-realMax, -realMax};
    real travel = 0;
    if (shapes_[s].type == ShapeType::Circle) {  // a crowd's body: no dispatch, travel at hand
      travel = updateCircle(s, primitive.r, known, boxMin, boxMax);
    } else {
      updateShape(s, known, true, boxMin, boxMax);
      travel = geometry_[s].travel;
    }
    body.boxMin = boxMin;
    body.boxMax = boxMax;
    // While it travels, the body is looked at in this loop even when its pose stays the same.
    setTravelling(state.filterKey, travel != 0);
    return;
  }
  updateComposedBody(state, changed, known);
}

// Inline (forced: out of line, it saved 9 instructions a body of a falling pile, not 40):
// called from updateGeometry's first loop, the only caller, for a crowd's bodies in motion,
// whose objects are then at hand (the second loop read each body again).
THYRIX_ALWAYS_INLINE void Simulator::updateMovedCircle(BodyState& state, bool changed) {
  // updateBody's path for a standalone circle, known (its filters are unchanged: `fixed` is
  // known) and travelling if unchanged (its key says so): the same operations.
  PhysicalObject& body = *state.object;
  auto& primitive = static_cast<Primitive&>(body);
  if (changed) {
    state.r = body.r;
    state.alpha = body.alpha;
  }
  if (primitive.sensing_) sensingPrimitives_.push_back(&primitive);
  const std::uint32_t s = state.firstShape;
  shapeMoved_[s] = 1;
  Vector2 boxMin{realMax, realMax};
  Vector2 boxMax{-realMax, -realMax};
  const real travel = updateCircle(s, primitive.r, true, boxMin, boxMax);
  body.boxMin = boxMin;
  body.boxMax = boxMax;
  setTravelling(state.filterKey, travel != 0);
}

// Out of line (the general case of updateComposedBody's second loop): its calls (a sensor
// noted, a part placed, a sine and a cosine) then leave the loop's registers alone.
THYRIX_NO_INLINE void Simulator::updateComposedShape(std::uint32_t s, bool changed, bool poseKnown,
                                                     Vector2& boxMin, Vector2& boxMax) {
  Primitive& primitive = *shapes_[s].primitive;
  if (primitive.sensing_) sensingPrimitives_.push_back(&primitive);
  ShapePose& pose = shapePoses_[s];
  ShapeGeometry& g = geometry_[s];
  const bool moved = changed || !sameBits(primitive.r, pose.r) ||
                     !sameBits(primitive.alpha, pose.alpha) || g.travel != 0;
  if (!moved) {  // (its shapeMoved_ entry is 0 since the start of the detection)
    addCachedBox(s, boxMin, boxMax);
    return;
  }
  shapeMoved_[s] = 1;
  // (Tested here first: a part its owner places, an articulated link, is where it is.)
  if (primitive.rigidlyAttached()) primitive.followOwner();
  if (shapes_[s].type == ShapeType::Capsule)
    updateCapsule(s, primitive, pose, g, poseKnown, gridTargets(), boxMin, boxMax);
  else  // a circle (or a border)
    updateShape(s, poseKnown, false, boxMin, boxMax);
}

// Out of line: the loops over a composed body's shapes (a chain's 1000 links) get the
// registers to themselves: the arrays' addresses loaded once, the body box kept in registers.
THYRIX_NO_INLINE void Simulator::updateComposedBody(const BodyState& state, bool changed,
                                                    bool known) {
  // Known or not, the same for every shape: the loops in two copies, each with its own
  // constant (measured: a flag read from the stack twice a shape otherwise). What they read
  // comes in as parameters, not captures: the AVX copy below is a call of its own, which read
  // captures from memory again after each of the loop's byte stores.
  const auto run = [this](auto knownConstant, const BodyState& body,
                          bool bodyChanged) THYRIX_LAMBDA_ALWAYS_INLINE {
    constexpr bool poseKnown = decltype(knownConstant)::value;
    const Shape* const shapes = shapes_.data();
    ShapePose* const poses = shapePoses_.data();
    ShapeGeometry* const geometry = geometry_.data();
    const std::uint32_t firstShape = body.firstShape;
    const std::uint32_t end = firstShape + body.shapeCount;
    // The shapes up to the first that moved: their sensors noted, nothing else (a body none
    // of whose shapes moved keeps its box and reads no shape's box).
    std::uint32_t firstMoved = firstShape;
    if (!bodyChanged) {
      for (; firstMoved < end; ++firstMoved) {
        Primitive& primitive = *shapes[firstMoved].primitive;
        const ShapePose& pose = poses[firstMoved];
        if (!sameBits(primitive.r, pose.r) || !sameBits(primitive.alpha, pose.alpha) ||
            geometry[firstMoved].travel != 0)
          break;
        if (primitive.sensing_) sensingPrimitives_.push_back(&primitive);
      }
      if (firstMoved == end) return;
    }
    // From the first moved shape on, the body box is rebuilt, from every shape in order:
    // those before it are added first, the unmoved ones after it as they come.
    std::uint8_t* const shapeMoved = shapeMoved_.data();
    const GridTargets grid = gridTargets();
    Vector2 boxMin{realMax, realMax};
    Vector2 boxMax{-realMax, -realMax};
    for (std::uint32_t t = firstShape; t < firstMoved; ++t)
      if (shapes[t].type != ShapeType::HalfPlane) addGeometryBox(geometry[t], boxMin, boxMax);
    // A chain's link: a capsule without sensors, placed by its owner, that moved, its half
    // axis at hand (the pose's, or the direction cached by the primitive: no sine or cosine).
    // Done here as updateComposedShape does it; false, nothing written, for every other shape.
    // Its grid box is @p gridBox (its caller's run knows it: no look-up), and is added to
    // @p extents (see the run below).
    const auto updateLink = [&](std::uint32_t s, BoundingBox& gridBox,
                                SweepAndPrune::Extents& extents) {
      const Primitive& primitive = *shapes[s].primitive;
      if (shapes[s].type != ShapeType::Capsule || sensingOrRigid(primitive)) return false;
      ShapePose& pose = poses[s];
      ShapeGeometry& g = geometry[s];
      const Vector2 r = primitive.r;
      const real alpha = primitive.alpha;
      // (Turned first: a chain's links turn at every step, and need no other test then.)
      const bool turned = !sameBits(alpha, pose.alpha);
      if (!turned && !bodyChanged && sameBits(r, pose.r) && g.travel == 0) return false;
      Vector2 axis = pose.axis;
      if (!poseKnown || turned) {
        if (alpha != primitive.directionAngle_) return false;  // direction() would compute it
        axis = primitive.direction_ * pose.halfLength;
        pose.axis = axis;
      }
      placeLinkCapsule(r, alpha, axis, pose, g, poseKnown, grid.travelFactor, gridBox, boxMin,
                       boxMax);
      addExtents(gridBox, extents);
      return true;
    };
    // A circle or capsule without sensors that did not move: its box as cached.
    const auto addUnmoved = [&](std::uint32_t s) {
      const Primitive& primitive = *shapes[s].primitive;
      const ShapePose& pose = poses[s];
      const ShapeGeometry& g = geometry[s];
      if (bodyChanged || primitive.sensing_ || shapes[s].type == ShapeType::HalfPlane ||
          !sameBits(primitive.r, pose.r) || !sameBits(primitive.alpha, pose.alpha) || g.travel != 0)
        return false;
      addGeometryBox(g, boxMin, boxMax);
      return true;
    };
    for (std::uint32_t s = firstMoved; s < end; ++s) {
      // A run of links: consecutive shapes in the grid, so in consecutive slots (shapes are
      // only ever appended, and the grid's slots with them). Their moved marks are set once
      // the run ends: a chain's 1000 links take a fill and 16 words, not a byte and a bit each.
      const std::uint32_t runStart = s;
      const std::uint32_t runSlot = grid.slots[s];  // (~0u, unused, for a half-plane)
      // The run's grid boxes are also added to the sweep's extents (gridExtents_), which the
      // broad phase then need not gather (a pass over the boxes, waiting on each sum): the
      // boxes of the slots before it first (they are final, see gatherExtentsUpTo).
      if (runSlot != ~0u && shapes[s].type == ShapeType::Capsule) gatherExtentsUpTo(runSlot);
      SweepAndPrune::Extents extents = gridExtents_;
      // The run's next grid box, one pointer stepped along (not its slot's address computed
      // for each link: the array's address then stays in a register). None for a half-plane.
      BoundingBox* gridBox = grid.boxes + (runSlot != ~0u ? runSlot : 0);
      while (s < end && updateLink(s, *gridBox, extents)) {
        ++s;
        ++gridBox;
      }
      if (s != runStart) {
        std::fill(shapeMoved + runStart, shapeMoved + s, std::uint8_t{1});
        setBits(grid.movedBits, runSlot, runSlot + (s - runStart));
        gridExtents_ = extents;
        gridExtentsCount_ = runSlot + (s - runStart);
      }
      if (s == end) break;
      if (addUnmoved(s)) [[likely]]
        continue;
      Vector2 lower = boxMin;  // (the box stays a local: it leaves registers only here)
      Vector2 upper = boxMax;
      updateComposedShape(s, bodyChanged, poseKnown, lower, upper);
      boxMin = lower;
      boxMax = upper;
    }
    body.object->boxMin = boxMin;
    body.object->boxMax = boxMax;
  };
#if defined(THYRIX_AVX_DISPATCH)
  // With AVX the same loops in VEX form: the same operations, so the same bits, but its
  // three-operand instructions need none of SSE2's register copies (a chain's link had 10).
  const auto runAvx = [&run](auto knownConstant, const BodyState& body, bool bodyChanged)
      __attribute__((target("avx"))) {
    run(knownConstant, body, bodyChanged);
  };
  if (processorHasAvx()) {
    if (known)
      runAvx(std::true_type{}, state, changed);
    else
      runAvx(std::false_type{}, state, changed);
    return;
  }
#endif
  if (known)
    run(std::true_type{}, state, changed);
  else
    run(std::false_type{}, state, changed);
}

THYRIX_NO_INLINE void Simulator::gatherExtentsUpTo(std::uint32_t slot) {
  // The boxes of slots before a shape of a pending body are final when updateComposedBody
  // reaches it: they are its body's earlier shapes, or shapes of bodies of lower index, done
  // before it or not moved (or circles, done in updateGeometry's first loop).
  for (; gridExtentsCount_ < slot; ++gridExtentsCount_)
    addExtents(gridBoxes_[gridExtentsCount_], gridExtents_);
}

void Simulator::updateGeometry() {
  // A new margin changes every shape's geometry; without rest skipping nothing is kept.
  // (Margins widened for one detection (widenMargins()) are set back at the next.)
  const bool newFraction =
      marginsWidened_ || !sameBits(settings_.speculativeFraction, geometryFraction_);
  marginsWidened_ = false;
  const bool everything = !restSkipping || newFraction || widening_ ||
                          !sameBits(settings_.speculativeTravel, geometryTravel_);
  geometryFraction_ = settings_.speculativeFraction;
  geometryTravel_ = settings_.speculativeTravel;
  if (newFraction)  // the margins are kept, and depend on nothing else (radii are fixed)
    for (ShapeGeometry& g : geometry_) g.margin = geometryFraction_ * g.radius;
  sensingPrimitives_.clear();
  gridExtents_ = {};
  gridExtentsCount_ = 0;
  gridMovedBits_.assign((gridShapes_.size() + 63) / 64, 0);
  // Every shape unmoved to begin with: a body at rest then writes nothing.
  std::fill(shapeMoved_.begin(), shapeMoved_.end(), std::uint8_t{0});
  const std::span<BodyState> states(bodyStates_);
  // Rest: the bodies that differ, or move, or are pushed, are this step's awake ones; the
  // others are at rest, and phases 5 and 8 pass them over (not in a gravity field, which
  // pushes every movable body).
  ++awakeNow_;
  awakeCount_ = 0;
  awakeValid_ = stepping_ && !everything && !hasGravity_;
  std::uint32_t* const awake = awake_.data();
  std::uint64_t* const awakeStamp = awakeStamp_.data();
  const std::uint64_t awakeNow = awakeNow_;
  const bool listing = awakeValid_;
  std::size_t awakeCount = 0;
  // Bodies for the second loop, each as 4 index + 2 if its filters changed + 1 if it changed
  // (else its several shapes are compared).
  pendingBodies_.resize(states.size());
  std::uint32_t* const pending = pendingBodies_.data();
  std::uint32_t pendingCount = 0;
  // A body is unchanged if its pose and its collision filters are: its rigid parts are then
  // where they were (followOwner would put them there again), unless moved by hand, which the
  // parts' own poses show; so do parts placed by their owner (articulated links). Every field
  // is compared by its bits (`fixed` never matches before the first detection), the filters
  // with the sensors and the travel in one word (see filterKey).
  const auto poseDifference = [](const PhysicalObject& body, const BodyState& state) {
    return (bitsOf(body.r.x) ^ bitsOf(state.r.x)) | (bitsOf(body.r.y) ^ bitsOf(state.r.y)) |
           (bitsOf(body.alpha) ^ bitsOf(state.alpha));
  };
  const auto flagDifference = [](const PhysicalObject& body, const BodyState& state) {
    return (filterBytes(body) & comparedMask) ^ state.filterKey;
  };
  // Not 0 when the body moves or is pushed: its velocities or accumulators are not all +0.
  const auto motion = [](const PhysicalObject& body) {
    return bitsOf(body.v.x) | bitsOf(body.v.y) | bitsOf(body.omega) | bitsOf(body.externalForce.x) |
           bitsOf(body.externalForce.y) | bitsOf(body.externalTorque);
  };
  // A body that differs (@p pose, @p flags not both 0), moves or is pushed: awake.
  // (Its index from its address, off the common path: a division.)
  const auto indexOfState = [&states](const BodyState& state) {
    return static_cast<std::uint32_t>(&state - states.data());
  };
  // Listing the awake bodies or not (@p listingConstant): without, in a gravity field, the
  // loops compare as they did before rest, without reading the motion.
  const auto visit = [&](BodyState& state, std::uint64_t pose, std::uint64_t flags,
                         auto listingConstant) THYRIX_LAMBDA_ALWAYS_INLINE {
    if constexpr (decltype(listingConstant)::value) {
      const std::uint32_t index = indexOfState(state);
      awakeStamp[index] = awakeNow;
      awake[awakeCount++] = index;
    }
    const std::uint64_t filters = flags & filterMask;
    const bool changed = (pose | filters) != 0;
    if (changed || (flags & travellingBit) != 0) {  // for the second loop
      // (But a crowd's body in motion, updated while its object is at hand.)
      if (state.standaloneCircle && filters == 0) {
        updateMovedCircle(state, changed);
        return;
      }
      pending[pendingCount++] =
          4 * indexOfState(state) + (filters != 0 ? 2 : 0) + (changed ? 1 : 0);
      return;
    }
    // At rest, with sensors: a primitive of its own (or a shapeless body) has nothing else to
    // do but note them (in any order: each sensing primitive is reset and read alone).
    if (state.standalone) sensingPrimitives_.push_back(&static_cast<Primitive&>(*state.object));
  };
  // In two copies: with everything recomputed (every body then differs), and without.
  const auto check = [&](auto everythingConstant,
                         auto listingConstant) THYRIX_LAMBDA_ALWAYS_INLINE {
    for (BodyState& state : states) {
      const PhysicalObject& body = *state.object;
      const std::uint64_t pose =
          decltype(everythingConstant)::value ? ~std::uint64_t{0} : poseDifference(body, state);
      const std::uint64_t flags = flagDifference(body, state);
      const std::uint64_t moving = decltype(listingConstant)::value ? motion(body) : 0;
      if ((pose | flags | moving) == 0) [[likely]]  // at rest, without sensors
        continue;
      visit(state, pose, flags, listingConstant);
    }
  };
  // (Everything recomputed: no rest, nothing listed.)
  if (everything)
    check(std::true_type{}, std::false_type{});
  else if (listing)
    check(std::false_type{}, std::true_type{});
  else
    check(std::false_type{}, std::false_type{});
  // The bodies that changed, or whose several shapes are compared one by one, in their own
  // loop: the one above, run for every body at every step, then keeps everything in
  // registers (measured: one loop spilled and took 45 instructions a body at rest, not 29).
  awakeCount_ = awakeCount;
  for (std::uint32_t k = 0; k < pendingCount; ++k)
    updateBody(pending[k] / 4, (pending[k] & 1) != 0, (pending[k] & 2) != 0);
  // Runs of links gathered the extents of their boxes and of those before: the rest too, so
  // that the broad phase gathers none.
  if (gridExtentsCount_ != 0) gatherExtentsUpTo(static_cast<std::uint32_t>(gridShapes_.size()));
}

}  // namespace thyrix
