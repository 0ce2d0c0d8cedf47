#include "ChipmunkScenes.h"

#include <chipmunk/chipmunk.h>

static_assert(CP_VERSION_MAJOR == 7, "the comparison is written for Chipmunk 7");

#include <algorithm>
#include <cmath>
#include <functional>

namespace thyrix::peers {
namespace {

cpVect vec(Point p) { return cpv(p.x, p.y); }

struct ArbiterCount {
  cpBody* body;
  std::size_t points;
};

/// Counts each arbiter once: from its dynamic body with the lower address, or from its only
/// dynamic body when the other is static.
void countArbiter(cpBody* body, cpArbiter* arbiter, void* data) {
  auto& count = *static_cast<ArbiterCount*>(data);
  cpBody* a = nullptr;
  cpBody* b = nullptr;
  cpArbiterGetBodies(arbiter, &a, &b);
  cpBody* other = a == body ? b : a;
  if (cpBodyGetType(other) != CP_BODY_TYPE_DYNAMIC || std::less<cpBody*>()(body, other))
    count.points += static_cast<std::size_t>(cpArbiterGetCount(arbiter));
}

}  // namespace

ChipmunkScene::ChipmunkScene(Point gravity, double timestep)
    : space_(cpSpaceNew()), timestep_(timestep) {
  cpSpaceSetGravity(space_, vec(gravity));
  // Chipmunk's damping is the fraction of velocity kept after one second, applied per step as
  // v <- v d^dt before the forces add F dt / m. Keeping 1 - c dt per step makes a force F
  // reach exactly F / (m c), as in Box2D (whose damping divides by 1 + c dt) and Thyrix.
  cpSpaceSetDamping(space_, std::pow(1 - peerDamping * timestep, 1 / timestep));
}

ChipmunkScene::~ChipmunkScene() {
  // The space first (it wakes its bodies as it goes), then what was in it.
  cpSpaceFree(space_);
  for (cpConstraint* constraint : constraints_) cpConstraintFree(constraint);
  for (cpShape* shape : shapes_) cpShapeFree(shape);
  for (cpBody* body : bodies_) cpBodyFree(body);
}

void ChipmunkScene::addWall(double x0, double y0, double x1, double y1) {
  addShape(cpBoxShapeNew2(cpSpaceGetStaticBody(space_), cpBBNew(x0, y0, x1, y1), 0));
}

cpBody& ChipmunkScene::addBody(Point position, double inertia) {
  cpBody* body = cpSpaceAddBody(space_, cpBodyNew(peerMass, inertia));
  cpBodySetPosition(body, vec(position));
  bodies_.push_back(body);
  return *body;
}

void ChipmunkScene::addShape(cpShape* shape) {
  cpShapeSetFriction(shape, 0);
  cpShapeSetElasticity(shape, 0);
  shapes_.push_back(cpSpaceAddShape(space_, shape));
}

cpConstraint& ChipmunkScene::addConstraint(cpConstraint* constraint) {
  constraints_.push_back(cpSpaceAddConstraint(space_, constraint));
  return *constraint;
}

cpBody& ChipmunkScene::addCircle(Point position, double radius) {
  cpBody& body = addBody(position, cpMomentForCircle(peerMass, 0, radius, cpvzero));
  addShape(cpCircleShapeNew(&body, radius, cpvzero));
  return body;
}

void ChipmunkScene::stepSpace() { cpSpaceStep(space_, timestep_); }

std::size_t ChipmunkScene::contactCount() const {
  ArbiterCount count{nullptr, 0};
  for (cpBody* body : bodies_) {
    count.body = body;
    cpBodyEachArbiter(
        body, [](cpBody* b, cpArbiter* arbiter, void* data) { countArbiter(b, arbiter, data); },
        &count);
  }
  return count.points;
}

std::uint64_t ChipmunkScene::stateHash() const {
  StateHash hash;
  for (const cpBody* body : bodies_) {
    const cpVect p = cpBodyGetPosition(body);
    const cpVect v = cpBodyGetVelocity(body);
    hash.mix(p.x);
    hash.mix(p.y);
    hash.mix(cpBodyGetAngle(body));
    hash.mix(v.x);
    hash.mix(v.y);
    hash.mix(cpBodyGetAngularVelocity(body));
  }
  return hash.value();
}

std::vector<Point> ChipmunkScene::centres() const {
  std::vector<Point> result;
  result.reserve(bodies_.size());
  for (const cpBody* body : bodies_) {
    const cpVect p = cpBodyGetPosition(body);
    result.push_back({p.x, p.y});
  }
  return result;
}

ChipmunkArena::ChipmunkArena(const ArenaLayout& layout)
    : ChipmunkScene({0, 0}, layout.timestep), layout_(layout) {
  const double s = layout.size;
  const double t = 1;  // wall thickness
  addWall(-t, -t, s + t, 0);
  addWall(-t, s, s + t, s + t);
  addWall(-t, -t, 0, s + t);
  addWall(s, -t, s + t, s + t);
  for (const AgentLayout& a : layout.agents) {
    cpBody* circles[2] = {nullptr, nullptr};
    for (int i = 0; i < 2; ++i) {
      circles[i] = &addCircle(a.circle[i], layout.agentRadius);
      agents_.push_back(circles[i]);
    }
    // A pin joint keeps the anchors at their initial distance; its bodies do not collide, like
    // the bodies of a Thyrix elastoid.
    cpConstraint& joint = addConstraint(cpPinJointNew(circles[0], circles[1], cpvzero, cpvzero));
    cpConstraintSetCollideBodies(&joint, cpFalse);
  }
  for (const Point p : layout.balls) addCircle(p, layout.ballRadius);
}

void ChipmunkArena::step() {
  push_.next();
  for (std::size_t i = 0; i < agents_.size(); ++i)
    cpBodySetForce(agents_[i], cpvmult(vec(push_.direction(i / 2)), layout_.pushForce));
  stepSpace();
}

ChipmunkPile::ChipmunkPile(const PileLayout& layout)
    : ChipmunkScene({0, -layout.gravity}, layout.timestep), layout_(layout) {
  const double t = 2;
  const double height = layout.top + 10;
  addWall(layout.leftWall - t, -t, layout.width + t, 0);
  addWall(layout.leftWall - t, -t, layout.leftWall, height);
  addWall(layout.width, -t, layout.width + t, height);
  bodies_.reserve(layout.circles.size());
  for (const Point p : layout.circles) addCircle(p, layout.radius);
}

ChipmunkChain::ChipmunkChain(const ChainLayout& layout)
    : ChipmunkScene({0, -layout.gravity}, layout.timestep) {
  cpBody* previous = cpSpaceGetStaticBody(space_);
  for (int i = 0; i < layout.links; ++i) {
    cpBody& body = addBody(layout.centre(i), layout.inertia());
    addShape(cpSegmentShapeNew(&body, cpv(-layout.halfLength, 0), cpv(layout.halfLength, 0),
                               layout.radius));
    cpConstraint& joint = addConstraint(cpPivotJointNew(previous, &body, vec(layout.joint(i))));
    cpConstraintSetCollideBodies(&joint, cpFalse);
    previous = &body;
  }
}

double ChipmunkChain::largestJointGap() const {
  double gap = 0;
  for (const cpConstraint* joint : constraints_) {
    const cpVect a = cpBodyLocalToWorld(cpConstraintGetBodyA(joint), cpPivotJointGetAnchorA(joint));
    const cpVect b = cpBodyLocalToWorld(cpConstraintGetBodyB(joint), cpPivotJointGetAnchorB(joint));
    gap = std::max(gap, cpvdist(a, b));
  }
  return gap;
}

}  // namespace thyrix::peers
