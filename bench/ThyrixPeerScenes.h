#pragma once
/// @file ThyrixPeerScenes.h
/// @brief The Thyrix side of the peer comparison: the arena and the pile built from the shared
/// layouts of PeerScenes.h. (The chains wait for ThyrixPro's integration with the simulator.)

#include "PeerScenes.h"

#include <ThyrixLite/Circle.h>
#include <ThyrixLite/Simulator.h>

#include <cstdint>
#include <vector>

namespace thyrix::peers {

/// arena in Thyrix: the agent is an Elastoid of two circles joined by a stiff ElasticLink
/// (Spherus's body without its sensors and controller), the balls are circles, the walls are
/// borders; every body has the quasistatic mass thyrixMass.
class ThyrixArena {
 public:
  /// Stiffness of the agent's link (N/m): stiff next to the 1 N pushes (a 1 N pull stretches
  /// it by 5 mm), the peers' joint being rigid; the implicit link force is stable at any value.
  static constexpr double linkStiffness = 200;

  ThyrixArena(const ArenaLayout& layout, ContactSolverKind solver);
  /// Pushes the agent, then advances the world by one step.
  void step();
  /// This step's contact points.
  [[nodiscard]] std::size_t contactCount() const { return simulator_.contacts.size(); }
  /// scenes::stateHash of the world.
  [[nodiscard]] std::uint64_t stateHash() const;

 private:
  ArenaLayout layout_;
  Simulator simulator_;
  Circle* agent_[2] = {nullptr, nullptr};
  long steps_ = 0;
};

/// pileN in Thyrix: borders for the open box, circles of quasistatic mass thyrixMass pushed
/// down each step by their peers' weight (peerMass g), so they fall at g / peerDamping = 1 m/s.
class ThyrixPile {
 public:
  ThyrixPile(const PileLayout& layout, ContactSolverKind solver);
  void step();
  [[nodiscard]] std::size_t contactCount() const { return simulator_.contacts.size(); }
  [[nodiscard]] std::uint64_t stateHash() const;
  /// The circles' centres, in layout order.
  [[nodiscard]] std::vector<Point> centres() const;
  [[nodiscard]] const PileLayout& layout() const { return layout_; }

 private:
  PileLayout layout_;
  Simulator simulator_;
  std::vector<Circle*> circles_;
};

}  // namespace thyrix::peers
