#include "ThyrixPeerScenes.h"

#include <Scenes.h>
#include <ThyrixLite/Border.h>
#include <ThyrixLite/Elastoid.h>
#include <ThyrixPro/ArticulatedLimb.h>
#include <ThyrixPro/ArticulatedLink.h>

#include <algorithm>
#include <cmath>
#include <memory>

namespace thyrix::peers {
namespace {

Vector2 vector(Point p) { return {static_cast<real>(p.x), static_cast<real>(p.y)}; }

}  // namespace

ThyrixArena::ThyrixArena(const ArenaLayout& layout, ContactSolverKind solver)
    : layout_(layout), simulator_(static_cast<real>(layout.timestep)) {
  simulator_.setContactSolver(solver);
  scenes::addWalls(simulator_, static_cast<real>(layout.size), static_cast<real>(layout.size));
  for (const AgentLayout& a : layout.agents) {
    auto agent = std::make_unique<Elastoid>();
    Circle* circles[2] = {nullptr, nullptr};
    for (int i = 0; i < 2; ++i) {
      circles[i] = &agent->addBody(std::make_unique<Circle>(static_cast<real>(layout.agentRadius),
                                                            static_cast<real>(thyrixMass)));
      circles[i]->r = vector(a.circle[i]);
      agents_.push_back(circles[i]);
    }
    agent->addLink(*circles[0], {}, *circles[1], {}, static_cast<real>(layout.linkLength()),
                   static_cast<real>(linkStiffness));
    simulator_.registerObject(std::move(agent));
  }
  for (const Point p : layout.balls) {
    auto& ball = simulator_.registerObject(std::make_unique<Circle>(
        static_cast<real>(layout.ballRadius), static_cast<real>(thyrixMass)));
    ball.r = vector(p);
  }
}

void ThyrixArena::step() {
  push_.next();
  for (std::size_t i = 0; i < agents_.size(); ++i)
    agents_[i]->externalForce +=
        vector(push_.direction(i / 2)) * static_cast<real>(layout_.pushForce);
  simulator_.advanceTime();
}

std::uint64_t ThyrixArena::stateHash() const { return scenes::stateHash(simulator_); }

ThyrixPile::ThyrixPile(const PileLayout& layout, ContactSolverKind solver)
    : layout_(layout), simulator_(static_cast<real>(layout.timestep)) {
  simulator_.setContactSolver(solver);
  // The peers' world gravity: a fall at a / d under F = m v, the weight thyrixMass * (a / d) =
  // peerMass * a on every circle, as a per-step force would give it (the same bits: m = 1).
  simulator_.setGravity({0, -static_cast<real>(layout.gravity / peerDamping)});
  // The borders of scenes::addPile: the floor and the two walls.
  simulator_.registerObject(std::make_unique<Border>(Vector2{0, 0}, Vector2{0, 1}));
  simulator_.registerObject(
      std::make_unique<Border>(Vector2{static_cast<real>(layout.leftWall), 0}, Vector2{1, 0}));
  simulator_.registerObject(
      std::make_unique<Border>(Vector2{static_cast<real>(layout.width), 0}, Vector2{-1, 0}));
  circles_.reserve(layout.circles.size());
  for (const Point p : layout.circles) {
    auto& circle = simulator_.registerObject(
        std::make_unique<Circle>(static_cast<real>(layout.radius), static_cast<real>(thyrixMass)));
    circle.r = vector(p);
    circles_.push_back(&circle);
  }
}

void ThyrixPile::step() { simulator_.advanceTime(); }

std::uint64_t ThyrixPile::stateHash() const { return scenes::stateHash(simulator_); }

std::vector<Point> ThyrixPile::centres() const {
  std::vector<Point> result;
  result.reserve(circles_.size());
  for (const Circle* circle : circles_)
    result.push_back({static_cast<double>(circle->r.x), static_cast<double>(circle->r.y)});
  return result;
}

ThyrixChain::ThyrixChain(const ChainLayout& layout, ContactSolverKind solver)
    : layout_(layout), simulator_(static_cast<real>(layout.timestep)) {
  simulator_.setContactSolver(solver);
  // The peers' world gravity, a / d under F = m v: each link is weighed at its centre of mass
  // (the fixed base is not), thyrixMass * (a / d) = peerMass * a.
  simulator_.setGravity({0, -static_cast<real>(layout.gravity / peerDamping)});
  const real halfLength = static_cast<real>(layout.halfLength);
  const real radius = static_cast<real>(layout.radius);
  ArticulatedLimb limb(Vector2{});
  for (int i = 0; i < layout.links; ++i) {
    // Link i's joint is on the base's centre (the origin) for the first, else on the previous
    // link's tip.
    const Vector2 joint = i == 0 ? Vector2{} : Vector2{2 * halfLength, 0};
    ArticulatedLink link =
        ArticulatedLink::capsule(i - 1, joint, halfLength, radius, static_cast<real>(thyrixMass));
    // The peers' moment of inertia (a box of the capsule's full size, ChainLayout::inertia())
    // times the damping, rather than the capsule's own: a turning link then meets the same
    // resistance as a peer link with angular damping peerDamping.
    link.inertia = static_cast<real>(peerDamping * layout.inertia());
    limb.addLink(link, radius);
  }
  // The base only carries the pin: a tiny circle, so small that no link can touch it except
  // the first, which never collides with its parent.
  auto agent = std::make_unique<ArticulatedAgentQuasistatic>(
      std::vector<ArticulatedBasePart>{ArticulatedBasePart::circle(real(1e-3), 1)},
      std::vector<ArticulatedLimb>{limb});
  agent->setPose(Vector2{}, 0);
  agent->fixed = true;
  agent_ = &simulator_.registerObject(std::move(agent));
}

void ThyrixChain::step() { simulator_.advanceTime(); }

std::uint64_t ThyrixChain::stateHash() const {
  StateHash hash;
  for (int i = 0; i < layout_.links; ++i) {
    const Vector2 c = agent_->centerOfMass(i);
    const Vector2 v = agent_->bodyVelocity(i);
    hash.mix(c.x);
    hash.mix(c.y);
    hash.mix(agent_->bodyAngle(i));
    hash.mix(v.x);
    hash.mix(v.y);
    hash.mix(agent_->bodyAngularVelocity(i));
  }
  return hash.value();
}

double ThyrixChain::largestJointGap() const {
  const auto distance = [](Vector2 a, Vector2 b) {
    return std::hypot(static_cast<double>(a.x - b.x), static_cast<double>(a.y - b.y));
  };
  double gap = distance(agent_->jointPosition(0), vector(layout_.joint(0)));
  for (int i = 1; i < layout_.links; ++i)
    gap = std::max(gap, distance(agent_->linkTip(i - 1), agent_->jointPosition(i)));
  return gap;
}

}  // namespace thyrix::peers
