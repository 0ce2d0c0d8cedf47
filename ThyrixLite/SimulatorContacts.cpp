/// @file SimulatorContacts.cpp
/// @brief Phases 2 and 3 of a step: shape geometry, broad and narrow phase, contact indexing.
#include <ThyrixLite/Border.h>
#include <ThyrixLite/NarrowPhase.h>
#include <ThyrixLite/Simulator.h>

#include <algorithm>
#include <bit>
#include <cmath>
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

/// Whether circles @p a and @p b (Simulator::ShapeGeometry, private: deduced) are too far
/// apart to touch, margins included. Most candidate pairs of a crowd are: a conservative test
/// on squared distances (no square root, no call) drops them; the rest get the exact test.
template <class Geometry>
bool circlesOutOfReach(const Geometry& a, const Geometry& b) {
  const real margin = std::min(a.margin, b.margin) + a.travel + b.travel;
  const Vector2 d = b.p0 - a.p0;
  const real reach = (a.radius + b.radius + margin) * (1 + 64 * realEpsilon);
  return d.lengthSquared() > reach * reach;
}

}  // namespace

// Inline: called from updateGeometry, the only caller, for the unmoved shapes of a composed
// body some of whose shapes moved (their geometry is as updateShape left it).
inline void Simulator::addCachedBox(std::uint32_t s, Vector2& boxMin, Vector2& boxMax) const {
  const ShapeGeometry& g = geometry_[s];
  Vector2 lower;
  Vector2 upper;
  switch (shapes_[s].type) {
    case ShapeType::HalfPlane:
      return;  // unbounded: no box
    case ShapeType::Circle:
      lower = g.p0 - Vector2{g.radius, g.radius};
      upper = g.p0 + Vector2{g.radius, g.radius};
      break;
    case ShapeType::Capsule:
      lower =
          Vector2{std::min(g.p0.x, g.p1.x), std::min(g.p0.y, g.p1.y)} - Vector2{g.radius, g.radius};
      upper =
          Vector2{std::max(g.p0.x, g.p1.x), std::max(g.p0.y, g.p1.y)} + Vector2{g.radius, g.radius};
      break;
  }
  boxMin = {std::min(boxMin.x, lower.x), std::min(boxMin.y, lower.y)};
  boxMax = {std::max(boxMax.x, upper.x), std::max(boxMax.y, upper.y)};
}

