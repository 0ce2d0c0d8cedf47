#include "Box2DV3Scenes.h"

#include <box2d/box2d.h>

#include <algorithm>
#include <cmath>

namespace thyrix::peers {
namespace {

float single(double x) { return static_cast<float>(x); }
b2Vec2 vec(Point p) { return {single(p.x), single(p.y)}; }

/// Frictionless like Thyrix's contacts; the mass is set by hand (setMass), not from a density.
b2ShapeDef shapeDef() {
  b2ShapeDef def = b2DefaultShapeDef();
  def.material.friction = 0;
  def.density = 0;
  def.updateBodyMass = false;
  return def;
}

}  // namespace

struct Box2DV3Scene::World {
  b2WorldId id{};
  b2BodyId ground{};
  std::vector<b2BodyId> bodies;  ///< dynamic bodies, in creation order
  std::vector<b2BodyId> agents;  ///< arena: the circles of agent k at 2k and 2k + 1
  std::vector<b2JointId> joints;
  float timestep = 0;

  World(Point gravity, double step) : timestep(single(step)) {
    b2WorldDef def = b2DefaultWorldDef();
    def.gravity = vec(gravity);
    id = b2CreateWorld(&def);
    b2BodyDef groundDef = b2DefaultBodyDef();
    ground = b2CreateBody(id, &groundDef);
  }
  World(const World&) = delete;
  World& operator=(const World&) = delete;
  ~World() { b2DestroyWorld(id); }

  /// A static box of half extents @p half centred at @p centre (boxes are solid on the outside
  /// too, like Thyrix's half-planes).
  void addWall(Point centre, Point half) {
    const b2Polygon box =
        b2MakeOffsetBox(single(half.x), single(half.y), vec(centre), b2Rot_identity);
    const b2ShapeDef def = shapeDef();
    b2CreatePolygonShape(ground, &def, &box);
  }

  /// A dynamic body at @p position, damped by peerDamping, with no shape yet: add its shapes,
  /// then setMass.
  b2BodyId addBody(Point position) {
    b2BodyDef def = b2DefaultBodyDef();
    def.type = b2_dynamicBody;
    def.position = vec(position);
    def.linearDamping = single(peerDamping);
    def.angularDamping = single(peerDamping);
    const b2BodyId body = b2CreateBody(id, &def);
    bodies.push_back(body);
    return body;
  }

  /// Gives @p body the mass peerMass and the moment of inertia @p inertia about its origin.
  static void setMass(b2BodyId body, double inertia) {
    b2MassData mass{};
    mass.mass = single(peerMass);
    mass.center = b2Vec2_zero;
    mass.rotationalInertia = single(inertia);
    b2Body_SetMassData(body, mass);
  }

