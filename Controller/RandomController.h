#pragma once
/// @file RandomController.h
/// @brief A controller that holds random actions for random durations.

#include <Controller/Controller.h>
#include <Tools/MTRandom.h>

#include <cstdint>
#include <vector>

namespace thyrix {

/// Draws every effector uniformly in [0, 1] and holds the values for a random number of steps
/// (uniform in [minHold, maxHold]) before drawing again, so an agent travels instead of
/// trembling in place. Sensors are ignored. The stream is seeded explicitly: the same seed
/// gives the same actions.
class RandomController : public Controller {
 public:
  /// @throws InvalidArgument naming "RandomController.minHold" (< 1) or
  ///         "RandomController.maxHold" (< minHold)
  explicit RandomController(std::uint32_t seed, int minHold = 20, int maxHold = 200);

  void control(std::span<const real> sensors, std::span<real> effectors) override;
  /// Restarts the stream from the seed.
  void reset() override;
  /// Appends the random stream, the held activations and the steps left to hold them.
  void saveState(StateRecord& record) const override;
  /// Reads back what saveState() appended.
  /// @throws std::runtime_error if the record does not hold a valid random stream
  void restoreState(StateRecord::Reader& reader) override;

 private:
  std::uint32_t seed_;
  int minHold_;
  int maxHold_;
  MTRandom random_;
  std::vector<real> held_;
  int remaining_ = 0;
};

}  // namespace thyrix