// Recomputes shape @p s's geometry and grid box; sets @p lower and @p upper to its box without
// margin (what the body box is the union of) and returns true, or returns false for a
// half-plane (unbounded: no box).
// Radius and margin are not recomputed: they are in geometry_ since registration (the margin
// since the last change of the fraction), and the half length is in shapePoses_.
inline bool Simulator::updateShape(std::uint32_t s, bool poseKnown, Vector2& lower,
                                   Vector2& upper) {
  Primitive& primitive = *shapes_[s].primitive;
  ShapePose& pose = shapePoses_[s];
  ShapeGeometry& g = geometry_[s];
  const ShapeType type = shapes_[s].type;
  const Vector2 r = primitive.r;
  const real alpha = primitive.alpha;
  const Vector2 last0 = g.p0;
  const Vector2 last1 = g.p1;
  switch (type) {
    case ShapeType::HalfPlane:
      g.p0 = r;
      g.p1 = static_cast<const Border&>(primitive).normal();
      pose.r = r;
      pose.alpha = alpha;
      return false;  // unbounded: no box, not in the grid
    case ShapeType::Circle:
      g.p0 = r;  // a circle's geometry does not depend on its angle
      g.p1 = r;  // (unread: lets the box below be the capsule's, min and max of equal ends)
      break;
    case ShapeType::Capsule:
      // The half axis turns with the angle only: a capsule that slides keeps it.
      if (!poseKnown || !sameBits(alpha, pose.alpha))
        // direction() is cached by the primitive, or set by an owner that placed it with
        // the (cos, sin) it already had (articulated links): no sine or cosine here then.
        pose.axis = primitive.direction() * pose.halfLength;
      g.p0 = r - pose.axis;
      g.p1 = r + pose.axis;
      break;
  }
  pose.r = r;
  pose.alpha = alpha;
  // The same boxes as before for a circle: min and max of two equal values are that value.
  const Vector2 least{std::min(g.p0.x, g.p1.x), std::min(g.p0.y, g.p1.y)};
  const Vector2 most{std::max(g.p0.x, g.p1.x), std::max(g.p0.y, g.p1.y)};
  lower = least - Vector2{g.radius, g.radius};
  upper = most + Vector2{g.radius, g.radius};
  const std::uint32_t slot = gridSlot_[s];
  gridMovedBits_[slot / 64] |= std::uint64_t{1} << (slot % 64);
  // How far the shape went in the last step, a bound on how far it goes in this one if it
  // keeps its speed: |dx| + |dy| of its axis's ends (no square root; at most 1.42 times the
  // distance), capped at the radius (a shape moved by hand did not travel).
  g.travel = 0;
  if (poseKnown) {
    const Vector2 d0 = g.p0 - last0;
    const Vector2 d1 = g.p1 - last1;
    const real displacement =
        std::max(std::abs(d0.x) + std::abs(d0.y), std::abs(d1.x) + std::abs(d1.y));
    g.travel = std::min(geometryTravel_ * displacement, g.radius);
  }
  // The shape's own box (not the body's), widened by its speculative margin and travel.
  const real widening = g.radius + g.margin + g.travel;
  const Vector2 reach{widening, widening};
  gridBoxes_[slot] = {least - reach, most + reach};
  return true;
}

// Inline (forced: GCC kept a call, which cost a pile of moving bodies 1% more instructions):
// called from updateGeometry, the only caller, for the bodies that changed or that have
// several shapes.
#if defined(__GNUC__)
#define THYRIX_FORCE_INLINE [[gnu::always_inline]] inline
#else
#define THYRIX_FORCE_INLINE inline
#endif
THYRIX_FORCE_INLINE void Simulator::updateBody(std::uint32_t index, bool changed, bool newFilters) {
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
    }
  }
  // The body box is the union of its shapes' boxes, taken in shape order (so NaNs and
  // signed zeros come out as they always did), starting from the empty box.
  Vector2 boxMin{realMax, realMax};
  Vector2 boxMax{-realMax, -realMax};
  Vector2 lower;
  Vector2 upper;
  if (state.standalone) {  // a primitive of its own: its pose is the body's (common case)
    const std::uint32_t s = state.firstShape;
    auto& primitive = static_cast<Primitive&>(body);  // the body is its one primitive
    if (primitive.tactile_.enabled()) sensingPrimitives_.push_back(&primitive);
    // A shape that travelled in the last step has a wider margin, narrowed when it stops.
    if (!changed && geometry_[s].travel == 0) return;
    shapeMoved[s] = 1;
    if (updateShape(s, known, lower, upper)) {
      boxMin = {std::min(boxMin.x, lower.x), std::min(boxMin.y, lower.y)};
      boxMax = {std::max(boxMax.x, upper.x), std::max(boxMax.y, upper.y)};
    }
    body.boxMin = boxMin;
    body.boxMax = boxMax;
    // While it travels, the body is looked at in this loop even when its pose stays the same.
    state.restsCheaply = geometry_[s].travel == 0;
    return;
  }
  // Once a shape has moved the body box is rebuilt, from every shape in order: those
  // before the first moved one are added then, the unmoved ones after it as they come.
  // A body none of whose shapes moved keeps its box and reads no shape's geometry.
  bool anyMoved = changed;
  const std::uint32_t end = state.firstShape + state.shapeCount;
  for (std::uint32_t s = state.firstShape; s < end; ++s) {
    Primitive& primitive = *shapes_[s].primitive;
    if (primitive.tactile_.enabled()) sensingPrimitives_.push_back(&primitive);
    const ShapePose& pose = shapePoses_[s];
    const bool moved = changed || !sameBits(primitive.r, pose.r) ||
                       !sameBits(primitive.alpha, pose.alpha) || geometry_[s].travel != 0;
    if (!moved) {  // (its shapeMoved_ entry is 0 since the start of the detection)
      if (anyMoved) addCachedBox(s, boxMin, boxMax);
      continue;
    }
    shapeMoved[s] = 1;
    if (!anyMoved)
      for (std::uint32_t t = state.firstShape; t < s; ++t) addCachedBox(t, boxMin, boxMax);
    anyMoved = true;
    primitive.followOwner();
    if (!updateShape(s, known, lower, upper)) continue;
    boxMin = {std::min(boxMin.x, lower.x), std::min(boxMin.y, lower.y)};
    boxMax = {std::max(boxMax.x, upper.x), std::max(boxMax.y, upper.y)};
  }
  if (!anyMoved) return;
  body.boxMin = boxMin;
  body.boxMax = boxMax;
}

