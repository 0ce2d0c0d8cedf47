#include <ThyrixLite/Border.h>
#include <ThyrixLite/GaussSeidelSolver.h>
#include <ThyrixLite/InvalidArgument.h>
#include <ThyrixLite/NarrowPhase.h>
#include <ThyrixLite/Simulator.h>

#include <algorithm>
#include <cmath>

namespace thyrix {
namespace {

/// Makes room for @p needed elements, growing geometrically: registering objects one by one
/// must not reallocate every array each time (quadratic in the number of objects).
template <class T>
void reserveFor(std::vector<T>& vector, std::size_t needed) {
  if (needed > vector.capacity()) vector.reserve(std::max(needed, 2 * vector.capacity()));
}

}  // namespace

Simulator::Simulator(real timestep) : timestep_(timestep) {
  requirePositive(timestep, "Simulator.timestep");
}

void Simulator::setTimestep(real timestep) {
  requirePositive(timestep, "Simulator.timestep");
  timestep_ = timestep;
}

void Simulator::prepareRegistration(std::span<PhysicalObject* const> added) {
  // Reserve everything registration will append to, so completing it cannot fail.
  std::size_t shapes = 0;
  for (const PhysicalObject* object : added) shapes += object->primitives().size();
  reserveFor(shapes_, shapes_.size() + shapes);
  reserveFor(geometry_, shapes_.size() + shapes);
  reserveFor(borderShapes_, borderShapes_.size() + shapes);
  reserveFor(sensingPrimitives_, shapes_.size() + shapes);
  reserveFor(gridShapes_, gridShapes_.size() + shapes);
  reserveFor(gridBoxes_, gridShapes_.size() + shapes);
  reserveFor(bodies_, objects.size() + added.size());
  reserveFor(movable_, objects.size() + added.size());
  reserveFor(multiBodies_, objects.size() + added.size());
  reserveFor(objectContactStart_, objects.size() + added.size() + 1);
}

void Simulator::completeRegistration(PhysicalObject& object, std::size_t index) noexcept {
  for (Primitive* primitive : object.primitives()) {
    const auto shape = static_cast<std::uint32_t>(shapes_.size());
    shapes_.push_back({primitive, static_cast<std::uint32_t>(index), primitive->shapeType()});
    geometry_.push_back({});
    if (primitive->shapeType() == ShapeType::HalfPlane) {
      borderShapes_.push_back(shape);
    } else {
      gridShapes_.push_back(shape);
      gridBoxes_.push_back({});
    }
  }
  bodies_.push_back({});
  movable_.push_back(0);
  multiBodies_.push_back(dynamic_cast<MultiBodyObject*>(&object));
  hasMultiBodies_ = hasMultiBodies_ || multiBodies_.back() != nullptr;
  object.onRegistered(*this);
}

void Simulator::reserveContacts(std::size_t count) {
  contacts.items_.reserve(count);
  objectContacts_.reserve(2 * count);
  pairs_.reserve(count);
  rows_.reserve(count);
  islands_.reserve(objects.size(), count);
  baraff_.reserve(
      std::min(count, static_cast<std::size_t>(std::max(settings_.baraffMaxContacts, 0))));
  lastForces_.reserve(count);
  if (hasMultiBodies_) {  // general islands: their matrix and the objects' sides
    const std::size_t island = std::min(count, std::size_t{256});
    for (auto* buffer : {&denseSlack_, &denseForces_, &ownerMagnitudes_}) buffer->reserve(island);
    denseMatrix_.reserve(island * island);
    response_.reserve(island * island);
    sides_.reserve(2 * island);
    ownerForces_.reserve(2 * island);
    ownerRows_.reserve(2 * island);
    internal_.reserve(island);
    internalOwner_.reserve(island);
  }
}

void Simulator::advanceTime() {
  eraseContacts();
  detectContacts();
  indexContacts();
  applyMouseForce();
  for (PhysicalObject& object : objects) object.computeDerivativesWithoutContacts();
  solveContacts();
  for (PhysicalObject& object : objects) object.control();
  integrator.integrate(objects, timestep_);
  ++stepCount_;
  time_ += timestep_;
}

void Simulator::eraseContacts() {
  contacts.items_.clear();
  for (PhysicalObject& object : objects) object.contacts = {};
}

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
        const Vector2 axis = Vector2{primitive.halfLength(), 0}.rotated(primitive.alpha);
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

void Simulator::startDrag(PhysicalObject& object, Vector2 grabPoint) {
  requireFinite(grabPoint, "Simulator.startDrag.grabPoint");
  PhysicalObject* body = &object;
  if (auto* primitive = dynamic_cast<Primitive*>(&object)) body = &primitive->owner();
  if (std::none_of(objects.begin(), objects.end(),
                   [body](const PhysicalObject& o) { return &o == body; }))
    throw InvalidArgument("Simulator.startDrag.object", "is not registered with this simulator");
  dragged_ = body;
  real smallest = realMax;
  for (const Primitive* primitive : body->primitives())
    if (primitive->radius() > 0) smallest = std::min(smallest, primitive->radius());
  dragMaxStep_ = smallest;
  dragLocalPoint_ = body->toLocal(grabPoint);
  dragTarget_ = grabPoint;
}

void Simulator::dragTo(Vector2 target) {
  requireFinite(target, "Simulator.dragTo.target");
  dragTarget_ = target;
}

void Simulator::applyMouseForce() {
  if (dragged_ == nullptr || dragged_->fixed) return;
  PhysicalObject& body = *dragged_;
  const Vector2 point = body.toWorld(dragLocalPoint_);
  Vector2 step = (dragTarget_ - point) * dragResponse;
  const real longest = dragMaxStepFraction * dragMaxStep_;
  if (step.length() > longest) step = step * (longest / step.length());
  const Vector2 wanted = step / timestep_;
  // The grabbed point moves at K F for a force F there, K = m^-1 Id + I^-1 q q^T with
  // q = perp(point - r): solve K F = wanted so the point, not the centre, heads to the mouse.
  const Vector2 q = (point - body.r).perpendicular();
  const real im = body.inverseMass();
  const real ii = body.inverseInertia();
  const real kxx = im + ii * q.x * q.x;
  const real kxy = ii * q.x * q.y;
  const real kyy = im + ii * q.y * q.y;
  const real det = kxx * kyy - kxy * kxy;
  const Vector2 force{(kyy * wanted.x - kxy * wanted.y) / det,
                      (kxx * wanted.y - kxy * wanted.x) / det};
  body.applyForce(force, point);
}

void Simulator::solveContacts() {
  statistics_.islands = statistics_.solvedIslands = 0;
  statistics_.gaussSeidelSweeps = statistics_.baraffPivots = statistics_.baraffFallbacks = 0;
  const real dt = timestep_;
  internal_.clear();
  internalOwner_.clear();
  if (hasMultiBodies_) {
    for (std::uint32_t i = 0; i < objects.size(); ++i) {
      if (multiBodies_[i] == nullptr) continue;
      multiBodies_[i]->collectInternalConstraints(dt, internal_);
      internalOwner_.resize(internal_.size(), i);
    }
  }
  if (contacts.empty() && internal_.empty()) {
    lastForces_.reset(0);
    updateTactileSensors();
    return;
  }

  for (std::uint32_t i = 0; i < objects.size(); ++i) {
    const PhysicalObject& object = objects[i];
    // A multi-body object answers for itself (general islands): zero here, so the rigid
    // formulas ignore its sides.
    bodies_[i] =
        multiBodies_[i] != nullptr
            ? SolverBody{}
            : SolverBody{object.v, object.omega, object.inverseMass(), object.inverseInertia()};
    movable_[i] = movable(i) ? 1 : 0;
  }
  const real correction = settings_.penetrationCorrection;
  rows_.resize(contacts.size() + internal_.size());
  for (std::size_t k = 0; k < contacts.size(); ++k) {
    const GlobalContactInfo& c = contacts.items_[k];
    ContactConstraint& row = rows_[k];
    row.a = c.bodyA;
    row.b = c.bodyB;
    row.normal = c.normal;
    row.armA = cross(c.point - c.objectA->r, c.normal);
    row.armB = cross(c.point - c.objectB->r, c.normal);
    // Overlap: separate at a fraction of the depth per step; gap: approach at most by the gap.
    row.target = c.depth > 0 ? correction * c.depth / dt : c.depth / dt;
    row.force = 0;
  }
  // A joint limit is a row of its object alone; its Jacobian is the object's business.
  for (std::size_t j = 0; j < internal_.size(); ++j)
    rows_[contacts.size() + j] = {
        internalOwner_[j], internalOwner_[j], {}, 0, 0, internal_[j].target, 0};

  islands_.build(rows_, movable_);
  statistics_.islands = islands_.count();
  for (std::size_t i = 0; i < islands_.count(); ++i) {
    const auto island = islands_.island(i);
    const bool general =
        hasMultiBodies_ && std::any_of(island.begin(), island.end(), [this](std::uint32_t k) {
          return multiBodies_[rows_[k].a] != nullptr || multiBodies_[rows_[k].b] != nullptr;
        });
    if (general)
      solveGeneralIsland(island);
    else
      solveIsland(island);
  }

  for (std::size_t i = 0; i < objects.size(); ++i) {
    PhysicalObject& object = objects[i];
    if (object.fixed || multiBodies_[i] != nullptr) continue;
    object.v = bodies_[i].v;
    object.omega = bodies_[i].omega;
  }
  lastForces_.reset(contacts.size());
  for (std::size_t k = 0; k < contacts.size(); ++k) {
    GlobalContactInfo& c = contacts.items_[k];
    c.force = rows_[k].force;
    if (c.force > 0)
      lastForces_.insert(ContactForceCache::key(c.shapeA, c.shapeB, c.feature), c.force);
  }
  for (ContactInfo& info : objectContacts_) info.force = rows_[info.index].force;
  updateTactileSensors();
}

void Simulator::solveGeneralIsland(std::span<const std::uint32_t> island) {
  const std::size_t m = island.size();
  const std::size_t contactCount = contacts.size();
  // The multi-body sides of every row, as unit forces of their objects.
  sides_.clear();
  for (std::uint32_t p = 0; p < m; ++p) {
    const std::uint32_t k = island[p];
    if (k >= contactCount) {
      const std::size_t j = k - contactCount;
      sides_.push_back({internalOwner_[j], p, internal_[j].force});
      continue;
    }
    const GlobalContactInfo& c = contacts.items_[k];
    if (multiBodies_[c.bodyA] != nullptr)
      sides_.push_back({c.bodyA, p, {c.primitiveA, c.point, -c.normal, -1, 0}});
    if (multiBodies_[c.bodyB] != nullptr)
      sides_.push_back({c.bodyB, p, {c.primitiveB, c.point, c.normal, -1, 0}});
  }

  // The LCP: rigid couplings, then each multi-body object's response block.
  denseMatrix_.assign(m * m, 0);
  denseSlack_.resize(m);
  for (std::size_t p = 0; p < m; ++p) {
    const ContactConstraint& row = rows_[island[p]];
    denseSlack_[p] = row.normalVelocity(bodies_[row.a], bodies_[row.b]) - row.target;
    for (std::size_t q = 0; q < m; ++q)
      denseMatrix_[p * m + q] = rigidCoupling(row, rows_[island[q]], bodies_);
  }
  for (const Side& side : sides_)
    denseSlack_[side.row] += multiBodies_[side.owner]->velocityAlong(side.force);
  const auto forEachOwner = [this](auto&& visit) {
    for (std::size_t s = 0; s < sides_.size(); ++s) {
      const std::uint32_t owner = sides_[s].owner;
      bool seen = false;
      for (std::size_t t = 0; t < s && !seen; ++t) seen = sides_[t].owner == owner;
      if (seen) continue;
      ownerForces_.clear();
      ownerRows_.clear();
      for (std::size_t t = s; t < sides_.size(); ++t) {
        if (sides_[t].owner != owner) continue;
        ownerForces_.push_back(sides_[t].force);
        ownerRows_.push_back(sides_[t].row);
      }
      visit(*multiBodies_[owner]);
    }
  };
  forEachOwner([&](MultiBodyObject& object) {
    const std::size_t n = ownerForces_.size();
    response_.resize(n * n);
    object.responseMatrix(ownerForces_, response_);
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = 0; j < n; ++j)
        denseMatrix_[ownerRows_[i] * m + ownerRows_[j]] += response_[i * n + j];
  });