  /// A dynamic frictionless circle body.
  b2BodyId addCircle(Point position, double radius) {
    const b2BodyId body = addBody(position);
    const b2Circle circle{b2Vec2_zero, single(radius)};
    const b2ShapeDef def = shapeDef();
    b2CreateCircleShape(body, &def, &circle);
    setMass(body, peerMass * radius * radius / 2);
    return body;
  }
};

Box2DV3Scene::Box2DV3Scene(Point gravity, double timestep)
    : world_(std::make_unique<World>(gravity, timestep)) {}

Box2DV3Scene::~Box2DV3Scene() = default;

void Box2DV3Scene::stepWorld() { b2World_Step(world_->id, world_->timestep, box2dV3SubSteps); }

std::size_t Box2DV3Scene::contactCount() const {
  // Each contact is on both bodies' lists: counted from the body of the lower index, or from
  // the only dynamic body when the other is static.
  std::size_t count = 0;
  std::vector<b2ContactData> contacts;
  for (const b2BodyId body : world_->bodies) {
    contacts.resize(static_cast<std::size_t>(b2Body_GetContactCapacity(body)));
    const int n = b2Body_GetContactData(body, contacts.data(), static_cast<int>(contacts.size()));
    for (int i = 0; i < n; ++i) {
      const b2ContactData& c = contacts[static_cast<std::size_t>(i)];
      b2BodyId other = b2Shape_GetBody(c.shapeIdA);
      if (B2_ID_EQUALS(other, body)) other = b2Shape_GetBody(c.shapeIdB);
      if (b2Body_GetType(other) == b2_staticBody || body.index1 < other.index1)
        count += static_cast<std::size_t>(c.manifold.pointCount);
    }
  }
  return count;
}

std::uint64_t Box2DV3Scene::stateHash() const {
  StateHash hash;
  for (const b2BodyId body : world_->bodies) {
    const b2Vec2 p = b2Body_GetPosition(body);
    const b2Rot q = b2Body_GetRotation(body);
    const b2Vec2 v = b2Body_GetLinearVelocity(body);
    hash.mix(p.x);
    hash.mix(p.y);
    hash.mix(q.c);
    hash.mix(q.s);
    hash.mix(v.x);
    hash.mix(v.y);
    hash.mix(b2Body_GetAngularVelocity(body));
  }
  return hash.value();
}

std::vector<Point> Box2DV3Scene::centres() const {
  std::vector<Point> result;
  result.reserve(world_->bodies.size());
  for (const b2BodyId body : world_->bodies) {
    const b2Vec2 p = b2Body_GetPosition(body);
    result.push_back({p.x, p.y});
  }
  return result;
}

Box2DV3Arena::Box2DV3Arena(const ArenaLayout& layout)
    : Box2DV3Scene({0, 0}, layout.timestep), layout_(layout) {
  World& w = *world_;
  const double s = layout.size;
  const double t = 0.5;  // half the wall thickness
  w.addWall({s / 2, -t}, {s / 2 + 2 * t, t});
  w.addWall({s / 2, s + t}, {s / 2 + 2 * t, t});
  w.addWall({-t, s / 2}, {t, s / 2 + 2 * t});
  w.addWall({s + t, s / 2}, {t, s / 2 + 2 * t});
  for (const AgentLayout& a : layout.agents) {
    b2BodyId circles[2];
    for (int i = 0; i < 2; ++i) {
      circles[i] = w.addCircle(a.circle[i], layout.agentRadius);
      w.agents.push_back(circles[i]);
    }
    // Rigid (no spring) at the agent's length, anchored at the centres; collideConnected stays
    // false, like the bodies of a Thyrix elastoid.
    b2DistanceJointDef joint = b2DefaultDistanceJointDef();
    joint.base.bodyIdA = circles[0];
    joint.base.bodyIdB = circles[1];
    joint.length = single(layout.linkLength());
    w.joints.push_back(b2CreateDistanceJoint(w.id, &joint));
  }
  for (const Point p : layout.balls) w.addCircle(p, layout.ballRadius);
}

void Box2DV3Arena::step() {
  push_.next();
  const std::vector<b2BodyId>& agents = world_->agents;
  for (std::size_t i = 0; i < agents.size(); ++i)
    b2Body_ApplyForceToCenter(agents[i], single(layout_.pushForce) * vec(push_.direction(i / 2)),
                              true);
  stepWorld();
}

Box2DV3Pile::Box2DV3Pile(const PileLayout& layout)
    : Box2DV3Scene({0, -layout.gravity}, layout.timestep), layout_(layout) {
  // The open box of the pile: a floor under y = 0 and walls at leftWall and width, reaching
  // well above the pile's top (as in Box2DPile).
  World& w = *world_;
  const double t = 1;
  const double height = layout.top + 10;
  const double middle = (layout.leftWall + layout.width) / 2;
  const double halfWidth = (layout.width - layout.leftWall) / 2;
  w.addWall({middle, -t}, {halfWidth + 2 * t, t});
  w.addWall({layout.leftWall - t, height / 2}, {t, height / 2});
  w.addWall({layout.width + t, height / 2}, {t, height / 2});
  w.bodies.reserve(layout.circles.size());
  for (const Point p : layout.circles) w.addCircle(p, layout.radius);
}

Box2DV3Chain::Box2DV3Chain(const ChainLayout& layout)
    : Box2DV3Scene({0, -layout.gravity}, layout.timestep) {
  World& w = *world_;
  const float h = single(layout.halfLength);
  b2BodyId previous = w.ground;
  for (int i = 0; i < layout.links; ++i) {
    const b2BodyId body = w.addBody(layout.centre(i));
    const b2Capsule capsule{{-h, 0}, {h, 0}, single(layout.radius)};
    const b2ShapeDef def = shapeDef();
    b2CreateCapsuleShape(body, &def, &capsule);
    World::setMass(body, layout.inertia());
    // The joint at the previous link's right cap centre (the ground's origin for the first) and
    // at this link's left cap centre; collideConnected false: neighbours do not collide.
    b2RevoluteJointDef joint = b2DefaultRevoluteJointDef();
    joint.base.bodyIdA = previous;
    joint.base.bodyIdB = body;
    joint.base.localFrameA.p = i == 0 ? vec(layout.joint(0)) : b2Vec2{h, 0};
    joint.base.localFrameB.p = {-h, 0};
    w.joints.push_back(b2CreateRevoluteJoint(w.id, &joint));
    previous = body;
  }
}

double Box2DV3Chain::largestJointGap() const {
  double gap = 0;
  for (const b2JointId joint : world_->joints) {
    const b2Vec2 a = b2Body_GetWorldPoint(b2Joint_GetBodyA(joint), b2Joint_GetLocalFrameA(joint).p);
    const b2Vec2 b = b2Body_GetWorldPoint(b2Joint_GetBodyB(joint), b2Joint_GetLocalFrameB(joint).p);
    gap = std::max(gap, static_cast<double>(b2Distance(a, b)));
  }
  return gap;
}

}  // namespace thyrix::peers