#undef THYRIX_FORCE_INLINE

void Simulator::updateGeometry() {
  // A new margin changes every shape's geometry; without rest skipping nothing is kept.
  const bool newFraction = !sameBits(settings_.speculativeFraction, geometryFraction_);
  const bool everything =
      !restSkipping || newFraction || !sameBits(settings_.speculativeTravel, geometryTravel_);
  geometryFraction_ = settings_.speculativeFraction;
  geometryTravel_ = settings_.speculativeTravel;
  if (newFraction)  // the margins are kept, and depend on nothing else (radii are fixed)
    for (ShapeGeometry& g : geometry_) g.margin = geometryFraction_ * g.radius;
  sensingPrimitives_.clear();
  gridMovedBits_.assign((gridShapes_.size() + 63) / 64, 0);
  // Every shape unmoved to begin with: a body at rest then writes nothing.
  std::fill(shapeMoved_.begin(), shapeMoved_.end(), std::uint8_t{0});
  const std::span<const BodyState> states(bodyStates_);
  // All ones when everything is recomputed: every body then differs.
  const std::uint64_t forced = everything ? ~std::uint64_t{0} : 0;
  // Bodies for the second loop, each as 4 index + 2 if its filters changed + 1 if it changed
  // (else its several shapes are compared).
  pendingBodies_.resize(states.size());
  std::uint32_t* const pending = pendingBodies_.data();
  std::uint32_t pendingCount = 0;
  std::uint32_t index = 0;  // of state (counted, not computed from the address: a division)
  for (const BodyState& state : states) {
    ++index;
    PhysicalObject& body = *state.object;
    // A body is unchanged if its pose and its collision filters are: its rigid parts are then
    // where they were (followOwner would put them there again), unless moved by hand, which
    // the parts' own poses show; so do parts placed by their owner (articulated links). Every
    // field is compared at once, by its bits (`fixed` never matches before the first detection).
    const std::uint32_t filters =
        (body.collisionGroup ^ state.group) | (std::uint32_t{body.fixed} ^ state.fixed);
    const std::uint64_t difference = (bitsOf(body.r.x) ^ bitsOf(state.r.x)) |
                                     (bitsOf(body.r.y) ^ bitsOf(state.r.y)) |
                                     (bitsOf(body.alpha) ^ bitsOf(state.alpha)) | filters | forced;
    if (difference != 0 || !state.restsCheaply) {  // for the second loop
      pending[pendingCount++] =
          4 * (index - 1) + (filters != 0 ? 2 : 0) + (difference != 0 ? 1 : 0);
      continue;
    }
    // The common case, a primitive of its own (or a shapeless body) at rest: nothing to do
    // but note its sensors (in any order: each sensing primitive is reset and read alone).
    if (state.standalone) {
      auto& primitive = static_cast<Primitive&>(body);
      if (primitive.tactile_.enabled()) sensingPrimitives_.push_back(&primitive);
    }
  }
  // The bodies that changed, or whose several shapes are compared one by one, in their own
  // loop: the one above, run for every body at every step, then keeps everything in
  // registers (measured: one loop spilled and took 45 instructions a body at rest, not 29).
  for (std::uint32_t k = 0; k < pendingCount; ++k)
    updateBody(pending[k] / 4, (pending[k] & 1) != 0, (pending[k] & 2) != 0);
}