  denseForces_.assign(m, 0);
  if (std::any_of(denseSlack_.begin(), denseSlack_.end(), [](real s) { return s < 0; })) {
    ++statistics_.solvedIslands;
    bool solved = false;
    if (solverKind_ == ContactSolverKind::Baraff) {
      solved = baraff_.solveMatrix(denseMatrix_, denseSlack_, denseForces_);
      statistics_.baraffPivots += static_cast<std::size_t>(baraff_.lastPivotCount());
      if (!solved) {
        ++statistics_.baraffFallbacks;
        std::fill(denseForces_.begin(), denseForces_.end(), real(0));
      }
    }
    if (!solved)
      statistics_.gaussSeidelSweeps += static_cast<std::size_t>(
          GaussSeidelSolver::solveMatrix(denseMatrix_, denseSlack_, denseForces_, settings_));
  }

  // Forces to velocities: rigid bodies through their rows, multi-body objects by themselves.
  for (std::size_t p = 0; p < m; ++p) {
    ContactConstraint& row = rows_[island[p]];
    row.force = denseForces_[p];
    row.applyImpulse(row.force, bodies_[row.a], bodies_[row.b]);
  }
  forEachOwner([&](MultiBodyObject& object) {
    ownerMagnitudes_.resize(ownerForces_.size());
    for (std::size_t i = 0; i < ownerForces_.size(); ++i)
      ownerMagnitudes_[i] = denseForces_[ownerRows_[i]];
    object.applyConstraintForces(ownerForces_, ownerMagnitudes_);
  });
}

