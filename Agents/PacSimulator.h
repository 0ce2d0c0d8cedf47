#pragma once
/// @file PacSimulator.h
/// @brief The Pac arena: walls, two Pacs facing each other and food circles to eat.

#include <Agents/Pac.h>

#include <ThyrixLite/Simulator.h>

#include <array>
#include <cstdint>
#include <vector>

namespace thyrix {

/// A square walled arena with two Pacs, at a quarter and three quarters of its width on the
/// middle line, facing each other, and food circles placed at random without overlap. The same
/// options give the same world.
class PacSimulator : public Simulator {
 public:
  /// How the arena is made.
  struct Options {
    int food = 16;                 ///< food circles
    real foodRadius = real(0.12);  ///< their radius (m)
    real foodMass = real(0.5);     ///< their quasistatic mass (N s/m)
    real size = 8;                 ///< side of the arena (m)
    std::uint32_t seed = 1;        ///< layout seed
    real timestep = real(0.01);    ///< s; at most 0.02 with the default Pac (PacParameters)
    PacParameters pac;             ///< both Pacs are made with these
  };

  /// Pac 0 is driven by @p first, Pac 1 by @p second (either may be null: driven by hand).
  /// @throws InvalidArgument naming "PacSimulator.food" (negative, or more than fit),
  ///         "PacSimulator.size" (less than 6 times `ringRadius + radius`: no room for the
  ///         two Pacs), or the fields that Simulator, Pac and Circle check
  PacSimulator(const Options& options, std::unique_ptr<Controller> first,
               std::unique_ptr<Controller> second);

  /// Pac 0 (left, facing +x) or 1 (right, facing -x).
  [[nodiscard]] Pac& pac(int i) const { return *pacs_[static_cast<std::size_t>(i)]; }
  /// The food circles, in registration order.
  [[nodiscard]] const std::vector<Circle*>& food() const { return food_; }
  /// How many food circles have their centre inside @p pac's ring.
  [[nodiscard]] int foodInside(const Pac& pac) const;
  /// The options the arena was made with.
  [[nodiscard]] const Options& options() const { return options_; }

 private:
  Options options_;
  std::array<Pac*, 2> pacs_{};
  std::vector<Circle*> food_;
};

}  // namespace thyrix
