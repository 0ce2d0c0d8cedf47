/// @file Simulator.cpp
/// @brief Registration, the order of one step, and dragging.
#include <ThyrixLite/Border.h>
#include <ThyrixLite/CappedRectangle.h>
#include <ThyrixLite/Circle.h>
#include <ThyrixLite/ComposedPhysicalObject.h>
#include <ThyrixLite/InvalidArgument.h>
#include <ThyrixLite/Simulator.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <typeinfo>

namespace thyrix {
namespace {

/// Makes room for @p needed elements, growing geometrically: registering objects one by one
/// must not reallocate every array each time (quadratic in the number of objects).
template <class T>
void reserveFor(std::vector<T>& vector, std::size_t needed) {
  if (needed > vector.capacity()) vector.reserve(std::max(needed, 2 * vector.capacity()));
}

/// True when @p object is exactly one of the core classes that keep PhysicalObject's step hooks
/// (computeDerivativesWithoutContacts, control, integrate, updateSensors): the simulator then
/// runs them without a virtual call, and skips the empty ones. Any other class, a user's
/// subclass of Circle included, is called through its virtual hooks.
bool hasDefaultHooks(const PhysicalObject& object) {
  const std::type_info& type = typeid(object);
  return type == typeid(Circle) || type == typeid(CappedRectangle) || type == typeid(Border) ||
         type == typeid(ComposedPhysicalObject);
}

}  // namespace

#ifdef NDEBUG
constexpr bool checkInputsByDefault = false;
#else
constexpr bool checkInputsByDefault = true;
#endif

Simulator::Simulator(real timestep)
    : World(timestep),
      checkInputs(checkInputsByDefault),
      integrator_(std::make_unique<Integrator>()) {}

void Simulator::setIntegrator(std::unique_ptr<Integrator> integrator) {
  if (!integrator) throw InvalidArgument("Simulator.setIntegrator.integrator", "must not be null");
  const Integrator& given = *integrator;
  eulerIntegrator_ = typeid(given) == typeid(Integrator);
  integrator_ = std::move(integrator);
}

void Simulator::setGravity(Vector2 gravity) {
  requireFinite(gravity, "Simulator.setGravity.gravity");
  // + 0 turns -0 into +0 (and leaves every other value as it is): the core shapes' shortcut for
  // an unpushed body can then write the field itself for +0 / m + gravity.
  gravity_ = {gravity.x + real(0), gravity.y + real(0)};
  hasGravity_ = gravity_.x != 0 || gravity_.y != 0;
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
  reserveFor(pairStart_, gridShapes_.size() + shapes + 1);
  reserveFor(bodies_, objects.size() + added.size());
  reserveFor(movable_, objects.size() + added.size());
  reserveFor(touched_, objects.size() + added.size());
  reserveFor(touchedStamp_, objects.size() + added.size());
  reserveFor(freeRunners_, objects.size() + added.size());
  reserveFor(multiBodies_, objects.size() + added.size());
  reserveFor(objectContactCursor_, objects.size() + added.size());
  // Rest skipping's memory of the shapes and bodies.
  std::size_t borders = borderShapes_.size();
  for (const PhysicalObject* object : added)
    for (const Primitive* primitive : object->primitives())
      borders += primitive->shapeType() == ShapeType::HalfPlane ? 1 : 0;
  const std::size_t gridShapes = gridShapes_.size() + shapes - (borders - borderShapes_.size());
  const std::size_t words = (gridShapes + 63) / 64;
  registrationFirst_ = objects.size();  // the others of added are its sub-bodies
  reserveFor(bodyStates_, objects.size() + added.size());
  reserveFor(awake_, objects.size() + added.size());
  reserveFor(awakeStamp_, objects.size() + added.size());
  reserveFor(pendingBodies_, objects.size() + added.size());
  reserveFor(customObjects_, objects.size() + added.size());
  reserveFor(listedObjects_, objects.size() + added.size() + 1);
  reserveFor(countedObjects_, objects.size() + added.size() + 1);
  reserveFor(shapePoses_, shapes_.size() + shapes);
  reserveFor(shapeMoved_, shapes_.size() + shapes);
  reserveFor(gridSlot_, shapes_.size() + shapes);
  reserveFor(gridMovedBits_, words);
  reserveFor(borderReach_, borders * words);
  reserveFor(previousStart_, shapes_.size() + shapes + 2);
  reserveFor(pairChains_, shapes_.size() + shapes);
  reserveFor(previousChains_, shapes_.size() + shapes);
}

void Simulator::completeRegistration(PhysicalObject& object, std::size_t index) noexcept {
  BodyState state;
  state.object = &object;
  state.firstShape = static_cast<std::uint32_t>(shapes_.size());
  state.shapeCount = static_cast<std::uint32_t>(object.primitives().size());
  state.standalone = state.shapeCount == 1 && object.primitives()[0] == &object;
  state.restsCheaply = state.standalone || state.shapeCount == 0;
  state.standaloneCircle =
      state.standalone && object.primitives()[0]->shapeType() == ShapeType::Circle;
  state.custom = !hasDefaultHooks(object);
  state.alwaysAwake = state.custom || index != registrationFirst_;
  bodyStates_.push_back(state);  // unknown: its first detection computes everything
  object.index_ = static_cast<std::uint32_t>(index);
  for (Primitive* primitive : object.primitives()) {
    const auto shape = static_cast<std::uint32_t>(shapes_.size());
    shapes_.push_back(
        {primitive, &object, static_cast<std::uint32_t>(index), 0, primitive->shapeType(), false});
    // A primitive's radius and half length are fixed at construction: kept here once, with
    // the margin of the fraction the cached margins were computed with (updateGeometry
    // recomputes every margin when the fraction changes).
    geometry_.push_back({{}, {}, primitive->radius(), geometryFraction_ * primitive->radius()});
    shapePoses_.push_back({});
    shapePoses_.back().halfLength = primitive->halfLength();
    shapeMoved_.push_back(1);
    if (primitive->shapeType() == ShapeType::HalfPlane) {
      borderShapes_.push_back(shape);
      gridSlot_.push_back(~0u);
    } else {
      smallestRadius_ = std::min(smallestRadius_, primitive->radius());
      gridSlot_.push_back(static_cast<std::uint32_t>(gridShapes_.size()));
      gridShapes_.push_back(shape);
      gridBoxes_.push_back({});
    }
  }
  if (!hasDefaultHooks(object)) customObjects_.push_back(static_cast<std::uint32_t>(index));
  bodies_.push_back({});
  movable_.push_back(0);
  touchedStamp_.push_back(0);
  awake_.push_back(0);
  awakeStamp_.push_back(0);
  objectContactCursor_.push_back(0);
  multiBodies_.push_back(dynamic_cast<MultiBodyObject*>(&object));
  hasMultiBodies_ = hasMultiBodies_ || multiBodies_.back() != nullptr;
  object.onRegistered(*this);
}

void Simulator::reserveContacts(std::size_t count) {
  contacts.items_.reserve(count);
  previousContacts_.reserve(count);  // the two swap at each step
  previousOrder_.reserve(count);
  previousSortedKeys_.reserve(count);
  if (contactPairs_.size() < count) contactPairs_.resize(count);  // (sized ahead: see there)
  if (previousPairs_.size() < count) previousPairs_.resize(count);
  objectContacts_.reserve(2 * count);
  pairs_.reserve(count);
  sortedPairs_.reserve(count);  // (sortPairs() swaps the two)
  broadPhase_.reservePairs(count);
  rows_.reserve(count);
  if (activeRows_.size() < count) activeRows_.resize(count);
  islands_.reserve(objects.size(), count);
  baraff_.reserve(
      std::min(count, static_cast<std::size_t>(std::max(settings_.baraffMaxIslandContacts, 0))));
  gaussSeidel_.reserve(objects.size(), count);
  if (hasMultiBodies_) {  // general islands: their matrix and the objects' sides
    const std::size_t island = std::min(count, std::size_t{256});
    for (auto* buffer : {&denseSlack_, &denseForces_, &ownerMagnitudes_}) buffer->reserve(island);
    denseMatrix_.reserve(island * island);
    response_.reserve(island * island);
    sides_.reserve(2 * island);
    sideOrder_.reserve(2 * island);
    ownerForces_.reserve(2 * island);
    ownerRows_.reserve(2 * island);
    internal_.reserve(island);
    internalOwner_.reserve(island);
  }
}

void Simulator::advanceTime() {
  if (checkInputs) checkFinite();
  eraseContacts();
  // Rest applies within advanceTime() only (the phases run by hand visit every body): its
  // detection lists the awake bodies, which this step's phases 5, 6 and 8 then read.
  struct Stepping {
    bool& flag;
    explicit Stepping(bool& f) : flag(f) { flag = true; }
    ~Stepping() { flag = false; }
    Stepping(const Stepping&) = delete;
    Stepping& operator=(const Stepping&) = delete;
  } stepping(stepping_);
  detectContacts();  // (the objects' lists are made when first read: PhysicalObject::contacts())
  const bool listsAfter = listsAfterSolve();
  applyMouseForce();
  // Rest: phase 5 for the awake bodies only; a body dragged while at rest wakes.
  if (awakeValid_) {
    if (dragged_ != nullptr) listAwake(draggedIndex_);
    computeAwakeDerivatives();
  } else {
    computeDerivativesWithoutContacts();
  }
  statistics_.substeps = 1;
  mayDivide_ = listsAfter && eulerIntegrator_;
  solveContacts();
  mayDivide_ = false;
  if (parts_ > 1) {  // (the objects still hold their free velocities)
    statistics_.awakeBodies = objects.size();
    awakeValid_ = false;
    stepInParts();
    World::advanceTime();
    return;
  }
  if (referenceMode) {
    for (PhysicalObject& object : objects) object.control();
  } else {
    for (const std::uint32_t i : customObjects_) objects[i].control();  // the others do nothing
  }
  // Phase 8: explicit Euler in its loop without virtual calls, unless replaced.
  // (A detection run again in the solve updated every body: awakeValid_ is then false.)
  if (eulerIntegrator_ && awakeValid_)
    integrateAwake(timestep());
  else if (eulerIntegrator_ && !referenceMode)
    Integrator::integrateExcept(objects, customObjects_, timestep());
  else
    integrator_->integrate(*this, timestep());
  statistics_.awakeBodies = awakeValid_ ? awakeCount_ : objects.size();
  awakeValid_ = false;
  World::advanceTime();
}

void Simulator::computeAwakeDerivatives() {
  // In registration order, as the full loop: an Elastoid pushes its bodies before they
  // compute their velocities. The bodies the loop leaves out are unpushed with v and omega
  // +0, the very values their hook would write. (The bodies that move otherwise than the field
  // are noted, as in computeDerivativesWithoutContacts().)
  freeRunners_.clear();
  for (std::size_t k = 0; k < awakeCount_; ++k) {
    const std::uint32_t i = awake_[k];
    PhysicalObject& object = objects[i];
    if (bodyStates_[i].custom) {
      object.computeDerivativesWithoutContacts();
      if (!object.primitives().empty()) noteFreeMotion(object);
    } else if (!object.velocitiesFromAccumulators<false>({})) {
      noteFreeMotion(object);
    }
  }
}

void Simulator::integrateAwake(real dt) {
  // The bodies left out have v and omega +0 and a pose that is not -0 (a body whose pose was
  // written is awake): r += 0 would leave every bit as it is.
  for (std::size_t k = 0; k < awakeCount_; ++k) {
    const std::uint32_t i = awake_[k];
    PhysicalObject& object = objects[i];
    if (bodyStates_[i].custom)
      object.integrate(dt);
    else
      object.PhysicalObject::integrate(dt);
  }
}

void Simulator::wake(PhysicalObject& object) {
  const std::size_t index = indexOf(object);
  if (index == objects.size())
    throw InvalidArgument("Simulator.wake.object", "is not registered with this simulator");
  // Never matching its filters, the body is compared and listed awake at the next detection;
  // within a step (a hook's call), it is listed now, for the phases still to come.
  bodyStates_[index].filterKey = ~std::uint64_t{0};
  if (stepping_ && awakeValid_) listAwake(static_cast<std::uint32_t>(index));
}

void Simulator::checkFinite() const {
  // x * 0 is 0 for a finite x and NaN for an infinite or NaN one: one sum tells whether a
  // field is not finite (or two finite ones overflowed: then the search below finds none).
  real zero = 0;
  for (const PhysicalObject& object : objects)
    zero += (object.r.x + object.r.y + object.alpha + object.externalForce.x +
             object.externalForce.y + object.externalTorque) *
            0;
  if (zero == 0) [[likely]]
    return;
  for (std::size_t i = 0; i < objects.size(); ++i) {
    const PhysicalObject& object = objects[i];
    const std::string where = " of objects[" + std::to_string(i) + "]";
    const auto check = [&](const char* name, real value) {
      if (!std::isfinite(value))
        throw InvalidArgument(object.typeName() + "." + name,
                              where + " must be finite (got " + std::to_string(value) +
                                  "): set between steps, refused before the step");
    };
    check("r", object.r.x);
    check("r", object.r.y);
    check("alpha", object.alpha);
    check("externalForce", object.externalForce.x);
    check("externalForce", object.externalForce.y);
    check("externalTorque", object.externalTorque);
  }
}

void Simulator::computeDerivativesInGravity() {
  // The field is decided once per step, not per object (computeDerivativesWithoutContacts()).
  // The core shapes add it to their velocity in their own pass (no extra pass over the objects,
  // no virtual call); the other objects add their weight to their accumulators by one virtual
  // call each, just before their own hook, since only they know where their mass is (an
  // articulated agent's links; an elastoid has none, its bodies are objects of their own).
  const Vector2 gravity = gravity_;
  forEachInRuns(
      objects, customObjects_,
      [this, gravity](PhysicalObject& object) {
        if (!object.computeDerivativesInField(gravity)) [[unlikely]]
          noteFreeMotion(object);
      },
      [this, gravity](PhysicalObject& object) {
        object.applyWeight(gravity);
        object.computeDerivativesWithoutContacts();
        if (!object.primitives().empty()) noteFreeMotion(object);
      });
}

void Simulator::eraseContacts() {
  // Last step's contacts are what rest skipping reuses: kept aside, not destroyed.
  previousValid_ = contactsComplete_;
  previousSolved_ = contactsComplete_ && contactsSolved_;
  contactsSolved_ = false;
  if (contactsComplete_) {
    std::swap(contacts.items_, previousContacts_);
    std::swap(contactPairs_, previousPairs_);  // (what finds them by pair goes with them)
    std::swap(pairChains_, previousChains_);
    previousListStamp_ = listStamp_;
  }
  contacts.items_.clear();
  contactsComplete_ = false;
  clearContactLists();
  listsPending_ = false;  // (no contact: every list is empty)
  resetCounts();          // (the list is empty: every contact is counted)
  countsComplete_ = true;
}

std::size_t Simulator::indexOf(const PhysicalObject& object) const {
  std::size_t i = 0;
  while (i < objects.size() && &objects[i] != &object) ++i;
  return i;
}

void Simulator::startDrag(PhysicalObject& object, Vector2 grabPoint) {
  requireFinite(grabPoint, "Simulator.startDrag.grabPoint");
  PhysicalObject* body = &object;
  if (auto* primitive = dynamic_cast<Primitive*>(&object)) body = &primitive->owner();
  const std::size_t index = indexOf(*body);
  if (index == objects.size())
    throw InvalidArgument("Simulator.startDrag.object", "is not registered with this simulator");
  if (body->primitives().empty())  // an elastoid, say: drag one of its bodies instead
    throw InvalidArgument("Simulator.startDrag.object", "has no shape of its own to grab");
  dragged_ = body;
  draggedIndex_ = static_cast<std::uint32_t>(index);
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
  const Vector2 wanted = step / timestep();
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

}  // namespace thyrix
