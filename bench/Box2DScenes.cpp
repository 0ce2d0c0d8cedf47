#include "Box2DScenes.h"

#include <box2d/box2d.h>

#include <algorithm>
#include <cmath>

namespace thyrix::peers {
namespace {

float single(double x) { return static_cast<float>(x); }
b2Vec2 vec(Point p) { return {single(p.x), single(p.y)}; }

}  // namespace

Box2DScene::Box2DScene(Point gravity, double timestep)
    : world_(std::make_unique<b2World>(vec(gravity))), timestep_(single(timestep)) {
  b2BodyDef ground;
  ground_ = world_->CreateBody(&ground);
}

Box2DScene::~Box2DScene() = default;

void Box2DScene::addWall(Point centre, Point half) {
  b2PolygonShape box;
  box.SetAsBox(single(half.x), single(half.y), vec(centre), 0);
  b2FixtureDef fixture;
  fixture.shape = &box;
  fixture.friction = 0;
  ground_->CreateFixture(&fixture);
}

b2Body& Box2DScene::addBody(Point position) {
  b2BodyDef def;
  def.type = b2_dynamicBody;
  def.position = vec(position);
  def.linearDamping = single(peerDamping);
  def.angularDamping = single(peerDamping);
  b2Body& body = *world_->CreateBody(&def);
  bodies_.push_back(&body);
  return body;
}

void Box2DScene::setMass(b2Body& body, double inertia) {
  b2MassData mass;
  mass.mass = single(peerMass);
  mass.center.SetZero();
  mass.I = single(inertia);
  body.SetMassData(&mass);
}

b2Body& Box2DScene::addCircle(Point position, double radius) {
  b2Body& body = addBody(position);
  b2CircleShape circle;
  circle.m_radius = single(radius);
  b2FixtureDef fixture;
  fixture.shape = &circle;
  fixture.friction = 0;
  body.CreateFixture(&fixture);
  setMass(body, peerMass * radius * radius / 2);
  return body;
}

void Box2DScene::stepWorld() {
  world_->Step(timestep_, box2dVelocityIterations, box2dPositionIterations);
}

std::size_t Box2DScene::contactCount() const {
  std::size_t count = 0;
  for (const b2Contact* c = world_->GetContactList(); c; c = c->GetNext())
    if (c->IsTouching()) count += static_cast<std::size_t>(c->GetManifold()->pointCount);
  return count;
}

std::uint64_t Box2DScene::stateHash() const {
  StateHash hash;
  for (const b2Body* body : bodies_) {
    hash.mix(body->GetPosition().x);
    hash.mix(body->GetPosition().y);
    hash.mix(body->GetAngle());
    hash.mix(body->GetLinearVelocity().x);
    hash.mix(body->GetLinearVelocity().y);
    hash.mix(body->GetAngularVelocity());
  }
  return hash.value();
}

std::vector<Point> Box2DScene::centres() const {
  std::vector<Point> result;
  result.reserve(bodies_.size());
  for (const b2Body* body : bodies_)
    result.push_back({body->GetPosition().x, body->GetPosition().y});
  return result;
}

Box2DArena::Box2DArena(const ArenaLayout& layout)
    : Box2DScene({0, 0}, layout.timestep), layout_(layout) {
  const double s = layout.size;
  const double t = 0.5;  // half the wall thickness
  addWall({s / 2, -t}, {s / 2 + 2 * t, t});
  addWall({s / 2, s + t}, {s / 2 + 2 * t, t});
  addWall({-t, s / 2}, {t, s / 2 + 2 * t});
  addWall({s + t, s / 2}, {t, s / 2 + 2 * t});
  for (const AgentLayout& a : layout.agents) {
    b2Body* circles[2] = {nullptr, nullptr};
    for (int i = 0; i < 2; ++i) {
      circles[i] = &addCircle(a.circle[i], layout.agentRadius);
      agents_.push_back(circles[i]);
    }
    b2DistanceJointDef joint;
    // Initialize makes the joint rigid at the current distance (stiffness 0, min = max
    // length); collideConnected stays false, like the bodies of a Thyrix elastoid.
    joint.Initialize(circles[0], circles[1], circles[0]->GetPosition(), circles[1]->GetPosition());
    world_->CreateJoint(&joint);
  }
  for (const Point p : layout.balls) addCircle(p, layout.ballRadius);
}

void Box2DArena::step() {
  push_.next();
  for (std::size_t i = 0; i < agents_.size(); ++i)
    agents_[i]->ApplyForceToCenter(single(layout_.pushForce) * vec(push_.direction(i / 2)), true);
  stepWorld();
}

Box2DPile::Box2DPile(const PileLayout& layout)
    : Box2DScene({0, -layout.gravity}, layout.timestep), layout_(layout) {
  // The open box of the pile: a floor under y = 0 and walls at leftWall and width, reaching
  // well above the pile's top.
  const double t = 1;
  const double height = layout.top + 10;
  const double middle = (layout.leftWall + layout.width) / 2;
  const double halfWidth = (layout.width - layout.leftWall) / 2;
  addWall({middle, -t}, {halfWidth + 2 * t, t});
  addWall({layout.leftWall - t, height / 2}, {t, height / 2});
  addWall({layout.width + t, height / 2}, {t, height / 2});
  bodies_.reserve(layout.circles.size());
  for (const Point p : layout.circles) addCircle(p, layout.radius);
}

Box2DChain::Box2DChain(const ChainLayout& layout)
    : Box2DScene({0, -layout.gravity}, layout.timestep) {
  b2Body* previous = ground_;
  for (int i = 0; i < layout.links; ++i) {
    b2Body& body = addBody(layout.centre(i));
    // The box is thinner by Box2D's polygon skin, which it adds around every polygon.
    b2PolygonShape box;
    box.SetAsBox(single(layout.halfLength), single(layout.radius) - b2_polygonRadius);
    b2FixtureDef fixture;
    fixture.friction = 0;
    fixture.shape = &box;
    body.CreateFixture(&fixture);
    for (const double end : {-layout.halfLength, layout.halfLength}) {
      b2CircleShape cap;
      cap.m_radius = single(layout.radius);
      cap.m_p.Set(single(end), 0);
      fixture.shape = &cap;
      body.CreateFixture(&fixture);
    }
    setMass(body, layout.inertia());
    b2RevoluteJointDef joint;  // collideConnected false: neighbours do not collide
    joint.Initialize(previous, &body, vec(layout.joint(i)));
    joints_.push_back(world_->CreateJoint(&joint));
    previous = &body;
  }
}

double Box2DChain::largestJointGap() const {
  double gap = 0;
  for (const b2Joint* joint : joints_) {
    const b2Vec2 d = joint->GetAnchorB() - joint->GetAnchorA();
    gap = std::max(gap, static_cast<double>(d.Length()));
  }
  return gap;
}

}  // namespace thyrix::peers