void Simulator::detectContacts() {
  // Appending to contacts of another detection: this list is no basis for the next reuse.
  const bool fromEmpty = contacts.empty();
  updateGeometry();
  // Reuse needs the last detection's complete list (eraseContacts kept it aside).
  // (Only pairs of unmoved shapes are reused: none when every shape moved.)
  const bool reuse = restSkipping && previousValid_ && fromEmpty;
  previousIndexed_ = false;
  statistics_.reusedContacts = 0;
  broadPhase_.findPairs(gridBoxes_, gridMovedBits_, pairs_);
  for (const BoxPair& pair : pairs_) {
    const std::uint32_t a = gridShapes_[pair.first];
    const std::uint32_t b = gridShapes_[pair.second];
    // Pairs within one body are settled here, without a call: a chain's neighbouring links
    // overlap in every step and never touch.
    const std::uint32_t body = shapes_[a].body;
    if (body == shapes_[b].body &&
        !ownShapesMayTouch(multiBodies_[body], bodyStates_[body].firstShape, a, b))
      continue;
    if (reuse && (shapeMoved_[a] | shapeMoved_[b]) == 0) {
      reuseContacts(a, b);
    } else if (shapes_[a].type == ShapeType::Circle && shapes_[b].type == ShapeType::Circle) {
      // Most candidate pairs of a crowd are two circles out of reach: addContacts' own test
      // (the same bits) drops them here, before its call and its large frame (it has room for
      // the manifold of every pair of shape types); it does not test the others again.
      if (!circlesOutOfReach(geometry_[a], geometry_[b])) addContacts(a, b, true);
    } else {
      addContacts(a, b);
    }
  }
  findBorderContacts(reuse);
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

/// Up to this many unmoved borders have their reach updated together (the piles have 3).
constexpr std::size_t fusedBorders = 4;

/// 1 when @p box (margin included) reaches behind @p line, that is, unless it lies entirely
/// on the free side; else 0.
std::uint64_t reachesBehind(const BorderLine& line, Vector2 centre, Vector2 half) {
  const real extent = line.absNormal.x * half.x + line.absNormal.y * half.y;
  return std::uint64_t{dot(centre - line.point, line.normal) - extent <= 0};
}

}  // namespace