void Simulator::updateTactileSensors() {
  for (Primitive* primitive : sensingPrimitives_) primitive->tactile_.clear();
  for (const GlobalContactInfo& c : contacts.items_) {
    if (c.force <= 0) continue;
    if (c.primitiveA->tactile_.enabled()) c.primitiveA->touch(c.point, c.force);
    if (c.primitiveB->tactile_.enabled()) c.primitiveB->touch(c.point, c.force);
  }
  for (Primitive* primitive : sensingPrimitives_) primitive->tactile_.finish();
}

void Simulator::solveIsland(std::span<const std::uint32_t> island) {
  // An island whose contacts all hold without force needs no solve: its bodies keep u0.
  const bool satisfied = std::all_of(island.begin(), island.end(), [this](std::uint32_t k) {
    const ContactConstraint& row = rows_[k];
    return row.normalVelocity(bodies_[row.a], bodies_[row.b]) >= row.target;
  });
  if (satisfied) return;
  ++statistics_.solvedIslands;
  if (solverKind_ == ContactSolverKind::Baraff &&
      island.size() <= static_cast<std::size_t>(settings_.baraffMaxContacts)) {
    const bool solved = baraff_.solve(island, rows_, bodies_);
    statistics_.baraffPivots += static_cast<std::size_t>(baraff_.lastPivotCount());
    if (solved) return;
    ++statistics_.baraffFallbacks;
  }
  if (settings_.warmStart) {
    for (const std::uint32_t k : island) {
      const GlobalContactInfo& c = contacts.items_[k];
      ContactConstraint& row = rows_[k];
      row.force = lastForces_.find(ContactForceCache::key(c.shapeA, c.shapeB, c.feature));
      if (row.force > 0) row.applyImpulse(row.force, bodies_[row.a], bodies_[row.b]);
    }
  }
  statistics_.gaussSeidelSweeps +=
      static_cast<std::size_t>(GaussSeidelSolver::solve(island, rows_, bodies_, settings_));
}

}  // namespace thyrix
