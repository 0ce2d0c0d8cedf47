/// @file SimulatorContacts.cpp
/// @brief Phases 2 and 3 of a step: shape geometry, broad and narrow phase, contact indexing.
#include <ThyrixLite/Border.h>
#include <ThyrixLite/NarrowPhase.h>
#include <ThyrixLite/Simulator.h>

#include <algorithm>
#include <cmath>

namespace thyrix {

void Simulator::updateGeometry() {
  const real fraction = settings_.speculativeFraction;
  for (PhysicalObject& object : objects) {
    object.boxMin = {realMax, realMax};
    object.boxMax = {-realMax, -realMax};
  }
  sensingPrimitives_.clear();
  for (std::size_t s = 0; s < shapes_.size(); ++s) {
    Primitive& primitive = *shapes_[s].primitive;
    primitive.followOwner();
    if (primitive.tactile_.enabled()) sensingPrimitives_.push_back(&primitive);
    ShapeGeometry& g = geometry_[s];
    g.radius = primitive.radius();
    g.margin = fraction * g.radius;
    Vector2 lower;
    Vector2 upper;
    switch (shapes_[s].type) {
      case ShapeType::HalfPlane:
        g.p0 = primitive.r;
        g.p1 = static_cast<const Border&>(primitive).normal();
        continue;  // unbounded: no box
      case ShapeType::Circle:
        g.p0 = primitive.r;
        lower = g.p0 - Vector2{g.radius, g.radius};
        upper = g.p0 + Vector2{g.radius, g.radius};
        break;
      case ShapeType::Capsule: {
        const Vector2 axis = primitive.direction() * primitive.halfLength();
        g.p0 = primitive.r - axis;
        g.p1 = primitive.r + axis;
        lower = Vector2{std::min(g.p0.x, g.p1.x), std::min(g.p0.y, g.p1.y)} -
                Vector2{g.radius, g.radius};
        upper = Vector2{std::max(g.p0.x, g.p1.x), std::max(g.p0.y, g.p1.y)} +
                Vector2{g.radius, g.radius};
        break;
      }
    }
    PhysicalObject& body = objects[shapes_[s].body];
    body.boxMin = {std::min(body.boxMin.x, lower.x), std::min(body.boxMin.y, lower.y)};
    body.boxMax = {std::max(body.boxMax.x, upper.x), std::max(body.boxMax.y, upper.y)};
  }
  for (std::size_t i = 0; i < gridShapes_.size(); ++i) {
    const std::uint32_t s = gridShapes_[i];
    // The shape's own box (not the body's), widened by its speculative margin.
    const ShapeGeometry& g = geometry_[s];
    const Vector2 reach{g.radius + g.margin, g.radius + g.margin};
    if (shapes_[s].type == ShapeType::Circle) {
      gridBoxes_[i] = {g.p0 - reach, g.p0 + reach};
    } else {
      gridBoxes_[i] = {Vector2{std::min(g.p0.x, g.p1.x), std::min(g.p0.y, g.p1.y)} - reach,
                       Vector2{std::max(g.p0.x, g.p1.x), std::max(g.p0.y, g.p1.y)} + reach};
    }
  }
}

void Simulator::detectContacts() {
  updateGeometry();
  broadPhase_.findPairs(gridBoxes_, pairs_);
  for (const BoxPair& pair : pairs_) addContacts(gridShapes_[pair.first], gridShapes_[pair.second]);
  for (const std::uint32_t border : borderShapes_) {
    const Vector2 point = geometry_[border].p0;
    const Vector2 normal = geometry_[border].p1;
    for (std::size_t i = 0; i < gridShapes_.size(); ++i) {
      // The box (margin included) lies entirely on the free side: no contact is possible.
      const BoundingBox& box = gridBoxes_[i];
      const Vector2 centre = (box.lower + box.upper) * real(0.5);
      const Vector2 half = (box.upper - box.lower) * real(0.5);
      const real reach = std::abs(normal.x) * half.x + std::abs(normal.y) * half.y;
      if (dot(centre - point, normal) - reach > 0) continue;
      addContacts(border, gridShapes_[i]);
    }
  }
  statistics_.contacts = contacts.size();
  for (PhysicalObject& object : objects) object.updateSensors(*this);
}

void Simulator::addContacts(std::uint32_t shapeA, std::uint32_t shapeB) {
  if (shapes_[shapeB].type < shapes_[shapeA].type) std::swap(shapeA, shapeB);
  const Shape& a = shapes_[shapeA];
  const Shape& b = shapes_[shapeB];
  if (a.body == b.body) {
    const MultiBodyObject* multi = multiBodies_[a.body];
    if (multi == nullptr || !multi->selfCollides(*a.primitive, *b.primitive)) return;
  }
  PhysicalObject& bodyA = objects[a.body];
  PhysicalObject& bodyB = objects[b.body];
  if (!movable(a.body) && !movable(b.body)) return;
  if (bodyA.collisionGroup != 0 && bodyA.collisionGroup == bodyB.collisionGroup) return;
  const ShapeGeometry& ga = geometry_[shapeA];
  const ShapeGeometry& gb = geometry_[shapeB];
  const real margin = a.type == ShapeType::HalfPlane ? gb.margin : std::min(ga.margin, gb.margin);

  Manifold manifold;
  switch (a.type) {
    case ShapeType::HalfPlane:
      manifold = b.type == ShapeType::Circle
                     ? collideHalfPlaneCircle(ga.p0, ga.p1, gb.p0, gb.radius, margin)
                     : collideHalfPlaneCapsule(ga.p0, ga.p1, gb.p0, gb.p1, gb.radius, margin);
      break;
    case ShapeType::Circle:
      manifold = b.type == ShapeType::Circle
                     ? collideCircles(ga.p0, ga.radius, gb.p0, gb.radius, margin)
                     : collideCircleCapsule(ga.p0, ga.radius, gb.p0, gb.p1, gb.radius, margin);
      break;
    case ShapeType::Capsule:
      manifold = collideCapsules(ga.p0, ga.p1, ga.radius, gb.p0, gb.p1, gb.radius, margin);
      break;
  }
  for (int i = 0; i < manifold.count; ++i) {
    const ManifoldPoint& p = manifold.points[i];
    GlobalContactInfo contact;
    contact.objectA = &bodyA;
    contact.objectB = &bodyB;
    contact.primitiveA = a.primitive;
    contact.primitiveB = b.primitive;
    contact.bodyA = a.body;
    contact.bodyB = b.body;
    contact.shapeA = shapeA;
    contact.shapeB = shapeB;
    contact.feature = p.feature;
    contact.point = p.point;
    contact.normal = manifold.normal;
    contact.depth = p.depth;
    contacts.items_.push_back(contact);
  }
}

void Simulator::indexContacts() {
  // Counting sort by object into one array; each object's `contacts` is its slice of it.
  const std::size_t objectCount = objects.size();
  objectContactStart_.assign(objectCount + 1, 0);
  for (const GlobalContactInfo& c : contacts.items_) {
    ++objectContactStart_[c.bodyA + 1];
    ++objectContactStart_[c.bodyB + 1];
  }
  for (std::size_t i = 0; i < objectCount; ++i)
    objectContactStart_[i + 1] += objectContactStart_[i];
  objectContacts_.resize(2 * contacts.size());
  for (std::uint32_t k = 0; k < contacts.size(); ++k) {
    const GlobalContactInfo& c = contacts.items_[k];
    objectContacts_[objectContactStart_[c.bodyA]++] =
        ContactInfo{k, c.objectB, c.primitiveA, c.primitiveB, c.point, -c.normal, c.depth, 0};
    objectContacts_[objectContactStart_[c.bodyB]++] =
        ContactInfo{k, c.objectA, c.primitiveB, c.primitiveA, c.point, c.normal, c.depth, 0};
  }
  // The fill advanced each start to the next object's start: walk back to slice.
  std::uint32_t begin = 0;
  for (std::size_t i = 0; i < objectCount; ++i) {
    const std::uint32_t end = objectContactStart_[i];
    objects[i].contacts = std::span(objectContacts_).subspan(begin, end - begin);
    begin = end;
  }
}

}  // namespace thyrix
