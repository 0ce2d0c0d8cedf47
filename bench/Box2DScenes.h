#pragma once
/// @file Box2DScenes.h
/// @brief The Box2D 2.4 side of the peer comparison: arena, pile and chain built from the
/// shared layouts of PeerScenes.h, with Box2D's usual settings (8 velocity and 3 position
/// iterations, sleeping allowed) and frictionless fixtures like Thyrix's contacts.

#include "PeerScenes.h"

#include <cstdint>
#include <memory>
#include <vector>

class b2World;
class b2Body;
class b2Joint;

namespace thyrix::peers {

/// Velocity iterations per Box2D step (the testbed's default).
inline constexpr int box2dVelocityIterations = 8;
/// Position iterations per Box2D step (the testbed's default).
inline constexpr int box2dPositionIterations = 3;

/// What the Box2D scenes share: the world, its dynamic bodies in creation order, and the
/// measures taken on them.
class Box2DScene {
 public:
  Box2DScene(const Box2DScene&) = delete;
  Box2DScene& operator=(const Box2DScene&) = delete;
  ~Box2DScene();
  /// Contact points of the touching contacts this step.
  [[nodiscard]] std::size_t contactCount() const;
  /// FNV-1a over the dynamic bodies' positions, angles and velocities (float bits).
  [[nodiscard]] std::uint64_t stateHash() const;
  /// The dynamic bodies' centres, in creation order.
  [[nodiscard]] std::vector<Point> centres() const;

 protected:
  Box2DScene(Point gravity, double timestep);
  /// A static box of half extents @p half centred at @p centre (walls and floors: boxes are
  /// solid on the outside too, like Thyrix's half-planes, where a thin edge is not).
  void addWall(Point centre, Point half);
  /// A dynamic body at @p position, damped by peerDamping, with no shape yet: add its
  /// fixtures (without density), then setMass.
  b2Body& addBody(Point position);
  /// Gives @p body the mass peerMass and the moment of inertia @p inertia about its origin.
  static void setMass(b2Body& body, double inertia);
  /// A dynamic frictionless circle body.
  b2Body& addCircle(Point position, double radius);
  void stepWorld();

  std::unique_ptr<b2World> world_;
  b2Body* ground_ = nullptr;
  std::vector<b2Body*> bodies_;
  float timestep_;
};

/// arena (and crowd) in Box2D: each agent's circles are joined by a rigid distance joint.
class Box2DArena : public Box2DScene {
 public:
  explicit Box2DArena(const ArenaLayout& layout);
  void step();

 private:
  ArenaLayout layout_;
  std::vector<b2Body*> agents_;  ///< the circles of agent k at 2k and 2k + 1
  ArenaPush push_{layout_};
};

/// pileN in Box2D.
class Box2DPile : public Box2DScene {
 public:
  explicit Box2DPile(const PileLayout& layout);
  void step() { stepWorld(); }
  [[nodiscard]] const PileLayout& layout() const { return layout_; }

 private:
  PileLayout layout_;
};

/// chainN in Box2D. Box2D 2.4 has no capsule shape: each link is a box between its cap
/// centres and a circle on each cap (three fixtures, the usual way).
class Box2DChain : public Box2DScene {
 public:
  explicit Box2DChain(const ChainLayout& layout);
  void step() { stepWorld(); }
  /// The largest distance between the two anchors of a joint (m).
  [[nodiscard]] double largestJointGap() const;

 private:
  std::vector<b2Joint*> joints_;
};

}  // namespace thyrix::peers