void Simulator::findBorderContacts(bool reuse) {
  // Borders skip the broad phase: each meets every grid shape whose box reaches behind its
  // line. Which shapes do is kept as one bit per grid shape and border, retested only for
  // moved shapes; the pairs are visited in the same order either way (border, then shape).
  const std::size_t count = gridShapes_.size();
  const std::size_t words = (count + 63) / 64;
  const std::size_t borders = borderShapes_.size();
  const bool remembered = restSkipping && reachShapes_ == count;
  reachShapes_ = count;
  borderReach_.resize(borders * words);
  const auto lineOf = [this](std::uint32_t border) {
    const Vector2 normal = geometry_[border].p1;
    return BorderLine{geometry_[border].p0, normal, {std::abs(normal.x), std::abs(normal.y)}};
  };
  bool anyBorderMoved = !remembered;
  for (std::size_t k = 0; k < borders && !anyBorderMoved; ++k)
    anyBorderMoved = shapeMoved_[borderShapes_[k]] != 0;
  const auto moved = [&](std::size_t k) {
    return anyBorderMoved && (!remembered || shapeMoved_[borderShapes_[k]] != 0);
  };
  if (!anyBorderMoved && borders <= fusedBorders) {
    // The common case, borders that stay: every border retests the moved shapes, so each
    // moved shape's box is read once for all of them.
    BorderLine lines[fusedBorders];
    for (std::size_t k = 0; k < borders; ++k) lines[k] = lineOf(borderShapes_[k]);
    for (std::size_t w = 0; w < words; ++w) {
      const std::uint64_t retest = gridMovedBits_[w];
      if (retest == 0) continue;
      std::uint64_t reach[fusedBorders];
      for (std::size_t k = 0; k < borders; ++k) reach[k] = borderReach_[k * words + w] & ~retest;
      for (std::uint64_t bits = retest; bits != 0; bits &= bits - 1) {
        const std::size_t i = 64 * w + static_cast<std::size_t>(std::countr_zero(bits));
        const BoundingBox& box = gridBoxes_[i];
        const Vector2 centre = (box.lower + box.upper) * real(0.5);
        const Vector2 half = (box.upper - box.lower) * real(0.5);
        const std::uint64_t bit = bits & (~bits + 1);
        for (std::size_t k = 0; k < borders; ++k)
          reach[k] |= bit & (std::uint64_t{0} - reachesBehind(lines[k], centre, half));
      }
      for (std::size_t k = 0; k < borders; ++k) borderReach_[k * words + w] = reach[k];
    }
  } else {
    for (std::size_t k = 0; k < borders; ++k) {
      const bool borderMoved = moved(k);
      const BorderLine line = lineOf(borderShapes_[k]);
      for (std::size_t w = 0; w < words; ++w) {
        const std::uint64_t retest = borderMoved ? wordMask(w, count) : gridMovedBits_[w];
        std::uint64_t& reach = borderReach_[k * words + w];
        reach &= ~retest;
        for (std::uint64_t bits = retest; bits != 0; bits &= bits - 1) {
          const std::size_t i = 64 * w + static_cast<std::size_t>(std::countr_zero(bits));
          const BoundingBox& box = gridBoxes_[i];
          const Vector2 centre = (box.lower + box.upper) * real(0.5);
          const Vector2 half = (box.upper - box.lower) * real(0.5);
          if (reachesBehind(line, centre, half) != 0) reach |= bits & (~bits + 1);
        }
      }
    }
  }
  for (std::size_t k = 0; k < borders; ++k) {
    const std::uint32_t border = borderShapes_[k];
    const bool borderMoved = moved(k);
    for (std::size_t w = 0; w < words; ++w) {
      for (std::uint64_t bits = borderReach_[k * words + w]; bits != 0; bits &= bits - 1) {
        const std::uint32_t shape =
            gridShapes_[64 * w + static_cast<std::size_t>(std::countr_zero(bits))];
        if (reuse && !borderMoved && shapeMoved_[shape] == 0)
          reuseContacts(border, shape);
        else
          addContacts(border, shape);
      }
    }
  }
}

void Simulator::reuseContacts(std::uint32_t shapeA, std::uint32_t shapeB) {
  // Neither shape moved and its filters did not change: the contacts are last detection's.
  // (Pairs within one multi-body object are always tested: whether they collide is its call.)
  if (shapes_[shapeB].type < shapes_[shapeA].type) std::swap(shapeA, shapeB);
  if (shapes_[shapeA].body == shapes_[shapeB].body) {
    addContacts(shapeA, shapeB);
    return;
  }
  if (!previousIndexed_) indexPreviousContacts();
  for (std::uint32_t k = previousStart_[shapeA]; k < previousStart_[shapeA + 1]; ++k) {
    const GlobalContactInfo& previous = previousContacts_[previousOrder_[k]];
    if (previous.shapeB != shapeB) continue;
    contacts.items_.push_back(previous);
    contacts.items_.back().force = 0;  // the solver's output, not detection's
    ++statistics_.reusedContacts;
  }
}

