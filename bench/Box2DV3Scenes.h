#pragma once
/// @file Box2DV3Scenes.h
/// @brief The Box2D v3 side of the peer comparison (issue 27): arena, crowd, pile and chain
/// built from the shared layouts of PeerScenes.h, with Box2D v3's defaults (sleeping on, soft
/// step, continuous collision, one worker) and 4 substeps per step, frictionless shapes like
/// Thyrix's contacts.
///
/// Box2D v3 is a C library whose header has the name of Box2D 2.4's (box2d/box2d.h): this
/// header keeps its types out of sight (they live in Box2DV3Scenes.cpp), so that the two
/// versions can be compared in one program.

#include "PeerScenes.h"

#include <cstdint>
#include <memory>
#include <vector>

namespace thyrix::peers {

/// Substeps per Box2D v3 step (its documented default).
inline constexpr int box2dV3SubSteps = 4;

/// What the Box2D v3 scenes share: the world, its dynamic bodies in creation order, and the
/// measures taken on them.
class Box2DV3Scene {
 public:
  Box2DV3Scene(const Box2DV3Scene&) = delete;
  Box2DV3Scene& operator=(const Box2DV3Scene&) = delete;
  ~Box2DV3Scene();
  /// Contact points of the touching contacts this step.
  [[nodiscard]] std::size_t contactCount() const;
  /// FNV-1a over the dynamic bodies' positions, rotations and velocities (float bits).
  [[nodiscard]] std::uint64_t stateHash() const;
  /// The dynamic bodies' centres, in creation order.
  [[nodiscard]] std::vector<Point> centres() const;

  /// Box2D's world and the ids of what the scenes added to it (Box2DV3Scenes.cpp).
  struct World;

 protected:
  Box2DV3Scene(Point gravity, double timestep);
  void stepWorld();

  std::unique_ptr<World> world_;
};

/// arena (and crowd) in Box2D v3: each agent's circles are joined by a rigid distance joint.
class Box2DV3Arena : public Box2DV3Scene {
 public:
  explicit Box2DV3Arena(const ArenaLayout& layout);
  /// Pushes the agents, then advances the world by one step.
  void step();

 private:
  ArenaLayout layout_;
  ArenaPush push_{layout_};
};

/// pileN in Box2D v3.
class Box2DV3Pile : public Box2DV3Scene {
 public:
  explicit Box2DV3Pile(const PileLayout& layout);
  void step() { stepWorld(); }
  [[nodiscard]] const PileLayout& layout() const { return layout_; }

 private:
  PileLayout layout_;
};

/// chainN in Box2D v3: each link is one capsule (v3 has the shape), joined to the previous by
/// a revolute joint.
class Box2DV3Chain : public Box2DV3Scene {
 public:
  explicit Box2DV3Chain(const ChainLayout& layout);
  void step() { stepWorld(); }
  /// The largest distance between the two anchors of a joint (m).
  [[nodiscard]] double largestJointGap() const;
};

}  // namespace thyrix::peers
