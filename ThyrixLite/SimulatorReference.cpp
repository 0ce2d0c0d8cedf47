/// @file SimulatorReference.cpp
/// @brief The plain algorithm that Simulator::referenceMode runs in place of every cache and
/// shortcut: each shape placed from its pose, every pair of boxes tested, every border against
/// every shape, the last step's forces found by a scan.
#include <ThyrixLite/Border.h>
#include <ThyrixLite/Simulator.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace thyrix {
namespace {

/// Widens the box (@p boxMin, @p boxMax) to take in the box (@p lower, @p upper).
void include(Vector2& boxMin, Vector2& boxMax, Vector2 lower, Vector2 upper) {
  boxMin = {std::min(boxMin.x, lower.x), std::min(boxMin.y, lower.y)};
  boxMax = {std::max(boxMax.x, upper.x), std::max(boxMax.y, upper.y)};
}

/// A shape's travel: how far its ends moved since they were last placed (|dx| + |dy|, the
/// larger of the two ends), times @p factor, at most its @p radius.
real travelOf(Vector2 p0, Vector2 p1, Vector2 last0, Vector2 last1, real factor, real radius) {
  const Vector2 d0 = p0 - last0;
  const Vector2 d1 = p1 - last1;
  return std::min(
      factor * std::max(std::abs(d0.x) + std::abs(d0.y), std::abs(d1.x) + std::abs(d1.y)), radius);
}

}  // namespace

void Simulator::updateGeometryPlainly() {
  // The margins are the fraction of each radius, but while a redetection's widened margins
  // are in force (widenMargins()).
  marginsWidened_ = false;
  geometryFraction_ = settings_.speculativeFraction;
  geometryTravel_ = settings_.speculativeTravel;
  if (!widening_)
    for (ShapeGeometry& g : geometry_) g.margin = geometryFraction_ * g.radius;
  sensingPrimitives_.clear();
  for (std::uint32_t index = 0; index < bodyStates_.size(); ++index) {
    BodyState& state = bodyStates_[index];
    PhysicalObject& body = *state.object;
    const bool known = state.fixed != BodyState::unknown;  // detected before: it travelled
    state.fixed = body.fixed ? 1 : 0;
    state.group = body.collisionGroup;
    state.movable = movable(index);
    state.r = body.r;  // (what the contact lists' p is relative to: the pose detected at)
    state.alpha = body.alpha;
    Vector2 boxMin{realMax, realMax};
    Vector2 boxMax{-realMax, -realMax};
    for (std::uint32_t s = state.firstShape; s < state.firstShape + state.shapeCount; ++s) {
      Shape& shape = shapes_[s];
      shape.group = state.group;
      shape.movable = state.movable;
      Primitive& primitive = *shape.primitive;
      if (primitive.sensing_) sensingPrimitives_.push_back(&primitive);
      if (!state.standalone && primitive.rigidlyAttached()) primitive.followOwner();
      ShapeGeometry& g = geometry_[s];
      const Vector2 r = primitive.r;
      if (shape.type == ShapeType::HalfPlane) {  // unbounded: no box, not in the grid
        g.p0 = r;
        g.p1 = static_cast<const Border&>(primitive).normal();
        continue;
      }
      const Vector2 last0 = g.p0;
      const Vector2 last1 = g.p1;
      if (shape.type == ShapeType::Capsule) {
        const Vector2 axis = primitive.direction() * shapePoses_[s].halfLength;
        g.p0 = r - axis;
        g.p1 = r + axis;
      } else {  // a circle's axis is its centre twice
        g.p0 = r;
        g.p1 = r;
      }
      g.travel = known ? travelOf(g.p0, g.p1, last0, last1, geometryTravel_, g.radius) : 0;
      const Vector2 least{std::min(g.p0.x, g.p1.x), std::min(g.p0.y, g.p1.y)};
      const Vector2 most{std::max(g.p0.x, g.p1.x), std::max(g.p0.y, g.p1.y)};
      include(boxMin, boxMax, least - Vector2{g.radius, g.radius},
              most + Vector2{g.radius, g.radius});
      const real widening = g.radius + g.margin + g.travel;
      gridBoxes_[gridSlot_[s]] = {least - Vector2{widening, widening},
                                  most + Vector2{widening, widening}};
    }
    body.boxMin = boxMin;
    body.boxMax = boxMax;
  }
}

void Simulator::findPairsPlainly() {
  pairs_.clear();
  const std::size_t count = gridBoxes_.size();
  for (std::uint32_t i = 0; i < count; ++i)
    for (std::uint32_t j = i + 1; j < count; ++j)
      if (gridBoxes_[i].overlaps(gridBoxes_[j])) pairs_.push_back({i, j});
}

void Simulator::findBorderContactsPlainly() {
  for (const std::uint32_t border : borderShapes_)
    for (const std::uint32_t shape : gridShapes_) addContactsPlainly(border, shape);
}

real Simulator::previousForcePlainly(const GlobalContactInfo& contact) const {
  for (const GlobalContactInfo& previous : previousContacts_)
    if (previous.sameContactAs(contact)) return previous.force;
  return 0;
}

void Simulator::forgetCaches() {
  // Every body is looked at again (its filters never match), every shape placed again with
  // its travel from its last place (kept in geometry_), every border's reach tested again,
  // the broad phase without memory of other calls' boxes.
  const real unknownPose = std::numeric_limits<real>::quiet_NaN();
  for (std::size_t i = 0; i < bodyStates_.size(); ++i) {
    BodyState& body = bodyStates_[i];
    body.r = {unknownPose, unknownPose};
    body.alpha = unknownPose;
    body.filterKey = ~std::uint64_t{0};
  }
  for (ShapePose& pose : shapePoses_) {
    pose.r = {unknownPose, unknownPose};  // (a capsule's axis is computed again)
    pose.alpha = unknownPose;
  }
  reachShapes_ = std::numeric_limits<std::size_t>::max();
  broadPhase_ = BroadPhase();
}

}  // namespace thyrix