void Simulator::indexPreviousContacts() {
  // Counting sort of the last detection's contacts by shape A (a pair's points stay in order).
  previousStart_.assign(shapes_.size() + 1, 0);
  for (const GlobalContactInfo& c : previousContacts_) ++previousStart_[c.shapeA + 1];
  for (std::size_t s = 0; s < shapes_.size(); ++s) previousStart_[s + 1] += previousStart_[s];
  previousOrder_.resize(previousContacts_.size());
  for (std::uint32_t k = 0; k < previousContacts_.size(); ++k)
    previousOrder_[previousStart_[previousContacts_[k].shapeA]++] = k;
  // The fill advanced each start to the next shape's start: shift back.
  for (std::size_t s = shapes_.size(); s > 0; --s) previousStart_[s] = previousStart_[s - 1];
  previousStart_[0] = 0;
  previousIndexed_ = true;
}

void Simulator::addContacts(std::uint32_t shapeA, std::uint32_t shapeB, bool inReach) {
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

  const auto append = [&](const Manifold& manifold) {
    for (int i = 0; i < manifold.count; ++i) {
      const ManifoldPoint& p = manifold.points[i];
      contacts.items_.push_back({a.object, b.object, a.primitive, b.primitive, a.body, b.body,
                                 shapeA, shapeB, p.feature, p.point, manifold.normal, p.depth, 0});
    }
  };
  switch (a.type) {
    case ShapeType::HalfPlane:
      append(b.type == ShapeType::Circle
                 ? collideHalfPlaneCircle(ga.p0, ga.p1, gb.p0, gb.radius, margin)
                 : collideHalfPlaneCapsule(ga.p0, ga.p1, gb.p0, gb.p1, gb.radius, margin));
      break;
    case ShapeType::Circle:
      if (b.type == ShapeType::Circle) {
        if (!inReach && circlesOutOfReach(ga, gb)) return;
        append(collideCircles(ga.p0, ga.radius, gb.p0, gb.radius, margin));
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
  // world of many objects with few contacts pays for its contacts, not for its size.
  clearContactLists();
  objectContacts_.resize(2 * contacts.size());
  // objectContactCursor_ is zero for every object between calls: count, listing each object
  // at its first contact.
  const auto count = [this](std::uint32_t body) {
    if (objectContactCursor_[body]++ == 0) listedObjects_.push_back(body);
  };
  for (const GlobalContactInfo& c : contacts.items_) {
    count(c.bodyA);
    count(c.bodyB);
  }
  std::uint32_t offset = 0;
  for (const std::uint32_t i : listedObjects_) {
    const std::uint32_t n = objectContactCursor_[i];
    objectContactCursor_[i] = offset;
    offset += n;
  }
  for (std::uint32_t k = 0; k < contacts.size(); ++k) {
    const GlobalContactInfo& c = contacts.items_[k];
    objectContacts_[objectContactCursor_[c.bodyA]++] =
        ContactInfo{k, c.objectB, c.primitiveA, c.primitiveB, c.point, -c.normal, c.depth, 0};
    objectContacts_[objectContactCursor_[c.bodyB]++] =
        ContactInfo{k, c.objectA, c.primitiveB, c.primitiveA, c.point, c.normal, c.depth, 0};
  }
  // Each cursor ended where the next listed object's slice begins: slice, and zero it again.
  std::uint32_t begin = 0;
  for (const std::uint32_t i : listedObjects_) {
    const std::uint32_t end = objectContactCursor_[i];
    objects[i].contacts = std::span(objectContacts_).subspan(begin, end - begin);
    objectContactCursor_[i] = 0;
    begin = end;
  }
}

void Simulator::clearContactLists() {
  for (const std::uint32_t i : listedObjects_) objects[i].contacts = {};
  listedObjects_.clear();
}

}  // namespace thyrix
