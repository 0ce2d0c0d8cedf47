#pragma once
/// @file SpherusSimulator.h
/// @brief The Spherus arena: walls, a Spherus in the middle and circles to push.

#include <Agents/Spherus.h>

#include <ThyrixLite/Simulator.h>

#include <cstdint>
#include <optional>
#include <vector>

namespace thyrix {

/// A square walled arena with one Spherus, at its centre facing +y or at a seeded random pose,
/// and circles placed at random without overlap. The same options give the same world.
class SpherusSimulator : public Simulator {
 public:
  /// How the arena is made.
  struct Options {
    int objects = 20;               ///< circles to push
    real objectRadius = real(0.2);  ///< their radius (m)
    real size = 10;                 ///< side of the arena (m)
    std::uint32_t seed = 1;         ///< layout seed
    real timestep = real(0.01);     ///< s
    /// Unset: the agent starts at the centre facing +y. Set: it starts at a pose drawn from
    /// this seed (its own stream, apart from `seed`'s): a heading uniform in [0, 2 pi) and a
    /// centre uniform over the arena, kept two agent reaches (each `maxLinkLength / 2 + radius`)
    /// from the walls; the circles are then placed around it as around the centre.
    std::optional<std::uint32_t> poseSeed;
  };

  /// @throws InvalidArgument naming "SpherusSimulator.objects" (negative or more than fit) or
  ///         "SpherusSimulator.size" (a random pose asked for in an arena too small for the
  ///         agent)
  SpherusSimulator(const Options& options, std::unique_ptr<Controller> controller);

  /// Contacts the buffers are sized for at construction (steps allocate nothing below it).
  static constexpr std::size_t contactCapacity = 24;

  /// The agent.
  [[nodiscard]] Spherus& spherus() const { return *spherus_; }
  /// The circles to push, in the order they were placed.
  [[nodiscard]] const std::vector<Circle*>& obstacles() const { return obstacles_; }

 private:
  Spherus* spherus_;
  std::vector<Circle*> obstacles_;
};

}  // namespace thyrix
