#pragma once
/// @file SpherusPeerScene.h
/// @brief spherus and batch: the real Spherus (35 sensors, random controller) in the arena of
/// the peer comparison (Thyrix only: the cost of sensing), and the check that its arena is the
/// one the arena scene builds for the peers.

#include "PeerScenes.h"

#include <Agents/SpherusSimulator.h>
#include <Controller/RandomController.h>
#include <Scenes.h>

#include <cmath>
#include <cstdint>
#include <memory>

namespace thyrix::peers {

/// SpherusSimulator with the random controller, both seeded with @p seed.
class ThyrixSpherus {
 public:
  ThyrixSpherus(std::uint32_t seed, int balls)
      : simulator_(options(seed, balls), std::make_unique<RandomController>(seed)) {}
  void step() { simulator_.advanceTime(); }
  [[nodiscard]] std::size_t contactCount() const { return simulator_.contacts.size(); }
  [[nodiscard]] std::uint64_t stateHash() const { return scenes::stateHash(simulator_); }
  [[nodiscard]] const SpherusSimulator& simulator() const { return simulator_; }

  static SpherusSimulator::Options options(std::uint32_t seed, int balls) {
    SpherusSimulator::Options result;
    result.objects = balls;
    result.seed = seed;
    return result;
  }

 private:
  SpherusSimulator simulator_;
};

/// True when @p layout has the agent and the balls of a SpherusSimulator built from @p seed:
/// the arena scene and the spherus scene then differ only by the sensors and the controller.
inline bool sameArena(const ArenaLayout& layout, std::uint32_t seed) {
  const ThyrixSpherus spherus(seed, static_cast<int>(layout.balls.size()));
  const auto close = [](Vector2 a, Point b) {
    return std::abs(static_cast<double>(a.x) - b.x) < 1e-6 &&
           std::abs(static_cast<double>(a.y) - b.y) < 1e-6;
  };
  const Spherus& agent = spherus.simulator().spherus();
  if (layout.agents.size() != 1 || !close(agent.leftCircle().r, layout.agents[0].circle[0]) ||
      !close(agent.rightCircle().r, layout.agents[0].circle[1]))
    return false;
  const auto& balls = spherus.simulator().obstacles();
  if (balls.size() != layout.balls.size()) return false;
  for (std::size_t i = 0; i < balls.size(); ++i)
    if (!close(balls[i]->r, layout.balls[i])) return false;
  return true;
}

}  // namespace thyrix::peers
