#pragma once
/// @file ChipmunkScenes.h
/// @brief The Chipmunk 7 side of the peer comparison: arena, pile and chain built from the
/// shared layouts of PeerScenes.h, with Chipmunk's usual settings (10 iterations, its default
/// collision slop and bounding-box tree, no sleeping) and frictionless shapes.

#include "PeerScenes.h"

#include <cstdint>
#include <vector>

// Chipmunk's types, declared as its own headers do, so that this header does not need them.
struct cpSpace;
struct cpBody;
struct cpShape;
struct cpConstraint;

namespace thyrix::peers {

/// What the Chipmunk scenes share: the space, what they added to it (freed with it), and the
/// measures taken on the dynamic bodies.
class ChipmunkScene {
 public:
  ChipmunkScene(const ChipmunkScene&) = delete;
  ChipmunkScene& operator=(const ChipmunkScene&) = delete;
  ~ChipmunkScene();
  /// Contact points of this step's arbiters.
  [[nodiscard]] std::size_t contactCount() const;
  /// FNV-1a over the dynamic bodies' positions, angles and velocities (double bits).
  [[nodiscard]] std::uint64_t stateHash() const;
  /// The dynamic bodies' centres, in creation order.
  [[nodiscard]] std::vector<Point> centres() const;

 protected:
  ChipmunkScene(Point gravity, double timestep);
  /// A static box [x0, x1] x [y0, y1] on the space's static body.
  void addWall(double x0, double y0, double x1, double y1);
  /// A dynamic body of mass peerMass and moment of inertia @p inertia at @p position.
  cpBody& addBody(Point position, double inertia);
  /// A frictionless shape, added to the space.
  void addShape(cpShape* shape);
  /// A constraint, added to the space.
  cpConstraint& addConstraint(cpConstraint* constraint);
  /// A dynamic frictionless circle body.
  cpBody& addCircle(Point position, double radius);
  void stepSpace();

  cpSpace* space_;
  double timestep_;
  std::vector<cpBody*> bodies_;
  std::vector<cpShape*> shapes_;
  std::vector<cpConstraint*> constraints_;
};

/// arena (and crowd) in Chipmunk: each agent's circles are joined by a pin joint (a rigid
/// distance).
class ChipmunkArena : public ChipmunkScene {
 public:
  explicit ChipmunkArena(const ArenaLayout& layout);
  void step();

 private:
  ArenaLayout layout_;
  std::vector<cpBody*> agents_;  ///< the circles of agent k at 2k and 2k + 1
  ArenaPush push_{layout_};
};

/// pileN in Chipmunk.
class ChipmunkPile : public ChipmunkScene {
 public:
  explicit ChipmunkPile(const PileLayout& layout);
  void step() { stepSpace(); }
  [[nodiscard]] const PileLayout& layout() const { return layout_; }

 private:
  PileLayout layout_;
};

/// chainN in Chipmunk: each link is a segment shape (a capsule), joints are pivot joints.
class ChipmunkChain : public ChipmunkScene {
 public:
  explicit ChipmunkChain(const ChainLayout& layout);
  void step() { stepSpace(); }
  /// The largest distance between the two anchors of a joint (m).
  [[nodiscard]] double largestJointGap() const;
};

}  // namespace thyrix::peers
