#include "ThyrixPeerScenes.h"

#include <Scenes.h>
#include <ThyrixLite/Border.h>
#include <ThyrixLite/Elastoid.h>

#include <memory>

namespace thyrix::peers {
namespace {

Vector2 vector(Point p) { return {static_cast<real>(p.x), static_cast<real>(p.y)}; }

}  // namespace

ThyrixArena::ThyrixArena(const ArenaLayout& layout, ContactSolverKind solver)
    : layout_(layout), simulator_(static_cast<real>(layout.timestep)) {
  simulator_.setContactSolver(solver);
  scenes::addWalls(simulator_, static_cast<real>(layout.size), static_cast<real>(layout.size));
  auto agent = std::make_unique<Elastoid>();
  for (int i = 0; i < 2; ++i) {
    agent_[i] = &agent->addBody(std::make_unique<Circle>(static_cast<real>(layout.agentRadius),
                                                         static_cast<real>(thyrixMass)));
    agent_[i]->r = vector(layout.agent[i]);
  }
  agent->addLink(*agent_[0], {}, *agent_[1], {}, static_cast<real>(layout.linkLength()),
                 static_cast<real>(linkStiffness));
  simulator_.registerObject(std::move(agent));
  for (const Point p : layout.balls) {
    auto& ball = simulator_.registerObject(std::make_unique<Circle>(
        static_cast<real>(layout.ballRadius), static_cast<real>(thyrixMass)));
    ball.r = vector(p);
  }
}

void ThyrixArena::step() {
  const Point direction = arenaPushDirection(layout_, steps_++);
  const Vector2 force = vector(direction) * static_cast<real>(layout_.pushForce);
  for (Circle* circle : agent_) circle->externalForce += force;
  simulator_.advanceTime();
}

std::uint64_t ThyrixArena::stateHash() const { return scenes::stateHash(simulator_); }

ThyrixPile::ThyrixPile(const PileLayout& layout, ContactSolverKind solver)
    : layout_(layout), simulator_(static_cast<real>(layout.timestep)) {
  simulator_.setContactSolver(solver);
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

void ThyrixPile::step() {
  const Vector2 weight{0, -static_cast<real>(peerMass * layout_.gravity)};
  for (Circle* circle : circles_) circle->externalForce += weight;
  simulator_.advanceTime();
}

std::uint64_t ThyrixPile::stateHash() const { return scenes::stateHash(simulator_); }

std::vector<Point> ThyrixPile::centres() const {
  std::vector<Point> result;
  result.reserve(circles_.size());
  for (const Circle* circle : circles_)
    result.push_back({static_cast<double>(circle->r.x), static_cast<double>(circle->r.y)});
  return result;
}

}  // namespace thyrix::peers
