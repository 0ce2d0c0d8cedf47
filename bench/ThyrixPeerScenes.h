#pragma once
/// @file ThyrixPeerScenes.h
/// @brief The Thyrix side of the peer comparison: the arena, the pile and the chain built from
/// the shared layouts of PeerScenes.h (the chain with ThyrixPro's articulated agent).

#include "PeerScenes.h"

#include <ThyrixLite/Circle.h>
#include <ThyrixLite/Simulator.h>
#include <ThyrixPro/ArticulatedAgentQuasistatic.h>

#include <cstdint>
#include <vector>

namespace thyrix::peers {

/// arena (and crowd) in Thyrix: each agent is an Elastoid of two circles joined by a stiff
/// ElasticLink (Spherus's body without its sensors and controller), the balls are circles, the
/// walls are borders; every body has the quasistatic mass thyrixMass.
class ThyrixArena {
 public:
  /// Stiffness of the agent's link (N/m): stiff next to the 1 N pushes (a 1 N pull stretches
  /// it by 5 mm), the peers' joint being rigid; the implicit link force is stable at any value.
  static constexpr double linkStiffness = 200;

  ThyrixArena(const ArenaLayout& layout, ContactSolverKind solver);
  /// Pushes the agents, then advances the world by one step.
  void step();
  /// This step's contact points.
  [[nodiscard]] std::size_t contactCount() const { return simulator_.contacts.size(); }
  /// scenes::stateHash of the world.
  [[nodiscard]] std::uint64_t stateHash() const;

 private:
  ArenaLayout layout_;
  Simulator simulator_;
  std::vector<Circle*> agents_;  ///< the circles of agent k at 2k and 2k + 1
  ArenaPush push_{layout_};
};

/// pileN in Thyrix: borders for the open box, circles of quasistatic mass thyrixMass in the
/// world gravity field g / peerDamping (Simulator::setGravity()), so each is pushed down by its
/// peer's weight (peerMass g) and falls at g / peerDamping = 1 m/s.
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

/// chainN in Thyrix: an ArticulatedAgentQuasistatic with a fixed base (one tiny circle at the
/// origin, the peers' pin) and one limb, a chain of N capsule links of length 2 halfLength (a
/// link's capsule runs from its joint to its tip, the peers' cap centres), so the joints sit at
/// integer x as in the peers. Neighbours do not collide by construction (a link never touches
/// its parent); other pairs collide, as in the peers. Each link has the quasistatic mass
/// thyrixMass and peerDamping times the peers' moment of inertia, and is pulled down by its
/// peer's weight (peerMass g) at its centre of mass, the world gravity field g / peerDamping
/// (Simulator::setGravity()), so it moves and turns as a peer link damped by peerDamping would.
class ThyrixChain {
 public:
  ThyrixChain(const ChainLayout& layout, ContactSolverKind solver);
  /// Advances the world by one step.
  void step();
  [[nodiscard]] std::size_t contactCount() const { return simulator_.contacts.size(); }
  /// FNV-1a over every link's centre of mass, angle, velocity and angular velocity (the base is
  /// fixed, and the agent's `r` is the base's: scenes::stateHash would not see the links).
  [[nodiscard]] std::uint64_t stateHash() const;
  /// The largest joint gap (m): the distance from each link's tip to the next link's joint,
  /// and from the first joint to the pin at the origin. Zero by construction (the joints are
  /// placed by forward kinematics), measured anyway like the peers'.
  [[nodiscard]] double largestJointGap() const;

 private:
  ChainLayout layout_;
  Simulator simulator_;
  ArticulatedAgentQuasistatic* agent_ = nullptr;
};

}  // namespace thyrix::peers
