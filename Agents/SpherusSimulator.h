#pragma once
/// @file SpherusSimulator.h
/// @brief The Spherus arena: walls, a Spherus in the middle and circles to push.

#include "Spherus.h"

#include <ThyrixLite/Simulator.h>

#include <cstdint>
#include <vector>

namespace thyrix {

/// A square walled arena with one Spherus at its centre facing +y and circles placed at random
/// without overlap. The same options give the same world.
class SpherusSimulator : public Simulator {
 public:
  /// How the arena is made.
  struct Options {
    int objects = 20;               ///< circles to push
    real objectRadius = real(0.2);  ///< their radius (m)
    real size = 10;                 ///< side of the arena (m)
    std::uint32_t seed = 1;         ///< layout seed
    real timestep = real(0.01);     ///< s
  };

  /// @throws InvalidArgument naming "SpherusSimulator.objects" (negative or more than fit)
  SpherusSimulator(const Options& options, std::unique_ptr<Controller> controller);

  /// Contacts the buffers are sized for at construction (steps allocate nothing below it).
  static constexpr std::size_t contactCapacity = 24;

  [[nodiscard]] Spherus& spherus() const { return *spherus_; }
  [[nodiscard]] const std::vector<Circle*>& obstacles() const { return obstacles_; }

 private:
  Spherus* spherus_;
  std::vector<Circle*> obstacles_;
};

}  // namespace thyrix
